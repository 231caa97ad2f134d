"""genbsp.batch against the program's batch, and the Dask example against
the serial batch, job by job."""

import importlib.util
import json
import os
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import genbsp
from conftest import run_cli

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "python" / "dask_batch.py"


def eyes(eye, n, seed=5):
    """n exact eyes around a scene's suggested one (dyadic steps, so that the
    program reads the same numbers from JSON)."""
    rng = np.random.default_rng(seed)
    e = [Fraction(c) for c in eye]
    return [[str(e[k] + Fraction(int(rng.integers(-40, 40)), 16)) for k in range(3)] for _ in range(n)]


def comparable(result):
    r = dict(result)
    r.pop("seconds", None)
    if "stats" in r:
        r["stats"] = {k: v for k, v in r["stats"].items() if "seconds" not in k and k != "peak_bytes" and k != "genbsp"}
    return r


def test_batch_equals_the_program(scenes, genbsp_cli, tmp_path):
    path, eye = scenes["room"]
    jobs = [{"id": i, "eye": e, "stats": True} for i, e in enumerate(eyes(eye, 12))]
    jobs[3]["map"] = str(tmp_path / "m3.json")
    jobs[5]["render"] = {"output": str(tmp_path / "r5.svg"), "size": [160, 120]}
    mine = genbsp.batch(path, jobs, workers=2)
    assert mine.summary["jobs"] == 12 and mine.summary["ok"] == 12 and mine.summary["workers"] == 2
    assert [r["job"] for r in mine.jobs] == list(range(12))
    svg = (tmp_path / "r5.svg").read_text()
    for f in ("m3.json", "r5.svg"):
        (tmp_path / f).unlink()
    (tmp_path / "manifest.json").write_text(json.dumps({"scene": str(path), "jobs": jobs}))
    lines = run_cli(genbsp_cli, "batch", tmp_path / "manifest.json", "--jobs", "1").stdout.splitlines()
    theirs = sorted((json.loads(l) for l in lines[:-1]), key=lambda r: r["job"])
    assert [comparable(r) for r in mine.jobs] == [comparable(r) for r in theirs]
    assert (tmp_path / "r5.svg").read_text() == svg
    # Each job's map is the one Scene.visibility_map makes.
    s = genbsp.Scene.from_file(path)
    m = s.visibility_map(jobs[7]["eye"])
    assert mine.jobs[7]["stats"]["map"] == {"vertices": len(m.vertices), "edges": len(m.edges), "faces": len(m.faces)}


def test_batch_shards_and_failures(scenes, tmp_path):
    path, eye = scenes["cube"]
    s = genbsp.Scene.from_file(path)
    jobs = [{"eye": e, "stats": True} for e in eyes(eye, 7)]
    parts = [genbsp.batch(s, jobs, shard=(i, 3)).jobs for i in range(3)]
    assert sorted(r["job"] for p in parts for r in p) == list(range(7))
    bad = [{"eye": [0, 0, 0], "map": str(tmp_path / "a.json")},
           {"eye": [0, 0, 0], "map": str(tmp_path / "b.json"), "render": {"output": str(tmp_path / "no" / "b.svg")}}]
    r = genbsp.batch(s, bad)
    assert r.jobs[0]["ok"] and not r.jobs[1]["ok"] and "cannot write" in r.jobs[1]["error"]
    # Job 1's map was written before its render failed, then removed: whole or not at all.
    assert r.summary["failed"] == 1 and (tmp_path / "a.json").exists() and not (tmp_path / "b.json").exists()
    # What can be checked before a job runs is, and nothing runs.
    with pytest.raises(ValueError, match=r"job 1\.render: .*c\.txt: unknown output format"):
        genbsp.batch(s, [{"eye": [0, 0, 0], "map": str(tmp_path / "c.json")}, {"eye": [0, 0, 0], "render": {"output": str(tmp_path / "c.txt")}}])
    assert not (tmp_path / "c.json").exists()
    with pytest.raises(ValueError, match='unknown key "rendr"'):
        genbsp.batch(s, [{"eye": [0, 0, 0], "rendr": {}}])
    with pytest.raises(ValueError, match="shard"):
        genbsp.batch(s, jobs, shard=(3, 3))


def test_dask_example_equals_the_serial_batch(scenes):
    distributed = pytest.importorskip("distributed")
    spec = importlib.util.spec_from_file_location("dask_batch", EXAMPLE)
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    path, eye = scenes["room"]
    scene = genbsp.Scene.from_arrays(genbsp.Scene.from_file(path).vertices(), genbsp.Scene.from_file(path).faces())
    jobs = [{"eye": e, "stats": True} for e in eyes(eye, 10, seed=11)]
    serial = genbsp.batch(scene, jobs).jobs
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            assert len(client.scheduler_info()["workers"]) == 2
            spread = example.batch_on_cluster(client, scene, jobs, chunk=3)
    assert [comparable(r) for r in spread] == [comparable(r) for r in serial]


@pytest.mark.parametrize("progress", [False, True])
def test_batch_progress_on_a_terminal_is_what_was_asked(scenes, progress):
    """progress=False is quiet even when standard error is a terminal;
    progress=True reports there."""
    pty = pytest.importorskip("pty")
    import subprocess
    import sys

    path, eye = scenes["cube"]
    code = (
        "import genbsp, sys\n"
        f"r = genbsp.batch({str(path)!r}, [{{'eye': {eye!r}, 'stats': True}}], workers=1, progress={progress})\n"
        "assert r.summary['ok'] == 1\n"
    )
    leader, follower = pty.openpty()
    try:
        env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
        r = subprocess.run([sys.executable, "-c", code], stderr=follower, stdout=subprocess.PIPE, env=env, timeout=120)
        os.close(follower)
        follower = -1
        chunks = []
        while True:
            try:
                b = os.read(leader, 4096)
            except OSError:  # the terminal's other end is closed
                break
            if not b:
                break
            chunks.append(b)
        text = b"".join(chunks).decode()
    finally:
        if follower >= 0:
            os.close(follower)
        os.close(leader)
    assert r.returncode == 0, text
    assert ("genbsp: batch 1/1 jobs" in text) == progress, text


def test_max_memory_is_the_programs_alone(tmp_path):
    """The interpreter owns the process: a command given --max-memory (before
    or after the subcommand) is refused, and writes nothing."""
    out = tmp_path / "x.off"
    for args in (["--max-memory", "1G", "scene", "random", "--n", "2", "-o", str(out)],
                 ["scene", "random", "--n", "2", "-o", str(out), "--max-memory", "1G"]):
        with pytest.raises(ValueError, match=r"^--max-memory: only for the genbsp program.*resource\.setrlimit"):
            genbsp._genbsp.run(args, None)
        assert not out.exists()
    # Without it, the same command runs.
    genbsp._genbsp.run(["scene", "random", "--n", "2", "-o", str(out)], None)
    assert out.exists()
