// Exact Boolean operations on the sphere (boolean::spherical_operand_of and
// combine) against Google S2's S2BooleanOperation (through
// S2Polygon::InitToUnion and InitToIntersection), on the same loops in the
// same run.  Built when Debian's libs2-dev is present (scripts/setup --bench).
//
// Inputs, two loops of n vertices each, seeded:
//   star   vertex i at azimuth 2π(i + 0.1 + 0.8u)/n around its centre and
//          at angular radius uniform in [0.3R, R], R = 30°: spikes whose
//          boundaries cross often;
//   wavy   the same with radii in [0.9R, R]: two random n-gons hugging one
//          circle.
// Centres at latitude 10°, longitudes 0° and 4.5°, latitude 13° for the
// second.  Every vertex is a unit vector of doubles; genbsp reads the same
// doubles as exact rationals, so both libraries see the same points.
//
// Timed, genbsp: both trees built from the loops, each operand's arcs
// classified against both trees (the merged tree is not built) and the
// result read back as polygons (the job of `genbsp bool --geometry s2`).  S2: both
// S2Polygons built from their S2Loops (validity checks off: the loops are
// valid by construction) and the operation, with S2Polygon's default snap
// function.  Each library runs each case in a child process, stopped after
// the limit.
#include <geometry/gmp_pool.hpp>
#include <boolean/spherical.hpp>

#include <s2/s2loop.h>
#include <s2/s2polygon.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "common.hpp"

namespace {

using clock_type = std::chrono::steady_clock;
using unit = std::array<double, 3>;

struct options {
  std::vector<std::size_t> sizes{100, 1000, 10000};
  std::vector<std::string> families{"star", "wavy"};
  double limit = 45;
  std::uint64_t seed = 20261207;
  std::optional<std::string> json;
  bench::repetition repeat; ///< runs per case; the median is reported
  int rounds = 1;           ///< times each case's two libraries run, in turn
};

void print_help() {
  std::puts("Usage: bench_spherical [--sizes N,...] [--families star,wavy] [--limit S] [--seed N] [--rounds K] [--json FILE] [--quick]\n"
            "\n"
            "Times genbsp's exact Boolean operations on the sphere (both regions built\n"
            "from their loops, their arcs classified against both, read back as polygons) against Google S2's\n"
            "S2Polygon::InitToUnion and InitToIntersection (S2BooleanOperation), on two\n"
            "spherical star loops of n vertices each (angular radii in [0.3R, R], R = 30°;\n"
            "wavy: in [0.9R, R]).  Reports median times (3 runs at least, more for short\n"
            "cases), output loops and vertices, areas and the ratio genbsp / S2.  Each\n"
            "library runs each case in a child process, stopped after the limit.\n"
            "\n"
            "  --sizes LIST     vertices per loop (default 100,1000,10000)\n"
            "  --families LIST  star, wavy or both (default both)\n"
            "  --limit S        stop a run after S seconds (default 45); larger sizes of that\n"
            "                   library, family and operation are then skipped\n"
            "  --seed N         seed of the loops (default 20261207)\n"
            "  --rounds K       run each case's two libraries K times, in turn (genbsp, S2,\n"
            "                   genbsp, ...), and report the median of all their runs, so\n"
            "                   that both meet the machine's slow and fast spells (default 1)\n"
            "  --json FILE      write the results as JSON\n"
            "  --quick          sizes 100 and 1000, limit 10 s\n"
            "  --help           this text");
}

std::optional<int> parse(int argc, char** argv, options& o) {
  bool sizes_given = false, limit_given = false, quick = false;
  for (int i = 1; i < argc; ++i) {
    std::string_view a = argv[i];
    if (a == "--help" || a == "-h") {
      print_help();
      return 0;
    }
    if (a == "--quick") {
      quick = true;
      continue;
    }
    if (a != "--sizes" && a != "--families" && a != "--limit" && a != "--seed" && a != "--rounds" && a != "--json") {
      std::fprintf(stderr, "bench_spherical: unknown argument '%s' (try --help)\n", argv[i]);
      return 2;
    }
    if (i + 1 >= argc) {
      std::fprintf(stderr, "bench_spherical: %s needs an argument (try --help)\n", argv[i]);
      return 2;
    }
    std::string v = argv[++i];
    auto bad = [&](char const* what) {
      std::fprintf(stderr, "bench_spherical: %s needs %s, not '%s'\n", argv[i - 1], what, v.c_str());
      return 2;
    };
    std::vector<std::string> items;
    for (std::size_t pos = 0; pos <= v.size();) {
      std::size_t comma = std::min(v.find(',', pos), v.size());
      items.push_back(v.substr(pos, comma - pos));
      pos = comma + 1;
    }
    if (a == "--sizes") {
      o.sizes.clear();
      for (auto const& s : items) {
        char* end = nullptr;
        unsigned long long n = std::strtoull(s.c_str(), &end, 10);
        if (s.empty() || s[0] == '-' || *end != '\0' || n < 3) return bad("a list of integers of at least 3");
        o.sizes.push_back(static_cast<std::size_t>(n));
      }
      sizes_given = true;
    } else if (a == "--families") {
      o.families.clear();
      for (auto const& s : items) {
        if (s != "star" && s != "wavy") return bad("star, wavy or star,wavy");
        o.families.push_back(s);
      }
    } else if (a == "--limit") {
      char* end = nullptr;
      double s = std::strtod(v.c_str(), &end);
      if (v.empty() || *end != '\0' || !(s > 0)) return bad("a positive number of seconds");
      o.limit = s;
      limit_given = true;
    } else if (a == "--rounds") {
      char* end = nullptr;
      long k = std::strtol(v.c_str(), &end, 10);
      if (v.empty() || *end != '\0' || k < 1 || k > 100) return bad("an integer from 1 to 100");
      o.rounds = static_cast<int>(k);
    } else if (a == "--seed") {
      char* end = nullptr;
      unsigned long long n = std::strtoull(v.c_str(), &end, 10);
      if (v.empty() || v[0] == '-' || *end != '\0') return bad("a non-negative integer");
      o.seed = n;
    } else {
      o.json = v;
    }
  }
  if (quick) {
    if (!sizes_given) o.sizes = {100, 1000};
    if (!limit_given) o.limit = 10;
  }
  return std::nullopt;
}

// ---------------------------------------------------------------------------
// Input

unit lonlat(double lon_deg, double lat_deg) {
  double lon = lon_deg * std::numbers::pi / 180, lat = lat_deg * std::numbers::pi / 180;
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

unit cross(unit const& a, unit const& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

unit normalised(unit v) {
  double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / l, v[1] / l, v[2] / l};
}

/// A loop of n vertices around the unit vector `c`, counter-clockwise seen
/// from outside (its region, the side holding `c`, on its left), strictly
/// star-shaped around `c` with every vertex within 90° of it: simple.
std::vector<unit> star_loop(std::mt19937_64& rng, std::size_t n, unit const& c, double radius, double f) {
  std::uniform_real_distribution<double> u(0, 1);
  unit e1 = normalised(cross({0, 0, 1}, c)), e2 = cross(c, e1); // (e1, e2, c) right-handed
  std::vector<unit> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    double t = 2 * std::numbers::pi * (static_cast<double>(i) + 0.1 + 0.8 * u(rng)) / static_cast<double>(n);
    double r = radius * (f + (1 - f) * u(rng));
    double cr = std::cos(r), sr = std::sin(r), ct = std::cos(t), st = std::sin(t);
    out.push_back(normalised({cr * c[0] + sr * (ct * e1[0] + st * e2[0]), cr * c[1] + sr * (ct * e1[1] + st * e2[1]),
                              cr * c[2] + sr * (ct * e1[2] + st * e2[2])}));
  }
  return out;
}

// ---------------------------------------------------------------------------
// Measurement

struct output {
  std::size_t polygons = 0, loops = 0, vertices = 0;
  double area = 0; ///< steradians
};

struct measurement {
  std::string status = "not run";
  std::vector<double> runs;
  double seconds = 0;
  output out;
};

using bench::median;

void send(int fd, char const* kind, double seconds) {
  char line[96];
  std::snprintf(line, sizeof line, "%s %.9g\n", kind, seconds);
  bench::write_all(fd, line);
}

void send_result(int fd, output const& r) {
  char line[160];
  std::snprintf(line, sizeof line, "result %zu %zu %zu %.17g\n", r.polygons, r.loops, r.vertices, r.area);
  bench::write_all(fd, line);
}

void genbsp_child(int fd, bool union_, std::vector<unit> const& a, std::vector<unit> const& b, options const& o) {
  auto exact = [](std::vector<unit> const& l) {
    boolean::loop out;
    for (auto const& p : l)
      out.emplace_back(std::array<geometry::rational, 3>{geometry::rational(p[0]), geometry::rational(p[1]),
                                                         geometry::rational(p[2])});
    return out;
  };
  boolean::loop la = exact(a), lb = exact(b);
  std::vector<double> runs;
  while (o.repeat.another_run(runs)) {
    auto t0 = clock_type::now();
    auto ra = boolean::spherical_operand_of(std::vector<boolean::loop>{la});
    auto rb = boolean::spherical_operand_of(std::vector<boolean::loop>{lb});
    auto polygons = boolean::combine(union_ ? boolean::set_op::union_ : boolean::set_op::intersection, ra, rb);
    runs.push_back(std::chrono::duration<double>(clock_type::now() - t0).count());
    send(fd, "run", runs.back());
    if (runs.size() == 1) {
      output res;
      res.polygons = polygons.size();
      for (auto const& p : polygons) {
        res.loops += 1 + p.holes.size();
        res.vertices += p.outer.size();
        for (auto const& h : p.holes) res.vertices += h.size();
      }
      res.area = boolean::area(polygons);
      send_result(fd, res);
    }
  }
}

void s2_child(int fd, bool union_, std::vector<unit> const& a, std::vector<unit> const& b, options const& o) {
  auto points = [](std::vector<unit> const& l) {
    std::vector<S2Point> out;
    for (auto const& p : l) out.emplace_back(p[0], p[1], p[2]);
    return out;
  };
  std::vector<S2Point> pa = points(a), pb = points(b);
  std::vector<double> runs;
  while (o.repeat.another_run(runs)) {
    auto t0 = clock_type::now();
    S2Polygon sa(std::make_unique<S2Loop>(pa, S2Debug::DISABLE), S2Debug::DISABLE);
    S2Polygon sb(std::make_unique<S2Loop>(pb, S2Debug::DISABLE), S2Debug::DISABLE);
    S2Polygon out;
    if (union_)
      out.InitToUnion(sa, sb);
    else
      out.InitToIntersection(sa, sb);
    runs.push_back(std::chrono::duration<double>(clock_type::now() - t0).count());
    send(fd, "run", runs.back());
    if (runs.size() == 1) {
      output res;
      res.loops = static_cast<std::size_t>(out.num_loops());
      for (int i = 0; i < out.num_loops(); ++i) res.polygons += out.loop(i)->is_hole() ? 0 : 1;
      res.vertices = static_cast<std::size_t>(out.num_vertices());
      res.area = out.GetArea();
      send_result(fd, res);
    }
  }
}

template <class Body> measurement measure(options const& o, Body body) {
  measurement m;
  bool got_result = false;
  auto end = bench::run_in_child(o.limit, body, [&](std::string const& kind, std::istringstream& in) {
    if (kind == "run") {
      double s = 0;
      in >> s;
      m.runs.push_back(s);
      std::fprintf(stderr, " %.3gs", s);
    } else if (kind == "result") {
      in >> m.out.polygons >> m.out.loops >> m.out.vertices >> m.out.area;
      got_result = true;
    }
  });
  m.status = end.timed_out && got_result ? "ok" : end.status;
  m.seconds = median(m.runs);
  return m;
}

// ---------------------------------------------------------------------------
// Results

struct row {
  std::string family, op;
  std::size_t size = 0;
  measurement genbsp, s2;
};

std::string number(double x, int digits = 6) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

std::string json_measurement(measurement const& m) {
  std::ostringstream j;
  j << "{\"status\": " << bench::json_string(m.status) << ", \"runs\": [";
  for (std::size_t i = 0; i < m.runs.size(); ++i) j << (i ? ", " : "") << number(m.runs[i]);
  j << "], \"seconds\": " << (m.runs.empty() ? "null" : number(m.seconds));
  if (m.status == "ok")
    j << ", \"polygons\": " << m.out.polygons << ", \"loops\": " << m.out.loops << ", \"vertices\": " << m.out.vertices
      << ", \"area\": " << number(m.out.area, 17);
  return j.str() + "}";
}

std::optional<double> ratio(row const& r) {
  if (r.genbsp.status != "ok" || r.s2.status != "ok" || r.s2.seconds <= 0) return std::nullopt;
  return r.genbsp.seconds / r.s2.seconds;
}

bool write_json(options const& o, std::vector<row> const& rows, bool finished) {
  std::ostringstream j;
  j << "{\n  \"benchmark\": \"bench_spherical\",\n  \"machine\": {\"hardware_threads\": "
    << std::thread::hardware_concurrency() << ", \"compiler\": " << bench::json_string(bench::compiler())
    << ", \"optimised\": " << (bench::optimised() ? "true" : "false") << "},\n  \"settings\": {\"seed\": " << o.seed
    << ", \"limit_seconds\": " << number(o.limit) << ", \"rounds\": " << o.rounds << ", \"finished\": " << (finished ? "true" : "false")
    << "},\n  \"results\": [\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    auto const& r = rows[i];
    auto q = ratio(r);
    j << "    {\"family\": " << bench::json_string(r.family) << ", \"operation\": " << bench::json_string(r.op)
      << ", \"size\": " << r.size << ",\n     \"genbsp\": " << json_measurement(r.genbsp)
      << ",\n     \"s2\": " << json_measurement(r.s2) << ", \"genbsp_over_s2\": " << (q ? number(*q) : "null") << "}"
      << (i + 1 < rows.size() ? "," : "") << "\n";
  }
  j << "  ]\n}\n";
  std::string tmp = *o.json + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << j.str();
    if (!out) return false;
  }
  return std::rename(tmp.c_str(), o.json->c_str()) == 0;
}

std::string cell(measurement const& m, double limit) {
  if (m.status == "ok") return number(m.seconds, 3);
  if (m.status == "not finished") return "> " + number(limit, 3) + " s";
  return m.status == "skipped" ? "skipped" : "error";
}

std::string sizes(measurement const& m) {
  if (m.status != "ok") return "—";
  return std::to_string(m.out.polygons) + " / " + std::to_string(m.out.loops) + " / " + std::to_string(m.out.vertices);
}

} // namespace

int main(int argc, char** argv) {
  geometry::use_gmp_pool(); // as the genbsp tool runs
  options o;
  if (auto code = parse(argc, argv, o)) return *code;
  std::printf("bench_spherical: %u hardware threads, %s%s; limit %g s per run; seed %llu; %d round%s\n\n",
              std::thread::hardware_concurrency(), bench::compiler().c_str(),
              bench::optimised() ? "" : " (NOT optimised: the numbers mean little)", o.limit,
              static_cast<unsigned long long>(o.seed), o.rounds, o.rounds == 1 ? "" : "s");
  std::puts("| Loops | Operation | n | genbsp s | S2 s | genbsp / S2 | genbsp P / L / V | S2 P / L / V | Area diff |");
  std::puts("| ----- | --------- | -: | -------: | ---: | ----------: | ---------------: | -----------: | --------: |");
  std::vector<row> rows;
  bool errors = false;
  for (auto const& family : o.families) {
    bool stopped[2][2] = {{false, false}, {false, false}}; // [library][operation]
    for (std::size_t n : o.sizes) {
      constexpr double radius = 30 * std::numbers::pi / 180;
      double f = family == "star" ? 0.3 : 0.9;
      std::mt19937_64 ra(o.seed + 2 * n), rb(o.seed + 2 * n + 1);
      auto a = star_loop(ra, n, lonlat(0, 10), radius, f);
      auto b = star_loop(rb, n, lonlat(4.5, 13), radius, f);
      for (int k = 0; k < 2; ++k) {
        bool union_ = k == 0;
        row r{family, union_ ? "union" : "intersection", n, {}, {}};
        std::fprintf(stderr, "%s %s %zu:", family.c_str(), r.op.c_str(), n);
        for (int round = 0; round < o.rounds; ++round)
          for (int lib = 0; lib < 2; ++lib) {
            measurement& m = lib == 0 ? r.genbsp : r.s2;
            std::fprintf(stderr, "%s", lib == 0 ? " genbsp" : "; S2");
            if (stopped[lib][k]) {
              m.status = "skipped";
              continue;
            }
            if (round > 0 && m.status != "ok") continue;
            auto got = lib == 0 ? measure(o, [&](int fd) { genbsp_child(fd, union_, a, b, o); })
                                : measure(o, [&](int fd) { s2_child(fd, union_, a, b, o); });
            if (round == 0) {
              m = std::move(got);
            } else if (got.status == "ok") { // later rounds add their runs
              m.runs.insert(m.runs.end(), got.runs.begin(), got.runs.end());
              m.seconds = median(m.runs);
            }
            if (m.status == "not finished") stopped[lib][k] = true;
            if (m.status.starts_with("error") || got.status.starts_with("error")) {
              errors = true;
              std::fprintf(stderr, " %s", got.status.c_str());
            }
          }
        std::fprintf(stderr, "\n");
        auto q = ratio(r);
        std::string diff = "—";
        if (r.genbsp.status == "ok" && r.s2.status == "ok" && r.genbsp.out.area > 0)
          diff = number(std::abs(r.s2.out.area - r.genbsp.out.area) / r.genbsp.out.area, 2);
        std::printf("| %s | %s | %zu | %s | %s | %s | %s | %s | %s |\n", family.c_str(), r.op.c_str(), n,
                    cell(r.genbsp, o.limit).c_str(), cell(r.s2, o.limit).c_str(),
                    q ? (number(*q, 3) + "×").c_str() : "—", sizes(r.genbsp).c_str(), sizes(r.s2).c_str(),
                    diff.c_str());
        std::fflush(stdout);
        rows.push_back(std::move(r));
        if (o.json && !write_json(o, rows, false)) {
          std::fprintf(stderr, "bench_spherical: cannot write %s\n", o.json->c_str());
          return 1;
        }
      }
    }
  }
  if (o.json && !write_json(o, rows, true)) return 1;
  std::puts("\nP / L / V: output polygons, loops (outer loops and holes), vertices; area diff: |S2 − genbsp| / genbsp "
            "(genbsp's area is 2π minus each output loop's turns, less 4π a hole, in double)");
  if (errors) std::fprintf(stderr, "bench_spherical: some cases failed\n");
  return errors ? 1 : 0;
}
