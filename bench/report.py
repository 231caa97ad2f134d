#!/usr/bin/python3
"""Markdown report of the spherical visibility map scaling benchmark.

Reads the results.json of bench/svm.py and prints the section of
docs/benchmarks.md: the machine, how to rerun, the targets with their
measured values, the fitted growth exponents, the exact/double cost ratio,
the largest n per family within the time limit, the plots, a table per
family, and a comparison with what the paper (section 3.3) states about its
four scene families. Standard library only.
"""

import argparse
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import svm  # noqa: E402

DASH = "—"
NAMES = {"bricks": "Bricks", "hidden-bricks": "Hidden Bricks", "platforms": "Platforms",
         "random": "Random", "terrain": "Terrain", "sphere": "Sphere"}
WHAT_N = {"bricks": "boxes", "hidden-bricks": "boxes behind one larger box",
          "platforms": "slabs", "random": "randomly oriented cubes",
          "terrain": "grid side", "sphere": "bands"}


# ---------------------------------------------------------------- formatting

def name(f):
    return NAMES.get(f, f)


def fs(t):
    if t is None:
        return DASH
    return f"{t:.0f}" if t >= 100 else f"{t:.3g}"


def fk(k):
    return DASH if k is None else f"{k:.2f}"


def fx(r):
    if r is None:
        return DASH
    return f"{r:.2f}×" if r < 10 else f"{r:.3g}×"


def fmb(b):
    return DASH if b is None else f"{b / 1e6:.1f}"


def fi(v):
    return DASH if v is None else f"{v:,}".replace(",", " ") if v >= 10000 else str(v)


def table(header, rows, align=None):
    """A Markdown table with padded columns; align: 'l' or 'r' per column."""
    align = align or ["l"] + ["r"] * (len(header) - 1)
    cells = [[str(c) for c in header]] + [[str(c) for c in r] for r in rows]
    widths = [max(len(r[i]) for r in cells) for i in range(len(header))]

    def line(r):
        return "| " + " | ".join(c.rjust(w) if a == "r" else c.ljust(w)
                                 for c, w, a in zip(r, widths, align)) + " |"
    rule = "| " + " | ".join(("-" * (w - 1) + ":") if a == "r" else "-" * w
                             for w, a in zip(widths, align)) + " |"
    return "\n".join([line(cells[0]), rule] + [line(r) for r in cells[1:]])


# ---------------------------------------------------------------- analysis

class Analysis:
    def __init__(self, results, min_seconds):
        self.r = results
        self.ms = min_seconds
        self.limit = results["config"]["limit"]
        self.families = [f for f in results["config"]["families"]
                         if any(x["family"] == f for x in results["rows"])]
        self.culls = sorted({bool(x["cull"]) for x in results["rows"]})

    def rows(self, family, mode, cull):
        return svm.ok_rows(self.r, family, mode, cull)

    def all_rows(self, family, mode, cull):
        return sorted((x for x in self.r["rows"] if x["family"] == family and x["mode"] == mode
                       and bool(x["cull"]) == cull), key=lambda x: x["n"])

    def k(self, family, mode, cull, y):
        return svm.fit_exponent(self.rows(family, mode, cull), y, min_seconds=self.ms)

    def exponents(self, family, cull):
        e = {}
        e["time"], e["points"] = self.k(family, "exact", cull, "seconds")
        e["time_double"], e["points_double"] = self.k(family, "double", cull, "seconds")
        e["space"], _ = self.k(family, "exact", cull, "peak_bytes")
        e["map"], _ = self.k(family, "exact", cull, "map_edges")
        e["map_unsimplified"], _ = self.k(family, "exact", cull, "map_unsimplified_edges")
        e["fragments"], _ = self.k(family, "exact", cull, "fragments")
        return e

    def ratios(self, family, cull):
        """exact/double time ratios at the sizes where both modes were measured:
        (n, ratio) pairs sorted by n."""
        d = {x["n"]: x for x in self.rows(family, "double", cull)}
        out = []
        for x in self.rows(family, "exact", cull):
            y = d.get(x["n"])
            if y and y["seconds"] > 0:
                out.append((x["n"], x["seconds"] / y["seconds"], x["seconds"]))
        return out

    def ratio_summary(self, family, cull):
        rs = self.ratios(family, cull)
        if not rs:
            return None, None, None
        last_n, last, _ = rs[-1]
        timed = [r for _, r, t in rs if t >= self.ms]
        return last_n, last, (statistics.median(timed) if timed else None)

    def largest(self, family, mode, cull):
        """(largest n within the limit, its seconds, next row or None, capped)."""
        rows = self.all_rows(family, mode, cull)
        within = [x for x in rows if x["status"] == "ok" and x["seconds"] <= self.limit]
        best = within[-1] if within else None
        after = [x for x in rows if best is None or x["n"] > best["n"]]
        nxt = after[0] if after else None
        return best, nxt

    def range_text(self, family, mode, cull):
        rows = self.rows(family, mode, cull)
        if not rows:
            return "no sizes"
        return (f"n = {rows[0]['n']} to {rows[-1]['n']}, {fi(rows[0]['input_edges'])} to "
                f"{fi(rows[-1]['input_edges'])} input edges")


# ---------------------------------------------------------------- sections

def section_intro(a):
    c = a.r["config"]
    runs = c["runs"]
    return f"""## Spherical visibility map scaling {{#svm_scaling}}

`bench/svm.py` builds the spherical visibility map of the scene families of
`genbsp scene` at doubling sizes n, from n = {c['start_n']}, seen from each scene's
suggested eye, with `genbsp stats`: in exact and in double arithmetic
(`--number`), two-sided and with `--cull-backfaces`. A series (family,
arithmetic, back-face setting) stops after the first n whose median build
time exceeds {c['limit']:g} s. Each size is built {runs} time{'s' if runs != 1 else ''}:

* **time** is the median of the map build times that `genbsp stats` reports
  (`seconds`: the build of the map, not reading the scene);
* **peak** is the largest peak resident memory of the `genbsp` process
  (`peak_bytes`, from `getrusage`), the whole process included;
* **input edges** is the sum of the vertex counts of the scene's faces, read
  from the OFF file (each face's own boundary; every face of these families is
  a quadrilateral);
* the counts (fragments, V nodes, map vertices/edges/faces after and before
  simplification, filter fallbacks) are those of the exact build, from
  `genbsp stats`;
* a **growth exponent** k is the least-squares slope of log y against
  log(input edges) over the builds that took at least {a.ms:g} s (shorter
  builds are dominated by fixed costs and timer noise); the plots draw those
  points filled and the others hollow.

n counts: {', '.join(f'{name(f)}: {WHAT_N.get(f, "n")}' for f in a.families)}."""


def section_machine(a):
    m, g, r = a.r["machine"], a.r.get("genbsp", {}), a.r
    cpu = m.get("cpu_model") or "unknown"
    mhz = f", {m['cpu_mhz']:.0f} MHz" if m.get("cpu_mhz") else ""
    mem = f", {m['memory_bytes'] / 2**30:.0f} GiB memory" if m.get("memory_bytes") else ""
    lines = ["### Machine", "",
             f"* {m.get('nproc')} hardware threads (`nproc`), CPU `{cpu}` (the `model name` "
             f"of `/proc/cpuinfo`{mhz}){mem}, Linux {m.get('kernel')}"]
    comp = g.get("cxx_compiler_version") or m.get("compiler")
    bt = g.get("cmake_build_type")
    flags = g.get("cmake_cxx_flags_release") if bt == "Release" else None
    lines.append(f"* {comp}" + (f", CMake `{bt}`" if bt else "")
                 + (f" (`{flags}`)" if flags else ""))
    rev = g.get("git_commit")
    if rev:
        lines.append(f"* source commit `{rev[:12]}`"
                     + (" with local changes" if g.get("git_dirty") else ""))
    la0, la1 = m.get("loadavg_start"), m.get("loadavg_end")
    load = ""
    if la0:
        load = f"; load average {la0[0]:.2f} at the start"
        if la1:
            load += f", {la1[0]:.2f} at the end"
    el = r.get("elapsed_seconds")
    lines.append(f"* run on {r.get('date')}"
                 + (f", {el / 60:.0f} min in all" if el and el >= 120 else
                    (f", {el:.0f} s in all" if el else "")) + load)
    return "\n".join(lines)


def section_rerun(a):
    c = a.r["config"]
    cmd = c.get("command", "bench/svm.py")
    el = a.r.get("elapsed_seconds")
    took = ""
    if el:
        took = f"  # about {el / 60:.0f} min" if el >= 120 else f"  # about {el:.0f} s"
    lines = ["### Rerun", "",
             "The scripts need Python 3; `bench/plot.py` also needs matplotlib "
             "(Debian: `apt-get install python3-matplotlib`, found by `/usr/bin/python3`).",
             "", "```sh",
             "cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release",
             "cmake --build build/release --target genbsp_cli",
             f"{cmd}{took}",
             "bench/plot.py                # docs/images/bench-{time,space,output}.{svg,png}",
             "bench/plot.py --cull on      # docs/images/bench-cull-*.{svg,png}",
             "bench/report.py > svm.md     # this section",
             "bench/svm.py --quick         # smoke run: limit 0.2 s, 1 run per size",
             "```", "",
             "`bench/svm.py` writes `build/bench-svm/results.json` and `results.csv` "
             "(one row per family, n, arithmetic and back-face setting) and keeps the "
             "scenes in `build/bench-svm/scenes/`; `--help` lists its options "
             "(families, limit, runs, sizes, seed, output directory)."]
    return "\n".join(lines)


def target_rows(a, cull):
    """(target text, measured text, verdict) for the issue's targets."""
    out = []

    def verdict(ok):
        return "not measured" if ok is None else ("PASS" if ok else "MISSED")

    def have(f):
        return f in a.families
    ex = {f: a.exponents(f, cull) for f in a.families}

    for fam, bound, key, what in (("hidden-bricks", 1.2, "time", "time exponent"),
                                  ("random", 1.3, "time", "time exponent"),
                                  ("platforms", 1.1, "map", "simplified map size exponent")):
        k = ex[fam][key] if have(fam) else None
        out.append((f"{name(fam)}: {what} ≤ {bound}", fk(k),
                    verdict(None if k is None else k <= bound)))
    if have("bricks"):
        kt, km = ex["bricks"]["time"], ex["bricks"]["map"]
        ok = None if kt is None or km is None else kt <= km + 0.2
        meas = f"{fk(kt)} against {fk(km)} + 0.2" if ok is not None else DASH
    else:
        ok, meas = None, DASH
    out.append(("Bricks: time exponent ≤ output-size exponent + 0.2", meas, verdict(ok)))
    for f in a.families:
        n, last, _ = a.ratio_summary(f, cull)
        out.append((f"{name(f)}: exact ≤ 1.5× double",
                    f"{fx(last)} at n = {n}" if last is not None else DASH,
                    verdict(None if last is None else last <= 1.5)))
    return out


def section_targets(a):
    two = target_rows(a, False)
    lines = ["### Targets", "",
             "Exponents are those of the exact builds against input edges; the exact/double "
             "ratio is the ratio of the median build times at the largest n built in both "
             "arithmetics (the exact series' last size, unless it failed)."]
    if True in a.culls:
        cul = target_rows(a, True)
        rows = [(t, m, v, m2, v2) for (t, m, v), (_, m2, v2) in zip(two, cul)]
        lines += ["", table(["Target", "two-sided", "", "cull-backfaces", ""], rows,
                            ["l", "r", "l", "r", "l"])]
    else:
        lines += ["", table(["Target", "two-sided", ""], two, ["l", "r", "l"])]
    return "\n".join(lines)


def section_exponents(a):
    rows = []
    for cull in a.culls:
        for f in a.families:
            e = a.exponents(f, cull)
            rows.append([name(f), svm.cull_name(cull), str(e["points"]), fk(e["time"]),
                         fk(e["time_double"]), fk(e["space"]), fk(e["map"]),
                         fk(e["map_unsimplified"]), fk(e["fragments"])])
    base = [x["peak_bytes"] for x in a.r["rows"] if x.get("status") == "ok" and x.get("peak_bytes")]
    note = ""
    if base:
        note = (f"\n\nThe smallest peak measured, {min(base) / 1e6:.1f} MB, is mostly the process "
                "itself (code, libraries, allocator); it flattens the space exponent at small sizes.")
    return ("### Growth exponents\n\n"
            f"Least-squares slopes on log–log against input edges, over the builds of at least "
            f"{a.ms:g} s (*points*: how many exact builds that is; the double fit uses the double "
            "builds of at least that time). Space, map and fragment exponents are those of the "
            "exact builds.\n\n"
            + table(["Family", "Setting", "Points", "Time exact", "Time double", "Space",
                     "Map edges", "Unsimplified edges", "Fragments"], rows,
                    ["l", "l"] + ["r"] * 7) + note)


def section_ratio(a):
    rows = []
    for cull in a.culls:
        for f in a.families:
            rs = a.ratios(f, cull)
            n, last, med = a.ratio_summary(f, cull)
            rng = (f"{fx(min(r for _, r, _ in rs))} to {fx(max(r for _, r, _ in rs))}"
                   if rs else DASH)
            rows.append([name(f), svm.cull_name(cull), str(n) if n else DASH, fx(last),
                         fx(med), rng])
    return ("### Exact against double\n\n"
            "Median exact build time over median double build time at the same scene. "
            f"*Median ratio* is over the sizes whose exact build took at least {a.ms:g} s. "
            "The double builds round every object to doubles and keep each sign exact for "
            "the rounded objects; their maps can differ from the exact ones (slivers where "
            "exact circles meet in a point; on Random, whose vertices are not doubles, wrong "
            "maps), and their counts are in `results.json`.\n\n"
            + table(["Family", "Setting", "Largest common n", "Ratio there", "Median ratio",
                     "Range over all n"], rows, ["l", "l", "r", "r", "r", "l"]))


def section_largest(a):
    series = [(m, c) for c in a.culls for m in ("exact", "double")]
    rows = []
    notes = False
    for f in a.families:
        row = [name(f)]
        for m, c in series:
            best, nxt = a.largest(f, m, c)
            if best is None and nxt is None:
                row.append(DASH)
                continue
            cell = f"{best['n']} ({fs(best['seconds'])} s)" if best else "none"
            if nxt is None:
                cell += " ¹"
                notes = True
            elif nxt["status"] == "ok":
                cell += f"; {nxt['n']}: {fs(nxt['seconds'])} s"
            else:
                cell += f"; {nxt['n']}: {nxt['status']}"
            row.append(cell)
        rows.append(row)
    header = ["Family"] + [f"{m}, {svm.cull_name(c)}" for m, c in series]
    text = ("### Largest n within the limit\n\n"
            f"The largest n whose median build took at most {a.limit:g} s, with that time, "
            "then the next n and its time.\n\n"
            + table(header, rows, ["l"] + ["r"] * len(series)))
    if notes:
        text += (f"\n\n¹ the series ended without exceeding {a.limit:g} s (the --max-n cap of "
                 f"{a.r['config']['max_n']}, or a run that was stopped).")
    return text


def section_plots(a, images):
    lines = ["### Plots", "",
             f"![Build time against input edges, log–log, two-sided; exact solid, double "
             f"dashed; k fitted over builds of at least {a.ms:g} s]({images}/bench-time.svg)", "",
             f"![Peak memory against input edges, log–log, exact, two-sided]"
             f"({images}/bench-space.svg)", "",
             f"![Map edges after (solid) and before (dotted) simplification against input "
             f"edges, log–log, exact, two-sided]({images}/bench-output.svg)"]
    if True in a.culls:
        lines += ["", "With `--cull-backfaces`: "
                  f"[time]({images}/bench-cull-time.svg), [space]({images}/bench-cull-space.svg), "
                  f"[map size]({images}/bench-cull-output.svg)."]
    return "\n".join(lines)


def _status_cell(row):
    if row is None:
        return DASH
    if row["status"] != "ok":
        return row["status"]
    return fs(row["seconds"])


def family_table(a, f, cull):
    """Two-sided: every count; with cull: a compact table (map edges only)."""
    ex = {x["n"]: x for x in a.all_rows(f, "exact", cull)}
    db = {x["n"]: x for x in a.all_rows(f, "double", cull)}
    rows = []
    for n in sorted(set(ex) | set(db)):
        e, d = ex.get(n), db.get(n)
        ok = e if e and e["status"] == "ok" else None
        ratio = (e["seconds"] / d["seconds"]
                 if ok and d and d["status"] == "ok" and d["seconds"] > 0 else None)
        edges = (e or d)["input_edges"]

        def c(key):
            return fi(ok[key]) if ok else DASH

        def vef(prefix):
            return " / ".join(fi(ok[f"{prefix}_{k}"]) for k in svm.MAP_COUNTS) if ok else DASH
        row = [str(n), fi(edges), _status_cell(e), _status_cell(d), fx(ratio),
               fmb(ok["peak_bytes"]) if ok else DASH]
        if cull:
            row += [c("discarded_backfacing"), c("fragments"), c("v_nodes"), c("map_edges"),
                    c("map_unsimplified_edges"), c("filter_fallbacks")]
        else:
            row += [c("fragments"), c("v_nodes"), vef("map"), vef("map_unsimplified"),
                    c("filter_fallbacks")]
        rows.append(row)
    header = ["n", "Input edges", "Exact s", "Double s", "Exact / double", "Peak MB"]
    if cull:
        header += ["Back faces dropped", "Fragments", "V nodes", "Map E", "Unsimplified E",
                   "Fallbacks"]
    else:
        header += ["Fragments", "V nodes", "Map V / E / F", "Unsimplified V / E / F",
                   "Fallbacks"]
    return table(header, rows)


def section_tables(a):
    out = ["### Results per family", "",
           "Times are medians in seconds; peak memory and the counts are those of the exact "
           "build (— where the exact series had stopped: the double series often goes further, "
           "and its counts, which can differ, are in `results.json`); *timeout* or *failed* "
           "marks a size whose series stopped there. V / E / F: vertices, edges, faces of the "
           "map after simplification and before. With `--cull-backfaces` the table is compact: "
           "map edges only."]
    for f in a.families:
        out += ["", f"#### {name(f)}", "", family_table(a, f, False)]
        if True in a.culls:
            out += ["", f"{name(f)} with `--cull-backfaces`:", "", family_table(a, f, True)]
    return "\n".join(out)


def section_paper(a):
    out = ["### Comparison with the paper", "",
           "Section 3.3 of the paper benchmarks four scene families and plots time and space "
           "against the number of input edges (its Figures 10 and 11); it states the expected "
           "behaviour of each family but gives no figures to compare with directly. The "
           "measured behaviour here (exact, two-sided):"]
    for f in a.families:
        if f not in ("bricks", "hidden-bricks", "platforms", "random"):
            continue
        e = a.exponents(f, False)
        rows = a.rows(f, "exact", False)
        rng = a.range_text(f, "exact", False)
        last = rows[-1] if rows else None
        if e["time"] is None:
            out += ["", f"**{name(f)}.** Too few exact builds of at least {a.ms:g} s to fit "
                    f"exponents ({rng})."]
            continue
        kt, ks, km, ku = e["time"], e["space"], e["map"], e["map_unsimplified"]
        if f == "bricks":
            worst = max(k for k in (kt, ks) if k is not None)
            txt = ("The paper places the observer so that the output has size Θ(n²) and asks "
                   "whether more than quadratic time or space is needed. Here "
                   f"({rng}) the simplified map grows with exponent {fk(km)} in the input "
                   f"edges (before simplification {fk(ku)}), the build time with {fk(kt)} and "
                   f"the peak memory with {fk(ks)}: ")
            txt += ("neither time nor space grows faster than quadratically over this range"
                    if worst <= 2.05 else
                    f"{'time' if kt >= (ks or 0) else 'space'} grows faster than quadratically "
                    "over this range")
            txt += (f"; the time exponent is {kt - km:+.2f} relative to the output-size "
                    "exponent (target: at most +0.20)." if km is not None else ".")
        elif f == "hidden-bricks":
            txt = ("The paper's Hidden Bricks diagrams confirm that hidden intersections are never "
                   "computed: time and space close to linear in the input edges. Here "
                   f"({rng}) the build time grows with exponent {fk(kt)} and the peak memory "
                   f"with {fk(ks)}, while the simplified map stays at "
                   f"{fi(last['map_faces'])} faces; fragments grow with exponent "
                   f"{fk(e['fragments'])} and the unsimplified map with {fk(ku)}. ")
            txt += ("The time is close to linear, as in the paper."
                    if kt <= 1.2 else
                    "The time exponent is above the 1.2 taken here for close to linear: "
                    "the hidden boxes still cost work, in the fragments and the partition.")
        elif f == "platforms":
            txt = ("The paper uses Platforms to show an inherent weakness of binary space "
                   "partitioning: every slab is cut by the partitioning planes through all "
                   "nearer edges, so the output map is of quadratic size although a linear one "
                   f"would describe it. Here ({rng}) the map before simplification grows with "
                   f"exponent {fk(ku)}, the simplified map with {fk(km)}, the build time with "
                   f"{fk(kt)} and the peak memory with {fk(ks)}. ")
            if km is not None:
                txt += ("Simplification removes the partition edges that the paper's map keeps: "
                        "the simplified map is linear." if km <= 1.1 else
                        "Even the simplified map grows faster than linearly.")
            if ku is not None:
                txt += (f" The build time's exponent is {kt - ku:+.2f} relative to that of the "
                        "unsimplified map, the partition that the tree actually builds.")
        else:
            txt = ("The paper uses randomly oriented cubes, a scene of linear-size output, to see "
                   "how random orientations affect time and space. Here "
                   f"({rng}) the simplified map grows with exponent {fk(km)}, the build time "
                   f"with {fk(kt)} and the peak memory with {fk(ks)}; ")
            txt += ("time stays close to linear." if kt <= 1.3 else
                    "time grows clearly faster than the output.")
        out += ["", f"**{name(f)}.** {txt}"]
    return "\n".join(out)


def report(results, images, min_seconds):
    a = Analysis(results, min_seconds)
    parts = [section_intro(a), section_machine(a), section_rerun(a), section_targets(a),
             section_exponents(a), section_ratio(a), section_largest(a), section_plots(a, images),
             section_paper(a), section_tables(a)]
    if results["config"].get("quick"):
        parts.insert(1, "*These figures come from a smoke run (`--quick`: a 0.2 s limit and "
                        "one run per size); they do not measure the targets.*")
    return "\n\n".join(parts) + "\n"


def main(argv=None):
    p = argparse.ArgumentParser(description="Print the Markdown section of docs/benchmarks.md "
                                            "for a bench/svm.py results.json.")
    p.add_argument("--results", default=svm.default_results_path(),
                   help="results.json of bench/svm.py (default: %(default)s)")
    p.add_argument("--images", default="images",
                   help="link prefix of the plots, relative to the Markdown file "
                        "(default: %(default)s)")
    p.add_argument("--min-seconds", type=float, default=svm.FIT_MIN_SECONDS,
                   help="fit only builds at least this long (default: %(default)s)")
    p.add_argument("-o", "--output", default=None, help="write here instead of stdout")
    args = p.parse_args(argv)
    text = report(svm.load_results(args.results), args.images, args.min_seconds)
    if args.output:
        with open(args.output, "w", encoding="utf-8") as f:
            f.write(text)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
