"""Shared fixtures: the genbsp program (to compare with), scenes, a work folder."""

import os
import subprocess

import pytest


def pytest_addoption(parser):
    parser.addoption("--genbsp", default=os.environ.get("GENBSP"), help="the genbsp program, to compare the module with")


@pytest.fixture(scope="session")
def genbsp_cli(request):
    path = request.config.getoption("--genbsp")
    if not path or not os.path.exists(path):
        pytest.skip("the genbsp program is not given (--genbsp PATH)")
    return path


def run_cli(cli, *args, stdin=None, check=True):
    r = subprocess.run([cli, *map(str, args)], input=stdin, capture_output=True, text=True)
    if check and r.returncode != 0:
        raise AssertionError(f"genbsp {' '.join(map(str, args))}: status {r.returncode}: {r.stderr}")
    return r


@pytest.fixture(scope="session")
def scenes(tmp_path_factory, genbsp_cli):
    """Scene files and their eyes: the paper's families, the room, and a
    cube in front of a square (degenerate directions along its edges)."""
    d = tmp_path_factory.mktemp("scenes")
    out = {}
    for family, n in (("bricks", 6), ("platforms", 5), ("random", 20), ("room", 1)):
        path = d / f"{family}.off"
        eye = run_cli(genbsp_cli, "scene", family, "--n", n, "-o", path).stdout.strip()
        out[family] = (path, eye.split(","))
    cube = d / "cube.off"
    cube.write_text(CUBE_OFF)
    out["cube"] = (cube, ["0", "0", "0"])
    return out


CUBE_OFF = """OFF
12 7 0
-0.5 -0.5 2
0.5 -0.5 2
0.5 0.5 2
-0.5 0.5 2
-0.5 -0.5 3
0.5 -0.5 3
0.5 0.5 3
-0.5 0.5 3
-4 -4 5
4 -4 5
4 4 5
-4 4 5
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 2 3 7 6
4 0 4 7 3
4 1 2 6 5
4 8 11 10 9
"""
