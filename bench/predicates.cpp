// Throughput of genbsp's predicates in three modes:
//   double    FT = double: plain floating point, no guarantee;
//   filtered  FT = rational, filter on: a semi-static double filter, exact
//             evaluation only when the sign is uncertain (the default);
//   exact     FT = rational, filter off: every evaluation exact, on the
//             vectors' integer multiples (128-, 256- or 512-bit integers on
//             the stack as the predicate's bound allows, GMP past that);
//   exact GMP the same with the fixed-width rungs off: GMP integers only.
// Heap allocations (operator new and GMP's) are counted over the timed
// calls and printed per call.
// Two input sets per predicate family: random decimals (the filter almost never
// fails) and near-degenerate ones (points on or a few ulps off the line, plane
// or circle; concurrent lines and circles), where it fails most of the time.
//
// Only predicate calls are timed; all objects are built beforehand.  Every
// result goes into a checksum that is printed, so no call can be elided.  The
// filtered and exact modes must give identical signs; the program fails if not.
#include <geometry/geometry.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <new>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>
#include <vector>

#include "common.hpp"

namespace {

using geometry::rational;
namespace e2 = geometry::e2;
namespace e3 = geometry::e3;
namespace s2 = geometry::s2;
using clock_type = std::chrono::steady_clock;

// ---------------------------------------------------------------------------
// Command line

struct options {
  bool quick = false;
  std::optional<std::string> json;
  std::uint64_t seed = 20240601;
  std::size_t queries = 4096;   ///< distinct predicate calls per data set
  int repetitions = 5;          ///< timed repetitions; the median is reported
  double target_seconds = 0.04; ///< minimum duration of one repetition
  int pairs = 9;                ///< repetitions of double and filtered in turn, for their ratio
};

void print_help() {
  std::puts("Usage: bench_predicates [--quick] [--json FILE] [--seed N] [--queries N]\n"
            "\n"
            "Measures the throughput of genbsp's predicates (E2 side of a point and of a\n"
            "vertex, E3 side of a point, S2 side of a direction and of a vertex) in three\n"
            "modes: plain double, filtered exact (FT = rational, the default) and always\n"
            "exact (filter off), on random and on near-degenerate input, and reports the\n"
            "filter's fallback rate.  Each time is the median of 5 timed repetitions;\n"
            "filt/dbl is the median ratio of 9 pairs of repetitions of the two modes\n"
            "taken in turn (after the blocks), so that changes of the machine's speed\n"
            "fall on both of its terms.\n"
            "\n"
            "  --quick      shorter repetitions (a smoke run, a few seconds at most)\n"
            "  --json FILE  also write the results as JSON to FILE\n"
            "  --seed N     seed of the random input (default 20240601)\n"
            "  --queries N  distinct predicate calls per data set (default 4096)\n"
            "  --help       this text");
}

/// Parses the command line; returns the exit code to stop with, if any.
std::optional<int> parse_options(int argc, char** argv, options& o) {
  for (int i = 1; i < argc; ++i) {
    std::string_view a = argv[i];
    if (a == "--help" || a == "-h") {
      print_help();
      return 0;
    } else if (a == "--quick") {
      o.quick = true;
    } else if (a == "--json" || a == "--seed" || a == "--queries") {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "bench_predicates: %s needs an argument (try --help)\n", argv[i]);
        return 2;
      }
      std::string_view v = argv[++i];
      if (a == "--json") {
        o.json = std::string(v);
      } else {
        char* end = nullptr;
        unsigned long long n = std::strtoull(argv[i], &end, 10);
        if (v.empty() || v.front() == '-' || *end != '\0' || (a == "--queries" && n == 0)) {
          std::fprintf(stderr, "bench_predicates: %s needs a %s integer, not '%s'\n", argv[i - 1],
                       a == "--seed" ? "non-negative" : "positive", argv[i]);
          return 2;
        }
        if (a == "--seed")
          o.seed = n;
        else
          o.queries = static_cast<std::size_t>(n);
      }
    } else {
      std::fprintf(stderr, "bench_predicates: unknown argument '%s' (try --help)\n", argv[i]);
      return 2;
    }
  }
  if (o.quick) o.target_seconds = 0.002;
  return std::nullopt;
}

// ---------------------------------------------------------------------------
// Input: kernel-neutral coordinates

/// One input coordinate: the decimal `n · 10^-digits`, read exactly by the
/// rational kernel and rounded to the nearest double by the double kernel; or,
/// once nudged by a few ulps, a double that both kernels read as it is.
struct coord {
  std::int64_t n = 0;
  int digits = 0;
  std::optional<double> value;
};

std::int64_t pow10(int d) {
  std::int64_t p = 1;
  while (d-- > 0) p *= 10;
  return p;
}

std::string decimal_text(coord const& c) { return std::to_string(c.n) + "e-" + std::to_string(c.digits); }

template <class FT> FT number_of(coord const& c) {
  if (c.value) return FT(*c.value); // a double converts to rational exactly
  return geometry::parse_number<FT>(decimal_text(c));
}

template <std::size_t D> using vec = std::array<coord, D>;

struct generator {
  std::mt19937_64 rng;

  std::int64_t uniform(std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
  }

  /// A random decimal in [-1000, 1000] with 3 to 6 digits after the point.
  coord decimal() {
    int d = static_cast<int>(uniform(3, 6));
    std::int64_t m = 1000 * pow10(d);
    return {uniform(-m, m), d, {}};
  }

  template <std::size_t D> vec<D> random_vec() {
    vec<D> v;
    for (auto& c : v) c = decimal();
    return v;
  }

  /// A random vector written with exactly 6 digits after the point (for combining).
  template <std::size_t D> vec<D> random_vec6() {
    vec<D> v = random_vec<D>();
    for (auto& c : v) c = {c.n * pow10(6 - c.digits), 6, {}};
    return v;
  }

  /// A multiplier j / 1000 with j in [lo, hi], j ≠ 0.
  std::int64_t multiplier(std::int64_t lo, std::int64_t hi) {
    for (;;)
      if (std::int64_t j = uniform(lo, hi); j != 0) return j;
  }

  /// Moves one coordinate of `v` by 1 to 4 ulps (of its nearest double), up or down.
  template <std::size_t D> void nudge(vec<D>& v) {
    auto& c = v[static_cast<std::size_t>(uniform(0, D - 1))];
    double x = c.value ? *c.value : geometry::parse_number<double>(decimal_text(c));
    std::int64_t k = multiplier(-4, 4);
    double toward = k > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    for (std::int64_t i = 0; i < (k > 0 ? k : -k); ++i) x = std::nextafter(x, toward);
    c = {0, 0, x};
  }
};

/// `base + Σ jᵢ/1000 · (otherᵢ − base)`, with `base` and `otherᵢ` at 6 digits: exact, at 9 digits.
template <std::size_t D, std::size_t K>
vec<D> affine(vec<D> const& base, std::array<vec<D>, K> const& other, std::array<std::int64_t, K> const& j) {
  vec<D> r;
  for (std::size_t k = 0; k < D; ++k) {
    std::int64_t n = base[k].n * 1000;
    for (std::size_t i = 0; i < K; ++i) n += j[i] * (other[i][k].n - base[k].n);
    r[k] = {n, 9, {}};
  }
  return r;
}

/// `Σ jᵢ/1000 · vᵢ`, with every `vᵢ` at 6 digits: exact, at 9 digits.
template <std::size_t D, std::size_t K>
vec<D> linear(std::array<vec<D>, K> const& v, std::array<std::int64_t, K> const& j) {
  vec<D> r;
  for (std::size_t k = 0; k < D; ++k) {
    std::int64_t n = 0;
    for (std::size_t i = 0; i < K; ++i) n += j[i] * v[i][k].n;
    r[k] = {n, 9, {}};
  }
  return r;
}

template <class FT> e2::point<FT> e2_point(vec<2> const& v) { return {number_of<FT>(v[0]), number_of<FT>(v[1])}; }
template <class FT> e3::point<FT> e3_point(vec<3> const& v) {
  return {number_of<FT>(v[0]), number_of<FT>(v[1]), number_of<FT>(v[2])};
}
template <class FT> s2::point<FT> s2_point(vec<3> const& v) {
  return s2::point<FT>(std::array<FT, 3>{number_of<FT>(v[0]), number_of<FT>(v[1]), number_of<FT>(v[2])});
}

// ---------------------------------------------------------------------------
// Predicate families.  Each has a kernel-neutral input (`raw`), random and
// near-degenerate generators, and a `query<FT>` holding the built objects.

/// E2: side of a point with respect to the line through two points.
struct e2_side_of_point {
  static constexpr char const* name = "E2 side of point";
  static constexpr char const* predicate = "e2::side(line_through(p, q), x)";
  using raw = std::array<vec<2>, 3>; // p, q, x

  static raw random(generator& g) { return {g.random_vec<2>(), g.random_vec<2>(), g.random_vec<2>()}; }
  /// x on the line pq (exact decimal); every other one then nudged by a few ulps.
  static raw degenerate(generator& g, bool nudge) {
    auto p = g.random_vec6<2>(), q = g.random_vec6<2>();
    auto x = affine<2, 1>(p, {q}, {g.multiplier(-500, 1500)});
    if (nudge) g.nudge(x);
    return {p, q, x};
  }

  template <class FT> struct query {
    e2::hyperplane<FT> h;
    e2::point<FT> x;
    explicit query(raw const& r) : h(e2::line_through(e2_point<FT>(r[0]), e2_point<FT>(r[1]))), x(e2_point<FT>(r[2])) {}
    int eval() const { return static_cast<int>(e2::side(h, x)); }
  };
};

/// E2: side of the intersection of two lines with respect to a third (det3 of lines).
struct e2_side_of_vertex {
  static constexpr char const* name = "E2 side of vertex";
  static constexpr char const* predicate = "e2::side_of_vertex(a, b, h), lines through two points each";
  using raw = std::array<vec<2>, 6>; // a through 0, 1; b through 2, 3; h through 4, 5

  static raw random(generator& g) {
    raw r;
    for (auto& v : r) v = g.random_vec<2>();
    return r;
  }
  /// Three lines through one point c (exactly concurrent); every other time h
  /// passes through c nudged by a few ulps instead.
  static raw degenerate(generator& g, bool nudge) {
    auto c = g.random_vec<2>(), ch = c;
    if (nudge) g.nudge(ch);
    return {c, g.random_vec<2>(), c, g.random_vec<2>(), ch, g.random_vec<2>()};
  }

  template <class FT> struct query {
    e2::hyperplane<FT> a, b, h;
    explicit query(raw const& r)
        : a(e2::line_through(e2_point<FT>(r[0]), e2_point<FT>(r[1]))),
          b(e2::line_through(e2_point<FT>(r[2]), e2_point<FT>(r[3]))),
          h(e2::line_through(e2_point<FT>(r[4]), e2_point<FT>(r[5]))) {}
    int eval() const { return static_cast<int>(e2::side_of_vertex(a, b, h)); }
  };
};

/// E3: side of a point with respect to the plane through three points.
struct e3_side_of_point {
  static constexpr char const* name = "E3 side of point";
  static constexpr char const* predicate = "e3::side(plane_through(p, q, r), x)";
  using raw = std::array<vec<3>, 4>; // p, q, r, x

  static raw random(generator& g) {
    return {g.random_vec<3>(), g.random_vec<3>(), g.random_vec<3>(), g.random_vec<3>()};
  }
  /// x on the plane pqr (exact decimal); every other one then nudged by a few ulps.
  static raw degenerate(generator& g, bool nudge) {
    auto p = g.random_vec6<3>(), q = g.random_vec6<3>(), r = g.random_vec6<3>();
    auto x = affine<3, 2>(p, {q, r}, {g.multiplier(-500, 1500), g.multiplier(-500, 1500)});
    if (nudge) g.nudge(x);
    return {p, q, r, x};
  }

  template <class FT> struct query {
    e3::hyperplane<FT> h;
    e3::point<FT> x;
    explicit query(raw const& r)
        : h(e3::plane_through(e3_point<FT>(r[0]), e3_point<FT>(r[1]), e3_point<FT>(r[2]))), x(e3_point<FT>(r[3])) {}
    int eval() const { return static_cast<int>(e3::side(h, x)); }
  };
};

/// S2: side of a direction with respect to the great circle through two directions.
struct s2_side_of_direction {
  static constexpr char const* name = "S2 side of direction";
  static constexpr char const* predicate = "s2::side(circle_through(a, b), x)";
  using raw = std::array<vec<3>, 3>; // a, b, x

  static raw random(generator& g) { return {g.random_vec<3>(), g.random_vec<3>(), g.random_vec<3>()}; }
  /// x = s·a + t·b on the circle (exact decimal); every other one then nudged by a few ulps.
  static raw degenerate(generator& g, bool nudge) {
    auto a = g.random_vec6<3>(), b = g.random_vec6<3>();
    auto x = linear<3, 2>({a, b}, {g.multiplier(-1000, 1000), g.multiplier(-1000, 1000)});
    if (nudge) g.nudge(x);
    return {a, b, x};
  }

  template <class FT> struct query {
    s2::hyperplane<FT> h;
    s2::point<FT> x;
    explicit query(raw const& r)
        : h(s2::circle_through(s2_point<FT>(r[0]), s2_point<FT>(r[1]))), x(s2_point<FT>(r[2])) {}
    int eval() const { return static_cast<int>(s2::side(h, x)); }
  };
};

/// S2: side of the intersection of two great circles with respect to a third.
struct s2_side_of_vertex {
  static constexpr char const* name = "S2 side of vertex";
  static constexpr char const* predicate = "s2::side_of_vertex(a, b, h), circles through two directions each";
  using raw = std::array<vec<3>, 6>;

  static raw random(generator& g) {
    raw r;
    for (auto& v : r) v = g.random_vec<3>();
    return r;
  }
  /// Three circles through one direction c; every other time h passes through
  /// c nudged by a few ulps instead.
  static raw degenerate(generator& g, bool nudge) {
    auto c = g.random_vec<3>(), ch = c;
    if (nudge) g.nudge(ch);
    return {c, g.random_vec<3>(), c, g.random_vec<3>(), ch, g.random_vec<3>()};
  }

  template <class FT> struct query {
    s2::hyperplane<FT> a, b, h;
    explicit query(raw const& r)
        : a(s2::circle_through(s2_point<FT>(r[0]), s2_point<FT>(r[1]))),
          b(s2::circle_through(s2_point<FT>(r[2]), s2_point<FT>(r[3]))),
          h(s2::circle_through(s2_point<FT>(r[4]), s2_point<FT>(r[5]))) {}
    int eval() const { return static_cast<int>(s2::side_of_vertex(a, b, h)); }
  };
};

// ---------------------------------------------------------------------------
// Heap allocations: every operator new and every GMP allocation is counted,
// so that the benchmark can print the allocations per predicate call.

std::uint64_t g_allocations = 0;

void* gmp_allocate(std::size_t n) {
  ++g_allocations;
  return std::malloc(n);
}
void* gmp_reallocate(void* p, std::size_t, std::size_t n) {
  ++g_allocations;
  return std::realloc(p, n);
}
void gmp_free(void* p, std::size_t) { std::free(p); }

// ---------------------------------------------------------------------------
// Timing

/// Makes the compiler assume that `p`'s memory is read and written here, so
/// that it cannot hoist or merge predicate calls across passes.
template <class T> void clobber(T const* p) { __asm__ __volatile__("" : : "g"(p) : "memory"); }

/// Sum of all timed checksums: printed at the end so that nothing is elided.
std::uint64_t g_sink = 0;

/// One pass over the queries; the checksum depends on every sign and its
/// position.  The bounds are read once: a predicate with an out-of-line
/// stage could otherwise make the compiler reload and divide the vector's
/// size at every call (it cannot know that the call leaves the vector
/// alone), a cost of the loop, not of the predicate, and paid by one mode
/// and not the other.
template <class Q> std::uint64_t run_pass(std::vector<Q> const& qs) {
  std::uint64_t cs = 0;
  Q const* const q = qs.data();
  std::size_t const n = qs.size();
  for (std::size_t i = 0; i < n; ++i) cs += static_cast<std::uint64_t>(q[i].eval() + 2) * (i + 1);
  return cs;
}

template <class Q> std::vector<signed char> signs_of(std::vector<Q> const& qs) {
  std::vector<signed char> s;
  s.reserve(qs.size());
  for (auto const& q : qs) s.push_back(static_cast<signed char>(q.eval()));
  return s;
}

struct mode_result {
  double ns_per_eval = 0;             ///< median over the repetitions
  std::vector<double> repetitions_ns; ///< ns per evaluation of each repetition
  std::uint64_t passes = 0;           ///< passes over the queries per repetition
  std::uint64_t checksum = 0;         ///< of one pass
  std::uint64_t evaluations = 0;      ///< filter counters of one untimed pass, every evaluation counted
  std::uint64_t fallbacks = 0;
  double allocations_per_eval = 0;    ///< heap allocations (operator new and GMP) per call, timed repetitions
};

double seconds_since(clock_type::time_point t0) {
  return std::chrono::duration<double>(clock_type::now() - t0).count();
}

template <class Q> std::uint64_t run_passes(std::vector<Q> const& qs, std::uint64_t passes) {
  std::uint64_t cs = 0;
  for (std::uint64_t p = 0; p < passes; ++p) {
    clobber(qs.data());
    cs += run_pass(qs);
  }
  return cs;
}

template <class Q> mode_result time_mode(std::vector<Q> const& qs, options const& o) {
  mode_result r;
  r.checksum = run_pass(qs); // also warms caches and the allocator
  // Calibrate: enough passes that one repetition lasts at least target_seconds.
  std::uint64_t passes = 1;
  for (;;) {
    auto t0 = clock_type::now();
    g_sink += run_passes(qs, passes);
    double s = seconds_since(t0);
    if (s >= o.target_seconds / 4 || passes >= (std::uint64_t{1} << 40)) {
      passes = std::max<std::uint64_t>(
          1, static_cast<std::uint64_t>(std::ceil(passes * o.target_seconds / std::max(s, 1e-9))));
      break;
    }
    passes *= 2;
  }
  r.passes = passes;
  geometry::filter_stats() = {};
  std::uint64_t allocations = 0;
  r.repetitions_ns.reserve(static_cast<std::size_t>(o.repetitions));
  for (int rep = 0; rep < o.repetitions; ++rep) {
    std::uint64_t const allocations0 = g_allocations;
    auto t0 = clock_type::now();
    g_sink += run_passes(qs, passes);
    double s = seconds_since(t0);
    allocations += g_allocations - allocations0;
    r.repetitions_ns.push_back(s * 1e9 / static_cast<double>(passes * qs.size()));
  }
  r.allocations_per_eval = static_cast<double>(allocations) /
                           static_cast<double>(passes * qs.size() * static_cast<std::uint64_t>(o.repetitions));
  // The counts from one more pass, untimed, with every evaluation counted
  // (counting them in the timed passes would slow them down).
  geometry::filter_stats() = {};
  geometry::filter_config().count_evaluations = true;
  g_sink += run_pass(qs);
  geometry::filter_config().count_evaluations = false;
  r.evaluations = geometry::filter_stats().evaluations;
  r.fallbacks = geometry::filter_stats().fallbacks;
  auto sorted = r.repetitions_ns;
  std::sort(sorted.begin(), sorted.end());
  r.ns_per_eval = sorted[sorted.size() / 2];
  return r;
}

/// Filtered over double from repetitions of the two taken in turn: the
/// median of the pairs' ratios, so that a change of the machine's speed
/// during the run (another process, the clock) falls on both sides of each
/// ratio instead of on one mode's whole block.
template <class QD, class QR>
double paired_ratio(std::vector<QD> const& qd, std::uint64_t passes_d, std::vector<QR> const& qr,
                    std::uint64_t passes_r, int pairs) {
  auto& config = geometry::filter_config();
  config.exact_double_signs = false; // plain double; the rational queries do not read it
  std::vector<double> ratios;
  for (int i = 0; i < pairs; ++i) {
    auto t0 = clock_type::now();
    g_sink += run_passes(qd, passes_d);
    double const d = seconds_since(t0) / static_cast<double>(passes_d * qd.size());
    t0 = clock_type::now();
    g_sink += run_passes(qr, passes_r);
    double const f = seconds_since(t0) / static_cast<double>(passes_r * qr.size());
    ratios.push_back(f / d);
  }
  config.exact_double_signs = true;
  std::sort(ratios.begin(), ratios.end());
  return ratios[ratios.size() / 2];
}

struct row {
  std::string family, predicate, input;
  std::size_t queries = 0;
  double filtered_over_double = 0; ///< paired_ratio
  mode_result plain, filtered, exact;
  mode_result gmp; ///< always exact, the fixed-width rungs off: GMP integers only
  double fallback_rate = 0;     ///< filtered mode: fallbacks / evaluations
  double double_wrong_rate = 0; ///< plain double: signs different from the exact ones
  bool consistent = true;       ///< filtered and exact signs identical
};

template <class Family>
row measure(char const* input, std::vector<typename Family::raw> const& raws, options const& o) {
  row r;
  r.family = Family::name;
  r.predicate = Family::predicate;
  r.input = input;
  r.queries = raws.size();
  std::vector<signed char> plain_signs;
  std::vector<typename Family::template query<double>> qd(raws.begin(), raws.end());
  // Plain floating point: the double kernel's exact signs switched off.
  geometry::filter_config().exact_double_signs = false;
  r.plain = time_mode(qd, o);
  plain_signs = signs_of(qd);
  geometry::filter_config().exact_double_signs = true;
  std::vector<typename Family::template query<rational>> qr(raws.begin(), raws.end());
  auto& config = geometry::filter_config();
  config.enabled = true;
  r.filtered = time_mode(qr, o);
  auto filtered_signs = signs_of(qr);
  r.filtered_over_double = paired_ratio(qd, r.plain.passes, qr, r.filtered.passes, o.pairs);
  qd = {};
  config.enabled = false;
  r.exact = time_mode(qr, o);
  auto exact_signs = signs_of(qr);
  config.fixed_width = false;
  r.gmp = time_mode(qr, o);
  auto gmp_signs = signs_of(qr);
  config.fixed_width = true;
  config.enabled = true;

  r.fallback_rate = r.filtered.evaluations
                        ? static_cast<double>(r.filtered.fallbacks) / static_cast<double>(r.filtered.evaluations)
                        : 0;
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < exact_signs.size(); ++i) wrong += plain_signs[i] != exact_signs[i];
  r.double_wrong_rate = static_cast<double>(wrong) / static_cast<double>(exact_signs.size());
  r.consistent = filtered_signs == exact_signs && gmp_signs == exact_signs && r.filtered.checksum == r.exact.checksum &&
                 r.gmp.checksum == r.exact.checksum;
  return r;
}

// ---------------------------------------------------------------------------
// Output

void print_header() {
  std::printf("%-21s %-10s %9s %9s %9s %9s %8s %9s %8s %9s %11s\n", "family", "input", "double", "filtered", "exact",
              "exact GMP", "filt/dbl", "exact/dbl", "fallback", "dbl wrong", "allocations");
  std::printf("%-21s %-10s %9s %9s %9s %9s %8s %9s %8s %9s %11s\n", "", "", "ns/eval", "ns/eval", "ns/eval", "ns/eval", "",
              "", "", "", "per eval");
}

void print_row(row const& r) {
  // The most of the double, filtered and exact modes (GMP allocates by design).
  double const allocations =
      std::max({r.plain.allocations_per_eval, r.filtered.allocations_per_eval, r.exact.allocations_per_eval});
  std::printf("%-21s %-10s %9.2f %9.2f %9.1f %9.1f %7.2fx %8.1fx %7.2f%% %8.2f%% %11.3g%s\n", r.family.c_str(),
              r.input.c_str(), r.plain.ns_per_eval, r.filtered.ns_per_eval, r.exact.ns_per_eval, r.gmp.ns_per_eval,
              r.filtered_over_double, r.exact.ns_per_eval / r.plain.ns_per_eval,
              100 * r.fallback_rate, 100 * r.double_wrong_rate, allocations, r.consistent ? "" : "  FILTERED != EXACT");
  std::fflush(stdout);
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

using bench::compiler;
using bench::json_string;
using bench::optimised;

std::string json_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

std::string json_mode(mode_result const& m) {
  std::ostringstream o;
  o << "{\"ns_per_eval\": " << json_number(m.ns_per_eval)
    << ", \"evals_per_second\": " << json_number(1e9 / m.ns_per_eval) << ", \"repetitions_ns_per_eval\": [";
  for (std::size_t i = 0; i < m.repetitions_ns.size(); ++i) o << (i ? ", " : "") << json_number(m.repetitions_ns[i]);
  o << "], \"passes_per_repetition\": " << m.passes << ", \"checksum\": " << m.checksum
    << ", \"allocations_per_eval\": " << json_number(m.allocations_per_eval) << "}";
  return o.str();
}

bool write_json(std::string const& file, options const& o, std::vector<row> const& rows) {
  std::ostringstream j;
  j << "{\n  \"benchmark\": \"bench_predicates\",\n";
  j << "  \"machine\": {\"hardware_threads\": " << std::thread::hardware_concurrency()
    << ", \"cpu\": " << json_string(cpu_model()) << ", \"compiler\": " << json_string(compiler())
    << ", \"optimised\": " << (optimised() ? "true" : "false") << "},\n";
  j << "  \"settings\": {\"quick\": " << (o.quick ? "true" : "false") << ", \"seed\": " << o.seed
    << ", \"queries\": " << o.queries << ", \"repetitions\": " << o.repetitions
    << ", \"pairs_for_filtered_over_double\": " << o.pairs << ", \"target_seconds_per_repetition\": " << json_number(o.target_seconds) << "},\n";
  j << "  \"results\": [\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    auto const& r = rows[i];
    j << "    {\"family\": " << json_string(r.family) << ", \"predicate\": " << json_string(r.predicate)
      << ", \"input\": " << json_string(r.input) << ", \"queries\": " << r.queries << ",\n"
      << "     \"double\": " << json_mode(r.plain) << ",\n"
      << "     \"filtered\": " << json_mode(r.filtered) << ",\n"
      << "     \"exact\": " << json_mode(r.exact) << ",\n"
      << "     \"exact_gmp\": " << json_mode(r.gmp) << ",\n"
      << "     \"filtered_over_double\": " << json_number(r.filtered_over_double)
      << ", \"exact_over_double\": " << json_number(r.exact.ns_per_eval / r.plain.ns_per_eval)
      << ", \"filter_evaluations\": " << r.filtered.evaluations << ", \"filter_fallbacks\": " << r.filtered.fallbacks
      << ", \"fallback_rate\": " << json_number(r.fallback_rate)
      << ", \"double_wrong_rate\": " << json_number(r.double_wrong_rate)
      << ", \"filtered_equals_exact\": " << (r.consistent ? "true" : "false") << "}" << (i + 1 < rows.size() ? "," : "")
      << "\n";
  }
  j << "  ]\n}\n";

  // Write next to the target, then rename: readers never see a partial file.
  std::filesystem::path target(file);
  std::filesystem::path tmp = target;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << j.str();
    out.flush();
    if (!out) {
      std::fprintf(stderr, "bench_predicates: cannot write '%s'\n", tmp.string().c_str());
      return false;
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, target, ec);
  if (ec) {
    std::fprintf(stderr, "bench_predicates: cannot rename '%s' to '%s': %s\n", tmp.string().c_str(), file.c_str(),
                 ec.message().c_str());
    std::filesystem::remove(tmp, ec);
    return false;
  }
  return true;
}

template <class Family> void run_family(options const& o, std::uint64_t index, std::vector<row>& rows) {
  generator g{std::mt19937_64(o.seed + 2 * index)};
  std::vector<typename Family::raw> random;
  for (std::size_t i = 0; i < o.queries; ++i) random.push_back(Family::random(g));
  rows.push_back(measure<Family>("random", random, o));
  print_row(rows.back());

  generator h{std::mt19937_64(o.seed + 2 * index + 1)};
  std::vector<typename Family::raw> degenerate;
  for (std::size_t i = 0; i < o.queries; ++i) degenerate.push_back(Family::degenerate(h, i % 2 == 1));
  rows.push_back(measure<Family>("degenerate", degenerate, o));
  print_row(rows.back());
}

} // namespace

// Every operator new of the program is counted (the GMP ones through
// mp_set_memory_functions in main).  Not inlined, so that the compiler does
// not pair the malloc inside with a delete-expression outside.
[[gnu::noinline]] void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void* operator new[](std::size_t n) { return ::operator new(n); }
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

int main(int argc, char** argv) {
  options o;
  if (auto code = parse_options(argc, argv, o)) return *code;
  mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free);

  auto start = clock_type::now();
  std::printf("bench_predicates: %s, %u hardware threads, %s\n", cpu_model().c_str(),
              std::thread::hardware_concurrency(), compiler().c_str());
  std::printf("%zu queries per data set, median of %d repetitions of >= %g ms each (filt/dbl: of %d pairs)%s, "
              "seed %llu\n",
              o.queries, o.repetitions, o.target_seconds * 1e3, o.pairs, o.quick ? " (--quick)" : "",
              static_cast<unsigned long long>(o.seed));
  if (!optimised()) std::printf("warning: built without optimisation; the numbers mean little\n");
  std::printf("degenerate input: half exactly on the line/plane/circle (or concurrent), half a few ulps off\n\n");
  print_header();

  std::vector<row> rows;
  run_family<e2_side_of_point>(o, 0, rows);
  run_family<e2_side_of_vertex>(o, 1, rows);
  run_family<e3_side_of_point>(o, 2, rows);
  run_family<s2_side_of_direction>(o, 3, rows);
  run_family<s2_side_of_vertex>(o, 4, rows);

  std::printf("\nchecksum %llu, %.1f s\n", static_cast<unsigned long long>(g_sink), seconds_since(start));

  bool ok = std::all_of(rows.begin(), rows.end(), [](row const& r) { return r.consistent; });
  if (!ok) std::fprintf(stderr, "bench_predicates: the filtered and exact modes disagree on some sign\n");
  if (o.json && !write_json(*o.json, o, rows)) return 1;
  if (o.json) std::printf("results written to %s\n", o.json->c_str());
  return ok ? 0 : 1;
}
