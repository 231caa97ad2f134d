#!/usr/bin/python3
"""Report of the Boolean-operations benchmark (bench/boolean.cpp, bench_boolean).

Reads the JSON that bench_boolean writes and produces

  * a log-log plot of the median time against the input vertices (both
    operands together), one colour per library, union solid and
    intersection dashed, one panel per input family
    (docs/images/bench-boolean.svg by default);
  * the Markdown of the measured part of the section "Boolean operations in
    the plane" of docs/benchmarks.md: machine, rerun commands, the targets
    (genbsp within 3x of the fastest other library, and faster than the other
    exact one, CGAL) per case, the results table, output sizes and validity
    and the area agreement.  Printed to stdout, or written between the
    markers <!-- boolean-report:begin --> and <!-- boolean-report:end --> of
    the file given to --update (the text around the markers is kept).

With --run BINARY it first runs the benchmark (writing the JSON and CSV given
by --json and --csv) and adds the source commit, memory and kernel to the
JSON, so that one command measures and reports:

  bench/boolean_report.py --run build/bench-bool/bench/bench_boolean --update docs/benchmarks.md

Needs matplotlib for the plot (Debian: python3-matplotlib), hence
/usr/bin/python3; --no-plot skips it.
"""

import argparse
import json
import os
import platform
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report import table  # noqa: E402  (the Markdown table of the map benchmark's report)

TARGET = 3.0  # genbsp's time may be at most this multiple of the fastest other library's
EXACT_PEER = "cgal"  # the other exact library: genbsp must be faster than it
BEGIN = "<!-- boolean-report:begin -->"
END = "<!-- boolean-report:end -->"
FAMILIES = ["star", "star-narrow", "grid"]
TITLES = {"star": "Stars, radii in [0.3R, R]", "star-narrow": "Narrow stars, radii in [0.9R, R]",
          "grid": "Grid of K×K squares and shifted copy"}
NAMES = {"star": "star", "star-narrow": "narrow star", "grid": "grid"}
DASH = "—"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


# ---------------------------------------------------------------- running

def memory_text():
    try:
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemTotal:"):
                    return f"{int(line.split()[1]) / 1024 / 1024:.0f} GiB"
    except OSError:
        pass
    return None


def commit_text():
    try:
        out = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short=12", "HEAD"], capture_output=True,
                             text=True, check=True).stdout.strip()
        # docs/ is what this run writes; it does not change what was measured.
        dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no", "--", ".",
                                ":(exclude)docs"],
                               capture_output=True, text=True, check=True).stdout.strip()
        return f"commit `{out}`" + (" with uncommitted changes" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return None


def run_benchmark(binary, json_path, csv_path, extra, source):
    cmd = [binary, "--json", json_path, "--csv", csv_path] + extra
    print("running: " + " ".join(cmd), file=sys.stderr)
    # The table goes to stderr here, so that stdout carries only the Markdown.
    rc = subprocess.run(cmd, stdout=sys.stderr).returncode
    if rc not in (0, 1):
        sys.exit(f"boolean_report.py: {binary} failed with exit code {rc}")
    with open(json_path) as f:
        data = json.load(f)
    data["machine"]["memory"] = memory_text()
    data["machine"]["kernel"] = platform.release()
    data["run"]["source_commit"] = source or commit_text()
    def shown(c):  # paths inside the source tree relative to it
        inside = os.path.exists(c) and os.path.abspath(c).startswith(ROOT + os.sep)
        return os.path.relpath(c, ROOT) if inside else c
    data["run"]["command"] = " ".join(shown(c) for c in cmd)
    tmp = json_path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    os.replace(tmp, json_path)
    return data


# ---------------------------------------------------------------- formatting

def fs(t):
    """Seconds, three significant digits."""
    if t is None:
        return DASH
    return f"{t:.0f}" if t >= 100 else f"{t:.3g}"


def fx(r):
    if r is None:
        return DASH
    return f"{r:.2f}×" if r < 10 else f"{r:.3g}×"


def fi(v):
    return DASH if v is None else (f"{v:,}".replace(",", " ") if v >= 10000 else str(v))


def fe(x):
    """A relative difference."""
    if x is None:
        return DASH
    return "0" if x == 0 else f"{x:.1e}"




def status_text(m, limit):
    s = m["status"]
    if s == "not finished":
        return f"> {limit:g} s"
    if s == "skipped":
        return "skipped"
    if s.startswith("error"):
        return "error"
    return None


def seconds_cell(m, limit):
    return status_text(m, limit) or fs(m.get("seconds"))


def size_cell(m):
    if m["status"] != "ok":
        return DASH
    return f"{fi(m['polygons'])} / {fi(m['rings'])} / {fi(m['vertices'])}"


def size_text(x):
    return f"K = {x['size']}" if x["family"] == "grid" else f"n = {fi(x['size'])}"


def case_name(x):
    return f"{NAMES.get(x['family'], x['family'])} {size_text(x)}, {x['operation']}"


def ordered(results):
    order = {f: i for i, f in enumerate(FAMILIES)}
    return sorted(results, key=lambda x: (order.get(x["family"], 99), x["size"],
                                          0 if x["operation"] == "union" else 1))


# ---------------------------------------------------------------- sections

def peer_names(d):
    return [p["name"] for p in d["settings"].get("peers", [])]


def peer_label(d, name):
    for p in d["settings"].get("peers", []):
        if p["name"] == name:
            return p["label"]
    return name


SHORT = {"boost": "Boost", "clipper": "Clipper", "cgal": "CGAL"}


def short(name):
    return SHORT.get(name, name)


def machine_section(d):
    m, r, s = d["machine"], d["run"], d["settings"]
    lines = ["### Machine", ""]
    mem = f", {m['memory']} memory" if m.get("memory") else ""
    kern = f", Linux {m['kernel']}" if m.get("kernel") else ""
    lines.append(f"* {m['hardware_threads']} hardware threads, CPU `{m['cpu']}` (the `model name` of "
                 f"`/proc/cpuinfo`){mem}{kern}")
    opt = "optimised" if m.get("optimised") else "NOT optimised"
    lines.append(f"* {m['compiler']}, CMake `Release` (`-O3 -DNDEBUG`, {opt}), Boost "
                 f"{m['boost'].replace('_', '.')}, GMP {m['gmp']}")
    for p in s.get("peers", []):
        lines.append(f"* peer {p['label']}{' (exact)' if p['exact'] else ''}: timed is {p['time']}")
    lines.append(f"* genbsp (exact): timed is {s['genbsp_time']}")
    if r.get("source_commit"):
        lines.append(f"* source: {r['source_commit']}")
    minutes = r["seconds"] / 60
    took = f"{minutes:.1f} min" if minutes >= 1 else f"{r['seconds']:.0f} s"
    lines.append(f"* run started {r['started']}, {took} in all; load average {r['load_average_start']} at the "
                 f"start, {r['load_average_now']} at the end{'' if r.get('finished') else ' (interrupted)'}")
    lines.append(f"* seed {s['seed']}; limit {s['limit_seconds']:g} s per run")
    return "\n".join(lines)


def rerun_section():
    return "\n".join([
        "### Rerun", "",
        "```sh",
        "scripts/setup --bench   # Boost.Geometry, Clipper (libpolyclipping-dev), CGAL (libcgal-dev), matplotlib",
        "cmake -S . -B build/bench-bool -G Ninja -DCMAKE_BUILD_TYPE=Release \\",
        "  -DGENBSP_BUILD_TESTS=ON -DGENBSP_BUILD_BENCH=ON -DGENBSP_BUILD_DOCS=ON",
        "cmake --build build/bench-bool -j1 --target bench_boolean",
        "# measure (about 15 min), write docs/data/boolean-results.{json,csv},",
        "# docs/images/bench-boolean.svg and the measured part of this section:",
        "bench/boolean_report.py --run build/bench-bool/bench/bench_boolean --update docs/benchmarks.md",
        "build/bench-bool/bench/bench_boolean --quick     # smoke run, about 10 s",
        "build/bench-bool/bench/bench_boolean --help      # sizes, limit, seed, libraries, operations",
        "```"])


def verdict(g, m, limit, bound):
    """(verdict, ratio, note) of genbsp against one measurement with the time bound `bound` (a multiple)."""
    q = g["seconds"] / m["seconds"] if g["status"] == "ok" and m["status"] == "ok" and m["seconds"] > 0 else None
    if q is not None:
        return ("PASS" if q <= bound else "MISSED"), q
    if g["status"] != "ok" and m["status"] == "ok":
        return "MISSED", None
    if g["status"] == "ok" and m["status"] != "ok":
        return "PASS", None
    return "open", None


def fastest(x):
    best = None
    for name, m in x["peers"].items():
        if m["status"] == "ok" and (best is None or m["seconds"] < x["peers"][best]["seconds"]):
            best = name
    return best


def target_section(d):
    limit = d["settings"]["limit_seconds"]
    names = peer_names(d)
    rows, tally = [], {"fast": [0, 0, 0], "exact": [0, 0, 0]}
    index = {"PASS": 0, "MISSED": 1, "open": 2}
    for x in ordered(d["results"]):
        g = x["genbsp"]
        f = fastest(x)
        if f is None:
            # No peer finished: genbsp passes if it did.
            v1, q1 = ("PASS" if g["status"] == "ok" else "open"), None
            fcell = "none finished"
        else:
            v1, q1 = verdict(g, x["peers"][f], limit, TARGET)
            fcell = f"{short(f)} {fs(x['peers'][f]['seconds'])} s"
        tally["fast"][index[v1]] += 1
        row = [NAMES.get(x["family"], x["family"]), x["operation"], size_text(x), seconds_cell(g, limit), fcell,
               fx(q1), v1]
        if EXACT_PEER in names:
            e = x["peers"][EXACT_PEER]
            v2, q2 = verdict(g, e, limit, 1.0)
            tally["exact"][index[v2]] += 1
            row += [seconds_cell(e, limit), fx(q2), v2]
        rows.append(row)
    header = ["Input", "Operation", "Size", "genbsp s", "Fastest other", "genbsp / fastest", "Within 3×"]
    align = ["l", "l", "l", "r", "l", "r", "l"]
    if EXACT_PEER in names:
        header += ["CGAL s", "genbsp / CGAL", "Faster than CGAL"]
        align += ["r", "r", "l"]
    others = ", ".join(peer_label(d, n) for n in names)
    lines = ["### Targets", "",
             f"Two targets per case: exact genbsp within {TARGET:g}× of the fastest other library ({others}), "
             f"and faster than CGAL's `Polygon_set_2` on the exact kernel, the only other exact one. Ratio: "
             f"genbsp's median time over the other's. A case that one side did not finish within {limit:g} s "
             f"counts against it; a case neither finished stays open.", ""]
    lines.append(table(header, rows, align))
    lines.append("")
    n = len(rows)
    fast = tally["fast"]
    text = f"Within {TARGET:g}× of the fastest: {fast[0]} of {n} cases, missed in {fast[1]}"
    text += f", open in {fast[2]}." if fast[2] else "."
    ratios = [r for r in (verdict(x["genbsp"], x["peers"][fastest(x)], limit, TARGET)[1]
                          for x in d["results"] if fastest(x)) if r is not None]
    if ratios:
        text += f" genbsp took {min(ratios):.3g} to {max(ratios):.3g} times the fastest library's time."
    if EXACT_PEER in names:
        ex = tally["exact"]
        text += f" Faster than CGAL: {ex[0]} of {n} cases, slower in {ex[1]}" + (f", open in {ex[2]}." if ex[2] else ".")
    lines.append(text)
    return "\n".join(lines)


def results_section(d):
    limit = d["settings"]["limit_seconds"]
    names = peer_names(d)
    rows = []
    for x in ordered(d["results"]):
        g = x["genbsp"]
        split = (f"{fs(g.get('build_seconds'))} / {fs(g.get('merge_seconds'))} / {fs(g.get('output_seconds'))}"
                 if g["status"] == "ok" else DASH)
        runs = ", ".join(str(len(m["runs"])) for m in [g] + [x["peers"][n] for n in names])
        rows.append([NAMES.get(x["family"], x["family"]), x["operation"], size_text(x), fi(x["input_vertices"]),
                     seconds_cell(g, limit), split] + [seconds_cell(x["peers"][n], limit) for n in names] + [runs])
    lines = ["### Results", "",
             "The raw measurements: [CSV](data/boolean-results.csv) (one line per case and library), "
             "[JSON](data/boolean-results.json). Times are medians in seconds; *build / classify / output* split "
             "genbsp's time into `operand_of` of both operands, `bsp::merged_boundary` (the boundaries "
             "classified, no merged tree) and the rings' assembly (medians of each part). *Runs*: per library, "
             "in the order of the columns.", ""]
    lines.append(table(["Input", "Operation", "Size", "Input vertices", "genbsp s", "build / classify / output"]
                       + [f"{short(n)} s" for n in names] + ["Runs"],
                       rows, ["l", "l", "l", "r", "r", "r"] + ["r"] * len(names) + ["r"]))
    return "\n".join(lines)


def sizes_section(d):
    names = peer_names(d)
    rows = []
    for x in ordered(d["results"]):
        g = x["genbsp"]
        row = [NAMES.get(x["family"], x["family"]), x["operation"], size_text(x), size_cell(g)]
        for n in names:
            m = x["peers"][n]
            if m["status"] != "ok":
                row.append(DASH)
                continue
            same = g["status"] == "ok" and all(g[k] == m[k] for k in ("polygons", "rings", "vertices"))
            cell = "same" if same else size_cell(m)
            if not m.get("output_valid", True):
                cell += " (invalid)"
            row.append(cell)
        rows.append(row)
    lines = ["### Output sizes", "",
             "*P / R / V*: output polygons, rings (outer rings and holes) and vertices; *same*: equal to "
             "genbsp's three counts. *(invalid)*: the output fails `bg::is_valid` (after `bg::correct`, so that "
             "ring orientation does not count).", ""]
    lines.append(table(["Input", "Operation", "Size", "genbsp P / R / V"] + [f"{short(n)} P / R / V" for n in names],
                       rows, ["l", "l", "l"] + ["r"] * (1 + len(names))))
    return "\n".join(lines)


def agreement_section(d):
    lines = ["### Agreement with the exact result", ""]
    texts = []
    for n in peer_names(d):
        both = [x for x in d["results"] if x["genbsp"]["status"] == "ok" and x["peers"][n]["status"] == "ok"]
        label = peer_label(d, n)
        if not both:
            texts.append(f"* {label}: no case finished by both.")
            continue
        diffs = [x["peers"][n]["area_relative_difference"] for x in both]
        worst = max(both, key=lambda x: x["peers"][n]["area_relative_difference"])
        same = [x for x in both if all(x["genbsp"][k] == x["peers"][n][k] for k in ("polygons", "rings", "vertices"))]
        invalid = [x for x in both if not x["peers"][n].get("output_valid", True)]
        text = (f"* {label}, on the {len(both)} cases both finished: area differs from the exact area by at most "
                f"{fe(max(diffs))} relative ({case_name(worst)}), median {fe(sorted(diffs)[len(diffs) // 2])}. ")
        if len(same) == len(both):
            text += "Output sizes agree in every case. "
        else:
            text += (f"Output sizes agree in {len(same)}; they differ in "
                     + ", ".join(case_name(x) for x in both if x not in same) + ". ")
        if invalid:
            def why(x):
                r = x["peers"][n].get("output_invalid_reason")
                return f" (“{r}”)" if r else ""
            text += "Invalid output (`bg::is_valid`) in " + ", ".join(case_name(x) + why(x) for x in invalid) + "."
        elif not any(p["name"] == n and p["exact"] for p in d["settings"].get("peers", [])):
            text += "Every output passes `bg::is_valid`."
        texts.append(text.rstrip())
    lines += texts
    bad_input = [x for x in d["results"] if not x.get("input_valid", True)]
    if bad_input:
        lines.append("")
        lines.append("Boost.Geometry calls some inputs invalid: " + ", ".join(case_name(x) for x in bad_input) + ".")
    return "\n".join(lines)


def plot_section(image):
    return "\n".join(["### Plot", "",
                      "![Median time against input vertices (both operands), log–log, one colour per library; "
                      "union solid, intersection dashed; a triangle on the dotted line marks a run stopped at the "
                      f"limit]({image})"])


def markdown(d, image):
    return "\n\n".join([machine_section(d), rerun_section(), target_section(d), results_section(d),
                        sizes_section(d), agreement_section(d), plot_section(image)]) + "\n"


def update(path, text):
    with open(path) as f:
        doc = f.read()
    if BEGIN not in doc or END not in doc:
        sys.exit(f"boolean_report.py: {path} has no {BEGIN} ... {END} markers")
    head, rest = doc.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(head + BEGIN + "\n\n" + text + "\n" + END + tail)
    os.replace(tmp, path)


# ---------------------------------------------------------------- plot

def plot(d, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib import ticker

    plt.rcParams["svg.hashsalt"] = "genbsp-bench-boolean"
    plt.rcParams["font.size"] = 9
    limit = d["settings"]["limit_seconds"]
    families = [f for f in FAMILIES if any(x["family"] == f for x in d["results"])]
    fig, axes = plt.subplots(1, len(families), figsize=(4.2 * len(families), 4.3), sharey=True, squeeze=False)
    libraries = ["genbsp"] + peer_names(d)
    colours = {"genbsp": "#d62728", "boost": "#1f77b4", "clipper": "#2ca02c", "cgal": "#9467bd"}
    markers = {"genbsp": "o", "boost": "s", "clipper": "v", "cgal": "D"}
    labels = {"genbsp": "genbsp (exact)"}
    labels.update({n: peer_label(d, n) for n in peer_names(d)})

    def measurement(x, lib):
        return x["genbsp"] if lib == "genbsp" else x["peers"][lib]

    any_stopped = False
    lowest = limit
    for ax, fam in zip(axes[0], families):
        rows = sorted((x for x in d["results"] if x["family"] == fam), key=lambda x: x["size"])
        for li, lib in enumerate(libraries):
            color = colours.get(lib, "#7f7f7f")
            for op, ls in (("union", "-"), ("intersection", "--")):
                pts = [(x["input_vertices"], measurement(x, lib)["seconds"]) for x in rows
                       if x["operation"] == op and measurement(x, lib)["status"] == "ok"]
                stopped = [x["input_vertices"] for x in rows
                           if x["operation"] == op and measurement(x, lib)["status"] == "not finished"]
                lowest = min([lowest] + [p[1] for p in pts])
                if pts:
                    ax.plot([p[0] for p in pts], [p[1] for p in pts], linestyle=ls, color=color,
                            marker=markers.get(lib, "o"), markersize=4, linewidth=1.3,
                            markerfacecolor=color if op == "union" else "white", label=f"{labels[lib]}, {op}")
                # Stopped at the limit: a triangle on the limit line, spread
                # around the size so that every library's mark stays visible.
                shift = 0.75 * 1.09 ** (2 * li + (op == "intersection"))
                for v in stopped:
                    ax.plot([v * shift], [limit], linestyle="none", marker="^", markersize=7, color=color,
                            markerfacecolor=color if op == "union" else "white")
                    any_stopped = True
        ax.axhline(limit, color="#888888", linewidth=0.8, linestyle=":")
        ax.set_xscale("log")
        ax.set_yscale("log")
        for axis in (ax.xaxis, ax.yaxis):
            axis.set_major_formatter(ticker.FuncFormatter(lambda v, _: f"{v:g}"))
        ax.set_xlabel("input vertices (both operands)")
        ax.set_title(TITLES.get(fam, fam), fontsize=10)
        ax.grid(True, which="major", linewidth=0.6, alpha=0.5)
        ax.grid(True, which="minor", linewidth=0.3, alpha=0.25)
    axes[0][0].set_ylim(lowest / 2, limit * 4)  # shared by all panels
    axes[0][0].set_ylabel("median time (s)")
    handles, labs = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labs, loc="lower center", ncol=4, fontsize=7, frameon=False)
    note = f"dotted line: limit of {limit:g} s per run"
    if any_stopped:
        note += "; ▲ on it: stopped there, not finished"
    fig.text(0.01, 0.97, note, fontsize=7, color="#444444")
    fig.tight_layout(rect=(0, 0.13, 1, 0.96))
    tmp = path + ".tmp.svg"
    fig.savefig(tmp, metadata={"Date": None})
    os.replace(tmp, path)
    plt.close(fig)


# ---------------------------------------------------------------- main

def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--json", default=os.path.join(ROOT, "docs/data/boolean-results.json"),
                   help="results JSON to read (and with --run, to write); default docs/data/boolean-results.json")
    p.add_argument("--csv", default=os.path.join(ROOT, "docs/data/boolean-results.csv"),
                   help="with --run: results CSV to write; default docs/data/boolean-results.csv")
    p.add_argument("--run", metavar="BINARY", help="run this bench_boolean first")
    p.add_argument("--plot", default=os.path.join(ROOT, "docs/images/bench-boolean.svg"),
                   help="SVG plot to write; default docs/images/bench-boolean.svg")
    p.add_argument("--no-plot", action="store_true", help="do not draw the plot")
    p.add_argument("--image", default="images/bench-boolean.svg",
                   help="the plot's path as the Markdown links it; default images/bench-boolean.svg")
    p.add_argument("--source", metavar="TEXT",
                   help="with --run: what was built, for the record (default: the git commit, and whether the "
                        "tree has uncommitted changes)")
    p.add_argument("--update", metavar="MARKDOWN",
                   help="write the section between the markers of this file instead of to stdout")
    p.add_argument("benchmark_args", nargs="*", help="with --run: further arguments for bench_boolean (after --)")
    a = p.parse_args()
    if a.run:
        d = run_benchmark(a.run, a.json, a.csv, a.benchmark_args, a.source)
    else:
        with open(a.json) as f:
            d = json.load(f)
    if not a.no_plot:
        plot(d, a.plot)
        print(f"plot written to {a.plot}", file=sys.stderr)
    text = markdown(d, a.image)
    if a.update:
        update(a.update, text)
        print(f"section written to {a.update}", file=sys.stderr)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
