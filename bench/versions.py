#!/usr/bin/python3
"""Two builds of genbsp on the same scenes, in the same run.

Times `genbsp stats` of a baseline build (--base) and of a candidate build
(--new) on scenes of `genbsp scene`, alternating the two so that both see
the same machine, and checks that both build the same map: every count of
`genbsp stats` (fragments, hidden pieces, V nodes, map sizes before and
after simplification) must be equal. Prints a Markdown table with the
median build time (`seconds` of genbsp stats, median of --runs runs) and
peak memory of each, and their ratio; --json writes the rows.

Standard library only.

Example (the build of an older commit in /tmp/old-build):
  bench/versions.py --base /tmp/old-build/tools/genbsp \\
      --new build/release/tools/genbsp bricks:64,256 platforms:32,64
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

# Counts that must agree between the two builds.
COUNTS = ["input_faces", "polygons", "discarded_faces", "fragments", "hidden_pieces", "v_nodes"]
MAPS = ["map", "map_unsimplified"]


def stats(genbsp, scene, eye, extra):
    out = subprocess.run([genbsp, "stats", scene, "--eye", eye, *extra],
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--base", required=True, help="the baseline genbsp program")
    ap.add_argument("--new", required=True, help="the candidate genbsp program")
    ap.add_argument("--runs", type=int, default=3, help="runs of each build per scene (median; default 3)")
    ap.add_argument("--number", choices=["exact", "double"], default="exact")
    ap.add_argument("--cull-backfaces", action="store_true")
    ap.add_argument("--json", help="also write the rows as JSON to this file")
    ap.add_argument("scenes", nargs="+", metavar="FAMILY:N[,N...]",
                    help="scene families of genbsp scene and their sizes")
    a = ap.parse_args()
    if a.runs < 1:
        ap.error("--runs must be at least 1")
    extra = ["--number", a.number] + (["--cull-backfaces"] if a.cull_backfaces else [])
    rows = []
    print("| Scene | Input faces | Map faces | Base (s) | New (s) | Base/new | Base peak (MB) | New peak (MB) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as tmp:
        for spec in a.scenes:
            family, _, sizes = spec.partition(":")
            if not sizes:
                ap.error(f"'{spec}' is not FAMILY:N[,N...]")
            for n in sizes.split(","):
                scene = os.path.join(tmp, f"{family}{n}.off")
                eye = subprocess.run([a.new, "scene", family, "--n", n, "-o", scene],
                                     capture_output=True, text=True, check=True).stdout.strip()
                times = {"base": [], "new": []}
                peaks = {"base": [], "new": []}
                last = {}
                for _ in range(a.runs):
                    for name, prog in (("base", a.base), ("new", a.new)):
                        s = stats(prog, scene, eye, extra)
                        times[name].append(s["seconds"])
                        peaks[name].append(s["peak_bytes"])
                        last[name] = s
                same = all(last["base"][k] == last["new"][k] for k in COUNTS + MAPS)
                if not same:
                    diff = {k: (last["base"][k], last["new"][k]) for k in COUNTS + MAPS
                            if last["base"][k] != last["new"][k]}
                    print(f"versions.py: {family} --n {n}: the builds disagree: {diff}", file=sys.stderr)
                    sys.exit(1)
                row = {"family": family, "n": int(n), "eye": eye, "number": a.number,
                       "cull_backfaces": a.cull_backfaces,
                       "input_faces": last["new"]["input_faces"], "map_faces": last["new"]["map"]["faces"],
                       "base_seconds": statistics.median(times["base"]),
                       "new_seconds": statistics.median(times["new"]),
                       "base_peak_bytes": max(peaks["base"]), "new_peak_bytes": max(peaks["new"]),
                       "base_filter_fallbacks": last["base"]["filter_fallbacks"],
                       "new_filter_fallbacks": last["new"]["filter_fallbacks"]}
                rows.append(row)
                print(f"| {family} --n {n} | {row['input_faces']:,} | {row['map_faces']:,} "
                      f"| {row['base_seconds']:.3f} | {row['new_seconds']:.3f} "
                      f"| {row['base_seconds'] / row['new_seconds']:.2f}× "
                      f"| {row['base_peak_bytes'] / 1e6:.0f} | {row['new_peak_bytes'] / 1e6:.0f} |", flush=True)
    if a.json:
        tmpname = a.json + ".tmp"
        with open(tmpname, "w", encoding="utf-8") as f:
            json.dump({"base": a.base, "new": a.new, "runs": a.runs, "rows": rows}, f, indent=1)
        os.replace(tmpname, a.json)


if __name__ == "__main__":
    main()
