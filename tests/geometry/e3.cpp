#include "support.hpp"

#include <catch2/catch.hpp>
#include <geometry/e3.hpp>

using namespace geometry;
using test::as;
using test::Q;

namespace geometry_e3_tests {

namespace {

template <class FT> e3::point<FT> pt(Q const& x, Q const& y, Q const& z) { return {as<FT>(x), as<FT>(y), as<FT>(z)}; }

template <class FT> e3::point<FT> random_point(bool decimal) {
  auto r = [&] { return decimal ? test::random_decimal(3, 10) : test::random_integer(100); };
  return pt<FT>(r(), r(), r());
}

template <class FT> void check_equal(FT const& a, FT const& b) {
  if constexpr (std::is_same_v<FT, double>)
    CHECK(a == Approx(b).epsilon(1e-9).margin(1e-9));
  else
    CHECK(a == b);
}

template <class FT> std::array<Q, 4> ex(e3::hyperplane<FT> const& h) {
  return {test::exact(h.n[0]), test::exact(h.n[1]), test::exact(h.n[2]), test::exact(h.n[3])};
}

} // namespace

TEMPLATE_TEST_CASE("E3 predicates agree with the exact value on random input", "[e3]", double, rational) {
  using FT = TestType;
  for (bool decimal : {false, true})
    for (int t = 0; t < 500; ++t) {
      auto a = random_point<FT>(decimal), b = random_point<FT>(decimal), c = random_point<FT>(decimal), d = random_point<FT>(decimal);
      auto e = [](e3::point<FT> const& p) { return std::array<Q, 3>{test::exact(p.x()), test::exact(p.y()), test::exact(p.z())}; };
      auto A = e(a), B = e(b), C = e(c), D = e(d);
      auto n = test::ref_cross({B[0] - A[0], B[1] - A[1], B[2] - A[2]}, {C[0] - A[0], C[1] - A[1], C[2] - A[2]});
      Q truth = test::ref_dot(n, {D[0] - A[0], D[1] - A[1], D[2] - A[2]});
      CHECK(static_cast<int>(e3::side(e3::plane_through(a, b, c), d)) == truth.sign());
    }
}

TEMPLATE_TEST_CASE("E3 convex polygons made directly equal those cut out of their plane edge by edge", "[e3]", double, rational) {
  using FT = TestType;
  auto same = [](e3::sub_hyperplane<FT> const& a, e3::sub_hyperplane<FT> const& b) {
    // Over double the two constructions round differently.
    if constexpr (!std::is_same_v<FT, double>) REQUIRE(parallel(a.support.n, b.support.n) == sign::positive);
    CHECK(a.axis == b.axis);
    auto va = e3::vertices(a), vb = e3::vertices(b);
    REQUIRE(va);
    REQUIRE(vb);
    REQUIRE(va->size() == vb->size());
    std::size_t n = va->size(), start = 0;
    auto near = [](e3::point<FT> const& p, e3::point<FT> const& q) {
      if constexpr (std::is_same_v<FT, double>)
        return std::abs(p.x() - q.x()) + std::abs(p.y() - q.y()) + std::abs(p.z() - q.z()) < 1e-9;
      else
        return p == q;
    };
    while (start < n && !near((*vb)[start], (*va)[0])) ++start;
    REQUIRE(start < n);
    for (std::size_t i = 0; i < n; ++i) CHECK(near((*vb)[(start + i) % n], (*va)[i]));
  };
  auto by_splits = [](std::vector<e3::point<FT>> const& v) {
    auto support = e3::plane_through(v[0], v[1], v[2]);
    std::size_t k = dominant_axis(hvec<FT, 3>(std::array<FT, 3>{support.n[0], support.n[1], support.n[2]}));
    return geometry::detail::convex_polygon_by_splits(v, support, k);
  };
  for (bool decimal : {false, true})
    for (int t = 0; t < 300; ++t) {
      auto a = random_point<FT>(decimal), b = random_point<FT>(decimal), c = random_point<FT>(decimal);
      auto const& h = e3::plane_through(a, b, c).n;
      if (h.sign_at(0) == sign::zero && h.sign_at(1) == sign::zero && h.sign_at(2) == sign::zero) continue; // collinear
      std::vector<e3::point<FT>> tri{a, b, c};
      auto made = e3::convex_polygon(tri);
      same(made, by_splits(tri));
      if constexpr (!std::is_same_v<FT, double>) {
        // Against the input: its vertices are the triangle's, and its
        // positive side is where (b − a) × (c − a) points, in exact arithmetic.
        auto e = [](e3::point<FT> const& p) { return std::array<Q, 3>{test::exact(p.x()), test::exact(p.y()), test::exact(p.z())}; };
        auto A = e(a), B = e(b), C = e(c);
        auto n = test::ref_cross({B[0] - A[0], B[1] - A[1], B[2] - A[2]}, {C[0] - A[0], C[1] - A[1], C[2] - A[2]});
        CHECK(e3::side(made.support, pt<FT>(A[0] + n[0], A[1] + n[1], A[2] + n[2])) == oriented_side::positive);
        auto vs = e3::vertices(made);
        REQUIRE(vs);
        REQUIRE(vs->size() == 3);
        std::size_t start = 0;
        while (start < 3 && !((*vs)[start] == a)) ++start;
        REQUIRE(start < 3);
        CHECK((*vs)[(start + 1) % 3] == b);
        CHECK((*vs)[(start + 2) % 3] == c);
      }
    }
  // Degenerate families: collinear consecutive vertices, and a square in each axis plane.
  std::vector<e3::point<FT>> with_collinear{pt<FT>(4, 4, 6), pt<FT>(0, 4, 4), pt<FT>(0, 0, 0), pt<FT>(2, 0, 1), pt<FT>(4, 0, 2)};
  same(e3::convex_polygon(with_collinear), by_splits(with_collinear));
  CHECK(e3::convex_polygon(with_collinear).bounds.size() == 4);
  for (std::size_t k = 0; k < 3; ++k) {
    auto at = [k](Q u, Q w) {
      std::array<Q, 3> c{Q(7), Q(7), Q(7)};
      c[(k + 1) % 3] = u;
      c[(k + 2) % 3] = w;
      return pt<FT>(c[0], c[1], c[2]);
    };
    std::vector<e3::point<FT>> square{at(0, 0), at(Q(1, 3), 0), at(Q(1, 3), Q(1, 3)), at(0, Q(1, 3))};
    same(e3::convex_polygon(square), by_splits(square));
  }
}

TEMPLATE_TEST_CASE("E3 polygons: vertices, orientation, split by area", "[e3]", double, rational) {
  using FT = TestType;
  // A quadrilateral on a slanted plane, counter-clockwise seen from its positive side.
  std::vector<e3::point<FT>> quad{pt<FT>(0, 0, 0), pt<FT>(4, 0, 2), pt<FT>(4, 4, 6), pt<FT>(0, 4, 4)};
  auto s = e3::convex_polygon(quad);
  auto v = e3::vertices(s);
  REQUIRE(v);
  REQUIRE(v->size() == 4);
  // Same cyclic order as the input.
  std::size_t start = 0;
  while (start < 4 && !((*v)[start] == quad[0])) ++start;
  REQUIRE(start < 4);
  for (std::size_t i = 0; i < 4; ++i) CHECK((*v)[(start + i) % 4] == quad[i]);
  check_equal<FT>(*e3::projected_area(s, 2), FT(16));
  SECTION("split by a crossing plane: projected areas add up, and the cut lies in the plane") {
    auto h = e3::plane_through(pt<FT>(1, 0, 0), pt<FT>(1, 1, 0), pt<FT>(3, 0, 9));
    auto r = e3::split(s, h);
    REQUIRE(r.positive);
    REQUIRE(r.negative);
    for (std::size_t k = 0; k < 3; ++k)
      check_equal<FT>(FT(*e3::projected_area(*r.positive, k) + *e3::projected_area(*r.negative, k)), *e3::projected_area(s, k));
    if constexpr (std::is_same_v<FT, rational>) {
      auto vs = e3::vertices(*r.positive);
      for (auto const& p : vs.value()) CHECK(e3::side(h, p) != oriented_side::negative);
    }
  }
  SECTION("coincidence in both orientations") {
    auto h = e3::plane_through(quad[0], quad[1], quad[2]);
    CHECK(e3::split(s, h).coincident == sign::positive);
    CHECK(e3::split(s, h.opposite()).coincident == sign::negative);
  }
  SECTION("a plane through an edge only") {
    auto h = e3::plane_through(pt<FT>(0, 0, 0), pt<FT>(4, 0, 2), pt<FT>(0, 0, 7));
    auto r = e3::split(s, h);
    CHECK(r.positive.has_value() != r.negative.has_value());
  }
  SECTION("the opposite polygon keeps its vertices, reversed") {
    auto o = e3::vertices(e3::opposite(s));
    REQUIRE(o);
    REQUIRE(o->size() == 4);
    std::size_t j = 0;
    while (j < 4 && !((*o)[j] == quad[0])) ++j;
    REQUIRE(j < 4);
    for (std::size_t i = 0; i < 4; ++i) CHECK((*o)[(j + 4 - i) % 4] == quad[i]);
  }
}

TEMPLATE_TEST_CASE("E3 split partitions volume exactly", "[e3]", double, rational) {
  using FT = TestType;
  auto box = e3::box(pt<FT>(-10, -10, -10), pt<FT>(10, 10, 10));
  check_equal<FT>(*e3::volume(box), FT(8000));
  CHECK(box.faces.size() == 6);
  int both = 0;
  for (bool decimal : {false, true})
    for (int t = 0; t < 150; ++t) {
      auto a = random_point<FT>(decimal), b = random_point<FT>(decimal), c = random_point<FT>(decimal);
      auto h = e3::plane_through(a, b, c);
      if (h.n[0] == 0 && h.n[1] == 0 && h.n[2] == 0) continue;
      // Cut the box twice so the second split meets a polyhedron with a plane-made face.
      auto first = e3::split(box, h);
      for (auto const* part : {&first.negative, &first.positive}) {
        if (!*part) continue;
        auto whole = *e3::volume(**part);
        auto h2 = e3::plane_through(random_point<FT>(decimal), random_point<FT>(decimal), random_point<FT>(decimal));
        if (h2.n[0] == 0 && h2.n[1] == 0 && h2.n[2] == 0) continue;
        auto r = e3::split(**part, h2);
        REQUIRE((r.negative || r.positive));
        FT sum(0);
        if (r.negative) sum = sum + *e3::volume(*r.negative);
        if (r.positive) sum = sum + *e3::volume(*r.positive);
        check_equal<FT>(sum, whole);
        if (r.negative && r.positive) ++both;
      }
    }
  CHECK(both > 30);
}

TEMPLATE_TEST_CASE("E3 degenerate and unbounded polyhedra", "[e3]", double, rational) {
  using FT = TestType;
  auto cube = e3::box(pt<FT>(0, 0, 0), pt<FT>(1, 1, 1));
  SECTION("a face's own plane leaves the cube on one side, in both orientations") {
    auto h = e3::plane_through(pt<FT>(0, 0, 0), pt<FT>(1, 0, 0), pt<FT>(0, 1, 0)); // z = 0, normal +z
    auto r = e3::split(cube, h);
    CHECK(r.positive);
    CHECK_FALSE(r.negative);
    auto r2 = e3::split(cube, h.opposite());
    CHECK(r2.negative);
    CHECK_FALSE(r2.positive);
  }
  SECTION("a plane through an edge, outside") {
    auto h = e3::plane_through(pt<FT>(1, 0, 0), pt<FT>(1, 1, 0), pt<FT>(2, 0, 1));
    auto r = e3::split(cube, h);
    CHECK(r.positive.has_value() != r.negative.has_value());
  }
  SECTION("a plane through a vertex, outside, and through two opposite edges") {
    auto h = e3::plane_through(pt<FT>(1, 1, 1), pt<FT>(2, 1, 0), pt<FT>(1, 2, 0));
    auto r = e3::split(cube, h);
    CHECK(r.positive.has_value() != r.negative.has_value());
    auto diag = e3::plane_through(pt<FT>(0, 0, 0), pt<FT>(1, 1, 0), pt<FT>(0, 0, 1));
    auto d = e3::split(cube, diag);
    REQUIRE(d.positive);
    REQUIRE(d.negative);
    check_equal<FT>(*e3::volume(*d.positive), FT(1) / FT(2));
    CHECK(d.positive->faces.size() == 5); // a triangular prism
  }
  SECTION("the whole space splits into unbounded halves; planes bound it again") {
    auto r = e3::split(e3::whole_space<FT>(), e3::plane_through(pt<FT>(0, 0, 0), pt<FT>(1, 0, 0), pt<FT>(0, 1, 0)));
    REQUIRE(r.positive);
    REQUIRE(r.negative);
    CHECK_FALSE(e3::volume(*r.positive));
    // A parallel plane below does not cut the upper half-space.
    auto below = e3::plane_through(pt<FT>(0, 0, -1), pt<FT>(1, 0, -1), pt<FT>(0, 1, -1));
    auto r2 = e3::split(*r.positive, below);
    CHECK(r2.positive);
    CHECK_FALSE(r2.negative);
    // The corner tetrahedron x, y, z ≥ 0, x + y + z ≤ 6.
    auto c = *r.positive;
    c = *e3::split(c, e3::plane_through(pt<FT>(0, 0, 0), pt<FT>(0, 1, 0), pt<FT>(0, 0, 1))).positive;
    c = *e3::split(c, e3::plane_through(pt<FT>(0, 0, 0), pt<FT>(0, 0, 1), pt<FT>(1, 0, 0))).positive;
    CHECK_FALSE(e3::volume(c));
    c = *e3::split(c, e3::plane_through(pt<FT>(6, 0, 0), pt<FT>(0, 0, 6), pt<FT>(0, 6, 0))).positive;
    REQUIRE(e3::volume(c));
    check_equal<FT>(*e3::volume(c), FT(36));
    CHECK(c.faces.size() == 4);
  }
}

TEST_CASE("det4 agrees with the cofactor expansion along the first row", "[e3][linear]") {
  for (int t = 0; t < 200; ++t) {
    std::array<std::array<Q, 4>, 4> m;
    for (auto& row : m)
      for (auto& x : row) x = test::random_decimal();
    if (t % 4 == 0) m[3] = {m[0][0] + m[1][0], m[0][1] + m[1][1], m[0][2] + m[1][2], m[0][3] + m[1][3]}; // singular
    Q expansion(0);
    for (std::size_t j = 0; j < 4; ++j) {
      std::array<std::array<Q, 3>, 3> minor;
      for (std::size_t r = 1; r < 4; ++r)
        for (std::size_t c = 0, k = 0; c < 4; ++c)
          if (c != j) minor[r - 1][k++] = m[r][c];
      Q cofactor = det3(minor[0], minor[1], minor[2]);
      expansion += (j % 2 ? Q(-1) : Q(1)) * m[0][j] * cofactor;
    }
    CHECK(det4(m[0], m[1], m[2], m[3]) == expansion);
    if (t % 4 == 0) CHECK(expansion == 0);
  }
}

} // namespace geometry_e3_tests
