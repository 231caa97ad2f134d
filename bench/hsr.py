#!/usr/bin/env python3
"""Hidden-surface removal against its peers: for each scene family and size,
`genbsp scene` writes the scene and names its eye, and `bench_hsr` times
genbsp's exact map, a software z-buffer of the same view and (when built with
it) gl2ps's BSP export, in one run.  Prints a Markdown table with the ratios,
and writes the measurements as JSON."""

import argparse
import json
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--genbsp", default=str(ROOT / "build/release/tools/genbsp"), help="the genbsp program")
    p.add_argument("--bench", default=str(ROOT / "build/release/bench/bench_hsr"), help="the bench_hsr program")
    p.add_argument("--scenes", default="bricks:1000,hidden-bricks:1000,platforms:1000,random:1000,sphere:113",
                   help="comma-separated FAMILY:N (default: the paper's four at n = 1000 and a 50,624-triangle sphere)")
    p.add_argument("--runs", type=int, default=3, help="runs of each method; medians are reported (default 3)")
    p.add_argument("--size", type=int, default=1024, help="image size for the z-buffer and gl2ps (default 1024)")
    p.add_argument("--out", default=str(ROOT / "build/bench-hsr"), help="output directory (default build/bench-hsr)")
    p.add_argument("--json", help="also write the measurements here")
    a = p.parse_args()
    out = pathlib.Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for item in a.scenes.split(","):
        family, n = item.split(":")
        scene = out / f"{family}-{n}.off"
        eye = subprocess.run([a.genbsp, "scene", family, "--n", n, "-o", str(scene)], check=True,
                             capture_output=True, text=True).stdout.strip()
        r = subprocess.run([a.bench, str(scene), "--eye", eye, "--runs", str(a.runs), "--size", str(a.size),
                            "--gl2ps-svg", str(out / f"{family}-{n}-gl2ps.svg")], capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"hsr.py: bench_hsr failed on {family} {n}: {r.stderr.strip()}")
        m = json.loads(r.stdout)
        m.update(family=family, n=int(n), eye=eye)
        rows.append(m)
        print(f"{family} n={n}: {r.stdout.strip()}", file=sys.stderr)
    if a.json:
        pathlib.Path(a.json).write_text(json.dumps(rows, indent=1) + "\n")
    print("| Scene | Polygons | Map faces in view | genbsp exact map of the view (s) | z-buffer " + f"{a.size}² (s)" +
          " | gl2ps BSP, best root (s) | genbsp / z-buffer | genbsp / gl2ps | genbsp, all directions (s) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for m in rows:
        g = m.get("gl2ps_seconds")
        gl2ps = "—" if g is None else "%.3g" % g
        ratio = "—" if g is None else "%.2f×" % (m["map_seconds"] / g)
        print(f"| {m['family']} --n {m['n']} | {m['polygons']:,} | {m['map_faces']:,} | {m['map_seconds']:.3g} | "
              f"{m['zbuffer_seconds']:.3g} | {gl2ps} | {m['map_seconds'] / m['zbuffer_seconds']:.2f}× | {ratio} | "
              f"{m['sphere_map_seconds']:.3g} |")


if __name__ == "__main__":
    main()
