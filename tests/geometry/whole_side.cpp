// `whole_side`, the cheap test that lets sub-hyperplanes pass down a tree
// unsplit, against `split` on random and degenerate input: whenever it names
// a side, `split` puts the whole piece on that side.
#include "../support.hpp"

#include <geometry/e2.hpp>
#include <geometry/e3.hpp>
#include <geometry/s2.hpp>

#include <catch2/catch.hpp>

using namespace geometry;
using test::Q;

namespace geometry_whole_side_tests {

namespace {

template <class K> void agree(typename K::sub_hyperplane const& s, typename K::hyperplane const& h, int& decided, int& straddling) {
  auto w = K::whole_side(s, h);
  auto r = K::split(s, h);
  if (w == oriented_side::on) {
    ++straddling;
    return;
  }
  ++decided;
  CHECK(!r.is_coincident());
  CHECK(r.negative.has_value() == (w == oriented_side::negative));
  CHECK(r.positive.has_value() == (w == oriented_side::positive));
}

} // namespace

TEST_CASE("whole_side agrees with split in E2, S2 and E3, degenerate cases included", "[geometry][whole_side]") {
  int decided = 0, straddling = 0;
  // Small integer coordinates: many lines through segment ends, parallel and coincident lines.
  auto small = [] { return Q(test::uniform(-3, 3)); };
  for (int t = 0; t < 2000; ++t) {
    e2::point<Q> p(small(), small()), q(small(), small()), a(small(), small()), b(small(), small());
    if (p == q || a == b) continue;
    agree<e2::exact_kernel>(e2::segment(p, q), e2::line_through(a, b), decided, straddling);
    agree<e2::exact_kernel>(e2::segment(p, q), e2::line_through(p, b), decided, straddling); // through an end
  }
  for (int t = 0; t < 2000; ++t) {
    s2::point<Q> p(std::array<Q, 3>{small(), small(), small()}), q(std::array<Q, 3>{small(), small(), small()}),
        a(std::array<Q, 3>{small(), small(), small()});
    if (p.is_zero() || q.is_zero() || a.is_zero() || parallel(p, q) != sign::zero || parallel(p, a) != sign::zero)
      continue;
    agree<s2::exact_kernel>(s2::arc(p, q), s2::circle_through(p, a), decided, straddling);
    if (parallel(q, a) == sign::zero) agree<s2::exact_kernel>(s2::arc(p, q), s2::circle_through(q, a), decided, straddling);
    // Bounded by the circles through its ends and a (the neighbours of a
    // loop), and tested against those same circles (shared numbers), their
    // opposites, the arc's own circle, and copies made apart.
    if (parallel(q, a) != sign::zero || s2::orientation(p, q, a) == sign::zero) continue;
    auto c = s2::circle_through(p, q), at_p = s2::circle_through(a, p), at_q = s2::circle_through(q, a);
    if (dot_sign(at_p.n, q) == sign::negative) at_p = at_p.opposite();
    if (dot_sign(at_q.n, p) == sign::negative) at_q = at_q.opposite();
    auto arc = s2::arc_bounded_by(c, p, q, at_p, at_q);
    for (auto const& h : {at_p, at_q, at_p.opposite(), at_q.opposite(), s2::circle_through(a, p), s2::circle_through(q, a)})
      agree<s2::exact_kernel>(arc, h, decided, straddling);
    CHECK(s2::exact_kernel::whole_side(arc, c) == oriented_side::on);
    CHECK(s2::exact_kernel::split(arc, c).is_coincident());
    for (auto const& h : {s2::circle_through(p, q), s2::circle_through(q, p)}) CHECK(s2::exact_kernel::split(arc, h).is_coincident());
    // The same ends as `arc(p, q)`.
    CHECK(s2::endpoint(arc, false) == s2::endpoint(s2::arc(p, q), false));
    CHECK(s2::endpoint(arc, true) == s2::endpoint(s2::arc(p, q), true));
  }
  for (int t = 0; t < 1000; ++t) {
    std::vector<e3::point<Q>> tri{{small(), small(), small()}, {small(), small(), small()}, {small(), small(), small()}};
    e3::point<Q> a(small(), small(), small()), b(small(), small(), small());
    if (e3::plane_through(tri[0], tri[1], tri[2]).n.is_zero()) continue;
    auto poly = e3::convex_polygon(tri);
    for (auto const& h : {e3::plane_through(a, b, tri[0]), e3::plane_through(tri[0], tri[1], a), e3::plane_through(tri[0], tri[1], tri[2])})
      if (!h.n.is_zero()) agree<e3::exact_kernel>(poly, h, decided, straddling);
  }
  CHECK(decided > 3000);
  CHECK(straddling > 1000);
}

TEST_CASE("whole_side in E3 names the side the vertices' exact signs name", "[geometry][whole_side]") {
  // The E3 test evaluates its filter for all vertices at once; against the
  // side of each input vertex, h(x) in rationals, on polygons of small
  // integers, of large fractions (where the filter fails more often), and
  // seen against planes through their vertices and near them.
  auto side_of_vertices = [](std::vector<e3::point<Q>> const& v, e3::hyperplane<Q> const& h) {
    auto const& c = h.n.exact();
    bool pos = false, neg = false;
    for (auto const& x : v) {
      Q value = c[0] * x.x() + c[1] * x.y() + c[2] * x.z() + c[3];
      pos = pos || value > 0;
      neg = neg || value < 0;
    }
    return pos && !neg ? oriented_side::positive : neg && !pos ? oriented_side::negative : oriented_side::on;
  };
  int compared = 0, decided = 0;
  for (int t = 0; t < 3000; ++t) {
    bool big = t % 2 == 1;
    auto coord = [&] {
      if (!big) return Q(test::uniform(-3, 3));
      return Q(test::uniform(-1000000000000L, 1000000000000L), test::uniform(1, 1000000007L));
    };
    auto pt = [&] { return e3::point<Q>(coord(), coord(), coord()); };
    std::vector<e3::point<Q>> v{pt(), pt(), pt()};
    if (e3::plane_through(v[0], v[1], v[2]).n.is_zero()) continue;
    auto poly = e3::convex_polygon(v);
    e3::point<Q> a = pt(), b = pt();
    // A point near the polygon's plane: its first vertex moved a little.
    e3::point<Q> near(v[0].x() + Q(1, 1000003), v[0].y(), v[0].z());
    for (auto const& h : {e3::plane_through(a, b, v[0]), e3::plane_through(v[0], v[1], a), e3::plane_through(v[0], v[1], near),
                          e3::plane_through(a, b, near), poly.support.opposite()}) {
      if (h.n.is_zero()) continue;
      auto w = e3::exact_kernel::whole_side(poly, h);
      CHECK(w == side_of_vertices(v, h));
      ++compared;
      decided += w != oriented_side::on;
    }
  }
  CHECK(compared > 10000);
  CHECK(decided > 3000);
}

} // namespace geometry_whole_side_tests
