// Exact Boolean operations in the plane (boolean::operand_of, combine)
// against the libraries people use instead, on the same inputs in the same
// run: Boost.Geometry (double), Clipper 1 (64-bit integers) and CGAL's
// Polygon_set_2 on the exact kernel Epeck, the last two when their Debian
// packages are present at build time (scripts/setup --bench).  Inputs:
//   star         two random star-shaped polygons of n vertices each, integer
//                coordinates, radii uniform in [0.3R, R], different centres
//                and seeds, heavily overlapping: long thin spikes whose
//                boundaries cross thousands of times from n = 1000 on;
//   star-narrow  the same with radii in [0.9R, R]: two random n-gons hugging
//                one circle, far fewer crossings;
//   grid         K×K unit squares at (2i, 2j) against the same grid shifted
//                by (1/2, 1/2): every square overlaps exactly one square of
//                the copy.
//
// The genbsp time of a case is the whole job from exact input rings to valid
// output rings: operand_of(A) + operand_of(B) (build), the boundaries
// classified against both trees (classify) and the rings assembled (output).
// A peer's time is its own whole job from its input type (boolean_peers.hpp;
// each peer's file says what is timed).  Converting the inputs and
// destroying the results is not timed.
//
// Each library runs each case in a child process, so that a run that exceeds
// the time limit can be stopped and recorded as not finished (every library
// grows faster than linearly on some of these inputs).  Progress goes to
// stderr, the table to stdout, the results to JSON and CSV (rewritten after
// every case, so an interrupted run keeps what it measured).
#include <geometry/gmp_pool.hpp>
#include <boolean/polygons.hpp>

#include <boost/version.hpp>

#include <gmp.h>
#include <poll.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>
#include <vector>

#include "boolean_peers.hpp"
#include "common.hpp"

namespace {

namespace peers = bench::boolean_peers;
using boolean::multipolygon;
using boolean::ring;
using boolean::set_op;
using geometry::rational;
using P = boolean::point2;
using clock_type = std::chrono::steady_clock;

double seconds_since(clock_type::time_point t0) {
  return std::chrono::duration<double>(clock_type::now() - t0).count();
}

// ---------------------------------------------------------------------------
// Command line

struct options {
  bool quick = false;
  std::optional<std::string> json, csv;
  std::uint64_t seed = 20261129;
  std::vector<std::size_t> stars{100, 1000, 10000, 100000};
  std::vector<std::size_t> narrow_stars{100, 1000, 10000, 100000};
  std::vector<std::size_t> grids{10, 30, 100};
  bool genbsp = true;                      ///< whether genbsp runs
  std::vector<peers::peer> peers;          ///< the peers that run (all built ones unless --libraries)
  bool union_ = true, intersection = true; ///< the operations to run
  /// Seconds one run may take before it is stopped.  With the default sizes
  /// a few runs per library reach it.
  double limit = 45;
  bench::repetition repeat; ///< runs per case; the median is reported
};

std::string library_names() {
  std::string s = "genbsp";
  for (auto const& p : peers::available()) s += "," + p.name;
  return s;
}

void print_help() {
  std::printf("Usage: bench_boolean [--quick] [--json FILE] [--csv FILE] [--seed N] [--limit S]\n"
              "                     [--stars N,...] [--narrow-stars N,...] [--grids K,...]\n"
              "                     [--libraries L,...] [--operations union,intersection]\n"
              "\n"
              "Times genbsp's exact Boolean operations in the plane (operand_of each operand,\n"
              "combine) against other libraries' union and intersection on the same input:\n"
              "two random star polygons of n vertices each (radii uniform in [0.3R, R];\n"
              "narrow stars: in [0.9R, R]), and a K x K grid of unit squares at (2i, 2j)\n"
              "against its copy shifted by (1/2, 1/2).  Reports the median time of 3 runs\n"
              "(more for cases under 0.25 s, one for cases over 10 s), the output size\n"
              "(polygons, rings, vertices), the area (exact for genbsp), whether an inexact\n"
              "library's output is valid (bg::is_valid), and genbsp's time over the fastest\n"
              "other library's.  Each library runs each case in a child process, stopped\n"
              "after the limit.\n"
              "\n"
              "Libraries in this build: %s\n",
              library_names().c_str());
  for (auto const& p : peers::available())
    std::printf("  %-8s %s: %s\n", p.name.c_str(), p.label.c_str(), p.timed.c_str());
  std::puts("(Clipper and CGAL are built in when libpolyclipping-dev and libcgal-dev are\n"
            "installed at configure time: scripts/setup --bench.)\n"
            "\n"
            "  --quick          stars of 100 and 1000 vertices, grids 10 and 30, limit 10 s\n"
            "  --json FILE      write the results as JSON to FILE\n"
            "  --csv FILE       write the results as CSV to FILE (one line per case and library)\n"
            "  --seed N         seed of the star polygons (default 20261129)\n"
            "  --limit S        stop a run after S seconds: not finished (default 45); larger\n"
            "                   sizes of the same library, family and operation are then skipped\n"
            "  --stars LIST     star sizes, vertices per polygon (default 100,1000,10000,100000);\n"
            "                   0 for none (also in the next two)\n"
            "  --narrow-stars LIST  narrow star sizes (default 100,1000,10000,100000)\n"
            "  --grids LIST     grid sides K (default 10,30,100)\n"
            "  --libraries L    some of the libraries above, comma-separated (default all)\n"
            "  --operations L   union, intersection or both (default union,intersection)\n"
            "  --help           this text");
}

std::optional<std::vector<std::size_t>> parse_list(std::string_view v) {
  std::vector<std::size_t> out;
  std::string s(v);
  std::size_t pos = 0;
  while (pos <= s.size()) {
    std::size_t comma = s.find(',', pos);
    if (comma == std::string::npos) comma = s.size();
    std::string item = s.substr(pos, comma - pos);
    char* end = nullptr;
    unsigned long long n = std::strtoull(item.c_str(), &end, 10);
    if (item.empty() || item.front() == '-' || *end != '\0') return std::nullopt;
    if (n > 0) out.push_back(static_cast<std::size_t>(n));
    pos = comma + 1;
  }
  return out;
}

/// The items of a comma-separated list.
std::vector<std::string> split(std::string_view v) {
  std::vector<std::string> out;
  std::string list(v);
  for (std::size_t pos = 0; pos <= list.size();) {
    std::size_t comma = std::min(list.find(',', pos), list.size());
    out.push_back(list.substr(pos, comma - pos));
    pos = comma + 1;
  }
  return out;
}

/// Parses the command line; returns the exit code to stop with, if any.
std::optional<int> parse_options(int argc, char** argv, options& o) {
  bool stars_given = false, narrow_given = false, grids_given = false, limit_given = false;
  o.peers = peers::available();
  for (int i = 1; i < argc; ++i) {
    std::string_view a = argv[i];
    if (a == "--help" || a == "-h") {
      print_help();
      return 0;
    }
    if (a == "--quick") {
      o.quick = true;
      continue;
    }
    if (a != "--json" && a != "--csv" && a != "--seed" && a != "--limit" && a != "--stars" && a != "--narrow-stars" &&
        a != "--grids" && a != "--libraries" && a != "--operations") {
      std::fprintf(stderr, "bench_boolean: unknown argument '%s' (try --help)\n", argv[i]);
      return 2;
    }
    if (i + 1 >= argc) {
      std::fprintf(stderr, "bench_boolean: %s needs an argument (try --help)\n", argv[i]);
      return 2;
    }
    std::string_view v = argv[++i];
    auto bad = [&](std::string const& what) {
      std::fprintf(stderr, "bench_boolean: %s needs %s, not '%s'\n", argv[i - 1], what.c_str(), argv[i]);
      return 2;
    };
    if (a == "--json") {
      o.json = std::string(v);
    } else if (a == "--csv") {
      o.csv = std::string(v);
    } else if (a == "--seed") {
      char* end = nullptr;
      unsigned long long n = std::strtoull(argv[i], &end, 10);
      if (v.empty() || v.front() == '-' || *end != '\0') return bad("a non-negative integer");
      o.seed = n;
    } else if (a == "--limit") {
      char* end = nullptr;
      double s = std::strtod(argv[i], &end);
      if (v.empty() || *end != '\0' || !(s > 0)) return bad("a positive number of seconds");
      o.limit = s;
      limit_given = true;
    } else if (a == "--libraries") {
      auto built = peers::available();
      o.genbsp = false;
      o.peers.clear();
      for (auto const& item : split(v)) {
        if (item == "genbsp") {
          o.genbsp = true;
          continue;
        }
        auto p = std::find_if(built.begin(), built.end(), [&](peers::peer const& q) { return q.name == item; });
        if (p == built.end()) {
          if (item == "clipper" || item == "cgal")
            std::fprintf(stderr,
                         "bench_boolean: this build has no %s (install libpolyclipping-dev and libcgal-dev with "
                         "scripts/setup --bench, then configure again)\n",
                         item.c_str());
          return bad("some of " + library_names());
        }
        if (std::none_of(o.peers.begin(), o.peers.end(), [&](peers::peer const& q) { return q.name == item; }))
          o.peers.push_back(*p);
      }
    } else if (a == "--operations") {
      o.union_ = o.intersection = false;
      for (auto const& item : split(v)) {
        if (item == "union")
          o.union_ = true;
        else if (item == "intersection")
          o.intersection = true;
        else
          return bad("union, intersection or union,intersection");
      }
    } else {
      auto l = parse_list(v);
      if (!l) return bad("a comma-separated list of non-negative integers");
      (a == "--stars" ? o.stars : a == "--grids" ? o.grids : o.narrow_stars) = *l;
      (a == "--stars" ? stars_given : a == "--grids" ? grids_given : narrow_given) = true;
    }
  }
  if (o.quick) {
    if (!stars_given) o.stars = {100, 1000};
    if (!narrow_given) o.narrow_stars = {100, 1000};
    if (!grids_given) o.grids = {10, 30};
    if (!limit_given) o.limit = 10;
  }
  return std::nullopt;
}

// ---------------------------------------------------------------------------
// Input

/// A star-shaped ring of about `n` vertices around (cx, cy), counter-clockwise,
/// integer coordinates: vertex i at angle 2π(i + 0.1 + 0.8u)/n and radius
/// R(f + (1 − f)u') (u, u' uniform in [0, 1)), rounded.  A vertex that rounding
/// would put on or behind the ray of its predecessor (seen from the centre) is
/// dropped, so the ring stays strictly star-shaped around the centre, hence
/// simple; with R = 10^6 and n ≤ 10^5 that does not happen.
ring random_star(std::mt19937_64& rng, std::size_t n, std::int64_t cx, std::int64_t cy, double radius, double f) {
  std::uniform_real_distribution<double> u(0, 1);
  struct ipoint {
    std::int64_t x, y;
  };
  std::vector<ipoint> v;
  v.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    double t = 2 * std::numbers::pi * (static_cast<double>(i) + 0.1 + 0.8 * u(rng)) / static_cast<double>(n);
    double r = radius * (f + (1 - f) * u(rng));
    v.push_back({cx + std::llround(r * std::cos(t)), cy + std::llround(r * std::sin(t))});
  }
  // Cross product of consecutive vertices seen from the centre (|coordinates| ≤ 2·10^6: no overflow).
  auto turns_left = [&](ipoint const& a, ipoint const& b) {
    return (a.x - cx) * (b.y - cy) - (a.y - cy) * (b.x - cx) > 0;
  };
  std::vector<ipoint> kept;
  for (auto const& p : v)
    if (kept.empty() || turns_left(kept.back(), p)) kept.push_back(p);
  while (kept.size() > 3 && !turns_left(kept.back(), kept.front())) kept.pop_back();
  ring out;
  out.reserve(kept.size());
  for (auto const& p : kept) out.emplace_back(rational(static_cast<long>(p.x)), rational(static_cast<long>(p.y)));
  return out;
}

/// K×K squares of side 1 at (2i + d, 2j + d), i, j < K.
multipolygon grid(std::size_t k, rational const& d) {
  multipolygon m;
  m.reserve(k * k);
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < k; ++j) {
      rational x0 = rational(static_cast<long>(2 * i)) + d, y0 = rational(static_cast<long>(2 * j)) + d;
      rational x1 = x0 + 1, y1 = y0 + 1;
      m.push_back({ring{P(x0, y0), P(x1, y0), P(x1, y1), P(x0, y1)}, {}});
    }
  return m;
}

std::size_t vertex_count(multipolygon const& m) {
  std::size_t n = 0;
  for (auto const& p : m) {
    n += p.outer.size();
    for (auto const& h : p.holes) n += h.size();
  }
  return n;
}

std::size_t ring_count(multipolygon const& m) {
  std::size_t n = 0;
  for (auto const& p : m) n += 1 + p.holes.size();
  return n;
}


/// `m` in double for the peers; every coordinate converts exactly (checked).
peers::polygons to_plain(multipolygon const& m) {
  auto conv = [](ring const& r) {
    peers::path out;
    for (auto const& p : r) {
      double x = p.x().convert_to<double>(), y = p.y().convert_to<double>();
      if (rational(x) != p.x() || rational(y) != p.y())
        throw std::logic_error("bench_boolean: an input coordinate is not exact in double");
      out.push_back({x, y});
    }
    return out;
  };
  peers::polygons out;
  for (auto const& p : m) {
    peers::polygon q{conv(p.outer), {}};
    for (auto const& h : p.holes) q.holes.push_back(conv(h));
    out.push_back(std::move(q));
  }
  return out;
}

// ---------------------------------------------------------------------------
// Measurement

/// Output size and area of one library's result.
struct output_size {
  std::size_t polygons = 0, rings = 0, vertices = 0;
  double area = 0;
};

struct measurement {
  std::string status = "not run";                ///< "ok", "not finished", "skipped" or "error: …"
  std::vector<double> runs;                      ///< seconds of each run (whole job)
  std::vector<double> build, merge, output;      ///< genbsp: seconds of each phase of each run
  double seconds = 0;                            ///< median of `runs`
  double build_s = 0, merge_s = 0, output_s = 0; ///< medians of the phases
  output_size out;
  std::size_t area_bits = 0; ///< genbsp: bits of the exact area's numerator and denominator
  /// genbsp: interior nodes and depth of the trees of A, of B and of the result.
  std::size_t tree_nodes[3] = {0, 0, 0}, tree_depth[3] = {0, 0, 0};
  bool valid = true;          ///< an inexact peer: bg::is_valid of its output
  std::string invalid_reason; ///< why bg::is_valid refuses it
};

using bench::median;

using bench::write_all;

/// Lines a measuring child process sends: "run SECONDS [BUILD MERGE OUTPUT]"
/// after each run, "result POLYGONS RINGS VERTICES AREA EXTRA" after the
/// first (EXTRA: bits of genbsp's exact area, or whether Boost's output is

/// Lines a measuring child process sends: "run SECONDS [BUILD MERGE OUTPUT]"
/// after each run, "result POLYGONS RINGS VERTICES AREA EXTRA" after the
/// first (EXTRA: bits of genbsp's exact area, or whether a peer's output is
/// valid), for genbsp also "trees NODES DEPTH …" (A, B, result), for an
/// invalid output "invalid REASON", then "done", or "error MESSAGE".
void send_run(int fd, double total, double build = -1, double merge = -1, double output = -1) {
  char line[160];
  std::snprintf(line, sizeof line, "run %.9g %.9g %.9g %.9g\n", total, build, merge, output);
  write_all(fd, line);
}

void send_result(int fd, std::size_t polygons, std::size_t rings, std::size_t vertices, double area,
                 std::size_t extra) {
  char line[160];
  std::snprintf(line, sizeof line, "result %zu %zu %zu %.17g %zu\n", polygons, rings, vertices, area, extra);
  write_all(fd, line);
}

/// The genbsp runs of one case (in a child process).
void genbsp_child(int fd, set_op op, multipolygon const& a, multipolygon const& b, options const& o) {
  std::vector<double> runs;
  while (o.repeat.another_run(runs)) {
    auto t0 = clock_type::now();
    auto ra = boolean::operand_of(a);
    auto rb = boolean::operand_of(b);
    auto t1 = clock_type::now();
    // What boolean::combine does, timed in its two parts: the operands'
    // boundaries classified against both trees, then the rings assembled.
    auto pieces = bsp::merged_boundary(ra.tree, ra.boundary, rb.tree, rb.boundary,
                                       [op](bool x, bool y) { return boolean::detail::label_op(op, x, y); });
    auto t2 = clock_type::now();
    auto m = boolean::detail::assemble_pieces(pieces);
    auto t3 = clock_type::now();
    auto d = [](auto x, auto y) { return std::chrono::duration<double>(y - x).count(); };
    runs.push_back(d(t0, t3));
    send_run(fd, d(t0, t3), d(t0, t1), d(t1, t2), d(t2, t3));
    if (runs.size() == 1) {
      auto area = boolean::area(m);
      send_result(fd, m.size(), ring_count(m), vertex_count(m), area.convert_to<double>(), geometry::bit_length(area));
      auto sa = ra.tree.statistics(), sb = rb.tree.statistics();
      bsp::tree_statistics sr; // no merged tree is built
      char line[160];
      std::snprintf(line, sizeof line, "trees %zu %zu %zu %zu %zu %zu\n", sa.interior_nodes, sa.depth,
                    sb.interior_nodes, sb.depth, sr.interior_nodes, sr.depth);
      write_all(fd, line);
    }
  }
}

/// One peer's runs of one case (in a child process).
void peer_child(int fd, peers::peer const& peer, set_op op, peers::polygons const& a, peers::polygons const& b,
                options const& o) {
  auto job = peer.prepare(op == set_op::union_ ? peers::operation::union_ : peers::operation::intersection, a, b);
  std::vector<double> runs;
  while (o.repeat.another_run(runs)) {
    auto t0 = clock_type::now();
    job->run();
    runs.push_back(seconds_since(t0));
    send_run(fd, runs.back());
    if (runs.size() == 1) {
      auto out = job->result();
      std::size_t rings = 0, vertices = 0;
      for (auto const& p : out.shape) {
        rings += 1 + p.holes.size();
        vertices += p.outer.size();
        for (auto const& h : p.holes) vertices += h.size();
      }
      std::string why;
      bool valid = peer.exact || peers::valid(out.shape, why);
      send_result(fd, out.shape.size(), rings, vertices, out.area, valid ? 1 : 0);
      if (!valid) write_all(fd, "invalid " + why + "\n");
    }
    job->clear();
  }
}

/// Runs `body(fd)` in a child process that reports on `fd`, and collects its
/// report; stops the child when it stays silent for longer than the limit
/// (one run, or the checks after the first).  Runs completed before a stop
/// still count.
template <class Body> measurement run_in_child(bool genbsp, options const& o, Body body) {
  measurement m;
  bool got_result = false;
  auto end = bench::run_in_child(o.limit, body, [&](std::string const& kind, std::istringstream& in) {
    if (kind == "run") {
      double total = 0, build = 0, merge = 0, output = 0;
      in >> total >> build >> merge >> output;
      m.runs.push_back(total);
      if (genbsp) {
        m.build.push_back(build);
        m.merge.push_back(merge);
        m.output.push_back(output);
      }
      std::fprintf(stderr, " %.3gs", total);
    } else if (kind == "result") {
      std::size_t extra = 0;
      in >> m.out.polygons >> m.out.rings >> m.out.vertices >> m.out.area >> extra;
      if (genbsp)
        m.area_bits = extra;
      else
        m.valid = extra != 0;
      got_result = true;
    } else if (kind == "invalid") {
      std::getline(in >> std::ws, m.invalid_reason);
    } else if (kind == "trees") {
      for (int i = 0; i < 3; ++i) in >> m.tree_nodes[i] >> m.tree_depth[i];
    }
  });
  m.status = end.timed_out && got_result ? "ok" : end.status;
  m.seconds = median(m.runs);
  m.build_s = median(m.build);
  m.merge_s = median(m.merge);
  m.output_s = median(m.output);
  return m;
}

// ---------------------------------------------------------------------------
// Results

struct row {
  std::string family;                                 ///< "star", "star-narrow" or "grid"
  std::string op;                                     ///< "union" or "intersection"
  std::size_t size = 0;                               ///< vertices per star, or grid side K
  std::size_t input_vertices = 0, input_polygons = 0; ///< both operands together
  measurement genbsp;
  std::vector<measurement> peers; ///< in the order of options::peers
  bool input_valid = true;        ///< bg::is_valid of both operands
};

/// genbsp's time over `m`'s, when both finished.
std::optional<double> ratio(measurement const& g, measurement const& m) {
  if (g.status != "ok" || m.status != "ok" || m.seconds <= 0) return std::nullopt;
  return g.seconds / m.seconds;
}

/// |area of `m` − exact area| / exact area, when both finished.
std::optional<double> area_difference(measurement const& g, measurement const& m) {
  if (g.status != "ok" || m.status != "ok") return std::nullopt;
  if (g.out.area == 0) return m.out.area == 0 ? 0.0 : 1.0;
  return std::abs(m.out.area - g.out.area) / std::abs(g.out.area);
}

/// The index of the fastest peer that finished, if any.
std::optional<std::size_t> fastest(row const& r) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < r.peers.size(); ++i)
    if (r.peers[i].status == "ok" && (!best || r.peers[i].seconds < r.peers[*best].seconds)) best = i;
  return best;
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.starts_with("model name")) {
      auto colon = line.find(':');
      if (colon != std::string::npos) {
        auto v = line.substr(colon + 1);
        v.erase(0, v.find_first_not_of(" \t"));
        return v;
      }
    }
  return "unknown";
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one;
  in >> one;
  return in ? one : "unknown";
}

std::string utc_now() {
  std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

using bench::compiler;
using bench::json_string;
using bench::optimised;

std::string number(double x, int digits = 6) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

std::string json_optional(std::optional<double> x) { return x ? number(*x) : "null"; }

std::string json_list(std::vector<double> const& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + number(v[i]);
  return s + "]";
}

std::string json_measurement(measurement const& m, bool genbsp) {
  std::ostringstream j;
  bool ok = m.status == "ok";
  j << "{\"status\": " << json_string(m.status) << ", \"runs\": " << json_list(m.runs)
    << ", \"seconds\": " << (m.runs.empty() ? "null" : number(m.seconds));
  if (genbsp)
    j << ", \"build_seconds\": " << (m.runs.empty() ? "null" : number(m.build_s))
      << ", \"merge_seconds\": " << (m.runs.empty() ? "null" : number(m.merge_s))
      << ", \"output_seconds\": " << (m.runs.empty() ? "null" : number(m.output_s))
      << ", \"build_runs\": " << json_list(m.build) << ", \"merge_runs\": " << json_list(m.merge)
      << ", \"output_runs\": " << json_list(m.output);
  if (ok) {
    j << ", \"polygons\": " << m.out.polygons << ", \"rings\": " << m.out.rings << ", \"vertices\": " << m.out.vertices
      << ", \"area\": " << number(m.out.area, 17);
    if (genbsp)
      j << ", \"area_exact_bits\": " << m.area_bits << ", \"tree_nodes\": {\"a\": " << m.tree_nodes[0]
        << ", \"b\": " << m.tree_nodes[1] << ", \"result\": " << m.tree_nodes[2]
        << "}, \"tree_depth\": {\"a\": " << m.tree_depth[0] << ", \"b\": " << m.tree_depth[1]
        << ", \"result\": " << m.tree_depth[2] << "}";
    else
      j << ", \"output_valid\": " << (m.valid ? "true" : "false")
        << (m.valid ? std::string() : ", \"output_invalid_reason\": " + json_string(m.invalid_reason));
  }
  return j.str() + "}";
}

bool write_file(std::string const& file, std::string const& text) {
  std::filesystem::path target(file), tmp = target;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) {
      std::fprintf(stderr, "bench_boolean: cannot write '%s'\n", tmp.string().c_str());
      return false;
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, target, ec);
  if (ec) {
    std::fprintf(stderr, "bench_boolean: cannot rename '%s' to '%s': %s\n", tmp.string().c_str(), file.c_str(),
                 ec.message().c_str());
    std::filesystem::remove(tmp, ec);
    return false;
  }
  return true;
}

struct run_info {
  std::string started, load_start;
  double seconds = 0;
  bool finished = false;
};


std::string json_results(options const& o, std::vector<row> const& rows, run_info const& info) {
  std::ostringstream j;
  j << "{\n  \"benchmark\": \"bench_boolean\",\n";
  j << "  \"machine\": {\"hardware_threads\": " << std::thread::hardware_concurrency()
    << ", \"cpu\": " << json_string(cpu_model()) << ", \"compiler\": " << json_string(compiler())
    << ", \"optimised\": " << (optimised() ? "true" : "false") << ", \"boost\": " << json_string(BOOST_LIB_VERSION)
    << ", \"gmp\": " << json_string(gmp_version) << "},\n";
  j << "  \"run\": {\"started\": " << json_string(info.started) << ", \"load_average_start\": " << info.load_start
    << ", \"load_average_now\": " << load_average() << ", \"seconds\": " << number(info.seconds)
    << ", \"finished\": " << (info.finished ? "true" : "false") << "},\n";
  j << "  \"settings\": {\"quick\": " << (o.quick ? "true" : "false") << ", \"seed\": " << o.seed
    << ", \"limit_seconds\": " << number(o.limit) << ", \"long_run_seconds\": " << number(o.repeat.long_run)
    << ", \"repetitions\": " << o.repeat.at_least << ", \"max_repetitions\": " << o.repeat.at_most
    << ", \"min_total_seconds\": " << number(o.repeat.min_total)
    << ",\n    \"star\": \"two star polygons of n vertices, integer coordinates, radii uniform in [3e5, 1e6], "
       "centres (0, 0) and (150000, 100000)\""
    << ",\n    \"star-narrow\": \"the same with radii uniform in [9e5, 1e6]\""
    << ",\n    \"grid\": \"K x K unit squares [2i, 2i+1] x [2j, 2j+1] against the same squares shifted by (1/2, 1/2)\""
    << ",\n    \"genbsp\": " << (o.genbsp ? "true" : "false")
    << ",\n    \"genbsp_time\": \"operand_of(A) + operand_of(B) + merged_boundary + assemble (= boolean::combine)\""
    << ",\n    \"peers\": [";
  for (std::size_t i = 0; i < o.peers.size(); ++i) {
    auto const& p = o.peers[i];
    j << (i ? ",\n      " : "\n      ") << "{\"name\": " << json_string(p.name) << ", \"label\": " << json_string(p.label)
      << ", \"exact\": " << (p.exact ? "true" : "false") << ", \"time\": " << json_string(p.timed) << "}";
  }
  j << "]},\n";
  j << "  \"results\": [\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    auto const& r = rows[i];
    j << "    {\"family\": " << json_string(r.family) << ", \"operation\": " << json_string(r.op)
      << ", \"size\": " << r.size << ", \"input_vertices\": " << r.input_vertices
      << ", \"input_polygons\": " << r.input_polygons << ", \"input_valid\": " << (r.input_valid ? "true" : "false")
      << ",\n     \"genbsp\": " << json_measurement(r.genbsp, true) << ",\n     \"peers\": {";
    for (std::size_t k = 0; k < r.peers.size(); ++k) {
      auto m = json_measurement(r.peers[k], false);
      m.pop_back(); // the closing brace: two more fields
      j << (k ? ",\n       " : "\n       ") << json_string(o.peers[k].name) << ": " << m
        << ", \"genbsp_over\": " << json_optional(ratio(r.genbsp, r.peers[k]))
        << ", \"area_relative_difference\": " << json_optional(area_difference(r.genbsp, r.peers[k])) << "}";
    }
    auto f = fastest(r);
    j << "},\n     \"fastest_peer\": " << (f ? json_string(o.peers[*f].name) : "null")
      << ", \"genbsp_over_fastest\": " << json_optional(f ? ratio(r.genbsp, r.peers[*f]) : std::nullopt) << "}"
      << (i + 1 < rows.size() ? "," : "") << "\n";
  }
  j << "  ]\n}\n";
  return j.str();
}

/// One line per case and library.
std::string csv_results(options const& o, std::vector<row> const& rows) {
  std::ostringstream c;
  c << "family,operation,size,input_vertices,input_polygons,library,status,runs,seconds,"
       "build_seconds,merge_seconds,output_seconds,polygons,rings,vertices,area,output_valid,"
       "genbsp_over_this,area_relative_difference\n";
  auto opt = [](std::optional<double> x) { return x ? number(*x) : std::string(); };
  auto quoted = [](std::string s) {
    std::string out = "\"";
    for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return out + "\"";
  };
  for (auto const& r : rows) {
    auto line = [&](std::string const& name, measurement const& m, bool genbsp) {
      bool ok = m.status == "ok";
      bool has = !m.runs.empty();
      c << r.family << ',' << r.op << ',' << r.size << ',' << r.input_vertices << ',' << r.input_polygons << ','
        << name << ',' << quoted(m.status) << ',' << m.runs.size() << ',' << (has ? number(m.seconds) : "") << ','
        << (genbsp && has ? number(m.build_s) : "") << ',' << (genbsp && has ? number(m.merge_s) : "") << ','
        << (genbsp && has ? number(m.output_s) : "") << ',';
      if (ok)
        c << m.out.polygons << ',' << m.out.rings << ',' << m.out.vertices << ',' << number(m.out.area, 17) << ','
          << (m.valid ? "true" : "false") << ',';
      else
        c << ",,,,,";
      c << (genbsp ? "" : opt(ratio(r.genbsp, m))) << ',' << (genbsp ? "" : opt(area_difference(r.genbsp, m)))
        << '\n';
    };
    if (o.genbsp) line("genbsp", r.genbsp, true);
    for (std::size_t k = 0; k < r.peers.size(); ++k) line(o.peers[k].name, r.peers[k], false);
  }
  return c.str();
}

void print_header(options const& o) {
  std::printf("%-11s %-12s %6s %7s | %9s %9s %9s %9s %18s", "family", "operation", "size", "in vert", "genbsp s",
              "build", "merge", "output", "out P/R/V");
  for (auto const& p : o.peers) std::printf(" | %9s %18s", (p.name + " s").c_str(), "out P/R/V");
  std::printf(" | %8s %9s\n", "fastest", "ratio");
}

std::string sizes(measurement const& m) {
  if (m.status != "ok") return m.status.substr(0, 18);
  return std::to_string(m.out.polygons) + "/" + std::to_string(m.out.rings) + "/" + std::to_string(m.out.vertices) +
         (m.valid ? "" : "!");
}

void print_row(options const& o, row const& r) {
  auto s = [](measurement const& m, double x) { return m.runs.empty() ? std::string("-") : number(x, 3); };
  std::printf("%-11s %-12s %6zu %7zu | %9s %9s %9s %9s %18s", r.family.c_str(), r.op.c_str(), r.size,
              r.input_vertices, s(r.genbsp, r.genbsp.seconds).c_str(), s(r.genbsp, r.genbsp.build_s).c_str(),
              s(r.genbsp, r.genbsp.merge_s).c_str(), s(r.genbsp, r.genbsp.output_s).c_str(), sizes(r.genbsp).c_str());
  for (auto const& m : r.peers) std::printf(" | %9s %18s", s(m, m.seconds).c_str(), sizes(m).c_str());
  auto f = fastest(r);
  auto q = f ? ratio(r.genbsp, r.peers[*f]) : std::nullopt;
  std::printf(" | %8s %9s\n", f ? o.peers[*f].name.c_str() : "-", q ? (number(*q, 3) + "x").c_str() : "-");
  std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv) {
  geometry::use_gmp_pool(); // as the genbsp tool runs
  options o;
  if (auto code = parse_options(argc, argv, o)) return *code;
  std::signal(SIGPIPE, SIG_IGN);

  run_info info;
  info.started = utc_now();
  info.load_start = load_average();
  auto start = clock_type::now();
  std::printf("bench_boolean: %s, %u hardware threads, %s, GMP %s\n", cpu_model().c_str(),
              std::thread::hardware_concurrency(), compiler().c_str(), gmp_version);
  std::printf("libraries:%s", o.genbsp ? " genbsp (exact)" : "");
  for (auto const& p : o.peers) std::printf(" %s%s", p.label.c_str(), p.exact ? " (exact)" : "");
  std::printf("\nload average %s at the start; seed %llu; limit %g s per run%s\n", info.load_start.c_str(),
              static_cast<unsigned long long>(o.seed), o.limit, o.quick ? " (--quick)" : "");
  if (!optimised()) std::printf("warning: built without optimisation; the numbers mean little\n");
  std::printf("times in seconds (median); genbsp = build (operand_of both) + classify (merged_boundary) + output "
              "(assemble); P/R/V = output polygons/rings/vertices, ! = invalid (bg::is_valid); ratio = genbsp / "
              "the fastest other library\n\n");
  print_header(o);

  std::vector<row> rows;
  auto save = [&] {
    info.seconds = seconds_since(start);
    bool ok = true;
    if (o.json) ok = write_file(*o.json, json_results(o, rows, info)) && ok;
    if (o.csv) ok = write_file(*o.csv, csv_results(o, rows)) && ok;
    return ok;
  };

  struct series {
    std::string family;
    std::vector<std::size_t> sizes;
    double min_radius; ///< stars: the smallest radius, as a fraction of the largest
  };
  std::vector<series> all{{"star", o.stars, 0.3}, {"star-narrow", o.narrow_stars, 0.9}, {"grid", o.grids, 0}};
  std::size_t libraries = 1 + o.peers.size(); // genbsp first
  bool write_ok = true;
  for (auto const& s : all) {
    // Per library and operation: a smaller size did not finish, so larger ones are skipped.
    std::vector<std::array<bool, 2>> stopped(libraries, {false, false});
    for (std::size_t index = 0; index < s.sizes.size(); ++index) {
      std::size_t n = s.sizes[index];
      multipolygon a, b;
      if (s.family != "grid") {
        constexpr double radius = 1e6;
        std::mt19937_64 ra(o.seed + 2 * n), rb(o.seed + 2 * n + 1);
        a.push_back({random_star(ra, n, 0, 0, radius, s.min_radius), {}});
        b.push_back({random_star(rb, n, 150000, 100000, radius, s.min_radius), {}});
      } else {
        a = grid(n, rational(0));
        b = grid(n, rational(1, 2));
      }
      auto pa = to_plain(a), pb = to_plain(b);
      std::string why;
      bool input_valid = peers::valid(pa, why) && peers::valid(pb, why);
      for (int k = 0; k < 2; ++k) {
        if (!(k == 0 ? o.union_ : o.intersection)) continue;
        set_op op = k == 0 ? set_op::union_ : set_op::intersection;
        row r;
        r.family = s.family;
        r.op = k == 0 ? "union" : "intersection";
        r.size = n;
        r.input_vertices = vertex_count(a) + vertex_count(b);
        r.input_polygons = a.size() + b.size();
        r.input_valid = input_valid;
        r.peers.resize(o.peers.size());
        std::fprintf(stderr, "%s %s %zu (%zu input vertices):", r.family.c_str(), r.op.c_str(), n, r.input_vertices);
        for (std::size_t lib = 0; lib < libraries; ++lib) {
          if (lib == 0 && !o.genbsp) continue;
          measurement& m = lib == 0 ? r.genbsp : r.peers[lib - 1];
          std::fprintf(stderr, "%s %s", lib == 0 || (lib == 1 && !o.genbsp) ? "" : ";",
                       lib == 0 ? "genbsp" : o.peers[lib - 1].name.c_str());
          if (stopped[lib][k]) {
            m.status = "skipped";
            std::fprintf(stderr, " skipped (a smaller size did not finish)");
            continue;
          }
          if (lib == 0)
            m = run_in_child(true, o, [&](int fd) { genbsp_child(fd, op, a, b, o); });
          else
            m = run_in_child(false, o, [&](int fd) { peer_child(fd, o.peers[lib - 1], op, pa, pb, o); });
          if (m.status == "not finished") {
            stopped[lib][k] = true;
            std::fprintf(stderr, " not finished within %g s", o.limit);
          } else if (m.status != "ok") {
            std::fprintf(stderr, " %s", m.status.c_str());
          }
        }
        std::fprintf(stderr, " [%.0f s so far]\n", seconds_since(start));
        rows.push_back(std::move(r));
        print_row(o, rows.back());
        write_ok = save() && write_ok;
      }
    }
  }
  info.finished = true;
  write_ok = save() && write_ok;
  std::printf("\n%.1f s in all; load average %s at the end\n", seconds_since(start), load_average().c_str());
  if (o.json) std::printf("results written to %s\n", o.json->c_str());
  if (o.csv) std::printf("results written to %s\n", o.csv->c_str());
  bool errors = std::any_of(rows.begin(), rows.end(), [](row const& r) {
    return r.genbsp.status.starts_with("error") ||
           std::any_of(r.peers.begin(), r.peers.end(), [](measurement const& m) { return m.status.starts_with("error"); });
  });
  if (errors) std::fprintf(stderr, "bench_boolean: some cases failed (see the status fields)\n");
  return errors || !write_ok ? 1 : 0;
}
