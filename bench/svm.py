#!/usr/bin/python3
"""Scaling benchmark of the spherical visibility map.

For each scene family, the scene size n doubles from --start-n; every size is
built with `genbsp stats` in each arithmetic mode (exact, double) and each
back-face setting (two-sided, --cull-backfaces). A series (family, mode,
back-face setting) stops after the first n whose median build time exceeds
--limit seconds. Results go to OUT/results.json and OUT/results.csv, rewritten
whole after every measured size, so an interrupted run keeps what it measured.

Standard library only. bench/plot.py draws the results, bench/report.py
writes them as Markdown.
"""

import argparse
import csv
import datetime
import io
import json
import math
import os
import platform
import signal
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_GENBSP = os.path.join("build", "release", "tools", "genbsp")
DEFAULT_OUT = os.path.join("build", "bench-svm")
PAPER_FAMILIES = ["bricks", "hidden-bricks", "platforms", "random"]
ALL_FAMILIES = PAPER_FAMILIES + ["terrain", "sphere"]
MODES = ["exact", "double"]
SCENE_MAX_N = 1000000  # the largest --n that `genbsp scene` accepts
FIT_MIN_SECONDS = 0.01  # fits use only builds at least this long

# Plain counts of `genbsp stats`, in the order of the CSV columns.
STAT_COUNTS = [
    "input_faces", "polygons", "degenerate_faces", "triangulated_faces",
    "discarded_faces", "discarded_edge_on", "discarded_backfacing",
    "fragments", "hidden_pieces", "v_nodes",
]
MAP_COUNTS = ["vertices", "edges", "faces"]
COLUMNS = (
    ["family", "n", "seed", "eye", "mode", "cull", "status", "runs",
     "seconds", "seconds_all", "wall_seconds", "peak_bytes", "within_limit",
     "input_edges"]
    + STAT_COUNTS
    + ["map_" + k for k in MAP_COUNTS]
    + ["map_unsimplified_" + k for k in MAP_COUNTS]
    + ["filter_fallbacks", "counts_vary", "error"]
)


# ---------------------------------------------------------------- helpers
# (also used by bench/plot.py and bench/report.py)

def cull_name(cull):
    return "cull-backfaces" if cull else "two-sided"


def default_results_path():
    return os.path.join(ROOT, DEFAULT_OUT, "results.json")


def load_results(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def ok_rows(results, family=None, mode=None, cull=None):
    """Rows measured without failure, filtered, sorted by n."""
    rows = [r for r in results["rows"] if r.get("status") == "ok"
            and (family is None or r["family"] == family)
            and (mode is None or r["mode"] == mode)
            and (cull is None or bool(r["cull"]) == bool(cull))]
    return sorted(rows, key=lambda r: r["n"])


def fit_exponent(rows, y, x="input_edges", min_seconds=FIT_MIN_SECONDS):
    """Least-squares slope of log y against log x over the rows whose build
    took at least min_seconds. y is a key or a function of a row. Returns
    (exponent, number of points used); exponent is None below 2 points."""
    get = y if callable(y) else (lambda r: r.get(y))
    pts = []
    for r in rows:
        xv, yv = r.get(x), get(r)
        if (r.get("seconds") is not None and r["seconds"] >= min_seconds
                and xv and yv and xv > 0 and yv > 0):
            pts.append((math.log(xv), math.log(yv)))
    if len(pts) < 2:
        return None, len(pts)
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    if sxx == 0:
        return None, len(pts)
    sxy = sum((p[0] - mx) * (p[1] - my) for p in pts)
    return sxy / sxx, len(pts)


# ---------------------------------------------------------------- machine

def _first_line(cmd):
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=30)
        text = (out.stdout or out.stderr).strip()
        return text.splitlines()[0] if text else None
    except (OSError, subprocess.SubprocessError):
        return None


def _cpuinfo():
    model = mhz = None
    try:
        with open("/proc/cpuinfo", encoding="utf-8", errors="replace") as f:
            for line in f:
                key, _, value = line.partition(":")
                key = key.strip()
                if key == "model name" and model is None:
                    model = value.strip()
                elif key == "cpu MHz" and mhz is None:
                    mhz = float(value.strip())
    except OSError:
        pass
    return model, mhz


def _memtotal():
    try:
        with open("/proc/meminfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("MemTotal:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    return None


def _loadavg():
    try:
        return list(os.getloadavg())
    except OSError:
        return None


def machine_info():
    model, mhz = _cpuinfo()
    try:
        usable = len(os.sched_getaffinity(0))
    except AttributeError:
        usable = os.cpu_count()
    return {
        "nproc": usable,
        "cpu_count": os.cpu_count(),
        "cpu_model": model,
        "cpu_mhz": mhz,
        "memory_bytes": _memtotal(),
        "kernel": platform.release(),
        "compiler": _first_line(["c++", "--version"]),
        "python": platform.python_version(),
        "loadavg_start": _loadavg(),
    }


def build_info(genbsp):
    """Build type and compiler from the CMake cache of genbsp's build tree
    (genbsp is BUILD/tools/genbsp), and the source commit."""
    info = {"path": genbsp}
    cache = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(genbsp))),
                         "CMakeCache.txt")
    try:
        with open(cache, encoding="utf-8", errors="replace") as f:
            for line in f:
                for key in ("CMAKE_BUILD_TYPE", "CMAKE_CXX_COMPILER", "CMAKE_CXX_FLAGS_RELEASE"):
                    if line.startswith(key + ":"):
                        info[key.lower()] = line.split("=", 1)[1].strip()
    except OSError:
        pass
    if "cmake_cxx_compiler" in info:
        info["cxx_compiler_version"] = _first_line([info["cmake_cxx_compiler"], "--version"])
    try:
        st = os.stat(genbsp)
        info["binary_mtime"] = datetime.datetime.fromtimestamp(
            st.st_mtime, datetime.timezone.utc).isoformat(timespec="seconds")
    except OSError:
        pass
    commit = _first_line(["git", "-C", ROOT, "rev-parse", "HEAD"])
    if commit and len(commit) == 40:
        info["git_commit"] = commit
        try:
            st = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no"],
                                capture_output=True, text=True, timeout=60)
            info["git_dirty"] = bool(st.stdout.strip())
        except (OSError, subprocess.SubprocessError):
            pass
    return info


# ---------------------------------------------------------------- scenes

def off_counts(path):
    """(vertices, faces, edges) of an OFF file; edges is the sum of the
    faces' vertex counts (each face's own boundary edges)."""
    def lines():
        with open(path, encoding="utf-8") as f:
            for line in f:
                tokens = line.split("#", 1)[0].split()
                if tokens:
                    yield tokens
    it = lines()
    head = next(it)
    if not head[0].endswith("OFF"):
        raise ValueError(f"{path}: not an OFF file")
    counts = head[1:] if len(head) > 1 else next(it)
    nv, nf = int(counts[0]), int(counts[1])
    for _ in range(nv):
        next(it)
    edges = 0
    for _ in range(nf):
        edges += int(next(it)[0])
    return nv, nf, edges


def make_scene(genbsp, family, n, seed, path):
    cmd = [genbsp, "scene", family, "--n", str(n), "-o", path]
    if seed is not None:
        cmd += ["--seed", str(seed)]
    out = subprocess.run(cmd, capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed: {out.stderr.strip()}")
    eye = out.stdout.strip().splitlines()[-1].strip()
    return eye


# ---------------------------------------------------------------- runs

# genbsp reports its peak memory as getrusage's ru_maxrss, which Linux keeps
# across exec: a process forked from this Python interpreter would report the
# interpreter's resident size if that were larger. So genbsp runs as a child
# of a small shell that forks it (the command is not the shell's last), and
# that shell also applies the memory limit.
_SHELL = 'ulimit -v "$1" 2>/dev/null; shift; "$@"; exit $?'


def stats_once(genbsp, scene, eye, mode, cull, timeout, max_bytes):
    cmd = [genbsp, "stats", scene, "--eye", eye, "--number", mode]
    if cull:
        cmd.append("--cull-backfaces")
    limit_kb = str(max_bytes // 1024) if max_bytes else "unlimited"
    start = time.perf_counter()
    proc = subprocess.Popen(["/bin/sh", "-c", _SHELL, "sh", limit_kb] + cmd,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True)
    try:
        stdout, stderr = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        raise
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        limit = f" (address space limited to {max_bytes / 1e9:.3g} GB)" if max_bytes else ""
        raise RuntimeError(f"exit status {proc.returncode}{limit}: {stderr.strip()[-500:]}")
    for line in reversed(stdout.splitlines()):
        if line.strip().startswith("{"):
            return json.loads(line), wall
    raise RuntimeError("no JSON object in the output of genbsp stats")


def _counts_of(s):
    c = {k: s.get(k) for k in STAT_COUNTS + ["filter_fallbacks"]}
    for part, prefix in (("map", "map_"), ("map_unsimplified", "map_unsimplified_")):
        for k in MAP_COUNTS:
            c[prefix + k] = (s.get(part) or {}).get(k)
    return c


def measure(genbsp, family, n, seed, scene, eye, edges, mode, cull, args):
    row = {"family": family, "n": n, "seed": seed, "eye": eye, "mode": mode,
           "cull": cull, "input_edges": edges, "status": "ok", "error": None}
    seconds, walls, peaks, counts = [], [], [], None
    try:
        for _ in range(args.runs):
            s, wall = stats_once(genbsp, scene, eye, mode, cull, args.timeout, args.max_memory)
            seconds.append(float(s["seconds"]))
            walls.append(wall)
            peaks.append(int(s["peak_bytes"]))
            c = _counts_of(s)
            if counts is None:
                counts = c
            elif c != counts:
                row["counts_vary"] = True
    except subprocess.TimeoutExpired:
        row["status"] = "timeout"
        row["error"] = f"a run took more than {args.timeout:g} s"
    except (RuntimeError, ValueError, KeyError) as e:
        row["status"] = "failed"
        row["error"] = str(e)
    row["runs"] = len(seconds)
    row["seconds_all"] = seconds
    row["seconds"] = statistics.median(seconds) if seconds and row["status"] == "ok" else None
    row["wall_seconds"] = statistics.median(walls) if walls and row["status"] == "ok" else None
    row["peak_bytes"] = max(peaks) if peaks else None
    row.setdefault("counts_vary", False)
    row.update(counts or {})
    row["within_limit"] = row["seconds"] is not None and row["seconds"] <= args.limit
    return row


# ---------------------------------------------------------------- output

def _write_whole(path, text):
    tmp = f"{path}.tmp{os.getpid()}"
    with open(tmp, "w", encoding="utf-8", newline="") as f:
        f.write(text)
    os.replace(tmp, path)


def write_results(out_dir, results):
    _write_whole(os.path.join(out_dir, "results.json"),
                 json.dumps(results, indent=1) + "\n")
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(COLUMNS)
    for r in results["rows"]:
        cells = []
        for c in COLUMNS:
            v = r.get(c)
            if c == "seconds_all":
                v = " ".join(f"{x:.6g}" for x in (v or []))
            elif c == "cull":
                v = cull_name(v)
            elif isinstance(v, bool):
                v = "true" if v else "false"
            elif v is None:
                v = ""
            cells.append(v)
        w.writerow(cells)
    _write_whole(os.path.join(out_dir, "results.csv"), buf.getvalue())


def progress(msg):
    print(msg, file=sys.stderr, flush=True)


def _fmt_seconds(t):
    return f"{t:.3g} s" if t < 100 else f"{t:.0f} s"


# ---------------------------------------------------------------- main

def parse_args(argv):
    p = argparse.ArgumentParser(
        description="Scaling benchmark of the spherical visibility map: `genbsp stats` "
                    "over doubling scene sizes, in exact and double arithmetic, "
                    "two-sided and with back faces culled.")
    p.add_argument("--genbsp", default=None,
                   help=f"the genbsp program (default: {DEFAULT_GENBSP} in the source tree)")
    p.add_argument("--families", default=",".join(PAPER_FAMILIES),
                   help="comma-separated scene families (default: the paper's four: %(default)s; "
                        "also: terrain, sphere)")
    p.add_argument("--limit", type=float, default=None,
                   help="seconds: a series stops after the first n whose median build time "
                        "exceeds this (default 10; 0.2 with --quick)")
    p.add_argument("--runs", type=int, default=None,
                   help="builds per size; the median is reported (default 3; 1 with --quick)")
    p.add_argument("--start-n", type=int, default=4, help="first n (default %(default)s)")
    p.add_argument("--max-n", type=int, default=SCENE_MAX_N,
                   help="no n above this (default and largest: %(default)s)")
    p.add_argument("--modes", default=",".join(MODES),
                   help="comma-separated arithmetic modes (default: %(default)s)")
    p.add_argument("--cull", choices=["both", "on", "off"], default="both",
                   help="back faces: off = two-sided, on = --cull-backfaces (default: %(default)s)")
    p.add_argument("--seed", type=int, default=None,
                   help="scene seed passed to `genbsp scene` (default: its own)")
    p.add_argument("--timeout", type=float, default=None,
                   help="seconds a single run may take before the series is stopped "
                        "(default: max(60, 6 x limit))")
    p.add_argument("--max-memory", type=float, default=None,
                   help="address-space limit of each genbsp run in GB (default: 3/4 of the "
                        "machine's memory; 0 for none)")
    p.add_argument("--out", default=None,
                   help=f"output directory (default: {DEFAULT_OUT} in the source tree)")
    p.add_argument("--quick", action="store_true",
                   help="smoke run: limit 0.2 s, 1 run per size")
    args = p.parse_args(argv)

    if args.limit is None:
        args.limit = 0.2 if args.quick else 10.0
    if args.runs is None:
        args.runs = 1 if args.quick else 3
    if args.timeout is None:
        args.timeout = max(60.0, 6.0 * args.limit)
    if args.max_memory is None:
        total = _memtotal()
        args.max_memory = total * 3 // 4 if total else 0
    else:
        args.max_memory = int(args.max_memory * 1e9)
    args.families = [f.strip() for f in args.families.split(",") if f.strip()]
    args.modes = [m.strip() for m in args.modes.split(",") if m.strip()]
    args.culls = {"both": [False, True], "off": [False], "on": [True]}[args.cull]
    for f in args.families:
        if f not in ALL_FAMILIES:
            p.error(f"unknown family {f!r} (known: {', '.join(ALL_FAMILIES)})")
    for m in args.modes:
        if m not in MODES:
            p.error(f"unknown mode {m!r} (known: {', '.join(MODES)})")
    if args.runs < 1 or args.start_n < 1 or args.max_n < args.start_n:
        p.error("need --runs >= 1 and 1 <= --start-n <= --max-n")
    args.max_n = min(args.max_n, SCENE_MAX_N)
    args.genbsp = args.genbsp or os.path.join(ROOT, DEFAULT_GENBSP)
    args.out = args.out or os.path.join(ROOT, DEFAULT_OUT)
    return args


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    if not os.access(args.genbsp, os.X_OK):
        sys.exit(f"svm.py: {args.genbsp} is not an executable; build it first "
                 "(cmake --build build/release --target genbsp_cli) or pass --genbsp")
    os.makedirs(args.out, exist_ok=True)
    scene_dir = os.path.join(args.out, "scenes")
    os.makedirs(scene_dir, exist_ok=True)

    started = time.time()
    results = {
        "benchmark": "svm-scaling",
        "format": 1,
        "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "machine": machine_info(),
        "genbsp": build_info(args.genbsp),
        "config": {
            "families": args.families, "modes": args.modes,
            "cull": [cull_name(c) for c in args.culls],
            "limit": args.limit, "runs": args.runs, "start_n": args.start_n,
            "max_n": args.max_n, "seed": args.seed, "timeout": args.timeout,
            "max_memory_bytes": args.max_memory, "quick": args.quick,
            "fit_min_seconds": FIT_MIN_SECONDS,
            "command": " ".join(["bench/svm.py"] + (sys.argv[1:] if argv is None else argv)),
        },
        "rows": [],
    }

    for family in args.families:
        active = [(m, c) for m in args.modes for c in args.culls]
        n = args.start_n
        while active and n <= args.max_n:
            scene = os.path.join(scene_dir, f"{family}-{n}.off")
            try:
                eye = make_scene(args.genbsp, family, n, args.seed, scene)
                _, faces, edges = off_counts(scene)
            except (RuntimeError, ValueError, OSError, StopIteration) as e:
                progress(f"{family} n={n}: scene failed: {e}")
                break
            for mode, cull in list(active):
                row = measure(args.genbsp, family, n, args.seed, scene, eye, edges,
                              mode, cull, args)
                results["rows"].append(row)
                label = f"{family} n={n} {mode} {cull_name(cull)}"
                if row["status"] == "ok":
                    progress(f"{label}: {_fmt_seconds(row['seconds'])} (median of {row['runs']}), "
                             f"map {row['map_faces']} faces, {edges} input edges, "
                             f"peak {row['peak_bytes'] / 1e6:.1f} MB")
                    if row["input_faces"] != faces:
                        progress(f"{label}: warning: genbsp read {row['input_faces']} faces, "
                                 f"the OFF file has {faces}")
                    if row["counts_vary"]:
                        progress(f"{label}: warning: the counts differ between runs")
                else:
                    progress(f"{label}: {row['status']}: {row['error']}")
                if row["status"] != "ok" or row["seconds"] > args.limit:
                    active.remove((mode, cull))
                write_results(args.out, results)
            n *= 2

    results["machine"]["loadavg_end"] = _loadavg()
    results["elapsed_seconds"] = round(time.time() - started, 1)
    write_results(args.out, results)
    progress(f"wrote {os.path.join(args.out, 'results.json')} and results.csv "
             f"({len(results['rows'])} rows, {results['elapsed_seconds']:.0f} s)")


if __name__ == "__main__":
    main()
