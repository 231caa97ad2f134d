#include "support.hpp"

#include <catch2/catch.hpp>
#include <geometry/e2.hpp>

using namespace geometry;
using test::as;
using test::Q;

namespace geometry_e2_tests {

namespace {

template <class FT> e2::point<FT> pt(Q const& x, Q const& y) { return {as<FT>(x), as<FT>(y)}; }

template <class FT> e2::point<FT> random_point(bool decimal) {
  return decimal ? pt<FT>(test::random_decimal(), test::random_decimal()) : pt<FT>(test::random_integer(), test::random_integer());
}

/// A random counter-clockwise triangle.
template <class FT> std::vector<e2::point<FT>> random_triangle(bool decimal) {
  for (;;) {
    std::vector<e2::point<FT>> v{random_point<FT>(decimal), random_point<FT>(decimal), random_point<FT>(decimal)};
    auto o = e2::orientation(v[0], v[1], v[2]);
    if (o == sign::zero) continue;
    if (o == sign::negative) std::swap(v[1], v[2]);
    return v;
  }
}

template <class FT> void check_equal(FT const& a, FT const& b) {
  if constexpr (std::is_same_v<FT, double>)
    CHECK(a == Approx(b).epsilon(1e-9).margin(1e-9));
  else
    CHECK(a == b);
}

template <class FT> void check_same(e2::point<FT> const& a, e2::point<FT> const& b) {
  check_equal<FT>(a.x(), b.x());
  check_equal<FT>(a.y(), b.y());
}

} // namespace

TEMPLATE_TEST_CASE("E2 predicates agree with the exact value on random input", "[e2]", double, rational) {
  using FT = TestType;
  for (bool decimal : {false, true})
    for (int t = 0; t < 500; ++t) {
      auto p = random_point<FT>(decimal), q = random_point<FT>(decimal), r = random_point<FT>(decimal);
      auto e = [](e2::point<FT> const& a) { return std::array<Q, 3>{test::exact(a.x()), test::exact(a.y()), Q(1)}; };
      Q truth = test::ref_det3(e(p), e(q), e(r));
      CHECK(static_cast<int>(e2::orientation(p, q, r)) == truth.sign());
      if (p == q) continue;
      CHECK(static_cast<int>(e2::side(e2::line_through(p, q), r)) == truth.sign());
      // The vertex of two lines against a third: det of the three lines.
      auto l1 = e2::line_through(p, q), l2 = e2::line_through(q, r), l3 = e2::line_through(r, p);
      auto le = [](auto const& l) { return std::array<Q, 3>{test::exact(l.n[0]), test::exact(l.n[1]), test::exact(l.n[2])}; };
      CHECK(static_cast<int>(e2::side_of_vertex(l1, l2, l3)) == test::ref_det3(le(l1), le(l2), le(l3)).sign());
    }
}

TEMPLATE_TEST_CASE("E2 split partitions a polygon exactly", "[e2]", double, rational) {
  using FT = TestType;
  int both = 0;
  for (bool decimal : {false, true})
    for (int t = 0; t < 300; ++t) {
      auto tri = random_triangle<FT>(decimal);
      auto c = e2::convex_polygon(tri);
      auto whole = *e2::area(c);
      CHECK(sign_of(whole) == sign::positive);
      auto h = e2::line_through(random_point<FT>(decimal), random_point<FT>(decimal));
      if (h.n.is_zero()) continue;
      auto r = e2::split(c, h);
      REQUIRE((r.negative || r.positive));
      CHECK_FALSE(r.is_coincident());
      FT sum(0);
      if (r.negative) sum = sum + *e2::area(*r.negative);
      if (r.positive) sum = sum + *e2::area(*r.positive);
      check_equal<FT>(sum, whole);
      if (r.negative && r.positive) ++both;
      if constexpr (std::is_same_v<FT, rational>) {
        // Each part lies on its side: every vertex is on h's closed side.
        if (r.positive) {
          auto vs = e2::vertices(*r.positive);
          for (auto const& v : vs.value()) CHECK(e2::side(h, v) != oriented_side::negative);
        }
        if (r.negative) {
          auto vs = e2::vertices(*r.negative);
          for (auto const& v : vs.value()) CHECK(e2::side(h, v) != oriented_side::positive);
        }
        // A part that is missing has no area on that side: the polygon's vertices say so.
        if (!r.positive)
          for (auto const& v : tri) CHECK(e2::side(h, v) != oriented_side::positive);
      }
    }
  CHECK(both > 50);
}

TEMPLATE_TEST_CASE("E2 split: degenerate cuts", "[e2]", double, rational) {
  using FT = TestType;
  auto P = [](int x, int y) { return pt<FT>(Q(x), Q(y)); };
  auto square = e2::convex_polygon<FT>({P(0, 0), P(2, 0), P(2, 2), P(0, 2)});
  SECTION("a line along an edge leaves the polygon on one side") {
    auto r = e2::split(square, e2::line_through(P(0, 0), P(1, 0)));
    CHECK(r.positive);
    CHECK_FALSE(r.negative);
    auto r2 = e2::split(square, e2::line_through(P(1, 0), P(0, 0)));
    CHECK(r2.negative);
    CHECK_FALSE(r2.positive);
  }
  SECTION("a line through a vertex only") {
    auto r = e2::split(square, e2::line_through(P(2, 0), P(3, 1)));
    CHECK(r.positive);
    CHECK_FALSE(r.negative);
  }
  SECTION("the diagonal through two vertices") {
    auto r = e2::split(square, e2::line_through(P(0, 0), P(2, 2)));
    REQUIRE(r.negative);
    REQUIRE(r.positive);
    check_equal<FT>(*e2::area(*r.negative), FT(2));
    check_equal<FT>(*e2::area(*r.positive), FT(2));
    CHECK(r.positive->bounds.size() == 3);
  }
  SECTION("a line missing the polygon") {
    auto r = e2::split(square, e2::line_through(P(5, 0), P(5, 1))); // x < 5 on its left
    REQUIRE(r.positive);
    CHECK_FALSE(r.negative);
    check_equal<FT>(*e2::area(*r.positive), FT(4));
  }
}

TEMPLATE_TEST_CASE("E2 unbounded cells are exact, with no bounding box", "[e2]", double, rational) {
  using FT = TestType;
  auto P = [](int x, int y) { return pt<FT>(Q(x), Q(y)); };
  auto plane = e2::whole_plane<FT>();
  CHECK_FALSE(e2::area(plane));
  auto half = e2::split(plane, e2::line_through(P(0, 0), P(1, 0)));
  REQUIRE(half.positive);
  REQUIRE(half.negative);
  CHECK_FALSE(e2::area(*half.positive));
  // Three cuts of the whole plane make the triangle (0,0) (3,0) (0,3).
  auto c = *half.positive;
  c = *e2::split(c, e2::line_through(P(3, 0), P(0, 3))).positive;
  CHECK_FALSE(e2::area(c)); // still an unbounded wedge
  c = *e2::split(c, e2::line_through(P(0, 3), P(0, 0))).positive;
  REQUIRE(e2::area(c));
  check_equal<FT>(*e2::area(c), FT(9) / FT(2));
  // A far line parallel to the edge cuts the half-plane, but not the triangle.
  auto far = e2::line_through(P(0, 100), P(1, 100));
  auto r = e2::split(*half.positive, far);
  CHECK(r.positive);
  CHECK(r.negative);
  auto r2 = e2::split(c, far);
  CHECK(r2.negative);
  CHECK_FALSE(r2.positive);
  // A line parallel to the boundary of a half-plane, outside it.
  auto r3 = e2::split(*half.positive, e2::line_through(P(0, -1), P(1, -1)));
  CHECK(r3.positive);
  CHECK_FALSE(r3.negative);
}

TEMPLATE_TEST_CASE("E2 segments split exactly and report coincidence", "[e2]", double, rational) {
  using FT = TestType;
  auto P = [](Q x, Q y) { return pt<FT>(x, y); };
  auto s = e2::segment(P(0, 0), P(4, 2));
  auto ends = e2::endpoints(s);
  REQUIRE(ends);
  check_same(ends->first, P(0, 0));
  check_same(ends->second, P(4, 2));
  SECTION("crossing line: the parts meet at the crossing point") {
    auto r = e2::split(s, e2::line_through(P(1, 3), P(1, -3)));
    REQUIRE(r.negative);
    REQUIRE(r.positive);
    auto a = *e2::endpoints(*r.negative), b = *e2::endpoints(*r.positive);
    // The line x = 1 run downward has x > 1 on its left, its positive side.
    check_same(a.first, P(0, 0));
    check_same(a.second, P(1, Q(1, 2)));
    check_same(b.first, P(1, Q(1, 2)));
    check_same(b.second, P(4, 2));
  }
  SECTION("coincidence, in both orientations") {
    auto r = e2::split(s, e2::line_through(P(8, 4), P(12, 6)));
    CHECK(r.coincident == sign::positive);
    CHECK_FALSE(r.negative);
    CHECK_FALSE(r.positive);
    auto r2 = e2::split(s, e2::line_through(P(12, 6), P(8, 4)));
    CHECK(r2.coincident == sign::negative);
  }
  SECTION("touching at an endpoint leaves it whole") {
    auto r = e2::split(s, e2::line_through(P(4, 2), P(4, 3)));
    CHECK(r.positive);
    CHECK_FALSE(r.negative);
  }
  SECTION("a whole line splits into two rays") {
    auto r = e2::split(e2::whole_line(e2::line_through(P(0, 0), P(1, 1))), e2::line_through(P(0, 2), P(2, 0)));
    REQUIRE(r.negative);
    REQUIRE(r.positive);
    CHECK_FALSE(e2::endpoints(*r.negative));
    // x + y > 2 is the positive side: the positive ray runs from (1, 1) out to infinity.
    auto h = e2::homogeneous_endpoints(*r.positive);
    REQUIRE(h.size() == 2);
    CHECK(sign_of(h[0][2]) == sign::positive);
    CHECK(h[0][0] == h[0][2]);
    CHECK(sign_of(h[1][2]) == sign::zero);
    auto g = e2::homogeneous_endpoints(*r.negative);
    REQUIRE(g.size() == 2);
    CHECK(sign_of(g[0][2]) == sign::zero);
    CHECK(sign_of(g[1][2]) == sign::positive);
  }
  SECTION("the opposite segment runs backwards") {
    auto o = *e2::endpoints(e2::opposite(s));
    check_same(o.first, P(4, 2));
    check_same(o.second, P(0, 0));
  }
}

TEMPLATE_TEST_CASE("E2 segments are the whole line cut by their two cross lines", "[e2]", double, rational) {
  using FT = TestType;
  // What `segment` builds directly must be what splitting the whole line
  // at both ends gives: the same support, axis, bounds and order.
  auto by_splits = [](e2::point<FT> const& p, e2::point<FT> const& q) {
    auto l = e2::line_through(p, q);
    auto s = e2::split(e2::whole_line(l), e2::cross_line(l, p, q)).positive;
    REQUIRE(s);
    auto t = e2::split(*s, e2::cross_line(l, q, p)).positive;
    REQUIRE(t);
    return *t;
  };
  auto check = [&](e2::point<FT> const& p, e2::point<FT> const& q) {
    auto a = e2::segment(p, q);
    auto b = by_splits(p, q);
    CHECK(a.support.n == b.support.n);
    CHECK(a.axis == b.axis);
    REQUIRE(a.bounds.size() == 2);
    REQUIRE(b.bounds.size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
      CHECK(a.bounds[i].original.n == b.bounds[i].original.n);
      CHECK(a.bounds[i].restricted == b.bounds[i].restricted);
    }
    auto ends = e2::endpoints(a);
    REQUIRE(ends);
    check_same(ends->first, p);
    check_same(ends->second, q);
  };
  auto P = [](Q x, Q y) { return pt<FT>(x, y); };
  // Horizontal, vertical and diagonal lines (|a| = |b|: the tie between
  // the two kinds of cross line), in both directions.
  for (auto [x, y] : std::vector<std::pair<int, int>>{{1, 0}, {0, 1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}, {-1, 0}, {0, -1}, {3, 7}, {-7, 3}})
    check(P(Q(1, 3), Q(-2, 5)), P(Q(1, 3) + x, Q(-2, 5) + y));
  for (int i = 0; i < 300; ++i) {
    bool decimal = i % 2 == 1;
    auto p = random_point<FT>(decimal), q = random_point<FT>(decimal);
    if (p == q) continue;
    check(p, q);
  }
}

TEST_CASE("E2 cell areas: integer corners and fractional ones alike", "[e2]") {
  // Triangles and the quadrilateral cells of a square cut by a line, with
  // corners of small integers (summed in 128 bits), fractions and integers
  // past 2^40 (in rationals), against the shoelace formula in rationals.
  Q const big = Q(geometry::integer(1) << 40);
  auto shoelace = [](std::vector<e2::point<rational>> const& v) {
    Q s(0);
    for (std::size_t i = 0; i < v.size(); ++i) {
      auto const &a = v[i], &b = v[(i + 1) % v.size()];
      s += a.x() * b.y() - a.y() * b.x();
    }
    return Q(s / 2);
  };
  for (int t = 0; t < 300; ++t) {
    int kind = t % 3;
    auto coordinate = [&] { return kind == 0 ? test::random_integer() : kind == 1 ? test::random_decimal() : big + test::random_integer(); };
    std::vector<e2::point<rational>> v;
    for (;;) {
      v = {pt<rational>(coordinate(), coordinate()), pt<rational>(coordinate(), coordinate()), pt<rational>(coordinate(), coordinate())};
      auto o = e2::orientation(v[0], v[1], v[2]);
      if (o == sign::zero) continue;
      if (o == sign::negative) std::swap(v[1], v[2]);
      break;
    }
    auto area = e2::area(e2::convex_polygon(v));
    REQUIRE(area);
    CHECK(*area == shoelace(v));
    // A square with those corners' spread, cut through two of its sides: both
    // parts' areas add up to the square's.
    Q lo = v[0].x(), hi = lo + 1000;
    auto square = e2::convex_polygon(std::vector<e2::point<rational>>{pt<rational>(lo, lo), pt<rational>(hi, lo), pt<rational>(hi, hi), pt<rational>(lo, hi)});
    auto cut = e2::split(square, e2::line_through(pt<rational>(lo - 1, lo + Q(1, 3)), pt<rational>(hi + 1, hi - 7)));
    REQUIRE(cut.negative);
    REQUIRE(cut.positive);
    CHECK(*e2::area(*cut.negative) + *e2::area(*cut.positive) == 1000 * 1000);
  }
}

TEST_CASE("E2 points from homogeneous integers are the same points", "[e2]") {
  for (int t = 0; t < 200; ++t) {
    auto p = random_point<rational>(t % 2 == 1);
    auto q = e2::point<rational>::from_homogeneous(p.homogeneous());
    CHECK(q == p);
    CHECK(q.x() == p.x());
    CHECK(q.y() == p.y());
  }
}

} // namespace geometry_e2_tests
