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

} // namespace geometry_whole_side_tests
