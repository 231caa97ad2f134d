#!/usr/bin/python3
"""Hidden-line removal against Open CASCADE: for each scene family and size,
`genbsp scene` writes the scene, and `bench_hlr` times genbsp's exact hidden
lines and OCCT's polygonal HLR (and, up to --exact-max polygons, its exact
HLR) in the same parallel view, in one run, and measures how far their
drawings agree.  Prints a Markdown table, writes the measurements as JSON
and, with --plot, a plot of time against polygons.

Needs bench_hlr, built when Open CASCADE is installed (scripts/setup
--bench), and matplotlib for the plot (python3-matplotlib), hence
/usr/bin/python3.
"""

import argparse
import json
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--genbsp", default=str(ROOT / "build/release/tools/genbsp"), help="the genbsp program")
    p.add_argument("--bench", default=str(ROOT / "build/release/bench/bench_hlr"), help="the bench_hlr program")
    p.add_argument("--scenes", default="bricks:100,hidden-bricks:100,platforms:100,random:100,"
                   "bricks:1000,hidden-bricks:1000,platforms:1000,random:1000,sphere:113",
                   help="comma-separated FAMILY:N (default: the paper's four at n = 100 and 1000, a 50,624-triangle sphere)")
    p.add_argument("--dir", default="-1,1,-1", help="the view direction (default: the iso view)")
    p.add_argument("--runs", type=int, default=3, help="runs of each method; medians are reported (default 3)")
    p.add_argument("--exact-max", type=int, default=2000, help="run OCCT's exact HLR up to this many polygons (default 2000)")
    p.add_argument("--out", default=str(ROOT / "build/bench-hlr"), help="output directory (default build/bench-hlr)")
    p.add_argument("--json", help="also write the measurements here")
    p.add_argument("--plot", help="write a plot here (SVG)")
    p.add_argument("--from-json", nargs="+", help="run nothing: read these measurements (from --json) instead")
    a = p.parse_args()
    out = pathlib.Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for f in a.from_json or []:
        rows += json.loads(pathlib.Path(f).read_text())
    for item in [] if a.from_json else a.scenes.split(","):
        family, n = item.split(":")
        scene = out / f"{family}-{n}.off"
        subprocess.run([a.genbsp, "scene", family, "--n", n, "-o", str(scene)], check=True, capture_output=True, text=True)
        polygons = int(scene.read_text().split("\n")[2].split()[1])
        cmd = [a.bench, str(scene), "--dir", a.dir, "--runs", str(a.runs)]
        if polygons <= a.exact_max:
            cmd.append("--occt-exact")
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"hlr.py: bench_hlr failed on {family} {n}: {r.stderr.strip()}")
        m = json.loads(r.stdout)
        m.update(family=family, n=int(n))
        rows.append(m)
        print(f"{family} n={n}: {r.stdout.strip()}", file=sys.stderr)
    if a.json:
        pathlib.Path(a.json).write_text(json.dumps(rows, indent=1) + "\n")

    def share(x, y):
        return "—" if y == 0 else "%.2f %%" % (100 * x / y)

    print("| Scene | Polygons | Visible / hidden edges | genbsp exact (s) | OCCT polygonal (s) | genbsp / OCCT polygonal "
          "| OCCT exact (s) | OCCT's visible lines on genbsp's | OCCT's hidden lines on genbsp's |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for m in rows:
        g, o = m["genbsp"], m["occt_poly"]
        e = m.get("occt_exact")
        exact = "—" if e is None else "%.3g" % e["seconds"]
        print(f"| {m['family']} --n {m['n']} | {m['polygons']:,} | {g['visible_edges']:,} / {g['hidden_edges']:,} | "
              f"{g['seconds']:.3g} | {o['seconds']:.3g} | {g['seconds'] / o['seconds']:.2f}× | {exact} | "
              f"{share(o['visible_agreeing'], o['visible_length_px'])} | {share(o['hidden_agreeing'], o['hidden_length_px'])} |")
    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.5))
        xs = [m["polygons"] for m in rows]
        ax.scatter(xs, [m["genbsp"]["seconds"] for m in rows], label="genbsp, exact (map + lines + drawing)", marker="o")
        ax.scatter(xs, [m["occt_poly"]["seconds"] for m in rows], label="OCCT HLRBRep_PolyAlgo", marker="s")
        ex = [(m["polygons"], m["occt_exact"]["seconds"]) for m in rows if "occt_exact" in m]
        if ex:
            ax.scatter([x for x, _ in ex], [y for _, y in ex], label="OCCT HLRBRep_Algo (exact B-rep)", marker="^")
        for m in rows:
            ax.annotate(f"{m['family']} {m['n']}", (m["polygons"], m["genbsp"]["seconds"]), fontsize=6, xytext=(3, 3),
                        textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("polygons")
        ax.set_ylabel("seconds (median)")
        ax.set_title("Hidden lines, iso view: genbsp against Open CASCADE, same run")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(a.plot)


if __name__ == "__main__":
    main()
