#!/usr/bin/python3
"""Plots the results of bench_spherical (its --json output, one or more
files, later files adding sizes): median seconds against the vertices per
loop, genbsp and Google S2, one panel per family of loops, union solid and
intersection dashed; a case a library did not finish within the limit is
drawn at the limit with an open marker.

    bench/spherical_plot.py docs/data/spherical-results-rejoin.json \\
        docs/data/spherical-results-rejoin-10000.json docs/images/bench-spherical.svg

Needs matplotlib (Debian: python3-matplotlib), hence /usr/bin/python3."""

import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 3 or any(a in ("-h", "--help") for a in sys.argv[1:]):
        print(__doc__)
        sys.exit(0 if len(sys.argv) >= 2 and sys.argv[1] in ("-h", "--help") else 2)
    rows = {}
    limit = 0
    for path in sys.argv[1:-1]:
        try:
            data = json.load(open(path, encoding="utf-8"))
        except (OSError, ValueError) as e:
            sys.exit(f"{path}: {e}")
        limit = max(limit, data["settings"]["limit_seconds"])
        for r in data["results"]:
            rows[(r["family"], r["operation"], r["size"])] = r
    families = sorted({k[0] for k in rows})
    fig, axes = plt.subplots(1, len(families), figsize=(5 * len(families), 4), squeeze=False)
    for ax, family in zip(axes[0], families):
        for op, line in (("union", "-"), ("intersection", "--")):
            case = sorted((r for k, r in rows.items() if k[0] == family and k[1] == op), key=lambda r: r["size"])
            for lib, label, color in (("genbsp", "genbsp (exact)", "C0"), ("s2", "Google S2", "C1")):
                done = [(r["size"], r[lib]["seconds"]) for r in case if r[lib]["status"] == "ok"]
                late = [(r["size"], limit) for r in case if r[lib]["status"] == "not finished"]
                if done:
                    ax.loglog(*zip(*done), "o" + line, color=color, label=f"{label}, {op}")
                if late:
                    ax.loglog(*zip(*late), "o", mfc="none", color=color, label=f"{label}, {op}: > {limit:g} s")
        ax.set_title(family + " loops")
        ax.set_xlabel("vertices per loop")
        ax.set_ylabel("seconds (median)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("Boolean operations on the sphere: genbsp (exact) and Google S2", fontsize=10)
    fig.tight_layout()
    fig.savefig(sys.argv[-1])


if __name__ == "__main__":
    main()
