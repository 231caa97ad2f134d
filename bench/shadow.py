#!/usr/bin/env python3
"""Shadows against the eye's map: for each scene family and size, `genbsp
scene` writes the scene and names its eye; `genbsp stats` times the eye's map
and `genbsp shadow` the pieces that a point light beside the eye reaches
(the light's visibility pass, the parts lifted back to their polygons), both
exact, in the same run; `genbsp stats --light` times the eye's map of those
pieces, which `render --shadows` draws.  Reports medians, the ratio, and the sizes, as a
Markdown table and JSON.

The light stands at the eye moved by a fifth of the scene's extent along x
and a tenth along y (plus 1/3 and 1/7, off every plane of the grid-aligned
families), so that it sees the scene much as the eye does and casts shadows
the eye can see."""

import argparse
import json
import pathlib
import statistics
import subprocess
import sys
import tempfile
from fractions import Fraction

ROOT = pathlib.Path(__file__).resolve().parent.parent


def extent(off):
    """The bounding box of an OFF file's vertices (exact fractions)."""
    words = []
    with open(off, encoding="utf-8") as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            words.extend(line)
    assert words[0] == "OFF"
    nv = int(words[1])
    coords = [Fraction(w) for w in words[4:4 + 3 * nv]]
    lo = [min(coords[k::3]) for k in range(3)]
    hi = [max(coords[k::3]) for k in range(3)]
    return lo, hi


def text(q):
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def median_seconds(cmd, runs, key):
    """Median of `runs` runs of `cmd`, each printing (or writing) JSON whose `key(json)` is seconds."""
    times, last = [], None
    for _ in range(runs):
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"shadow.py: {' '.join(cmd)} failed: {r.stderr.strip()}")
        last = key(r)
        times.append(last["seconds"])
    return statistics.median(times), last


def plot(rows, path):
    """Bars: the eye's map, the shadows and the eye's map of the pieces, per scene (log scale)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = [f"{r['family']}\nn = {r['n']}" for r in rows]
    x = range(len(rows))
    w = 0.27
    fig, ax = plt.subplots(figsize=(11, 4.2))
    ax.bar([i - w for i in x], [r["map_seconds"] for r in rows], w, label="eye's map of the scene")
    ax.bar(list(x), [r["shadow_seconds"] for r in rows], w, label="shadows (one light)")
    ax.bar([i + w for i in x], [r["lit_map_seconds"] for r in rows], w, label="eye's map of the lit pieces")
    ax.set_yscale("log")
    ax.set_ylabel("seconds (median)")
    ax.set_xticks(list(x))
    ax.set_xticklabels(names, fontsize=8)
    ax.legend(fontsize=8)
    ax.set_title("Exact shadows against the eye's map (genbsp shadow / genbsp stats, same run)")
    fig.tight_layout()
    fig.savefig(path)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--genbsp", default=str(ROOT / "build/release/tools/genbsp"), help="the genbsp program")
    p.add_argument("--scenes", default="bricks:64,bricks:256,hidden-bricks:64,hidden-bricks:256,platforms:64,platforms:256,"
                                      "random:64,random:256,random:1000,sphere:40,sphere:113",
                   help="comma-separated FAMILY:N")
    p.add_argument("--runs", type=int, default=3, help="runs of each; medians are reported (default 3)")
    p.add_argument("--json", help="write the measurements here")
    p.add_argument("--plot", help="draw the measurements here (SVG; needs matplotlib)")
    p.add_argument("--from-json", help="report (and plot) these measurements instead of measuring")
    a = p.parse_args()
    rows = []
    if a.from_json:
        rows = json.loads(pathlib.Path(a.from_json).read_text())["rows"]
        a.scenes = ""
    with tempfile.TemporaryDirectory() as tmp:
        for item in filter(None, a.scenes.split(",")):
            family, n = item.split(":")
            scene = pathlib.Path(tmp) / f"{family}-{n}.off"
            eye = subprocess.run([a.genbsp, "scene", family, "--n", n, "-o", str(scene)], check=True,
                                 capture_output=True, text=True).stdout.strip()
            e = [Fraction(x) for x in eye.split(",")]
            lo, hi = extent(scene)
            light = [e[0] + (hi[0] - lo[0]) / 5 + Fraction(1, 3), e[1] + (hi[1] - lo[1]) / 10 + Fraction(1, 7), e[2]]
            light_text = ",".join(text(q) for q in light)
            map_s, stats = median_seconds([a.genbsp, "stats", str(scene), "--eye", eye], a.runs,
                                          lambda r: json.loads(r.stdout))
            out = pathlib.Path(tmp) / "shadow.json"

            def shadow_json(_):
                return json.loads(out.read_text())["stats"]

            shadow_s, sst = median_seconds([a.genbsp, "shadow", str(scene), "--light", light_text, "-o", str(out)], a.runs,
                                           shadow_json)
            lit_map_s, lit_stats = median_seconds([a.genbsp, "stats", str(scene), "--eye", eye, "--light", light_text], a.runs,
                                                  lambda r: json.loads(r.stdout))
            row = {"family": family, "n": int(n), "eye": eye, "light": light_text, "polygons": stats["polygons"],
                   "map_seconds": map_s, "shadow_seconds": shadow_s, "ratio": shadow_s / map_s,
                   "map_fragments": stats["fragments"], "shadow_fragments": sst["fragments"],
                   "lit_parts": sst["lit_parts"], "shadowed_parts": sst["shadowed_parts"], "pieces": sst["pieces"],
                   "map_faces": stats["map"]["faces"], "lit_map_seconds": lit_map_s,
                   "lit_map_fragments": lit_stats["fragments"], "lit_map_faces": lit_stats["map"]["faces"],
                   "total_ratio": (shadow_s + lit_map_s) / map_s}
            rows.append(row)
            print(f"{family} n={n}: map {map_s:.3f} s, shadows {shadow_s:.3f} s ({row['ratio']:.2f}x), "
                  f"{row['pieces']} pieces", file=sys.stderr)
    print("| Scene | Polygons | Eye's map | Shadows | Shadows / map | Lit pieces (parts found lit + in shadow) "
          "| Eye's map of the pieces | (Shadows + that) / map | Map faces, without → with shadows |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print(f"| {r['family']} n = {r['n']} | {r['polygons']:,} | {r['map_seconds']:.3f} s | {r['shadow_seconds']:.3f} s | "
              f"{r['ratio']:.2f}× | {r['pieces']:,} ({r['lit_parts']:,} + {r['shadowed_parts']:,}) | "
              f"{r['lit_map_seconds']:.3f} s | {r['total_ratio']:.2f}× | {r['map_faces']:,} → {r['lit_map_faces']:,} |")
    if a.json and not a.from_json:
        pathlib.Path(a.json).write_text(json.dumps({"runs": a.runs, "rows": rows}, indent=1) + "\n")
    if a.plot:
        plot(rows, a.plot)


if __name__ == "__main__":
    main()
