// Filtered predicates: plain double gets near-degenerate signs wrong, the
// filtered exact kernel never does, and it falls back to exact arithmetic only
// when it has to.
#include "support.hpp"

#include <catch2/catch.hpp>
#include <geometry/geometry.hpp>

#include <cstdint>
#include <random>

using namespace geometry;
using test::Q;

namespace geometry_filter_tests {

namespace {

/// Plain double for the length of a test: the double kernel's signs
/// evaluated once in floating point, as any double code would.
struct plain_double {
  plain_double() { filter_config().exact_double_signs = false; }
  ~plain_double() { filter_config().exact_double_signs = true; }
  plain_double(plain_double const&) = delete;
  plain_double& operator=(plain_double const&) = delete;
};

/// Counting of every filtered evaluation for the length of a test.
struct counting {
  counting() { filter_config().count_evaluations = true; }
  ~counting() { filter_config().count_evaluations = false; }
  counting(counting const&) = delete;
  counting& operator=(counting const&) = delete;
};

struct counts {
  int compared = 0, double_wrong = 0, filtered_wrong = 0;
};

std::array<Q, 3> q3(double a, double b, double c) { return {Q(a), Q(b), Q(c)}; }

} // namespace

TEST_CASE("E2: points 1 ulp off a line", "[filter][e2]") {
  plain_double plain;
  counting count;
  // The classic orientation experiment (Kettner et al.): a grid of points
  // ulps away from (0.5, 0.5), against the line through (12, 12) and (24, 24).
  counts c;
  auto const s0 = filter_stats();
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) {
      double px = test::up(0.5, i), py = test::up(0.5, j);
      Q truth = test::ref_det3(q3(12, 12, 1), q3(24, 24, 1), q3(px, py, 1));
      auto d = e2::orientation<double>({12, 12}, {24, 24}, {px, py});
      auto f = e2::orientation<Q>({Q(12), Q(12)}, {Q(24), Q(24)}, {Q(px), Q(py)});
      ++c.compared;
      c.double_wrong += static_cast<int>(d) != truth.sign();
      c.filtered_wrong += static_cast<int>(f) != truth.sign();
    }
  auto const s1 = filter_stats();
  INFO("compared " << c.compared << ", double wrong " << c.double_wrong);
  CHECK(c.double_wrong > 0);
  CHECK(c.filtered_wrong == 0);
  CHECK(s1.fallbacks > s0.fallbacks); // the filter did hand over
  // … but only where it has to: a point clearly off the line is decided in double.
  CHECK(e2::orientation<Q>({Q(12), Q(12)}, {Q(24), Q(24)}, {Q(0.5), Q(0.75)}) == sign::positive);
  CHECK(filter_stats().fallbacks == s1.fallbacks);
  CHECK(filter_stats().evaluations == s1.evaluations + 1);
}

TEST_CASE("E3: points 1 ulp off a plane", "[filter][e3]") {
  plain_double plain;
  // Points of a plane through three random decimal points, moved up to 2 ulps in z.
  counts c;
  for (int t = 0; t < 400; ++t) {
    std::array<Q, 3> a{test::random_decimal(3, 10), test::random_decimal(3, 10), test::random_decimal(3, 10)};
    std::array<Q, 3> b{test::random_decimal(3, 10), test::random_decimal(3, 10), test::random_decimal(3, 10)};
    std::array<Q, 3> d{test::random_decimal(3, 10), test::random_decimal(3, 10), test::random_decimal(3, 10)};
    auto n = test::ref_cross({b[0] - a[0], b[1] - a[1], b[2] - a[2]}, {d[0] - a[0], d[1] - a[1], d[2] - a[2]});
    if (n[2] == 0) continue;
    // The point of the plane above (x, y) = random, rounded to doubles, then nudged.
    double x = test::random_decimal(3, 10).convert_to<double>(), y = test::random_decimal(3, 10).convert_to<double>();
    Q z = a[2] - (n[0] * (Q(x) - a[0]) + n[1] * (Q(y) - a[1])) / n[2];
    double zd = test::up(z.convert_to<double>(), static_cast<int>(test::uniform(-2, 2)) + 2);
    zd = test::down(zd, 2);
    Q truth = test::ref_dot(n, {Q(x) - a[0], Q(y) - a[1], Q(zd) - a[2]});
    auto pd = [](std::array<Q, 3> const& v) { return e3::point<double>(v[0].convert_to<double>(), v[1].convert_to<double>(), v[2].convert_to<double>()); };
    auto pq = [](std::array<Q, 3> const& v) { return e3::point<Q>(v[0], v[1], v[2]); };
    auto hd = e3::plane_through(pd(a), pd(b), pd(d));
    auto hq = e3::plane_through(pq(a), pq(b), pq(d));
    auto sd = e3::side(hd, e3::point<double>(x, y, zd));
    auto sq = e3::side(hq, e3::point<Q>(Q(x), Q(y), Q(zd)));
    // The double kernel sees the decimal input rounded; the truth is about the exact input.
    ++c.compared;
    c.double_wrong += static_cast<int>(sd) != truth.sign();
    c.filtered_wrong += static_cast<int>(sq) != truth.sign();
  }
  INFO("compared " << c.compared << ", double wrong " << c.double_wrong);
  CHECK(c.compared > 300);
  CHECK(c.double_wrong > 0);
  CHECK(c.filtered_wrong == 0);
}

TEST_CASE("S2: the circle through nearly antipodal directions", "[filter][s2]") {
  plain_double plain;
  counts c;
  // The same inputs whichever test cases ran before; plain double errs on
  // about 1 in 200 of them (14 to 26 of 4000 over six seeds tried).
  test::rng().seed(20261122);
  for (int t = 0; t < 4000; ++t) {
    double ax = test::random_decimal(4, 1).convert_to<double>() + 2, ay = test::random_decimal(4, 1).convert_to<double>(),
           az = test::random_decimal(4, 1).convert_to<double>();
    // b is -a moved by a few ulps: the circle through a and b is barely determined.
    double bx = -test::up(ax, static_cast<int>(test::uniform(1, 3))), by = -test::down(ay, static_cast<int>(test::uniform(0, 3))),
           bz = -az;
    // Directions near the circle: a perpendicular-ish direction, nudged.
    double rx = test::up(ay, static_cast<int>(test::uniform(0, 4))), ry = -ax, rz = test::down(az * 0.5, static_cast<int>(test::uniform(0, 4)));
    auto n = test::ref_cross(q3(ax, ay, az), q3(bx, by, bz));
    Q truth = test::ref_dot(n, q3(rx, ry, rz));
    using PD = s2::point<double>;
    using PQ = s2::point<Q>;
    auto sd = s2::side(s2::circle_through(PD({ax, ay, az}), PD({bx, by, bz})), PD({rx, ry, rz}));
    auto sq = s2::side(s2::circle_through(PQ(q3(ax, ay, az)), PQ(q3(bx, by, bz))), PQ(q3(rx, ry, rz)));
    ++c.compared;
    c.double_wrong += static_cast<int>(sd) != truth.sign();
    c.filtered_wrong += static_cast<int>(sq) != truth.sign();
  }
  INFO("compared " << c.compared << ", double wrong " << c.double_wrong);
  CHECK(c.double_wrong > 0);
  CHECK(c.filtered_wrong == 0);
}

TEST_CASE("S2 and E2: the vertex of nearly coincident circles", "[filter][s2]") {
  plain_double plain;
  counts c;
  for (int t = 0; t < 400; ++t) {
    std::array<double, 3> n1{test::random_decimal(3, 1).convert_to<double>(), test::random_decimal(3, 1).convert_to<double>(), 1.0};
    std::array<double, 3> n2{test::up(n1[0], static_cast<int>(test::uniform(1, 4))), test::down(n1[1], static_cast<int>(test::uniform(0, 4))), 1.0};
    // A third circle through (almost) the vertex n1 × n2.
    auto v = test::ref_cross(q3(n1[0], n1[1], n1[2]), q3(n2[0], n2[1], n2[2]));
    double vx = v[0].convert_to<double>(), vy = v[1].convert_to<double>(), vz = v[2].convert_to<double>();
    std::array<double, 3> h{test::up(vy, static_cast<int>(test::uniform(0, 2))), -vx, test::random_decimal(2, 1).convert_to<double>() * vz};
    Q truth = test::ref_det3(q3(n1[0], n1[1], n1[2]), q3(n2[0], n2[1], n2[2]), q3(h[0], h[1], h[2]));
    using HD = s2::hyperplane<double>;
    using HQ = s2::hyperplane<Q>;
    auto sd = s2::side_of_vertex(HD(hvec<double, 3>(n1)), HD(hvec<double, 3>(n2)), HD(hvec<double, 3>(h)));
    auto sq = s2::side_of_vertex(HQ(hvec<Q, 3>(q3(n1[0], n1[1], n1[2]))), HQ(hvec<Q, 3>(q3(n2[0], n2[1], n2[2]))),
                                 HQ(hvec<Q, 3>(q3(h[0], h[1], h[2]))));
    ++c.compared;
    c.double_wrong += static_cast<int>(sd) != truth.sign();
    c.filtered_wrong += static_cast<int>(sq) != truth.sign();
  }
  INFO("compared " << c.compared << ", double wrong " << c.double_wrong);
  CHECK(c.double_wrong > 0);
  CHECK(c.filtered_wrong == 0);
}

TEST_CASE("the filter certifies exact zeros without exact arithmetic when every monomial vanishes", "[filter]") {
  counting count;
  auto s0 = filter_stats();
  hvec<Q, 3> a(std::array<Q, 3>{Q(1), Q(0), Q(0)}), b(std::array<Q, 3>{Q(0), Q(1), Q(0)});
  CHECK(dot_sign(a, b) == sign::zero);
  auto s1 = filter_stats();
  CHECK(s1.evaluations == s0.evaluations + 1);
  CHECK(s1.fallbacks == s0.fallbacks);
}

TEST_CASE("parallel: shared numbers without arithmetic, else the primitive integers", "[filter]") {
  auto v = [](Q x, Q y, Q z) { return hvec<Q, 3>(std::array<Q, 3>{x, y, z}); };
  auto a = v(Q(3, 7), Q(-5, 11), Q(2, 13));
  auto copy = a, opposite = -a;
  auto apart = v(Q(6, 7), Q(-10, 11), Q(4, 13)); // 2a, made apart
  CHECK(shares_numbers(a, copy));
  CHECK(shares_numbers(a, opposite));
  CHECK_FALSE(shares_numbers(a, apart));
  auto s0 = filter_stats();
  CHECK(parallel(a, copy) == sign::positive);
  CHECK(parallel(a, opposite) == sign::negative);
  CHECK(parallel(opposite, a) == sign::negative);
  CHECK(filter_stats().fallbacks == s0.fallbacks); // told by the shared numbers
  CHECK(parallel(a, apart) == sign::positive);
  CHECK(parallel(a, -apart) == sign::negative);
  // The first minor vanishes, the vectors are independent.
  CHECK(parallel(v(Q(0), Q(0), Q(1)), v(Q(0), Q(1), Q(1))) == sign::zero);
  CHECK(parallel(v(Q(1), Q(2), Q(3)), v(Q(2), Q(4), Q(5))) == sign::zero);
  CHECK(parallel(v(Q(1), Q(2), Q(3)), v(Q(-2), Q(-4), Q(-6))) == sign::negative);
  // Against the definition (every 2×2 minor zero, then the dot product's
  // sign) on random small vectors, many of them parallel.
  for (int i = 0; i < 2000; ++i) {
    auto r = [] { return Q(test::uniform(-3, 3)); };
    auto p = v(r(), r(), r());
    auto k = Q(test::uniform(-2, 2));
    auto q = test::uniform(0, 1) ? v(k * p[0], k * p[1], k * p[2]) : v(r(), r(), r());
    if (p.is_zero() || q.is_zero()) continue;
    bool dependent = p[0] * q[1] == p[1] * q[0] && p[0] * q[2] == p[2] * q[0] && p[1] * q[2] == p[2] * q[1];
    Q d = p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
    CHECK(parallel(p, q) == (!dependent ? sign::zero : d > 0 ? sign::positive : sign::negative));
  }
}

TEST_CASE("switching the filter off makes every evaluation exact, with the same signs", "[filter]") {
  std::vector<std::array<Q, 3>> v;
  for (int i = 0; i < 300; ++i) v.push_back({test::random_decimal(), test::random_decimal(), test::random_decimal()});
  std::vector<sign> on, off;
  for (std::size_t i = 0; i + 2 < v.size(); ++i)
    on.push_back(det_sign(hvec<Q, 3>(v[i]), hvec<Q, 3>(v[i + 1]), hvec<Q, 3>(v[i + 2])));
  filter_config().enabled = false;
  auto s0 = filter_stats();
  for (std::size_t i = 0; i + 2 < v.size(); ++i)
    off.push_back(det_sign(hvec<Q, 3>(v[i]), hvec<Q, 3>(v[i + 1]), hvec<Q, 3>(v[i + 2])));
  auto s1 = filter_stats();
  filter_config().enabled = true;
  CHECK(on == off);
  CHECK(s1.fallbacks - s0.fallbacks == off.size());
}

TEST_CASE("numbers outside the filter's range go exact and stay right", "[filter]") {
  Q huge = Q(boost::multiprecision::mpz_int(1) << 300), tiny = Q(1) / huge;
  hvec<Q, 2> a(std::array<Q, 2>{huge, Q(1)}), b(std::array<Q, 2>{tiny, Q(-1)});
  auto s0 = filter_stats();
  CHECK(dot_sign(a, b) == sign::zero); // huge·tiny − 1 = 0
  CHECK(filter_stats().fallbacks == s0.fallbacks + 1);
}

TEST_CASE("vectors past 190 bits: the filter reads them scaled by a power of two, and never a wrong sign", "[filter]") {
  using big = boost::multiprecision::mpz_int;
  auto random_big = [](int bits) {
    big x = 1; // the top bit set: exactly `bits` bits
    for (int b = 1; b < bits; ++b) x = 2 * x + test::uniform(0, 1);
    return test::uniform(0, 1) ? x : big(-x);
  };
  int fallbacks_expected = 0, total = 0, wrong = 0;
  auto const s0 = filter_stats();
  for (int t = 0; t < 600; ++t) {
    int bits = static_cast<int>(test::uniform(191, 700));
    std::array<Q, 3> a{Q(random_big(bits)), Q(random_big(bits - 1)), Q(random_big(bits - 2))};
    std::array<Q, 3> b{Q(random_big(bits)), Q(random_big(bits)), Q(random_big(bits - 3))};
    std::array<Q, 3> c;
    for (std::size_t k = 0; k < 3; ++k) c[k] = a[k] + b[k];
    int kind = t % 3; // 0: dependent, 1: nudged by one unit, 2: independent
    if (kind == 1) c[static_cast<std::size_t>(t % 2)] += 1;
    if (kind == 2) c = {Q(random_big(bits)), Q(random_big(bits)), Q(random_big(bits))};
    hvec<Q, 3> A(a), B(b), C(c);
    // The doubles: each entry's value over 2^s (s the largest bit length
    // less 190), truncated, and at least 1.
    auto const& z = A.integer_view().big();
    std::size_t top = 0;
    for (auto const& x : z) top = std::max(top, mpz_sizeinbase(x.backend().data(), 2));
    for (std::size_t k = 0; k < 3; ++k) {
      double v = A.approx().v[k];
      Q exact = Q(z[k]) / Q(big(1) << static_cast<unsigned>(top - 190));
      CHECK(std::fabs(v) >= 1);
      CHECK(std::fabs(v) < 0x1p190);
      CHECK(abs(Q(v) - exact) <= abs(exact) * Q(std::ldexp(1.0, -51)));
      CHECK((v > 0) == (z[k] > 0));
    }
    CHECK_FALSE(A.approx().integral);
    Q truth = test::ref_det3(a, b, c);
    ++total;
    wrong += static_cast<int>(det_sign(A, B, C)) != truth.sign();
    fallbacks_expected += kind != 2;
  }
  CHECK(total == 600);
  CHECK(wrong == 0);
  // Independent triples are decided in double; dependent and nudged ones
  // (relative gaps near 2^-700) need exact arithmetic.
  CHECK(filter_stats().fallbacks - s0.fallbacks <= static_cast<std::uint64_t>(fallbacks_expected) + 5);
  CHECK(filter_stats().fallbacks - s0.fallbacks >= static_cast<std::uint64_t>(fallbacks_expected) / 2);
  // An entry that would fall below 1 leaves the vector to the exact stages.
  hvec<Q, 3> lopsided(std::array<Q, 3>{Q(big(1) << 400), Q(3), Q(-5)});
  CHECK(std::isnan(lopsided.approx().v[1]));
  CHECK(std::isnan(lopsided.approx().norm));
  CHECK(lopsided.sign_at(2) == sign::negative);
}

TEST_CASE("every exact stage gives the true sign: double, 128-bit and GMP integers, rationals", "[filter]") {
  // Degenerate triples c = a + b (determinant 0) and nudged ones (±1 in one
  // coordinate), with integers of 20, 40 and 70 bits and with fractions, so
  // that each stage of the exact evaluation is taken.
  for (int bits : {20, 40, 70}) {
    for (bool fractions : {false, true}) {
      int wrong = 0, total = 0;
      auto big = [&] {
        test::Q x(boost::multiprecision::mpz_int(test::uniform(1, 1000000)) << (bits - 20));
        return fractions ? test::Q(x / test::Q(test::uniform(1, 97))) : x;
      };
      for (int t = 0; t < 200; ++t) {
        std::array<Q, 3> a{big(), big(), big()}, b{big(), big(), big()};
        std::array<Q, 3> c{a[0] + b[0], a[1] + b[1], a[2] + b[2]};
        if (t % 2) c[static_cast<std::size_t>(t % 3)] += (t % 4 == 1 ? 1 : -1);
        Q truth = test::ref_det3(a, b, c);
        ++total;
        wrong += static_cast<int>(det_sign(hvec<Q, 3>(a), hvec<Q, 3>(b), hvec<Q, 3>(c))) != truth.sign();
      }
      INFO(bits << " bits, fractions " << fractions);
      CHECK(total == 200);
      CHECK(wrong == 0);
    }
  }
}

TEST_CASE("over double, signs are exact for the doubles given", "[filter][double]") {
  // The points 1 ulp off the line y = x: plain double gets some wrong; with
  // exact signs (the default) the double kernel gets every one right, since
  // these inputs are doubles exactly.
  int compared = 0, plain_wrong = 0, exact_wrong = 0;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) {
      double px = test::up(0.5, i), py = test::up(0.5, j);
      Q truth = test::ref_det3(q3(12, 12, 1), q3(24, 24, 1), q3(px, py, 1));
      sign exact = e2::orientation<double>({12, 12}, {24, 24}, {px, py});
      sign plain;
      {
        plain_double p;
        plain = e2::orientation<double>({12, 12}, {24, 24}, {px, py});
      }
      ++compared;
      plain_wrong += static_cast<int>(plain) != truth.sign();
      exact_wrong += static_cast<int>(exact) != truth.sign();
    }
  INFO("compared " << compared << ", plain double wrong " << plain_wrong);
  CHECK(plain_wrong > 0);
  CHECK(exact_wrong == 0);
}

namespace {

/// A random integer of exactly `bits` bits (top bit set), of random sign.
integer random_bits(int bits) {
  integer x(1);
  for (int i = 1; i < bits; ++i) x = 2 * x + test::uniform(0, 1);
  return test::uniform(0, 1) ? integer(-x) : x;
}

/// The largest coefficient size whose bound, as `integer_sign` computes it
/// for `f` on `K` vectors, stays within `limit` bits.
template <std::size_t N, std::size_t K, class F> int largest_bits_within(F const& f, int limit) {
  auto bound = [&](int b) {
    std::array<detail::bits_counter, N> v;
    v.fill({b});
    return [&]<std::size_t... I>(std::index_sequence<I...>) { return f(((void)I, v)...).b; }(std::make_index_sequence<K>{});
  };
  int b = 1;
  while (bound(b + 1) <= limit) ++b;
  REQUIRE(bound(b) <= limit);
  REQUIRE(bound(b + 1) > limit);
  return b;
}

} // namespace

TEST_CASE("each rung of the exact ladder agrees with GMP at its width boundary", "[filter]") {
  // For each fixed-width rung (128, 256 and 512 bits), coefficients of the
  // largest size that rung accepts and of one bit more (the next rung),
  // random, all of the largest magnitude, and exactly degenerate, against
  // the sign over GMP integers and over rationals.
  using Z = integer;
  auto det3f = [](auto const& x, auto const& y, auto const& z) { return det3(x, y, z); };
  auto dot4f = [](auto const& x, auto const& y) { return dot(x, y); };
  auto to_q = [](std::array<Z, 3> const& a) { return std::array<Q, 3>{Q(a[0]), Q(a[1]), Q(a[2])}; };
  for (int limit : {detail::int128_bits, detail::fixed256_bits, detail::fixed512_bits}) {
    int const b3 = largest_bits_within<3, 3>(det3f, limit);
    int const b4 = largest_bits_within<4, 2>(dot4f, limit);
    for (int extra : {0, 1}) {
      int wrong = 0, zeros = 0;
      int const bits = b3 + extra;
      for (int t = 0; t < 120; ++t) {
        std::array<Z, 3> a, b, c;
        for (std::size_t i = 0; i < 3; ++i) a[i] = random_bits(bits), b[i] = random_bits(bits), c[i] = random_bits(bits);
        if (t % 3 == 1) {
          // Largest magnitudes: every coefficient ±(2^bits − 1).
          Z m = (Z(1) << bits) - 1;
          for (auto* v : {&a, &b, &c})
            for (auto& x : *v) x = test::uniform(0, 1) ? m : Z(-m);
        } else if (t % 3 == 2) {
          // Degenerate: the first two columns are constant, so the determinant is 0.
          b[0] = c[0] = a[0], b[1] = c[1] = a[1];
          if (t % 2) c[2] += 1; // and one step off it
        }
        sign s = detail::integer_sign(det3f, a, b, c);
        Q truth = test::ref_det3(to_q(a), to_q(b), to_q(c));
        zeros += s == sign::zero;
        wrong += static_cast<int>(s) != truth.sign() || s != sign_of(det3(a, b, c));
      }
      int const bits4 = b4 + extra;
      for (int t = 0; t < 120; ++t) {
        std::array<Z, 4> p, h;
        for (std::size_t i = 0; i < 4; ++i) p[i] = random_bits(bits4), h[i] = random_bits(bits4);
        if (t % 2) h = {p[1], Z(-p[0]), p[3], Z(-p[2])}; // p · h = 0
        sign s = detail::integer_sign(dot4f, p, h);
        Q truth = Q(p[0] * h[0]) + Q(p[1] * h[1]) + Q(p[2] * h[2]) + Q(p[3] * h[3]);
        zeros += s == sign::zero;
        wrong += static_cast<int>(s) != truth.sign();
      }
      INFO("rung limit " << limit << " bits; det3 coefficients of " << bits << " bits, dot4 of " << bits4);
      CHECK(zeros >= 60 + 20); // the degenerate half of dot4, and det3's exact zeros
      CHECK(wrong == 0);
    }
  }
}

TEST_CASE("exact vectors share their numbers with their copies and their opposite", "[filter]") {
  std::array<Q, 3> c{Q(1) / 3, Q(-2) / 5, Q(7)};
  hvec<Q, 3> a(c), b = a, n = -a;
  CHECK(a == b);
  CHECK(&a.exact() == &b.exact()); // one set of numbers
  CHECK(n.exact() == std::array<Q, 3>{Q(-1) / 3, Q(2) / 5, Q(-7)});
  CHECK(-n == a);
  CHECK(&(-n).exact() == &a.exact());
  // The primitive integer multiple: 15 × c = (5, −6, 105), whose gcd is 1.
  using Z = integer;
  CHECK(a.integers() == std::array<Z, 3>{Z(5), Z(-6), Z(105)});
  CHECK(n.integers() == std::array<Z, 3>{Z(-5), Z(6), Z(-105)});
  hvec<Q, 3> even(std::array<Q, 3>{Q(4), Q(-6), Q(10)});
  CHECK(even.integers() == std::array<Z, 3>{Z(2), Z(-3), Z(5)});
  CHECK(hvec<Q, 3>().is_zero());
  CHECK(det_sign(a, n, hvec<Q, 3>(std::array<Q, 3>{Q(0), Q(1), Q(0)})) == sign::zero);
}

TEST_CASE("the static stage: constants from the polynomial, and never a wrong certain sign", "[filter]") {
  using detail::static_constants_of;
  auto det = [](auto const& x, auto const& y, auto const& z) { return det3(x, y, z); };
  auto dot4 = [](auto const& x, auto const& y) { return dot(x, y); };
  auto pencil = [](auto const& x, auto const& y, auto const& z) { return dot(x, x) * dot(z, y) - dot(x, y) * dot(z, x); };
  constexpr auto kd = static_constants_of<decltype(det), 3, 3, 3>(std::make_index_sequence<3>{});
  constexpr auto kp = static_constants_of<decltype(dot4), 4, 4>(std::make_index_sequence<2>{});
  constexpr auto kc = static_constants_of<decltype(pencil), 3, 3, 3>(std::make_index_sequence<3>{});
  STATIC_REQUIRE(kd.degree == std::array<int, 3>{1, 1, 1});
  STATIC_REQUIRE(kd.weight == 6.0);
  STATIC_REQUIRE(kp.degree == std::array<int, 2>{1, 1});
  STATIC_REQUIRE(kp.weight == 4.0);
  STATIC_REQUIRE(kc.degree == std::array<int, 3>{2, 1, 1});
  STATIC_REQUIRE(kc.weight == 18.0);
  // Nearly dependent triples with coordinates of very different sizes (the
  // norm bound is loosest there): c = a + b nudged by one unit in the last
  // place of one coordinate, or not at all.
  int certain = 0, wrong = 0, total = 0;
  for (int t = 0; t < 3000; ++t) {
    auto coordinate = [&] { return std::ldexp(test::uniform(1, 1 << 20), test::uniform(-40, 40)); };
    std::array<double, 3> a{coordinate(), coordinate(), coordinate()}, b{coordinate(), coordinate(), coordinate()};
    std::array<double, 3> c{a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    auto& nudged = c[static_cast<std::size_t>(t % 3)];
    if (t % 3) nudged = t % 2 ? test::up(nudged) : test::down(nudged);
    if (t % 5 == 0) c = {coordinate(), coordinate(), coordinate()}; // independent
    hvec<Q, 3> A(q3(a[0], a[1], a[2])), B(q3(b[0], b[1], b[2])), C(q3(c[0], c[1], c[2]));
    Q truth = test::ref_det3(q3(a[0], a[1], a[2]), q3(b[0], b[1], b[2]), q3(c[0], c[1], c[2]));
    auto r = detail::static_stage(det, A.approx(), B.approx(), C.approx());
    ++total;
    if (!r.certain) continue;
    ++certain;
    wrong += static_cast<int>(r.s) != truth.sign();
  }
  INFO(certain << " of " << total << " certified by the static stage");
  CHECK(total == 3000);
  CHECK(wrong == 0);
  CHECK(certain >= 300); // the independent triples at least
}

TEST_CASE("the static stage decides small integers exactly, zeros included, and nothing past 2^53", "[filter]") {
  auto det = [](auto const& x, auto const& y, auto const& z) { return det3(x, y, z); };
  // Coordinates below 2^15, the third row up to 2^17: 6 · 2^47 < 2^53, every
  // operation exact.  Dependent rows half the time: exact zeros.
  int zeros = 0, wrong = 0;
  for (int t = 0; t < 3000; ++t) {
    auto small = [] { return static_cast<double>(test::uniform(-(1 << 15), 1 << 15)); };
    std::array<double, 3> a{small(), small(), small()}, b{small(), small(), small()}, c{small(), small(), small()};
    if (t % 2) {
      double k = static_cast<double>(test::uniform(-1, 1)), l = static_cast<double>(test::uniform(-1, 1));
      c = {k * a[0] + l * b[0], k * a[1] + l * b[1], k * a[2] + l * b[2]};
    }
    hvec<Q, 3> A(q3(a[0], a[1], a[2])), B(q3(b[0], b[1], b[2])), C(q3(c[0], c[1], c[2]));
    Q truth = test::ref_det3(q3(a[0], a[1], a[2]), q3(b[0], b[1], b[2]), q3(c[0], c[1], c[2]));
    auto r = detail::static_stage(det, A.approx(), B.approx(), C.approx());
    CHECK(r.certain);
    wrong += static_cast<int>(r.s) != truth.sign();
    zeros += truth.sign() == 0;
  }
  CHECK(wrong == 0);
  CHECK(zeros > 1000);
  // Past 2^53 (rows near 2^20), a zero is left to the later stages.
  double big = 1 << 20;
  hvec<Q, 3> A(q3(big + 1, 3, 5)), B(q3(7, big - 3, 11)), C(q3(big + 8, big, 16));
  CHECK(test::ref_det3(q3(big + 1, 3, 5), q3(7, big - 3, 11), q3(big + 8, big, 16)) == 0);
  CHECK_FALSE(detail::static_stage(det, A.approx(), B.approx(), C.approx()).certain);
  CHECK(det_sign(A, B, C) == sign::zero);
}

TEST_CASE("evaluations are counted only when asked for; fallbacks always", "[filter]") {
  Q big = Q(boost::multiprecision::mpz_int(1) << 60) + 1; // not a double: the filter hands over
  hvec<Q, 3> a(std::array<Q, 3>{big, Q(1), Q(0)}), b(std::array<Q, 3>{Q(1), -big, Q(5)});
  auto s0 = filter_stats();
  CHECK(dot_sign(a, b) == sign::zero);
  auto s1 = filter_stats();
  CHECK(s1.evaluations == s0.evaluations);
  CHECK(s1.fallbacks == s0.fallbacks + 1);
  {
    counting count;
    CHECK(dot_sign(a, b) == sign::zero);
  }
  CHECK(filter_stats().evaluations == s1.evaluations + 1);
  CHECK(filter_stats().fallbacks == s1.fallbacks + 1);
}

TEST_CASE("constructions on integers: the true vector up to a positive factor, primitive, on every rung", "[filter][construct]") {
  // Coordinates of 20, 40 and 70 bits, as integers and as fractions: cross
  // products of 3-vectors then take the 128-bit rung or GMP integers; with
  // the fixed-width rungs off, GMP integers always.  Checked against
  // properties the construction must have, in rationals: `cross(a, b)` is
  // orthogonal to both and turns positively; `restrict_to(p, k, b)` gives
  // every point x of p the side `b · x`.
  auto primitive = [](auto const& v) {
    integer g(0);
    for (auto const& z : v.integers()) g = boost::multiprecision::gcd(g, z);
    return g == 1;
  };
  for (bool fixed : {true, false}) {
    filter_config().fixed_width = fixed;
    for (int bits : {20, 40, 70}) {
      for (bool fractions : {false, true}) {
        auto big = [&] {
          Q x(boost::multiprecision::mpz_int(test::uniform(-1000000, 1000000)) << (bits - 20));
          return fractions ? Q(x / Q(test::uniform(1, 97))) : x;
        };
        int crossed = 0, restricted = 0;
        for (int t = 0; t < 100; ++t) {
          std::array<Q, 3> a{big(), big(), big()}, b{big(), big(), big()};
          auto c = cross(hvec<Q, 3>(a), hvec<Q, 3>(b));
          std::array<Q, 3> const& r = c.exact();
          if (r == std::array<Q, 3>{}) continue; // a, b parallel
          CHECK(test::ref_dot(r, a) == 0);
          CHECK(test::ref_dot(r, b) == 0);
          CHECK(test::ref_det3(a, b, r) > 0);
          CHECK(primitive(c));
          ++crossed;
          // The plane through three points, a point x in it, a plane h.
          std::array<std::array<Q, 3>, 3> q;
          for (auto& pt : q) pt = {big(), big(), big()};
          std::array<Q, 3> u{q[1][0] - q[0][0], q[1][1] - q[0][1], q[1][2] - q[0][2]};
          std::array<Q, 3> w{q[2][0] - q[0][0], q[2][1] - q[0][1], q[2][2] - q[0][2]};
          std::array<Q, 3> n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
          if (n == std::array<Q, 3>{}) continue;
          hvec<Q, 4> P(std::array<Q, 4>{n[0], n[1], n[2], -test::ref_dot(n, q[0])});
          Q s(test::uniform(-5, 5), 7), v(test::uniform(-5, 5), 3);
          std::array<Q, 4> x{q[0][0] + s * u[0] + v * w[0], q[0][1] + s * u[1] + v * w[1], q[0][2] + s * u[2] + v * w[2], Q(1)};
          std::array<Q, 4> h{big(), big(), big(), big()};
          std::size_t k = dominant_axis(P);
          auto R = restrict_to(P, k, hvec<Q, 4>(h));
          auto X = drop(P, k, hvec<Q, 4>(x));
          Q bx = h[0] * x[0] + h[1] * x[1] + h[2] * x[2] + h[3] * x[3];
          Q rx = R[0] * X[0] + R[1] * X[1] + R[2] * X[2];
          CHECK(rx.sign() == bx.sign());
          CHECK(primitive(R));
          ++restricted;
        }
        INFO(bits << " bits, fractions " << fractions << ", fixed widths " << fixed);
        CHECK(crossed >= 95);
        CHECK(restricted >= 95);
      }
    }
  }
  filter_config().fixed_width = true;
}

TEST_CASE("exact vectors are equal when they are the same up to a positive factor", "[filter]") {
  hvec<Q, 3> a(std::array<Q, 3>{Q(1, 2), Q(-1, 3), Q(2)}), twice(std::array<Q, 3>{Q(1), Q(-2, 3), Q(4)});
  CHECK(a == twice);
  CHECK_FALSE(a == -twice);
  CHECK(-a == -twice);
  CHECK_FALSE(a == hvec<Q, 3>(std::array<Q, 3>{Q(1, 2), Q(-1, 3), Q(3)}));
  // A vector made from integers equals the rational one it is a multiple of.
  auto c = cross(hvec<Q, 3>(std::array<Q, 3>{Q(1), Q(0), Q(0)}), hvec<Q, 3>(std::array<Q, 3>{Q(0), Q(1, 5), Q(0)}));
  CHECK(c == hvec<Q, 3>(std::array<Q, 3>{Q(0), Q(0), Q(1, 5)}));
}

TEST_CASE("the 128-bit gcd of constructions agrees with GMP's", "[filter][construct]") {
  using detail::uint128;
  std::mt19937_64 rng(20261204);
  auto to_mpz = [](uint128 v) {
    integer z(static_cast<std::uint64_t>(v >> 64));
    z <<= 64;
    z += static_cast<std::uint64_t>(v);
    return z;
  };
  // Random sizes from 0 to 128 bits, with common factors (odd ones and powers
  // of two) multiplied in, so that every branch runs: both below 2^64, one
  // below and one above (the division first), both above, zeros.
  auto sized = [&rng](int bits) -> uint128 {
    if (bits == 0) return 0;
    uint128 v = (uint128{rng()} << 64) | rng();
    return bits == 128 ? v : v & ((uint128{1} << bits) - 1);
  };
  int checked = 0;
  for (int i = 0; i < 20000; ++i) {
    int fb = static_cast<int>(rng() % 40);
    uint128 f = sized(fb) | 1;
    f <<= rng() % 8;
    int fbits = 128 - (f >> 64 ? __builtin_clzll(static_cast<std::uint64_t>(f >> 64)) : 64 + __builtin_clzll(static_cast<std::uint64_t>(f)));
    int room = 128 - fbits;
    uint128 a = sized(static_cast<int>(rng() % (room + 1))) * f, b = sized(static_cast<int>(rng() % (room + 1))) * f;
    integer g;
    mpz_gcd(g.backend().data(), to_mpz(a).backend().data(), to_mpz(b).backend().data());
    REQUIRE(to_mpz(detail::gcd(a, b)) == g);
    REQUIRE(to_mpz(detail::gcd(b, a)) == g);
    ++checked;
  }
  CHECK(detail::gcd(0, 0) == 0);
  CHECK(detail::gcd(uint128{1} << 127, uint128{3} << 100) == (uint128{1} << 100));
  CHECK(checked == 20000);
}

} // namespace geometry_filter_tests
