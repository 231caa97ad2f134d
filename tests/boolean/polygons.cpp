// Boolean operations on polygons in the plane: exact areas on hand-computed
// degenerate cases, inclusion–exclusion on random star polygons, fill rules,
// and every output checked by an independent validity checker and by point
// membership against the result's tree.
#include "../support.hpp"
#include "validity.hpp"

#include <catch2/catch.hpp>

#include <boolean/polygons.hpp>

#include <cmath>

using namespace geometry;
using boolean::multipolygon;
using boolean::ring;
using boolean::set_op;
using test::Q;
using P = boolean::point2;

namespace boolean_polygons_tests {

namespace {

ring rect(Q x0, Q y0, Q x1, Q y1) { return {P(x0, y0), P(x1, y0), P(x1, y1), P(x0, y1)}; }

/// A random star-shaped ring around (cx, cy), counter-clockwise.
ring random_star(int k, long radius, bool decimals) {
  for (;;) {
    std::vector<double> angles;
    for (int i = 0; i < k; ++i) angles.push_back(static_cast<double>(test::uniform(0, 62831)) / 10000);
    std::sort(angles.begin(), angles.end());
    ring r;
    long cx = test::uniform(-10, 10), cy = test::uniform(-10, 10);
    for (double t : angles) {
      double rad = static_cast<double>(test::uniform(radius / 4, radius));
      double x = static_cast<double>(cx) + rad * std::cos(t), y = static_cast<double>(cy) + rad * std::sin(t);
      r.push_back(decimals ? P(Q(std::lround(x * 10), 10), Q(std::lround(y * 10), 10)) : P(Q(std::lround(x)), Q(std::lround(y))));
    }
    P c{Q(cx), Q(cy)};
    bool ok = true;
    for (std::size_t i = 0; i < r.size() && ok; ++i) ok = e2::orientation(c, r[i], r[(i + 1) % r.size()]) == sign::positive;
    if (ok) return r;
  }
}

/// Checks the output of `r`: valid rings, the tree's exact area, and the
/// same membership as the tree at sample points (vertices, midpoints, random).
void check_output(boolean::region2 const& r) {
  auto m = boolean::polygons(r);
  // The rings on integer vertices are those of the rational path, vertex for vertex.
  CHECK(m == boolean::assemble(boolean::detail::left_edges(bsp::oriented_boundary(r))));
  INFO("polygons: " << m.size());
  CHECK(test::validity_problem(m) == "");
  CHECK(boolean::area(m) == *boolean::area(r));
  std::vector<P> pts;
  for (auto const& p : m) {
    for (auto const* rr : {&p.outer}) pts.insert(pts.end(), rr->begin(), rr->end());
    for (auto const& h : p.holes) pts.insert(pts.end(), h.begin(), h.end());
  }
  std::size_t nv = pts.size();
  for (std::size_t i = 0; i + 1 < nv; ++i) pts.emplace_back((pts[i].x() + pts[i + 1].x()) / 2, (pts[i].y() + pts[i + 1].y()) / 2);
  for (int i = 0; i < 60; ++i) pts.emplace_back(test::random_decimal(2, 40), test::random_decimal(2, 40));
  int mismatches = 0;
  for (auto const& p : pts) {
    int inside = test::member(m, p);
    auto c = bsp::classify(r, p);
    if (inside != 0 && (!c || *c != (inside > 0))) ++mismatches;
  }
  CHECK(mismatches == 0);
}

/// The fast path (`combine`: boundaries classified, no merged tree) gives
/// valid polygons with the exact area of the merged tree, for every operation.
void check_combine(boolean::operand const& a, boolean::operand const& b) {
  for (auto op : {set_op::union_, set_op::intersection, set_op::difference, set_op::symmetric_difference}) {
    auto m = boolean::combine(op, a, b);
    CHECK(test::validity_problem(m) == "");
    auto pieces = bsp::merged_boundary(a.tree, a.boundary, b.tree, b.boundary,
                                       [op](bool x, bool y) { return boolean::detail::label_op(op, x, y); });
    CHECK(m == boolean::assemble(boolean::detail::left_edges(pieces)));
    CHECK(boolean::area(m) == *boolean::area(boolean::apply(op, a.tree, b.tree)));
  }
}

boolean::region2 simple(std::vector<ring> rings) {
  multipolygon m;
  for (auto& r : rings) m.push_back({std::move(r), {}});
  return boolean::region(m);
}

} // namespace

TEST_CASE("E2 Boolean operations: exact areas and valid output on degenerate cases", "[boolean][e2]") {
  struct hand {
    char const* name;
    multipolygon a, b;
    Q uni, inter, diff;
    std::size_t union_rings;
  };
  ring hole{P(0, 2), P(2, 3), P(2, 1)}; // its left vertex on the outer ring
  // A 3x3 grid of unit squares two units apart, and its copy shifted by half a unit.
  multipolygon grid, shifted;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      grid.push_back({rect(2 * i, 2 * j, 2 * i + 1, 2 * j + 1), {}});
      shifted.push_back({rect(Q(4 * i + 1, 2), Q(4 * j + 1, 2), Q(4 * i + 3, 2), Q(4 * j + 3, 2)), {}});
    }
  std::vector<hand> cases{
      {"grid and its half-shifted copy", grid, shifted, 9 * Q(7, 4), 9 * Q(1, 4), 9 * Q(3, 4), 9},
      {"squares sharing an edge", {{rect(0, 0, 2, 2), {}}}, {{rect(2, 0, 4, 2), {}}}, 8, 0, 4, 1},
      {"L-shapes overlapping along edges", {{{P(0, 0), P(2, 0), P(2, 1), P(1, 1), P(1, 2), P(0, 2)}, {}}},
       {{{P(1, 0), P(3, 0), P(3, 2), P(2, 2), P(2, 1), P(1, 1)}, {}}}, 5, 1, 2, 1},
      {"L-shapes filling a square", {{{P(0, 0), P(2, 0), P(2, 1), P(1, 1), P(1, 2), P(0, 2)}, {}}},
       {{{P(2, 1), P(2, 2), P(1, 2), P(1, 1)}, {}}}, 4, 0, 3, 1},
      {"squares touching at a corner", {{rect(0, 0, 1, 1), {}}}, {{rect(1, 1, 2, 2), {}}}, 2, 0, 1, 2},
      {"collinear overlapping edges", {{rect(0, 0, 2, 1), {}}}, {{rect(1, 0, 3, 1), {}}}, 3, 1, 1, 1},
      {"identical operands", {{rect(0, 0, 3, 2), {}}}, {{rect(0, 0, 3, 2), {}}}, 6, 6, 0, 1},
      {"a hole touching its outer ring", {{rect(0, 0, 4, 4), {hole}}}, {{rect(1, 1, 3, 3), {}}}, Q(31, 2), 4 - Q(3, 2),
       14 - 4 + Q(3, 2), 2},
      {"a square inside a hole", {{rect(0, 0, 6, 6), {rect(1, 1, 5, 5)}}}, {{rect(2, 2, 4, 4), {}}}, 24, 0, 20, 3},
      {"a hole given counter-clockwise", {{rect(0, 0, 6, 6), {rect(1, 1, 5, 5)}}}, {{rect(0, 0, 6, 6), {}}}, 36, 20, 0, 1},
  };
  for (auto const& c : cases) {
    INFO(c.name);
    auto OA = boolean::operand_of(c.a), OB = boolean::operand_of(c.b);
    auto const &A = OA.tree, &B = OB.tree;
    check_combine(OA, OB);
    auto U = boolean::apply(set_op::union_, A, B);
    auto I = boolean::apply(set_op::intersection, A, B);
    auto D = boolean::apply(set_op::difference, A, B);
    auto X = boolean::apply(set_op::symmetric_difference, A, B);
    CHECK(*boolean::area(U) == c.uni);
    CHECK(*boolean::area(I) == c.inter);
    CHECK(*boolean::area(D) == c.diff);
    CHECK(*boolean::area(X) == c.uni - c.inter);
    std::size_t rings = 0;
    for (auto const& p : boolean::polygons(U)) rings += 1 + p.holes.size();
    CHECK(rings == c.union_rings);
    for (auto const* r : {&U, &I, &D, &X}) check_output(*r);
  }
}

TEST_CASE("E2 Boolean operations: the hole touching its outer ring stays one ring pair", "[boolean][e2]") {
  ring hole{P(0, 2), P(2, 3), P(2, 1)};
  auto m = boolean::polygons(boolean::region(multipolygon{{rect(0, 0, 4, 4), {hole}}}));
  REQUIRE(m.size() == 1);
  CHECK(m[0].outer.size() == 4);
  REQUIRE(m[0].holes.size() == 1);
  CHECK(m[0].holes[0].size() == 3);
  CHECK(test::validity_problem(m) == "");
}

TEST_CASE("E2 Boolean operations: invalid polygons are refused, paths take fill rules", "[boolean][e2]") {
  // A bow tie: as a polygon it is invalid; as a path it has two lobes of area 1 winding +1 and -1.
  ring bow{P(0, 0), P(2, 2), P(2, 0), P(0, 2)};
  CHECK_THROWS_AS(boolean::region(multipolygon{{bow, {}}}), boolean::invalid_polygon);
  CHECK_THROWS_AS(simple({rect(0, 0, 2, 2), rect(1, 1, 3, 3)}), boolean::invalid_polygon); // overlapping
  using boolean::fill_rule;
  CHECK(*boolean::area(boolean::region({bow}, fill_rule::evenodd)) == 2);
  CHECK(*boolean::area(boolean::region({bow}, fill_rule::nonzero)) == 2);
  CHECK(*boolean::area(boolean::region({bow}, fill_rule::positive)) == 1);
  CHECK(*boolean::area(boolean::region({bow}, fill_rule::negative)) == 1);
  // Two overlapping squares, both counter-clockwise: winding 2 in the overlap.
  std::vector<ring> two{rect(0, 0, 2, 2), rect(1, 1, 3, 3)};
  CHECK(*boolean::area(boolean::region(two, fill_rule::evenodd)) == 6);
  CHECK(*boolean::area(boolean::region(two, fill_rule::nonzero)) == 7);
  CHECK(*boolean::area(boolean::region(two, fill_rule::negative)) == 0);
  // A pentagram: even-odd leaves the centre out; non-zero fills it.
  ring star{P(0, 10), P(6, -8), P(-10, 3), P(10, 3), P(-6, -8)};
  auto eo = boolean::region({star}, fill_rule::evenodd), nz = boolean::region({star}, fill_rule::nonzero);
  CHECK(*boolean::area(nz) > *boolean::area(eo));
  auto centre = boolean::apply(set_op::difference, nz, eo);
  auto cm = boolean::polygons(centre);
  REQUIRE(cm.size() == 1);
  CHECK(cm[0].outer.size() == 5);
  for (auto const* r : {&eo, &nz, &centre}) check_output(*r);
  // Paths with overlapping edges: the fast path reads their boundary off the tree.
  check_combine(boolean::operand_of({star}, fill_rule::evenodd), boolean::operand_of(two, fill_rule::nonzero));
  check_combine(boolean::operand_of({bow, rect(1, 0, 3, 2)}, fill_rule::positive), boolean::operand_of({star}, fill_rule::nonzero));
}

TEST_CASE("E2 Boolean operations: inclusion-exclusion on random star polygons", "[boolean][e2]") {
  for (int t = 0; t < 24; ++t) {
    bool decimals = t % 2 == 1;
    ring ra = random_star(static_cast<int>(test::uniform(3, 30)), 30, decimals);
    ring rb = random_star(static_cast<int>(test::uniform(3, 30)), 30, decimals);
    multipolygon a{{ra, {}}}, b{{rb, {}}};
    if (t % 3 == 0) a = {{rect(-40, -40, 40, 40), {ra}}}; // the star as a hole
    auto OA = boolean::operand_of(a), OB = boolean::operand_of(b);
    auto const &A = OA.tree, &B = OB.tree;
    check_combine(OA, OB);
    auto U = boolean::apply(set_op::union_, A, B), I = boolean::apply(set_op::intersection, A, B);
    auto D = boolean::apply(set_op::difference, A, B), X = boolean::apply(set_op::symmetric_difference, A, B);
    Q area_a = *boolean::area(A), area_b = *boolean::area(B);
    CHECK(area_a == (t % 3 == 0 ? 6400 - boolean::signed_area(ra) : boolean::signed_area(ra)));
    CHECK(*boolean::area(U) + *boolean::area(I) == area_a + area_b);
    CHECK(*boolean::area(D) == area_a - *boolean::area(I));
    CHECK(*boolean::area(X) == *boolean::area(U) - *boolean::area(I));
    for (auto const* r : {&U, &I, &D, &X}) check_output(*r);
  }
}

TEST_CASE("Ring areas: integer vertices summed apart, fractions and large integers in rationals", "[boolean][e2]") {
  // The shoelace sum, term by term in rationals, against twice_signed_area,
  // which sums the terms between small integer vertices in 128 bits.
  auto shoelace = [](ring const& r) {
    Q s(0);
    for (std::size_t i = 0; i < r.size(); ++i) {
      auto const &a = r[i], &b = r[(i + 1) % r.size()];
      s += a.x() * b.y() - a.y() * b.x();
    }
    return s;
  };
  Q const big = Q(geometry::integer(1) << 40), huge = Q(geometry::integer(1) << 70);
  for (int t = 0; t < 200; ++t) {
    ring r;
    auto n = test::uniform(3, 40);
    for (long i = 0; i < n; ++i) {
      auto kind = test::uniform(0, 5);
      auto coordinate = [&] {
        switch (kind) {
        case 0: return test::random_decimal();                       // a fraction
        case 1: return big - 1 - test::uniform(0, 5);                // just below 2^40
        case 2: return big + test::random_integer();                 // at or past 2^40
        case 3: return huge * test::random_integer();                // far past it
        default: return test::random_integer(1000000);               // small integers
        }
      };
      r.push_back(P(coordinate(), kind == 1 ? -coordinate() : coordinate()));
    }
    CHECK(boolean::twice_signed_area(r) == shoelace(r));
  }
  // Integer vertices only, near the limit, a long ring: every term in 128 bits.
  ring square{P(-big + 1, -big + 1), P(big - 1, -big + 1), P(big - 1, big - 1), P(-big + 1, big - 1)};
  CHECK(boolean::twice_signed_area(square) == 2 * (2 * big - 2) * (2 * big - 2));
  CHECK(boolean::twice_signed_area(square) == shoelace(square));
}

TEST_CASE("Ring orientation: the turn at the least vertex against the signed area", "[boolean][e2]") {
  // Simple rings: random stars (integer and decimal vertices, collinear
  // neighbours possible) in both directions, and rings whose least vertex
  // has a vertical or straight neighbourhood.
  for (int t = 0; t < 300; ++t) {
    ring r = random_star(static_cast<int>(test::uniform(3, 25)), 40, t % 2 == 0);
    if (t % 3 == 0) std::reverse(r.begin(), r.end());
    std::rotate(r.begin(), r.begin() + test::uniform(0, static_cast<long>(r.size()) - 1), r.end());
    auto a = boolean::twice_signed_area(r);
    auto expected = a > 0 ? sign::positive : a < 0 ? sign::negative : sign::zero;
    CHECK(boolean::detail::orientation(r) == expected);
  }
  // Least vertex with a vertical edge above it, and a vertex straight on
  // right after it: the turn is still strict there.
  ring box{P(Q(0), Q(0)), P(Q(2), Q(0)), P(Q(4), Q(0)), P(Q(4), Q(3)), P(Q(0), Q(3))};
  CHECK(boolean::detail::orientation(box) == sign::positive);
  std::reverse(box.begin(), box.end());
  CHECK(boolean::detail::orientation(box) == sign::negative);
  // Flat and too short rings have no orientation.
  CHECK(boolean::detail::orientation(ring{P(Q(0), Q(0)), P(Q(1), Q(1)), P(Q(2), Q(2))}) == sign::zero);
  CHECK(boolean::detail::orientation(ring{P(Q(0), Q(0)), P(Q(1), Q(1))}) == sign::zero);
}

} // namespace boolean_polygons_tests
