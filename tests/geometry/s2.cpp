#include "support.hpp"

#include <catch2/catch.hpp>
#include <geometry/s2.hpp>

#include <numbers>
#include <random>

using namespace geometry;
using test::as;
using test::Q;

namespace geometry_s2_tests {

namespace {

constexpr double pi = std::numbers::pi;

template <class FT> s2::point<FT> dir(Q const& x, Q const& y, Q const& z) {
  return s2::point<FT>(std::array<FT, 3>{as<FT>(x), as<FT>(y), as<FT>(z)});
}

template <class FT> s2::point<FT> random_dir(bool decimal) {
  auto r = [&] { return decimal ? test::random_decimal(3, 1) : test::random_integer(20); };
  for (;;) {
    auto p = dir<FT>(r(), r(), r());
    if (!p.is_zero()) return p;
  }
}

template <class FT> std::array<Q, 3> ex(hvec<FT, 3> const& v) { return {test::exact(v[0]), test::exact(v[1]), test::exact(v[2])}; }

/// A random small counter-clockwise spherical triangle around a random direction.
template <class FT> std::vector<s2::point<FT>> random_triangle(bool decimal) {
  for (;;) {
    std::vector<s2::point<FT>> v{random_dir<FT>(decimal), random_dir<FT>(decimal), random_dir<FT>(decimal)};
    auto o = s2::orientation(v[0], v[1], v[2]);
    if (o == sign::zero) continue;
    if (o == sign::negative) std::swap(v[1], v[2]);
    return v;
  }
}

} // namespace

TEMPLATE_TEST_CASE("S2 predicates agree with the exact value on random input", "[s2]", double, rational) {
  using FT = TestType;
  for (bool decimal : {false, true})
    for (int t = 0; t < 500; ++t) {
      auto a = random_dir<FT>(decimal), b = random_dir<FT>(decimal), c = random_dir<FT>(decimal), d = random_dir<FT>(decimal);
      CHECK(static_cast<int>(s2::orientation(a, b, c)) == test::ref_det3(ex(a), ex(b), ex(c)).sign());
      s2::hyperplane<FT> h1(a), h2(b), h3(c);
      CHECK(static_cast<int>(s2::side(h1, d)) == test::ref_dot(ex(a), ex(d)).sign());
      CHECK(static_cast<int>(s2::side_of_vertex(h1, h2, h3)) == test::ref_det3(ex(a), ex(b), ex(c)).sign());
    }
}

TEMPLATE_TEST_CASE("S2 polytopes: the sphere, hemispheres, lunes and polygons have the right areas", "[s2]", double, rational) {
  using FT = TestType;
  auto X = dir<FT>(1, 0, 0), Y = dir<FT>(0, 1, 0), Z = dir<FT>(0, 0, 1);
  CHECK(s2::area(s2::whole_sphere<FT>()) == Approx(4 * pi));
  auto octant = s2::convex_polygon<FT>({X, Y, Z});
  CHECK(s2::area(octant) == Approx(pi / 2).epsilon(1e-14));
  // The whole sphere cut by the equator, then by a meridian plane, then by x = y.
  auto r = s2::split(s2::whole_sphere<FT>(), s2::hyperplane<FT>(Z));
  REQUIRE(r.positive);
  REQUIRE(r.negative);
  CHECK(s2::area(*r.positive) == Approx(2 * pi));
  auto lune = s2::split(*r.positive, s2::hyperplane<FT>(X));
  REQUIRE(lune.positive);
  CHECK(lune.positive->bounds.size() == 2);
  CHECK(s2::area(*lune.positive) == Approx(pi));
  // A circle through both vertices of the lune (±Y): it splits the lune into two lunes.
  auto diag = s2::hyperplane<FT>(dir<FT>(1, 0, -1));
  auto two = s2::split(*lune.positive, diag);
  REQUIRE(two.positive);
  REQUIRE(two.negative);
  CHECK(two.positive->bounds.size() == 2);
  CHECK(two.negative->bounds.size() == 2);
  CHECK(s2::area(*two.positive) + s2::area(*two.negative) == Approx(pi).epsilon(1e-14));
  CHECK(s2::area(*two.positive) == Approx(pi / 2).epsilon(1e-14));
  // A circle through both vertices but outside the lune.
  auto outside = s2::split(*lune.positive, s2::hyperplane<FT>(dir<FT>(1, 0, 1)));
  CHECK(outside.positive);
  CHECK_FALSE(outside.negative);
  // A circle crossing the lune: two triangles.
  auto tri = s2::split(*lune.positive, s2::hyperplane<FT>(dir<FT>(0, 1, 0)));
  REQUIRE(tri.positive);
  REQUIRE(tri.negative);
  CHECK(tri.positive->bounds.size() == 3);
  CHECK(s2::area(*tri.positive) == Approx(pi / 2).epsilon(1e-14));
  // The hemisphere and its own circle: one side only, in both orientations.
  auto same = s2::split(*r.positive, s2::hyperplane<FT>(Z));
  CHECK(same.positive);
  CHECK_FALSE(same.negative);
  auto opp = s2::split(*r.positive, s2::hyperplane<FT>(dir<FT>(0, 0, -3)));
  CHECK(opp.negative);
  CHECK_FALSE(opp.positive);
}

TEMPLATE_TEST_CASE("S2 split partitions spherical area", "[s2]", double, rational) {
  using FT = TestType;
  int both = 0;
  for (bool decimal : {false, true})
    for (int t = 0; t < 300; ++t) {
      auto c = s2::convex_polygon(random_triangle<FT>(decimal));
      s2::hyperplane<FT> h(random_dir<FT>(decimal));
      auto r = s2::split(c, h);
      REQUIRE((r.negative || r.positive));
      double sum = (r.negative ? s2::area(*r.negative) : 0.0) + (r.positive ? s2::area(*r.positive) : 0.0);
      CHECK(sum == Approx(s2::area(c)).epsilon(1e-12).margin(1e-12));
      if (r.negative && r.positive) {
        ++both;
        // The new vertices lie on h.
        if constexpr (std::is_same_v<FT, rational>)
          for (auto const& v : s2::vertices(*r.positive)) CHECK(s2::side(h, v) != oriented_side::negative);
      }
    }
  CHECK(both > 50);
}

TEMPLATE_TEST_CASE("S2 arcs split by length and report coincidence", "[s2]", double, rational) {
  using FT = TestType;
  auto X = dir<FT>(1, 0, 0), Y = dir<FT>(0, 1, 0), Z = dir<FT>(0, 0, 1);
  auto equator = s2::circle_through(X, Y);
  auto halves = s2::split(s2::whole_circle(equator), s2::hyperplane<FT>(X));
  REQUIRE(halves.positive);
  REQUIRE(halves.negative);
  CHECK(s2::length(*halves.positive) == Approx(pi));
  auto a = s2::arc(X, Y);
  CHECK(s2::length(a) == Approx(pi / 2));
  auto e = s2::endpoints(a);
  CHECK(s2::side(s2::hyperplane<FT>(X), e[0]) == oriented_side::positive);
  CHECK(s2::side(s2::hyperplane<FT>(Y), e[1]) == oriented_side::positive); // … and the end Y's
  auto cut = s2::split(a, s2::hyperplane<FT>(dir<FT>(1, -1, 0)));
  REQUIRE(cut.positive);
  REQUIRE(cut.negative);
  CHECK(s2::length(*cut.positive) == Approx(pi / 4));
  CHECK(s2::length(*cut.negative) == Approx(pi / 4));
  CHECK(s2::split(a, s2::hyperplane<FT>(dir<FT>(0, 0, 5))).coincident == sign::positive);
  CHECK(s2::split(a, s2::hyperplane<FT>(dir<FT>(0, 0, -1))).coincident == sign::negative);
  // Touching at an endpoint.
  auto touch = s2::split(a, s2::hyperplane<FT>(dir<FT>(0, 1, 1)));
  CHECK(touch.positive);
  CHECK_FALSE(touch.negative);
  // Random arcs: the parts' lengths add up.
  for (int t = 0; t < 200; ++t) {
    auto p = random_dir<FT>(true), q = random_dir<FT>(true);
    if (s2::circle_through(p, q).n.is_zero() || s2::orientation(p, q, Z) == sign::zero) continue;
    auto s = s2::arc(p, q);
    auto r = s2::split(s, s2::hyperplane<FT>(random_dir<FT>(true)));
    double sum = (r.negative ? s2::length(*r.negative) : 0.0) + (r.positive ? s2::length(*r.positive) : 0.0);
    CHECK(sum == Approx(s2::length(s)).epsilon(1e-12));
  }
}

TEST_CASE("S2 arcs are bounded as splitting the whole circle by the circles through their ends would bound them", "[s2]") {
  // `arc` restricts the circles through its ends from the ends themselves
  // (`restricted_through`); splitting restricts them from the circles.
  std::mt19937_64 rng(20261207);
  std::uniform_real_distribution<double> u(-1, 1);
  int compared = 0;
  for (int t = 0; t < 4000; ++t) {
    auto p = t % 2 ? dir<Q>(Q(u(rng)), Q(u(rng)), Q(u(rng))) : random_dir<Q>(false);
    auto q = t % 2 ? dir<Q>(Q(u(rng)), Q(u(rng)), Q(u(rng))) : random_dir<Q>(false);
    if (p.is_zero() || q.is_zero() || parallel(p, q) != sign::zero) continue;
    ++compared;
    auto a = s2::arc(p, q);
    auto c = s2::circle_through(p, q);
    auto half = s2::split(s2::whole_circle(c), s2::hyperplane<Q>(cross(c.n, p))).positive;
    REQUIRE(half);
    auto b = s2::split(*half, s2::hyperplane<Q>(cross(q, c.n))).positive;
    REQUIRE(b);
    CHECK(a.support == b->support);
    CHECK(a.axis == b->axis);
    REQUIRE(a.bounds.size() == 2);
    REQUIRE(b->bounds.size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
      CHECK(a.bounds[i].original == b->bounds[i].original);
      CHECK(a.bounds[i].restricted == b->bounds[i].restricted);
    }
    CHECK(s2::endpoint(a, false) == p);
    CHECK(s2::endpoint(a, true) == q);
  }
  CHECK(compared > 3500);
}

} // namespace geometry_s2_tests
