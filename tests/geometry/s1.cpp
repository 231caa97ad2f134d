#include "support.hpp"

#include <catch2/catch.hpp>
#include <geometry/s1.hpp>

#include <numbers>

using namespace geometry;
using test::as;
using test::Q;

namespace geometry_s1_tests {

namespace {
constexpr double pi = std::numbers::pi;
template <class FT> s1::point<FT> dir(Q const& x, Q const& y) { return s1::point<FT>(std::array<FT, 2>{as<FT>(x), as<FT>(y)}); }
template <class FT> s1::point<FT> random_dir() {
  for (;;) {
    auto p = dir<FT>(test::random_decimal(3, 1), test::random_decimal(3, 1));
    if (!p.is_zero()) return p;
  }
}
} // namespace

TEMPLATE_TEST_CASE("S1 predicates agree with the exact value", "[s1]", double, rational) {
  using FT = TestType;
  for (int t = 0; t < 500; ++t) {
    auto n = random_dir<FT>(), p = random_dir<FT>();
    Q truth = test::exact(n[0]) * test::exact(p[0]) + test::exact(n[1]) * test::exact(p[1]);
    CHECK(static_cast<int>(s1::side(s1::hyperplane<FT>(n), p)) == truth.sign());
  }
}

TEMPLATE_TEST_CASE("S1 arcs split by length", "[s1]", double, rational) {
  using FT = TestType;
  auto E = dir<FT>(1, 0), N = dir<FT>(0, 1), W = dir<FT>(-1, 0);
  auto halves = s1::split(s1::whole_circle<FT>(), s1::hyperplane_at(E));
  REQUIRE(halves.positive);
  REQUIRE(halves.negative);
  CHECK(s1::length(*halves.positive) == Approx(pi));
  // The upper half circle starts at E (hyperplane_at(E) enters its positive side there).
  CHECK(s1::classify(*halves.positive, N) == oriented_side::positive);
  CHECK(s1::classify(*halves.positive, W) == oriented_side::on);
  auto q = s1::split(*halves.positive, s1::hyperplane_at(dir<FT>(1, 1)));
  REQUIRE(q.positive);
  REQUIRE(q.negative);
  CHECK(s1::length(*q.positive) == Approx(3 * pi / 4));
  CHECK(s1::length(*q.negative) == Approx(pi / 4));
  auto ends = s1::endpoints(*q.negative);
  CHECK(parallel(ends[0], E) == sign::positive);
  CHECK(parallel(ends[1], dir<FT>(1, 1)) == sign::positive);
  // A half circle whose ends both lie on the cut: it is wholly on one side.
  auto same = s1::split(*halves.positive, s1::hyperplane_at(W));
  CHECK(same.negative);
  CHECK_FALSE(same.positive);
  for (int t = 0; t < 300; ++t) {
    auto a = random_dir<FT>(), b = random_dir<FT>();
    if (det_sign(a, b) != sign::positive) continue; // arcs of less than a half circle
    auto arc = s1::arc(a, b);
    auto r = s1::split(arc, s1::hyperplane<FT>(random_dir<FT>()));
    double sum = (r.negative ? s1::length(*r.negative) : 0.0) + (r.positive ? s1::length(*r.positive) : 0.0);
    CHECK(sum == Approx(s1::length(arc)).epsilon(1e-12));
  }
}

TEMPLATE_TEST_CASE("S1 point pairs split and report coincidence", "[s1]", double, rational) {
  using FT = TestType;
  s1::sub_hyperplane<FT> s{s1::hyperplane_at(dir<FT>(1, 0))}; // the points E and W
  auto r = s1::split(s, s1::hyperplane_at(dir<FT>(0, 1)));    // positive: the left half circle
  REQUIRE(r.positive);
  REQUIRE(r.negative);
  CHECK(r.positive->has_end); // W
  CHECK_FALSE(r.positive->has_start);
  CHECK(r.negative->has_start); // E
  CHECK(s1::split(s, s1::hyperplane_at(dir<FT>(2, 0))).coincident == sign::positive);
  CHECK(s1::split(s, s1::hyperplane_at(dir<FT>(-1, 0))).coincident == sign::negative);
  // After the split only one point is left: it lies on one side.
  auto one = s1::split(*r.negative, s1::hyperplane_at(dir<FT>(0, 1)));
  CHECK(one.negative);
  CHECK_FALSE(one.positive);
}

} // namespace geometry_s1_tests
