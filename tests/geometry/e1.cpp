#include "support.hpp"

#include <catch2/catch.hpp>
#include <geometry/e1.hpp>

using namespace geometry;
using test::as;
using test::Q;

namespace geometry_e1_tests {

TEMPLATE_TEST_CASE("E1 predicates agree with the exact value", "[e1]", double, rational) {
  using FT = TestType;
  for (int t = 0; t < 500; ++t) {
    Q a = test::random_decimal(), x = test::random_decimal();
    bool up = t % 2 == 0;
    auto s = e1::side(e1::hyperplane_at(as<FT>(a), up), e1::point<FT>(as<FT>(x)));
    Q ax = test::exact(as<FT>(a)), xx = test::exact(as<FT>(x));
    CHECK(static_cast<int>(s) == (up ? (xx - ax).sign() : (ax - xx).sign()));
  }
}

TEMPLATE_TEST_CASE("E1 intervals split by length, exactly", "[e1]", double, rational) {
  using FT = TestType;
  auto iv = e1::interval<FT>(FT(-2), FT(5));
  REQUIRE(e1::length(iv));
  CHECK(*e1::length(iv) == FT(7));
  for (int t = 0; t < 300; ++t) {
    FT a = as<FT>(test::random_decimal(3, 4));
    auto r = e1::split(iv, e1::hyperplane_at(a, t % 2 == 0));
    FT sum(0);
    if (r.negative) sum = sum + *e1::length(*r.negative);
    if (r.positive) sum = sum + *e1::length(*r.positive);
    CHECK(sum == FT(7));
    CHECK((r.negative && r.positive) == (FT(-2) < a && a < FT(5)));
  }
  SECTION("a cut at an end leaves the interval whole") {
    auto r = e1::split(iv, e1::hyperplane_at(FT(5)));
    CHECK(r.negative);
    CHECK_FALSE(r.positive);
  }
  SECTION("the whole line and rays are unbounded") {
    auto r = e1::split(e1::whole_line<FT>(), e1::hyperplane_at(FT(3)));
    REQUIRE(r.positive);
    REQUIRE(r.negative);
    CHECK_FALSE(e1::length(*r.positive));
    auto [lo, hi] = e1::ends(*r.positive);
    CHECK(lo == FT(3));
    CHECK_FALSE(hi);
    auto bounded = e1::split(*r.positive, e1::hyperplane_at(FT(10), false));
    REQUIRE(bounded.positive);
    CHECK(*e1::length(*bounded.positive) == FT(7));
  }
}

TEMPLATE_TEST_CASE("E1 points split and report coincidence", "[e1]", double, rational) {
  using FT = TestType;
  e1::sub_hyperplane<FT> s{e1::hyperplane_at(FT(2))};
  CHECK(e1::split(s, e1::hyperplane_at(FT(2))).coincident == sign::positive);
  CHECK(e1::split(s, e1::hyperplane_at(FT(2), false)).coincident == sign::negative);
  CHECK(e1::split(s, e1::hyperplane_at(FT(1))).positive);
  CHECK(e1::split(s, e1::hyperplane_at(FT(3))).negative);
  CHECK(e1::split(s, e1::hyperplane_at(FT(3), false)).positive);
  // The orientation of the point's own hyperplane does not move the point.
  e1::sub_hyperplane<FT> t{e1::hyperplane_at(FT(2), false)};
  CHECK(e1::split(t, e1::hyperplane_at(FT(1))).positive);
}

} // namespace geometry_e1_tests
