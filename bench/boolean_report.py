#!/usr/bin/python3
"""Report of the Boolean-operations benchmark (bench/boolean.cpp, bench_boolean).

Reads the JSON that bench_boolean writes and produces

  * a log-log plot of the median time against the input vertices (both
    operands together), genbsp solid and Boost.Geometry dashed, one panel per
    input family (docs/images/bench-boolean.svg by default);
  * the Markdown of the measured part of the section "Boolean operations in
    the plane" of docs/benchmarks.md: machine, rerun commands, the target
    (genbsp within 3x of Boost.Geometry's time) per case, the results table
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

TARGET = 3.0  # genbsp's time may be at most this multiple of Boost.Geometry's
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
        dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no"],
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

def machine_section(d):
    m, r, s = d["machine"], d["run"], d["settings"]
    lines = ["### Machine", ""]
    mem = f", {m['memory']} memory" if m.get("memory") else ""
    kern = f", Linux {m['kernel']}" if m.get("kernel") else ""
    lines.append(f"* {m['hardware_threads']} hardware threads, CPU `{m['cpu']}` (the `model name` of "
                 f"`/proc/cpuinfo`){mem}{kern}")
    opt = "optimised" if m.get("optimised") else "NOT optimised"
    lines.append(f"* {m['compiler']}, CMake `Release` (`-O3 -DNDEBUG`, {opt}), Boost "
                 f"{m['boost'].replace('_', '.')} (Boost.Geometry), GMP {m['gmp']}")
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
        "cmake -S . -B build/bench-bool -G Ninja -DCMAKE_BUILD_TYPE=Release \\",
        "  -DGENBSP_BUILD_TESTS=ON -DGENBSP_BUILD_BENCH=ON -DGENBSP_BUILD_DOCS=ON",
        "cmake --build build/bench-bool -j1 --target bench_boolean",
        "# measure (about 9 min), write docs/data/boolean-results.{json,csv},",
        "# docs/images/bench-boolean.svg and the measured part of this section:",
        "bench/boolean_report.py --run build/bench-bool/bench/bench_boolean --update docs/benchmarks.md",
        "build/bench-bool/bench/bench_boolean --quick     # smoke run, about 15 s",
        "build/bench-bool/bench/bench_boolean --help      # sizes, limit, seed, one library or operation",
        "```"])


def target_section(d):
    limit = d["settings"]["limit_seconds"]
    rows, met, missed, open_ = [], [], [], []
    for x in ordered(d["results"]):
        g, b, q = x["genbsp"], x["boost"], x.get("genbsp_over_boost")
        if q is not None:
            verdict = "PASS" if q <= TARGET else "MISSED"
            by = DASH if q <= TARGET else fx(q / TARGET)
            (met if q <= TARGET else missed).append((x, q))
        elif g["status"] != "ok" and b["status"] == "ok":
            verdict, by = "MISSED", f"genbsp {status_text(g, limit)}, Boost {fs(b['seconds'])} s"
            missed.append((x, None))
        elif g["status"] == "ok" and b["status"] != "ok":
            verdict, by = "PASS", f"Boost {status_text(b, limit)}"
            met.append((x, None))
        else:
            verdict = "open"
            by = ("not run: a smaller size did not finish" if "skipped" in (g["status"], b["status"])
                  else "neither finished")
            open_.append(x)
        rows.append([NAMES.get(x["family"], x["family"]), x["operation"], size_text(x), fx(q), verdict, by])
    lines = ["### Target", "",
             f"The target: exact genbsp within {TARGET:g}× of Boost.Geometry's double-precision time on every "
             f"2D case. Ratio: genbsp's median time over Boost.Geometry's. A case that one library did not "
             f"finish within {limit:g} s counts against it; a case neither finished stays open.", ""]
    lines.append(table(["Input", "Operation", "Size", "genbsp / Boost", "Verdict", "Over the target by"], rows,
                       ["l", "l", "l", "r", "l", "l"]))
    ratios = [q for _, q in met + missed if q is not None]
    lines.append("")
    summary = (f"{len(met)} of {len(rows)} cases meet the target, {len(missed)} miss it"
               + (f", {len(open_)} stay open" if open_ else "") + ".")
    if ratios:
        summary += (f" Where both finished, genbsp took {min(ratios):.3g} to {max(ratios):.3g} times Boost's "
                    f"time.")
    lines.append(summary)
    return "\n".join(lines)


def results_section(d):
    limit = d["settings"]["limit_seconds"]
    rows = []
    for x in ordered(d["results"]):
        g, b = x["genbsp"], x["boost"]
        split = (f"{fs(g.get('build_seconds'))} / {fs(g.get('merge_seconds'))} / {fs(g.get('output_seconds'))}"
                 if g["status"] == "ok" else DASH)
        runs = f"{len(g['runs'])}, {len(b['runs'])}"
        rows.append([NAMES.get(x["family"], x["family"]), x["operation"], size_text(x), fi(x["input_vertices"]),
                     seconds_cell(g, limit), split, seconds_cell(b, limit), fx(x.get("genbsp_over_boost")),
                     size_cell(g), size_cell(b), fe(x.get("area_relative_difference")), runs])
    lines = ["### Results", "",
             "The raw measurements: [CSV](data/boolean-results.csv), [JSON](data/boolean-results.json). Times "
             "are medians in seconds; *build / classify / output* split genbsp's time into `operand_of` of both "
             "operands, `bsp::merged_boundary` (the boundaries classified, no merged tree) and the rings' assembly (medians of each part). *P / R / V*: output polygons, rings "
             "(outer rings and holes) and vertices. *Area diff*: |Boost's area − exact area| / exact area. "
             "*Runs*: genbsp's and Boost's.", ""]
    lines.append(table(["Input", "Operation", "Size", "Input vertices", "genbsp s", "build / classify / output",
                        "Boost s", "genbsp / Boost", "genbsp P / R / V", "Boost P / R / V", "Area diff", "Runs"],
                       rows, ["l", "l", "l", "r", "r", "r", "r", "r", "r", "r", "r", "r"]))
    return "\n".join(lines)


def agreement_section(d):
    both = [x for x in d["results"] if x["genbsp"]["status"] == "ok" and x["boost"]["status"] == "ok"]
    lines = ["### Agreement with Boost.Geometry", ""]
    if not both:
        lines.append("No case finished in both libraries.")
        return "\n".join(lines)
    diffs = [x["area_relative_difference"] for x in both]
    worst = max(both, key=lambda x: x["area_relative_difference"])
    same = [x for x in both if all(x["genbsp"][k] == x["boost"][k] for k in ("polygons", "rings", "vertices"))]
    invalid = [x for x in both if not x["boost"].get("output_valid", True)]
    text = (f"On the {len(both)} cases both libraries finished, Boost.Geometry's area differs from the exact "
            f"area by at most {fe(max(diffs))} relative ({case_name(worst)}); the median is "
            f"{fe(sorted(diffs)[len(diffs) // 2])}. ")
    if len(same) == len(both):
        text += "The output sizes (polygons, rings, vertices) agree in every one of them. "
    else:
        diff_names = ", ".join(case_name(x) for x in both if x not in same)
        text += f"The output sizes agree in {len(same)} of them; they differ in {diff_names}. "
    if invalid:
        def why(x):
            r = x["boost"].get("output_invalid_reason")
            return f" (“{r}”)" if r else ""
        text += ("Boost.Geometry's output fails `bg::is_valid` in "
                 + ", ".join(case_name(x) + why(x) for x in invalid) + ".")
    else:
        text += "Every Boost.Geometry output passes `bg::is_valid`."
    bad_input = [x for x in d["results"] if not x.get("boost_input_valid", True)]
    if bad_input:
        text += " Boost.Geometry calls some inputs invalid: " + ", ".join(case_name(x) for x in bad_input) + "."
    lines.append(text)
    return "\n".join(lines)


def plot_section(image):
    return "\n".join(["### Plot", "",
                      "![Median time against input vertices (both operands), log–log; genbsp solid, "
                      "Boost.Geometry dashed; a triangle on the dotted line marks a run stopped at the "
                      f"limit]({image})"])


def markdown(d, image):
    return "\n\n".join([machine_section(d), rerun_section(), target_section(d), results_section(d),
                        agreement_section(d), plot_section(image)]) + "\n"


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
    fig, axes = plt.subplots(1, len(families), figsize=(4.2 * len(families), 4.0), sharey=True, squeeze=False)
    styles = {("genbsp", "union"): ("#1f77b4", "o", "-"), ("genbsp", "intersection"): ("#ff7f0e", "s", "-"),
              ("boost", "union"): ("#1f77b4", "o", "--"), ("boost", "intersection"): ("#ff7f0e", "s", "--")}
    any_stopped = False
    lowest = limit
    for ax, fam in zip(axes[0], families):
        rows = sorted((x for x in d["results"] if x["family"] == fam), key=lambda x: x["size"])
        for lib, label in (("genbsp", "genbsp exact"), ("boost", "Boost.Geometry double")):
            for op in ("union", "intersection"):
                color, marker, ls = styles[(lib, op)]
                pts = [(x["input_vertices"], x[lib]["seconds"]) for x in rows
                       if x["operation"] == op and x[lib]["status"] == "ok"]
                stopped = [x["input_vertices"] for x in rows
                           if x["operation"] == op and x[lib]["status"] == "not finished"]
                lowest = min([lowest] + [p[1] for p in pts])
                if pts:
                    ax.plot([p[0] for p in pts], [p[1] for p in pts], linestyle=ls, color=color, marker=marker,
                            markersize=5, linewidth=1.4, markerfacecolor=color if lib == "genbsp" else "white",
                            label=f"{label}, {op}")
                # Stopped at the limit: an upward triangle on the limit line, genbsp
                # left of the size and Boost right of it, so that all four stay visible.
                shift = {("genbsp", "union"): 0.8, ("genbsp", "intersection"): 0.92,
                         ("boost", "union"): 1.08, ("boost", "intersection"): 1.25}[(lib, op)]
                for v in stopped:
                    ax.plot([v * shift], [limit], linestyle="none", marker="^", markersize=8, color=color,
                            markerfacecolor=color if lib == "genbsp" else "white")
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
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=8, frameon=False)
    note = f"dotted line: limit of {limit:g} s per run"
    if any_stopped:
        note += "; ▲: stopped there, not finished (genbsp left of its size, Boost.Geometry right)"
    fig.text(0.01, 0.97, note, fontsize=7, color="#444444")
    fig.tight_layout(rect=(0, 0.07, 1, 0.96))
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
