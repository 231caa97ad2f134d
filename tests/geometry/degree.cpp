// Bounded degree (the paper's key point): splitting one region by a thousand
// hyperplanes in sequence never feeds a constructed coordinate into a later
// construction, so the numbers that predicates see do not grow.
#include "support.hpp"

#include <catch2/catch.hpp>
#include <geometry/geometry.hpp>

#include <cmath>
#include <iostream>

using namespace geometry;
using test::Q;

namespace geometry_degree_tests {

namespace {

/// Splits `region` by `n` hyperplanes from `make`, keeping the part holding
/// the centre; returns the largest exact bit length seen after 10, 100 and n splits.
template <class Region, class Make, class Split>
std::array<std::size_t, 3> split_many(Region region, int n, Make make, Split split, std::size_t& cuts) {
  filter_config().enabled = false; // every predicate exact, so every input is seen
  filter_config().track_bits = true;
  filter_stats().max_exact_bits = 0;
  std::array<std::size_t, 3> at{};
  for (int i = 1; i <= n; ++i) {
    auto r = split(region, make());
    cuts += r.negative && r.positive;
    region = r.positive.value_or(region);
    if (i == 10) at[0] = filter_stats().max_exact_bits;
    if (i == 100) at[1] = filter_stats().max_exact_bits;
  }
  at[2] = filter_stats().max_exact_bits;
  filter_config() = {};
  return at;
}

/// A decimal with three digits near `x`.
Q decimal(double x) { return Q(static_cast<long>(std::lround(x * 1000)), 1000); }

/// A random direction angle.
double angle() { return std::uniform_real_distribution<double>(0, 6.283185307179586)(test::rng()); }

void report(char const* what, std::array<std::size_t, 3> const& at, std::size_t cuts) {
  std::cout << what << ": max bits after 10 / 100 / 1000 splits: " << at[0] << " / " << at[1] << " / " << at[2]
            << " (" << cuts << " of the 1000 hyperplanes cut the region)\n";
  CHECK(at[2] <= at[1] + 8); // no growth with the number of splits …
  CHECK(at[2] < 400);        // … and far from the thousands of bits of a chain of constructions
  CHECK(cuts > 100);          // the region really was cut many times
}

} // namespace

TEST_CASE("E2: predicate bit length does not grow over 1000 splits", "[degree][e2]") {
  using P = e2::point<Q>;
  std::size_t cuts = 0;
  auto at = split_many(
      e2::convex_polygon<Q>({P(-1, -1), P(1, -1), P(1, 1), P(-1, 1)}), 1000,
      [] {
        // A line nearly tangent to the circle of radius 1/2, the centre on its positive side:
        // each one cuts a corner off the circumscribed polygon built so far.
        double t = angle();
        P a(decimal(0.5 * std::cos(t)), decimal(0.5 * std::sin(t)));
        P b(a.x() - decimal(std::sin(t)), a.y() + decimal(std::cos(t)));
        auto h = e2::line_through(a, b);
        return e2::side(h, P(0, 0)) == oriented_side::negative ? h.opposite() : h;
      },
      [](auto const& c, auto const& h) { return e2::split(c, h); }, cuts);
  report("E2", at, cuts);
}

TEST_CASE("E3: predicate bit length does not grow over 1000 splits", "[degree][e3]") {
  using P = e3::point<Q>;
  std::size_t cuts = 0;
  auto poly = e3::convex_polygon<Q>({P(-1, -1, Q(1, 3)), P(1, -1, Q(2, 3)), P(1, 1, Q(4, 3)), P(-1, 1, Q(1))});
  auto at = split_many(
      poly, 1000,
      [] {
        // A plane nearly tangent to the vertical cylinder of radius 1/2 around the polygon's centre.
        double t = angle();
        P a(decimal(0.5 * std::cos(t)), decimal(0.5 * std::sin(t)), decimal(std::sin(3 * t)));
        P b(a.x() - decimal(std::sin(t)), a.y() + decimal(std::cos(t)), a.z());
        P c(a.x(), a.y(), a.z() + 1);
        auto h = e3::plane_through(a, b, c);
        return e3::side(h, P(0, 0, Q(5, 6))) == oriented_side::negative ? h.opposite() : h;
      },
      [](auto const& s, auto const& h) { return e3::split(s, h); }, cuts);
  report("E3 polygon", at, cuts);
}

TEST_CASE("E3 polyhedron: predicate bit length does not grow over 1000 splits", "[degree][e3]") {
  using P = e3::point<Q>;
  std::size_t cuts = 0;
  auto at = split_many(
      e3::box<Q>(P(-1, -1, -1), P(1, 1, 1)), 1000,
      [] {
        // A plane nearly tangent to the sphere of radius 1/2.
        double t = angle(), z = std::uniform_real_distribution<double>(-1, 1)(test::rng());
        double r = std::sqrt(1 - z * z);
        std::array<Q, 3> n{decimal(r * std::cos(t)), decimal(r * std::sin(t)), decimal(z)};
        e3::hyperplane<Q> h(hvec<Q, 4>(std::array<Q, 4>{n[0], n[1], n[2], Q(1, 2)}));
        return e3::side(h, P(0, 0, 0)) == oriented_side::negative ? h.opposite() : h;
      },
      [](auto const& c, auto const& h) { return e3::split(c, h); }, cuts);
  report("E3 polyhedron", at, cuts);
}

TEST_CASE("S2: predicate bit length does not grow over 1000 splits", "[degree][s2]") {
  using P = s2::point<Q>;
  auto d = [](Q x, Q y, Q z) { return P(std::array<Q, 3>{x, y, z}); };
  std::size_t cuts = 0;
  auto at = split_many(
      s2::convex_polygon<Q>({d(-1, -1, 1), d(1, -1, 1), d(1, 1, 1), d(-1, 1, 1)}), 1000,
      [] {
        // A great circle 30° from the pole, the pole on its positive side.
        double t = angle();
        s2::hyperplane<Q> h(P(std::array<Q, 3>{decimal(0.866 * std::cos(t)), decimal(0.866 * std::sin(t)), decimal(0.5)}));
        return h;
      },
      [](auto const& c, auto const& h) { return s2::split(c, h); }, cuts);
  report("S2", at, cuts);
}

} // namespace geometry_degree_tests
