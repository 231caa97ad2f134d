#!/usr/bin/python3
"""Plots of the spherical visibility map scaling benchmark (bench/svm.py).

Reads results.json and draws, log-log against the number of input edges, one
curve per scene family:

  PREFIX-time    build time (median), the chosen mode solid, the other mode
                 dashed;
  PREFIX-space   peak memory of the genbsp process;
  PREFIX-output  map edges after simplification (solid) and before (dotted).

Each legend entry gives the growth exponent k, the least-squares slope of
log y against log x over the builds that took at least 0.01 s (filled
markers; hollow markers are drawn but not fitted). Writes SVG and PNG.

Needs matplotlib (Debian: apt-get install python3-matplotlib), hence
/usr/bin/python3.
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import ticker  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import svm  # noqa: E402

COLORS = {"bricks": "#1f77b4", "hidden-bricks": "#ff7f0e", "platforms": "#2ca02c",
          "random": "#d62728", "terrain": "#9467bd", "sphere": "#8c564b"}
MARKERS = {"bricks": "o", "hidden-bricks": "s", "platforms": "^", "random": "D",
           "terrain": "v", "sphere": "P"}
PNG_MAX_BYTES = 150 * 1024


def families_of(results):
    order = results.get("config", {}).get("families") or []
    seen = {r["family"] for r in results["rows"]}
    return [f for f in order if f in seen] + sorted(seen - set(order))


def k_text(k):
    return f"k = {k:.2f}" if k is not None else "k: too few points"


def draw(ax, rows, y, label, family, linestyle, min_seconds, scale=1.0):
    pts = [(r["input_edges"], y(r) * scale, r["seconds"] >= min_seconds)
           for r in rows if r.get("input_edges") and y(r)]
    if not pts:
        return
    color, marker = COLORS.get(family, "black"), MARKERS.get(family, "o")
    ax.plot([p[0] for p in pts], [p[1] for p in pts], linestyle=linestyle, color=color,
            linewidth=1.4, label=label)
    for fitted in (True, False):
        sel = [p for p in pts if p[2] == fitted]
        if sel:
            ax.plot([p[0] for p in sel], [p[1] for p in sel], linestyle="none", marker=marker,
                    markersize=5, color=color, markerfacecolor=color if fitted else "white")


def finish(fig, ax, title, ylabel, min_seconds, path_base):
    ax.set_xscale("log")
    ax.set_yscale("log")
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_formatter(ticker.FuncFormatter(lambda v, _: f"{v:g}"))
        axis.set_minor_formatter(ticker.LogFormatter(labelOnlyBase=False))
    ax.set_xlabel("input edges (sum of the polygons' vertex counts)")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=11)
    ax.grid(True, which="major", linewidth=0.6, alpha=0.5)
    ax.grid(True, which="minor", linewidth=0.3, alpha=0.25)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    fig.text(0.01, 0.01,
             f"k: least-squares slope on log-log over builds of at least {min_seconds:g} s "
             "(filled markers)", fontsize=7, color="#444444")
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    fig.savefig(path_base + ".svg", metadata={"Date": None})
    for dpi in (100, 80, 64, 50):
        fig.savefig(path_base + ".png", dpi=dpi)
        if os.path.getsize(path_base + ".png") <= PNG_MAX_BYTES:
            break
    plt.close(fig)
    print(f"wrote {path_base}.svg, {path_base}.png", file=sys.stderr)


def main(argv=None):
    p = argparse.ArgumentParser(description="Plot bench/svm.py results: time, space and map "
                                            "size against input edges, log-log.")
    p.add_argument("--results", default=svm.default_results_path(),
                   help="results.json of bench/svm.py (default: %(default)s)")
    p.add_argument("--out-dir", default=os.path.join(svm.ROOT, "docs", "images"),
                   help="where the SVG and PNG files go (default: %(default)s)")
    p.add_argument("--mode", choices=svm.MODES, default="exact",
                   help="the arithmetic drawn solid (default: %(default)s)")
    p.add_argument("--cull", choices=["off", "on"], default="off",
                   help="off: two-sided builds; on: --cull-backfaces (default: %(default)s)")
    p.add_argument("--no-other-mode", action="store_true",
                   help="leave the other arithmetic mode (dashed) off the time plot")
    p.add_argument("--prefix", default=None,
                   help="file name prefix (default: bench, or bench-cull with --cull on)")
    p.add_argument("--min-seconds", type=float, default=svm.FIT_MIN_SECONDS,
                   help="fit only builds at least this long (default: %(default)s)")
    args = p.parse_args(argv)

    results = svm.load_results(args.results)
    cull = args.cull == "on"
    prefix = args.prefix or ("bench-cull" if cull else "bench")
    other = [m for m in svm.MODES if m != args.mode][0]
    setting = svm.cull_name(cull)
    os.makedirs(args.out_dir, exist_ok=True)
    plt.rcParams["svg.hashsalt"] = "genbsp-bench-svm"
    plt.rcParams["font.size"] = 9
    families = families_of(results)
    ms = args.min_seconds

    # Time.
    fig, ax = plt.subplots(figsize=(9.0, 5.0))
    for fam in families:
        rows = svm.ok_rows(results, fam, args.mode, cull)
        k, _ = svm.fit_exponent(rows, "seconds", min_seconds=ms)
        draw(ax, rows, lambda r: r["seconds"], f"{fam}, {args.mode}: {k_text(k)}", fam, "-", ms)
        if not args.no_other_mode:
            rows = svm.ok_rows(results, fam, other, cull)
            k, _ = svm.fit_exponent(rows, "seconds", min_seconds=ms)
            draw(ax, rows, lambda r: r["seconds"], f"{fam}, {other}: {k_text(k)}", fam, "--", ms)
    finish(fig, ax, f"Spherical visibility map: build time\n{setting}, {args.mode}"
           + ("" if args.no_other_mode else f" solid, {other} dashed"),
           "build time, s (median)", ms, os.path.join(args.out_dir, f"{prefix}-time"))

    # Space.
    fig, ax = plt.subplots(figsize=(9.0, 5.0))
    for fam in families:
        rows = svm.ok_rows(results, fam, args.mode, cull)
        k, _ = svm.fit_exponent(rows, "peak_bytes", min_seconds=ms)
        draw(ax, rows, lambda r: r["peak_bytes"], f"{fam}: {k_text(k)}", fam, "-", ms, 1e-6)
    finish(fig, ax, f"Spherical visibility map: peak memory of the process\n{setting}, {args.mode}",
           "peak memory, MB", ms, os.path.join(args.out_dir, f"{prefix}-space"))

    # Output size.
    fig, ax = plt.subplots(figsize=(9.0, 5.0))
    for fam in families:
        rows = svm.ok_rows(results, fam, args.mode, cull)
        k, _ = svm.fit_exponent(rows, "map_edges", min_seconds=ms)
        draw(ax, rows, lambda r: r["map_edges"], f"{fam}, map: {k_text(k)}", fam, "-", ms)
        k, _ = svm.fit_exponent(rows, "map_unsimplified_edges", min_seconds=ms)
        draw(ax, rows, lambda r: r["map_unsimplified_edges"],
             f"{fam}, unsimplified: {k_text(k)}", fam, ":", ms)
    finish(fig, ax, "Spherical visibility map: map edges\n"
           f"{setting}, {args.mode}; simplified solid, unsimplified dotted",
           "map edges", ms, os.path.join(args.out_dir, f"{prefix}-output"))


if __name__ == "__main__":
    main()
