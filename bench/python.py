#!/usr/bin/python3
"""The Python package and `genbsp batch`, measured in one run:

1. overhead: the exact map of the 50,624-triangle sphere built from Python
   (`Scene.visibility_map`, the scene read beforehand) against the build
   time `genbsp stats` reports for the same scene and eye;
2. `VisibilityMap.locate` of 10^6 random directions from a numpy array
   (exact map and --number double map);
3. throughput of a batch of 64 viewpoints of the room: `genbsp batch
   --jobs 1` against `--jobs 2`, and the same batch on a Dask LocalCluster
   of 2 worker processes, whose results must equal the serial batch's job
   by job.

Runs alternate and medians are reported.  Prints a Markdown table, writes
the measurements as JSON (--json) and a plot (--plot, matplotlib).
Run with PYTHONPATH=build/release/python (the package built with
-DGENBSP_BUILD_PYTHON=ON).
"""

import argparse
import importlib.util
import json
import os
import pathlib
import statistics
import subprocess
import sys
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "build/release/python"))
import genbsp  # noqa: E402


def cli(genbsp_program, *args):
    r = subprocess.run([genbsp_program, *map(str, args)], capture_output=True, text=True, check=True)
    return r.stdout


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--genbsp", default=str(ROOT / "build/release/tools/genbsp"))
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--out", default=str(ROOT / "build/bench-python"))
    p.add_argument("--json")
    p.add_argument("--plot")
    a = p.parse_args()
    out = pathlib.Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    res = {"genbsp": genbsp.__version__, "runs": a.runs}

    # 1. Overhead on the sphere.
    sphere = out / "sphere.off"
    eye = cli(a.genbsp, "scene", "sphere", "--n", 113, "-o", sphere).strip()
    scene = genbsp.Scene.from_file(sphere)
    cli_times, py_times = [], []
    for _ in range(a.runs):
        cli_times.append(json.loads(cli(a.genbsp, "stats", sphere, "--eye", eye))["seconds"])
        t = time.perf_counter()
        m = scene.visibility_map(eye.split(","))
        py_times.append(time.perf_counter() - t)
    res["sphere"] = {"triangles": scene.num_faces, "cli_build_s": statistics.median(cli_times), "python_build_s": statistics.median(py_times),
                     "cli_runs": cli_times, "python_runs": py_times}
    res["sphere"]["overhead"] = res["sphere"]["python_build_s"] / res["sphere"]["cli_build_s"] - 1

    # 2. locate of 10^6 directions.
    d = np.random.default_rng(1).normal(size=(1_000_000, 3))
    for exact in (True, False):
        mm = m if exact else scene.visibility_map(eye.split(","), exact=False)
        times = []
        for _ in range(a.runs):
            t = time.perf_counter()
            mm.locate(d)
            times.append(time.perf_counter() - t)
        res["locate_exact" if exact else "locate_double"] = {"directions": len(d), "seconds": statistics.median(times), "runs": times}

    # 3. Batches of the room.
    room = out / "room.off"
    reye = [float(x if "/" not in x else int(x.split("/")[0]) / int(x.split("/")[1])) for x in cli(a.genbsp, "scene", "room", "-o", room).strip().split(",")]
    rng = np.random.default_rng(3)
    jobs = [{"eye": [round(reye[0] + rng.uniform(-30, 30), 3), round(reye[1] + rng.uniform(-20, 20), 3), round(reye[2] + rng.uniform(-40, 10), 3)],
             "stats": True} for _ in range(64)]
    manifest = out / "room-64.json"
    manifest.write_text(json.dumps({"scene": str(room), "jobs": jobs}))
    wall = {1: [], 2: []}
    for _ in range(a.runs):
        for w in (1, 2):
            t = time.perf_counter()
            cli(a.genbsp, "batch", manifest, "--jobs", w)
            wall[w].append(time.perf_counter() - t)
    res["batch"] = {"jobs": 64, "jobs1_s": statistics.median(wall[1]), "jobs2_s": statistics.median(wall[2]), "runs": wall}
    res["batch"]["speedup"] = res["batch"]["jobs1_s"] / res["batch"]["jobs2_s"]
    # The same batch on Dask, against the serial batch.
    spec = importlib.util.spec_from_file_location("dask_batch", ROOT / "examples/python/dask_batch.py")
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    from dask.distributed import Client, LocalCluster

    rscene = genbsp.Scene.from_file(room)
    # Eyes as the manifest's decimals, so that both read the same numbers.
    exact_jobs = [{"eye": [repr(c) for c in j["eye"]], "stats": True} for j in jobs]
    serial = genbsp.batch(rscene, exact_jobs, workers=1).jobs
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, Client(cluster) as client:
        times = []
        for _ in range(a.runs):
            t = time.perf_counter()
            spread = example.batch_on_cluster(client, rscene, exact_jobs, chunk=4)
            times.append(time.perf_counter() - t)

    def same(r):
        return {k: v for k, v in r.items() if k != "seconds" and k != "stats"} | {
            "map": r["stats"]["map"], "fragments": r["stats"]["fragments"]}

    agree = sum(same(x) == same(y) for x, y in zip(spread, serial))
    res["dask"] = {"workers": 2, "seconds": statistics.median(times), "runs": times, "jobs_agreeing": agree, "jobs": len(serial)}

    s, b, dk = res["sphere"], res["batch"], res["dask"]
    print("| Measure | Result |\n|---|---|")
    print(f"| Sphere ({s['triangles']:,} triangles), exact build: genbsp stats | {s['cli_build_s']:.2f} s |")
    print(f"| Same, from Python | {s['python_build_s']:.2f} s ({100 * s['overhead']:+.1f} %) |")
    print(f"| locate 10^6 directions, exact map | {res['locate_exact']['seconds']:.3f} s |")
    print(f"| locate 10^6 directions, double map | {res['locate_double']['seconds']:.3f} s |")
    print(f"| Room, 64 viewpoints: batch --jobs 1 | {b['jobs1_s']:.2f} s |")
    print(f"| Same, --jobs 2 | {b['jobs2_s']:.2f} s ({b['speedup']:.2f}x) |")
    print(f"| Same on a Dask LocalCluster of 2 processes | {dk['seconds']:.2f} s; {dk['jobs_agreeing']}/{dk['jobs']} jobs equal the serial batch |")
    if a.json:
        pathlib.Path(a.json).write_text(json.dumps(res, indent=1) + "\n")
    if a.plot:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, axes = plt.subplots(1, 2, figsize=(9, 3.2))
        ax = axes[0]
        ax.bar(["genbsp stats", "Python"], [s["cli_build_s"], s["python_build_s"]], color=["#777", "#3a6ea5"])
        ax.set_ylabel("seconds")
        ax.set_title(f"Exact map, sphere of {s['triangles']:,} triangles", fontsize=9)
        ax = axes[1]
        ax.bar(["--jobs 1", "--jobs 2", "Dask, 2 workers"], [b["jobs1_s"], b["jobs2_s"], dk["seconds"]], color=["#777", "#3a6ea5", "#a5673a"])
        ax.set_ylabel("seconds")
        ax.set_title("64 viewpoints of the room", fontsize=9)
        fig.tight_layout()
        fig.savefig(a.plot, metadata={"Date": None})
    return 0 if dk["jobs_agreeing"] == dk["jobs"] else 1


if __name__ == "__main__":
    sys.exit(main())
