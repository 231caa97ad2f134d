#!/usr/bin/env python3
"""Plots the results of bench_visibility2d (its --json output): median time
per query against the number of edges, for genbsp and CGAL's two
Visibility_2 classes, one panel per input family; preprocessing apart.

    build/release/bench/bench_visibility2d --json docs/data/visibility2d-results.json
    bench/visibility2d_plot.py docs/data/visibility2d-results.json docs/images/bench-visibility2d.svg"""

import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: visibility2d_plot.py RESULTS.json OUT.svg")
    data = json.load(open(sys.argv[1], encoding="utf-8"))
    families = sorted({r["family"] for r in data["results"]})
    fig, axes = plt.subplots(1, len(families), figsize=(5 * len(families), 4), squeeze=False)
    for ax, family in zip(axes[0], families):
        rows = sorted((r for r in data["results"] if r["family"] == family), key=lambda r: r["edges"])
        n = [r["edges"] for r in rows]
        for key, label, style in [("genbsp_query_s", "genbsp (exact)", "o-"),
                                  ("tev_query_s", "CGAL triangular expansion (Epeck)", "s--"),
                                  ("rsv_query_s", "CGAL rotational sweep (Epeck)", "^--")]:
            ax.loglog(n, [1e3 * r[key] for r in rows], style, label=label)
        ax.loglog(n, [1e3 * r["genbsp_preprocessing_s"] for r in rows], "o:", color="grey", label="genbsp preprocessing (once)")
        ax.set_title(family)
        ax.set_xlabel("edges")
        ax.set_ylabel("ms per query (median)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("2D visibility polygons, exact; CGAL " + data.get("cgal", ""), fontsize=10)
    fig.tight_layout()
    fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
