// Boolean operations on spherical polygons: areas against closed forms
// (octants, lunes, hemispheres, the complement of a small square), polygons
// across the antimeridian, around a pole and larger than a hemisphere, and
// the output loops read back into exactly the same region.
#include "../support.hpp"

#include <boolean/spherical.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

using boolean::direction;
using boolean::loop;
using boolean::set_op;
using test::Q;

namespace boolean_spherical_tests {

namespace {

constexpr double pi = std::numbers::pi;

direction d(long x, long y, long z) { return direction(std::array<Q, 3>{Q(x), Q(y), Q(z)}); }
direction ll(double lon, double lat) { return boolean::from_lonlat(Q(lon), Q(lat)); }

boolean::region_s2 region(std::vector<loop> loops) { return boolean::spherical_region(loops); }

/// The number of inside cells: zero exactly when the region is empty.
std::size_t inside_cells(boolean::region_s2 const& r) {
  std::size_t n = 0;
  for (auto const& c : bsp::cells(r)) n += r.leaf_data(c.leaf);
  return n;
}

/// Polygons read back as a region.  Every output arc must be a minor arc
/// (consecutive vertices independent), and each polygon disjoint from the
/// ones before it.
boolean::region_s2 read_back(std::vector<boolean::spherical_polygon> const& polys) {
  boolean::region_s2 back(false);
  for (auto const& p : polys) {
    std::vector<loop> loops{p.outer};
    loops.insert(loops.end(), p.holes.begin(), p.holes.end());
    for (auto const& l : loops)
      for (std::size_t i = 0; i < l.size(); ++i) CHECK(geometry::parallel(l[i], l[(i + 1) % l.size()]) == geometry::sign::zero);
    auto one = region(loops);
    CHECK(inside_cells(boolean::apply(set_op::intersection, back, one)) == 0);
    back = bsp::set_union(back, one);
  }
  return back;
}

/// The output polygons of `r`, read back as a region, must be `r` exactly.
void check_round_trip(boolean::region_s2 const& r) {
  CHECK(inside_cells(boolean::apply(set_op::symmetric_difference, read_back(boolean::spherical_polygons(r)), r)) == 0);
}

/// Independent area of a spherical polygon around a point `c` inside it: the
/// sum of the triangles (c, v_i, v_i+1) by Van Oosterom and Strackee's formula.
double fan_area(std::vector<std::array<double, 3>> const& v, std::array<double, 3> const& c) {
  auto dot = [](auto const& a, auto const& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto cross = [](auto const& a, auto const& b) {
    return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  double s = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    auto const &a = v[i], &b = v[(i + 1) % v.size()];
    s += 2 * std::atan2(dot(c, cross(a, b)), 1 + dot(c, a) + dot(a, b) + dot(b, c));
  }
  return s;
}

std::array<double, 3> unit(double lon, double lat) {
  lon *= pi / 180, lat *= pi / 180;
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}


/// `combine` on operands built from `a` and `b` must give the polygons that
/// the merged tree gives: the same region exactly (read back), as many
/// polygons with as many holes each, the same area.
void check_combine(std::vector<loop> const& a, std::vector<loop> const& b) {
  auto A = boolean::spherical_operand_of(a), B = boolean::spherical_operand_of(b);
  for (auto op : {set_op::union_, set_op::intersection, set_op::difference, set_op::symmetric_difference}) {
    auto r = boolean::apply(op, A.tree, B.tree);
    bool whole = inside_cells(boolean::apply(set_op::difference, boolean::region_s2(true), r)) == 0;
    if (whole) {
      CHECK_THROWS_AS(boolean::combine(op, A, B), std::invalid_argument);
      continue;
    }
    auto fast = boolean::combine(op, A, B);
    auto slow = boolean::spherical_polygons(r);
    REQUIRE(fast.size() == slow.size());
    auto holes = [](std::vector<boolean::spherical_polygon> const& ps) {
      std::vector<std::size_t> h;
      for (auto const& p : ps) h.push_back(p.holes.size());
      std::sort(h.begin(), h.end());
      return h;
    };
    CHECK(holes(fast) == holes(slow));
    auto back = read_back(fast);
    CHECK(inside_cells(boolean::apply(set_op::symmetric_difference, back, r)) == 0);
    CHECK(boolean::area(fast) == Approx(boolean::area(r)).epsilon(1e-11).margin(1e-13));
  }
}
} // namespace

TEST_CASE("S2 Boolean operations: octants, lunes and hemispheres have their closed-form areas", "[boolean][s2]") {
  boolean::region_s2 all(false);
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) {
        loop l{d(sx, 0, 0), d(0, sy, 0), d(0, 0, sz)};
        if (sx * sy * sz < 0) std::reverse(l.begin(), l.end());
        auto o = region({l});
        CHECK(boolean::area(o) == Approx(pi / 2).epsilon(1e-14));
        CHECK(inside_cells(boolean::apply(set_op::intersection, all, o)) == 0); // octants do not overlap
        all = boolean::apply(set_op::union_, all, o);
        if (boolean::area(all) < 4 * pi - 1) check_round_trip(all);
      }
  CHECK(boolean::area(all) == Approx(4 * pi).epsilon(1e-14));
  CHECK_THROWS(boolean::spherical_polygons(all)); // the whole sphere has no boundary
  // Lunes between meridians: area 2 × their angle.
  for (int deg : {10, 45, 90, 135, 170}) {
    auto lune = region({{ll(0, 90), ll(0, 0), ll(0, -90), ll(deg, 0)}});
    CHECK(boolean::area(lune) == Approx(2 * deg * pi / 180).epsilon(1e-13));
    check_round_trip(lune);
  }
  // Hemispheres: the northern one and its complement; a tilted one by its great circle.
  auto north = region({{ll(0, 0), ll(90, 0), ll(180, 0), ll(-90, 0)}});
  auto south = region({{ll(-90, 0), ll(180, 0), ll(90, 0), ll(0, 0)}});
  CHECK(boolean::area(north) == Approx(2 * pi).epsilon(1e-14));
  CHECK(inside_cells(boolean::apply(set_op::symmetric_difference, south, bsp::complement(north))) == 0);
  auto tilted = region({{d(1, 0, 1), d(0, 1, 0), d(-1, 0, -1), d(0, -1, 0)}});
  CHECK(boolean::area(tilted) == Approx(2 * pi).epsilon(1e-14));
  // Normals (0, 0, 1) and (-1, 0, 1) are 45° apart: the lune between the hemispheres spans 135°.
  CHECK(boolean::area(boolean::apply(set_op::intersection, north, tilted)) == Approx(1.5 * pi).epsilon(1e-13));
  for (auto const* r : {&north, &south, &tilted}) check_round_trip(*r);
}

TEST_CASE("S2 Boolean operations: the complement of a small square, the antimeridian, the poles", "[boolean][s2]") {
  // A 2° square: its complement is larger than a hemisphere, given by the reversed ring.
  loop square{ll(-1, -1), ll(1, -1), ll(1, 1), ll(-1, 1)};
  loop reversed(square.rbegin(), square.rend());
  auto small = region({square}), big = region({reversed});
  std::vector<std::array<double, 3>> sv{unit(-1, -1), unit(1, -1), unit(1, 1), unit(-1, 1)};
  double a = fan_area(sv, {1, 0, 0});
  CHECK(boolean::area(small) == Approx(a).epsilon(1e-12));
  CHECK(boolean::area(big) == Approx(4 * pi - a).epsilon(1e-12));
  CHECK(inside_cells(boolean::apply(set_op::intersection, small, big)) == 0);
  CHECK(boolean::area(boolean::apply(set_op::union_, small, big)) == Approx(4 * pi).epsilon(1e-14));
  auto polys = boolean::spherical_polygons(big);
  REQUIRE(polys.size() == 1);
  CHECK(polys[0].outer.size() == 4);
  check_round_trip(big);

  // The same square moved across the antimeridian has the same area, and
  // overlapping squares on either side of it unite across it.
  auto across = region({{ll(179, -1), ll(-179, -1), ll(-179, 1), ll(179, 1)}});
  CHECK(boolean::area(across) == Approx(a).epsilon(1e-12));
  auto west = region({{ll(178, -1), ll(180, -1), ll(180, 1), ll(178, 1)}});
  auto east = region({{ll(-180, -1), ll(-178, -1), ll(-178, 1), ll(-180, 1)}});
  auto both = boolean::apply(set_op::union_, west, east);
  CHECK(boolean::area(both) == Approx(2 * a).epsilon(1e-12));
  CHECK(bsp::classify(both, d(-1, 0, 0)) == std::optional<bool>(true)); // (180°, 0°): the shared edge is gone
  auto bp = boolean::spherical_polygons(both);
  REQUIRE(bp.size() == 1);
  CHECK(bp[0].outer.size() == 6); // the edges at ±1° are two great circles each, meeting at 180°
  check_round_trip(both);

  // A cap around the north pole at latitude 80°, as an octagon, and the same
  // with a hole around the pole.
  loop cap, hole;
  std::vector<std::array<double, 3>> cv;
  for (int k = 0; k < 8; ++k) cap.push_back(ll(45 * k, 80)), cv.push_back(unit(45 * k, 80));
  for (int k = 7; k >= 0; --k) hole.push_back(ll(45 * k, 85));
  auto cr = region({cap});
  CHECK(boolean::area(cr) == Approx(fan_area(cv, {0, 0, 1})).epsilon(1e-12));
  CHECK(bsp::classify(cr, d(0, 0, 1)) == std::optional<bool>(true));
  auto ring = region({cap, hole});
  CHECK(bsp::classify(ring, d(0, 0, 1)) == std::optional<bool>(false));
  CHECK(boolean::area(ring) == Approx(boolean::area(cr) - boolean::area(region({loop(hole.rbegin(), hole.rend())}))).epsilon(1e-12));
  auto rp = boolean::spherical_polygons(ring);
  REQUIRE(rp.size() == 1);
  CHECK(rp[0].holes.size() == 1);
  check_round_trip(ring);
  // Both poles' caps minus a band: two polygons.
  loop south_cap;
  for (int k = 7; k >= 0; --k) south_cap.push_back(ll(45 * k, -80));
  auto caps = boolean::apply(set_op::union_, cr, region({south_cap}));
  CHECK(boolean::spherical_polygons(caps).size() == 2);
  check_round_trip(caps);
}

TEST_CASE("S2 Boolean operations: inclusion-exclusion on random spherical polygons", "[boolean][s2]") {
  for (int t = 0; t < 12; ++t) {
    auto random_loop = [] {
      double lon = static_cast<double>(test::uniform(-180, 180)), lat = static_cast<double>(test::uniform(-60, 60));
      int k = static_cast<int>(test::uniform(3, 12));
      loop l;
      for (int i = 0; i < k; ++i) {
        double r = static_cast<double>(test::uniform(5, 40)), t = 2 * pi * i / k;
        l.push_back(boolean::from_lonlat(Q(std::lround((lon + r * std::cos(t)) * 10), 10), Q(std::lround((lat + r / 2 * std::sin(t)) * 10), 10)));
      }
      return l;
    };
    auto A = region({random_loop()}), B = region({random_loop()});
    auto U = boolean::apply(set_op::union_, A, B), I = boolean::apply(set_op::intersection, A, B);
    CHECK(boolean::area(U) + boolean::area(I) == Approx(boolean::area(A) + boolean::area(B)).epsilon(1e-12));
    auto X = boolean::apply(set_op::symmetric_difference, A, B);
    CHECK(boolean::area(X) == Approx(boolean::area(U) - boolean::area(I)).epsilon(1e-12).margin(1e-12));
    for (auto const* r : {&U, &I, &X})
      if (inside_cells(*r)) check_round_trip(*r);
  }
}


TEST_CASE("S2 Boolean operations: combine without the merged tree gives the merged tree's polygons", "[boolean][s2]") {
  loop square{ll(-1, -1), ll(1, -1), ll(1, 1), ll(-1, 1)};
  loop reversed(square.rbegin(), square.rend());
  loop shifted{ll(0, 0), ll(2, 0), ll(2, 2), ll(0, 2)};
  loop beside{ll(1, -1), ll(3, -1), ll(3, 1), ll(1, 1)};     // shares the edge at 1°
  loop corner{ll(1, 1), ll(3, 1), ll(3, 3), ll(1, 3)};       // touches at (1°, 1°)
  loop inner{ll(-0.5, -0.5), ll(0.5, -0.5), ll(0.5, 0.5), ll(-0.5, 0.5)};
  loop far{ll(100, 20), ll(110, 20), ll(110, 30), ll(100, 30)};
  loop cap, hole, island;
  for (int k = 0; k < 8; ++k) cap.push_back(ll(45 * k, 80)), island.push_back(ll(45 * k + 10, 88));
  for (int k = 7; k >= 0; --k) hole.push_back(ll(45 * k, 85));
  loop octant{d(1, 0, 0), d(0, 1, 0), d(0, 0, 1)};
  loop north{ll(0, 0), ll(90, 0), ll(180, 0), ll(-90, 0)};
  SECTION("areas from the output loops against closed forms") {
    // Gauss–Bonnet on the loops, against the octant (π/2), the lune between
    // the northern hemisphere and the tilted one (3π/2, read off the merged
    // tree: it lies in no open hemisphere) and the square's fan area.
    auto O = boolean::spherical_operand_of({octant}), N = boolean::spherical_operand_of({north});
    CHECK(boolean::area(boolean::combine(set_op::union_, O, O)) == Approx(pi / 2).epsilon(1e-14));
    CHECK(boolean::area(boolean::combine(set_op::intersection, O, N)) == Approx(pi / 2).epsilon(1e-14));
    auto T = boolean::spherical_operand_of({{d(1, 0, 1), d(0, 1, 0), d(-1, 0, -1), d(0, -1, 0)}});
    CHECK(boolean::area(boolean::combine(set_op::intersection, N, T)) == Approx(1.5 * pi).epsilon(1e-13));
    std::vector<std::array<double, 3>> sv{unit(-1, -1), unit(1, -1), unit(1, 1), unit(-1, 1)};
    auto S = boolean::spherical_operand_of({square});
    CHECK(boolean::area(boolean::combine(set_op::union_, S, S)) == Approx(fan_area(sv, {1, 0, 0})).epsilon(1e-12));
    // The square's complement: 4π less it, with its one loop.
    auto R = boolean::spherical_operand_of({reversed});
    CHECK(boolean::area(boolean::combine(set_op::union_, R, R)) == Approx(4 * pi - fan_area(sv, {1, 0, 0})).epsilon(1e-12));
  }
  SECTION("degenerate pairs") {
    check_combine({square}, {square});   // identical
    check_combine({square}, {reversed}); // complements: the union is the whole sphere
    check_combine({square}, {shifted});
    check_combine({square}, {beside});
    check_combine({square}, {corner});
    check_combine({square}, {inner});    // one inside the other
    check_combine({square}, {far});      // disjoint
    check_combine({reversed}, {inner});  // larger than a hemisphere
    check_combine({reversed}, {far});
    check_combine({octant}, {north});    // vertices and arcs on the axes and the equator
    check_combine({north}, {square});    // a half circle through the square
    // Boundaries touching inside an arc: a corner on the other's arc, a
    // hole's corner on its outer loop's arc (the arc is not cut there).
    // Directions (10, y, z): arcs are segments in the (y, z) plane, seen from outside as drawn.
    loop outer{d(10, -2, -2), d(10, 2, -2), d(10, 2, 2), d(10, -2, 2)};
    loop touching_hole{d(10, -2, 0), d(10, 0, 1), d(10, 0, -1)};
    loop on_edge{d(10, -2, 0), d(10, -4, 1), d(10, -4, -1)};
    check_combine({outer, touching_hole}, {inner});
    check_combine({outer, touching_hole}, {shifted});
    check_combine({outer}, {on_edge});
    check_combine({outer, touching_hole}, {on_edge});
  }
  SECTION("an operand's arcs end at its loops' vertices, which combine takes instead of constructing them") {
    auto A = boolean::spherical_operand_of({square, cap, hole});
    REQUIRE(A.boundary.size() == 4 + 8 + 8);
    REQUIRE(A.ends.size() == 2 * A.boundary.size());
    for (std::size_t i = 0; i < A.boundary.size(); ++i) {
      auto const& arc = A.boundary[i];
      for (bool end : {false, true}) {
        auto const& e = A.ends[2 * i + (end ? 1 : 0)];
        auto const& b = end ? arc.bounds.back() : arc.bounds.front();
        CHECK(e.support == arc.support);
        CHECK(e.bound == b.original);
        CHECK(e.vertex == geometry::s2::endpoint(arc, end));
        CHECK(geometry::dot_sign(e.bound.n, e.vertex) == geometry::sign::zero);
        CHECK(geometry::dot_sign(e.support.n, e.vertex) == geometry::sign::zero);
        // The bound is the neighbouring arc's circle (or the perpendicular
        // one), turned so the arc lies on its positive side: its other end.
        CHECK(geometry::dot_sign(e.bound.n, geometry::s2::endpoint(arc, !end)) == geometry::sign::positive);
        // The restricted bound is the restriction of its original.
        CHECK(geometry::parallel(b.line(), geometry::restrict_to(arc.support.n, arc.axis, b.original.n)) ==
              geometry::sign::positive);
      }
    }
    // Arc i of a loop runs from vertex i + 1 to vertex i: it is bounded by
    // the circles of arcs i + 1 and i − 1, the same numbers.
    std::size_t first = 0;
    for (std::size_t k : {4, 8, 8}) {
      for (std::size_t i = 0; i < k; ++i) {
        auto const& arc = A.boundary[first + i];
        CHECK(geometry::shares_numbers(arc.bounds.front().original.n, A.boundary[first + (i + 1) % k].support.n));
        CHECK(geometry::shares_numbers(arc.bounds.back().original.n, A.boundary[first + (i + k - 1) % k].support.n));
      }
      first += k;
    }
    // Along one circle (the equator) the bounds are perpendicular to it.
    for (auto const& arc : boolean::spherical_operand_of({north}).boundary)
      for (auto const& b : arc.bounds) CHECK(geometry::dot_sign(b.original.n, arc.support.n) == geometry::sign::zero);
    // Without the table (a boundary read off a tree), the same polygons.
    auto B = boolean::spherical_operand_of({shifted});
    boolean::spherical_operand A0{{A.tree, A.boundary}, {}}, B0{{B.tree, B.boundary}, {}};
    for (auto op : {set_op::union_, set_op::intersection, set_op::difference}) {
      auto with = boolean::combine(op, A, B), without = boolean::combine(op, A0, B0);
      REQUIRE(with.size() == without.size());
      for (std::size_t i = 0; i < with.size(); ++i) {
        CHECK(with[i].outer == without[i].outer);
        CHECK(with[i].holes == without[i].holes);
      }
    }
  }
  SECTION("holes and islands") {
    check_combine({cap, hole}, {island});   // a polygon with a hole, an island in the hole
    check_combine({cap, hole}, {inner});
    check_combine({cap, hole}, {cap});
  }
  SECTION("random stars") {
    for (int t = 0; t < 8; ++t) {
      auto star = [](double lon, double lat) {
        int k = static_cast<int>(test::uniform(5, 40));
        loop l;
        for (int i = 0; i < k; ++i) {
          double r = static_cast<double>(test::uniform(4, 30)), a = 2 * pi * (i + 0.5) / k;
          l.push_back(boolean::from_lonlat(Q(std::lround((lon + r * std::cos(a)) * 10), 10), Q(std::lround((lat + r * std::sin(a)) * 10), 10)));
        }
        return l;
      };
      check_combine({star(0, 0)}, {star(static_cast<double>(test::uniform(-5, 5)), static_cast<double>(test::uniform(-5, 5)))});
    }
  }
}

TEST_CASE("S2 Boolean operations: nesting by central projection agrees with a tree per loop", "[boolean][s2]") {
  // Two levels of nesting (a cap with a hole, in it an island with a hole
  // of its own, whose box lies in both outer loops' boxes, and another cap
  // beside them), and unions of random stars.
  loop cap, hole, island, lake, other;
  for (int k = 0; k < 8; ++k) {
    cap.push_back(ll(45 * k, 60)), island.push_back(ll(45 * k + 10, 80));
    other.push_back(ll(20 + 3 * std::cos(k * pi / 4), 30 + 3 * std::sin(k * pi / 4)));
  }
  for (int k = 7; k >= 0; --k) hole.push_back(ll(45 * k, 70)), lake.push_back(ll(45 * k + 20, 85));
  std::vector<boolean::region_s2> regions{bsp::set_union(bsp::set_union(region({cap, hole}), region({island, lake})), region({other}))};
  for (int t = 0; t < 6; ++t) {
    auto star = [](double lon) {
      loop l;
      for (int i = 0; i < 24; ++i) {
        double r = static_cast<double>(test::uniform(3, 25)), a = 2 * pi * (i + 0.5) / 24;
        l.push_back(boolean::from_lonlat(Q(std::lround((lon + r * std::cos(a)) * 10), 10), Q(std::lround((10 + r * std::sin(a)) * 10), 10)));
      }
      return l;
    };
    regions.push_back(bsp::set_union(region({star(0)}), region({star(3)})));
  }
  std::size_t with_holes = 0;
  for (auto const& r : regions) {
    auto all = boolean::detail::loops_of(bsp::oriented_boundary(r));
    auto c = boolean::detail::centre_of(all);
    REQUIRE(c);
    REQUIRE(bsp::classify(r, -*c) == std::optional<bool>(false));
    auto copy = all;
    auto projected = boolean::detail::nest_in_hemisphere(copy, *c);
    REQUIRE(projected);
    auto by_trees = boolean::detail::nest_by_trees(all, -*c);
    REQUIRE(projected->size() == by_trees.size());
    for (std::size_t i = 0; i < by_trees.size(); ++i) {
      CHECK((*projected)[i].outer == by_trees[i].outer);
      CHECK((*projected)[i].holes == by_trees[i].holes);
      with_holes += !by_trees[i].holes.empty();
    }
    CHECK(boolean::area(*projected) == Approx(boolean::area(r)).epsilon(1e-11));
  }
  CHECK(with_holes >= 2); // the cap's and the island's polygons
  // Loops around the whole sphere's middle lie in no open hemisphere: none.
  loop band_north, band_south; // the region between them on their left
  for (int k = 7; k >= 0; --k) band_north.push_back(ll(45 * k, 10));
  for (int k = 0; k < 8; ++k) band_south.push_back(ll(45 * k, -10));
  auto band = region({band_north, band_south});
  auto all = boolean::detail::loops_of(bsp::oriented_boundary(band));
  CHECK_FALSE(boolean::detail::nest_in_hemisphere(all, d(0, 0, 1)));
  check_round_trip(band);
}

} // namespace boolean_spherical_tests
