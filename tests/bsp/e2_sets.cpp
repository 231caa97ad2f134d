// Point sets in E2: polygons with holes, non-convex rings, and the degenerate
// families (shared edges, touching corners, collinear overlap, identical
// operands, a hole touching its outer ring), against exact areas and an
// independent winding-number test.
#include "../support.hpp"
#include "laws.hpp"

#include <bsp/boolean.hpp>
#include <geometry/e2.hpp>

#include <algorithm>
#include <cmath>

using namespace geometry;
using test::Q;

namespace bsp_e2_sets_tests {

namespace {

using K = e2::exact_kernel;
using P = e2::point<Q>;
using ring = std::vector<P>;         // the set on the left of each edge
using polygon = std::vector<ring>;   // outer rings counter-clockwise, holes clockwise

std::vector<e2::sub_hyperplane<Q>> boundary_of(polygon const& poly) {
  std::vector<e2::sub_hyperplane<Q>> out;
  for (auto const& r : poly)
    for (std::size_t i = 0; i < r.size(); ++i) out.push_back(e2::segment(r[(i + 1) % r.size()], r[i]));
  return out;
}

/// Independent membership: the winding number, with exact rational orientation tests.
int winding_test(polygon const& poly, P const& p) {
  int w = 0;
  for (auto const& r : poly)
    for (std::size_t i = 0; i < r.size(); ++i) {
      auto const &a = r[i], &b = r[(i + 1) % r.size()];
      Q cross = (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
      bool between_x = (a.x() <= p.x() && p.x() <= b.x()) || (b.x() <= p.x() && p.x() <= a.x());
      bool between_y = (a.y() <= p.y() && p.y() <= b.y()) || (b.y() <= p.y() && p.y() <= a.y());
      if (cross == 0 && between_x && between_y) return 0; // on an edge
      if (a.y() <= p.y()) {
        if (b.y() > p.y() && cross > 0) ++w;
      } else if (b.y() <= p.y() && cross < 0) {
        --w;
      }
    }
  return w != 0 ? 1 : -1;
}

Q shoelace(ring const& r) {
  Q s(0);
  for (std::size_t i = 0; i < r.size(); ++i) s += r[i].x() * r[(i + 1) % r.size()].y() - r[i].y() * r[(i + 1) % r.size()].x();
  return s / 2;
}

ring rect(Q x0, Q y0, Q x1, Q y1) { return {P(x0, y0), P(x1, y0), P(x1, y1), P(x0, y1)}; }
ring reversed(ring r) { return ring(r.rbegin(), r.rend()); }

/// A random star-shaped ring (counter-clockwise), simple by construction.
ring random_star(bool decimals, bool general_position = false) {
  for (;;) {
    long cx = test::uniform(-30, 30), cy = test::uniform(-30, 30);
    int k = static_cast<int>(test::uniform(3, 10));
    std::vector<double> angles;
    for (int i = 0; i < k; ++i) angles.push_back(static_cast<double>(test::uniform(0, 6283)) / 1000);
    std::sort(angles.begin(), angles.end());
    ring r;
    for (double t : angles) {
      double rad = static_cast<double>(test::uniform(5, 40));
      double x = static_cast<double>(cx) + rad * std::cos(t), y = static_cast<double>(cy) + rad * std::sin(t);
      r.push_back(decimals ? P(Q(std::lround(x * 10), 10), Q(std::lround(y * 10), 10)) : P(Q(std::lround(x)), Q(std::lround(y))));
    }
    P c{Q(cx), Q(cy)};
    bool ok = true;
    for (std::size_t i = 0; i < r.size() && ok; ++i) ok = e2::orientation(c, r[i], r[(i + 1) % r.size()]) == sign::positive;
    // For inexact arithmetic: no three vertices on a line.
    for (std::size_t i = 0; i < r.size() && ok && general_position; ++i)
      for (std::size_t j = i + 1; j < r.size() && ok; ++j)
        for (std::size_t k = j + 1; k < r.size() && ok; ++k) ok = e2::orientation(r[i], r[j], r[k]) != sign::zero;
    if (ok) return r;
  }
}

std::vector<P> sample_points(int n, polygon const& a, polygon const& b) {
  std::vector<P> pts;
  for (int i = 0; i < n; ++i) pts.emplace_back(test::random_decimal(2, 80), test::random_decimal(2, 80));
  for (auto const* poly : {&a, &b}) // degenerate samples: vertices and edge midpoints, on boundaries
    for (auto const& r : *poly)
      for (std::size_t i = 0; i < r.size(); ++i) {
        pts.push_back(r[i]);
        pts.emplace_back((r[i].x() + r[(i + 1) % r.size()].x()) / 2, (r[i].y() + r[(i + 1) % r.size()].y()) / 2);
      }
  return pts;
}

struct hand_case {
  char const* name;
  polygon a, b;
  Q area_union, area_intersection;
};

} // namespace

TEST_CASE("E2 point sets: exact areas and the laws on hand-computed degenerate cases", "[bsp][e2]") {
  ring hole{P(0, 2), P(2, 3), P(2, 1)}; // clockwise, its left vertex on the outer ring
  std::vector<hand_case> cases{
      {"squares sharing an edge", {rect(0, 0, 2, 2)}, {rect(2, 0, 4, 2)}, 8, 0},
      {"L-shapes filling a square", {{P(0, 0), P(2, 0), P(2, 1), P(1, 1), P(1, 2), P(0, 2)}},
       {{P(2, 1), P(2, 2), P(1, 2), P(1, 1)}}, 4, 0},
      {"L-shapes overlapping along edges", {{P(0, 0), P(2, 0), P(2, 1), P(1, 1), P(1, 2), P(0, 2)}},
       {{P(1, 0), P(3, 0), P(3, 2), P(2, 2), P(2, 1), P(1, 1)}}, 5, 1},
      {"squares touching at a corner", {rect(0, 0, 1, 1)}, {rect(1, 1, 2, 2)}, 2, 0},
      {"collinear overlapping edges", {rect(0, 0, 2, 1)}, {rect(1, 0, 3, 1)}, 3, 1},
      {"identical operands", {rect(0, 0, 3, 2)}, {rect(0, 0, 3, 2)}, 6, 6},
      {"a hole touching its outer ring", {rect(0, 0, 4, 4), hole}, {rect(1, 1, 3, 3)}, 14 + Q(3, 2), 4 - Q(3, 2)},
      {"a square inside a hole", {rect(0, 0, 6, 6), reversed(rect(1, 1, 5, 5))}, {rect(2, 2, 4, 4)}, 24, 0},
      {"decimal coordinates", {rect(Q(1, 10), Q(2, 10), Q(7, 10), Q(9, 10))}, {rect(Q(3, 10), 0, 1, Q(1, 2))}, 0, 0},
  };
  // The decimal case: areas from the shoelace formula of the exact answer.
  cases.back().area_intersection = Q(4, 10) * Q(3, 10);
  cases.back().area_union = Q(6, 10) * Q(7, 10) + Q(7, 10) * Q(1, 2) - cases.back().area_intersection;
  int compared = 0;
  for (auto const& c : cases) {
    INFO(c.name);
    auto A = bsp::build_point_set<K>(boundary_of(c.a)), B = bsp::build_point_set<K>(boundary_of(c.b));
    Q area_a(0), area_b(0);
    for (auto const& r : c.a) area_a += shoelace(r);
    for (auto const& r : c.b) area_b += shoelace(r);
    CHECK(laws::size<K>(A) == area_a);
    CHECK(laws::size<K>(B) == area_b);
    CHECK(laws::size<K>(bsp::set_union(A, B)) == c.area_union);
    CHECK(laws::size<K>(bsp::set_intersection(A, B)) == c.area_intersection);
    auto pts = sample_points(200, c.a, c.b);
    laws::check_all<K>(A, B, [&](P const& p) { return winding_test(c.a, p); }, [&](P const& p) { return winding_test(c.b, p); },
                       pts, compared);
  }
  CHECK(compared > 5000);
}

TEST_CASE("E2 point sets from rings meeting edge to edge: every splitting order gives the exact area", "[bsp][e2]") {
  // Two or three rectangles in one boundary, each sharing part of an edge
  // with the next (their pieces lie on one line, opposite ways round): both
  // sides of such a line are inside, whichever piece is chosen to cut there.
  int compared = 0;
  for (int t = 0; t < 41; ++t) {
    polygon p;
    Q expected(0);
    if (t == 0) { // once lost 10, 12 or 18 of its area 34 (orders 3, 15, 18 …)
      p = {rect(-6, -4, 0, 0), rect(0, -3, 5, -1)};
      expected = 34;
    }
    long x = test::uniform(-5, 0);
    for (int i = 0, n = t == 0 ? 0 : static_cast<int>(test::uniform(2, 3)); i < n; ++i) {
      long w = test::uniform(1, 4), y0 = test::uniform(-4, 2), y1 = y0 + test::uniform(1, 5);
      p.push_back(rect(x, y0, x + w, y1));
      expected += Q(w * (y1 - y0));
      x += w;
    }
    for (std::uint64_t seed = 0; seed < 25; ++seed) {
      auto a = bsp::build_point_set<K>(boundary_of(p), true, false, bsp::random_order(seed));
      CHECK(laws::size<K>(a) == expected);
      for (int k = 0; k < 20; ++k) {
        P q(Q(test::uniform(-60, 130), 10), Q(test::uniform(-50, 80), 10));
        int w = winding_test(p, q);
        if (w == 0) continue;
        CHECK(bsp::classify(a, q) == std::optional<bool>(w > 0));
        ++compared;
      }
    }
  }
  CHECK(compared > 10000);
}

TEST_CASE("E2 point sets: the laws on random star polygons, with and without holes", "[bsp][e2]") {
  int compared = 0;
  for (int t = 0; t < 40; ++t) {
    bool decimals = t % 2 == 1;
    polygon a{random_star(decimals)}, b{random_star(decimals)};
    if (t % 4 == 0) a = {rect(-80, -80, 80, 80), reversed(random_star(decimals))}; // the star as a hole
    auto A = bsp::build_point_set<K>(boundary_of(a), true, false, bsp::random_order(static_cast<std::uint64_t>(t)));
    auto B = bsp::build_point_set<K>(boundary_of(b), true, false, bsp::least_splits(4, static_cast<std::uint64_t>(t)));
    Q area_a(0);
    for (auto const& r : a) area_a += shoelace(r);
    CHECK(laws::size<K>(A) == area_a);
    laws::check_all<K>(A, B, [&](P const& p) { return winding_test(a, p); }, [&](P const& p) { return winding_test(b, p); },
                       sample_points(150, a, b), compared);
  }
  CHECK(compared > 20000);
}

TEST_CASE("E2 merged boundaries: rejoined pieces end only at vertices and crossings, and bound the same set", "[bsp][e2]") {
  // On the closed segment from a to b.
  auto on_segment = [](P const& p, P const& a, P const& b) {
    if (e2::orientation(a, b, p) != sign::zero) return false;
    return (p.x() - a.x()) * (p.x() - b.x()) <= 0 && (p.y() - a.y()) * (p.y() - b.y()) <= 0;
  };
  auto on_boundary = [&](polygon const& poly, P const& p) {
    for (auto const& r : poly)
      for (std::size_t i = 0; i < r.size(); ++i)
        if (on_segment(p, r[i], r[(i + 1) % r.size()])) return true;
    return false;
  };
  auto is_vertex = [](polygon const& poly, P const& p) {
    for (auto const& r : poly)
      if (std::find(r.begin(), r.end(), p) != r.end()) return true;
    return false;
  };
  ring hole{P(0, 2), P(2, 3), P(2, 1)}; // its left vertex on the outer ring
  std::vector<std::pair<polygon, polygon>> pairs{
      {{rect(0, 0, 2, 2)}, {rect(1, 1, 3, 3)}},
      {{rect(0, 0, 4, 4), hole}, {rect(1, 1, 3, 3)}},
      {{rect(0, 0, 2, 1)}, {rect(1, 0, 3, 1)}},
      {{rect(0, 0, 1, 1)}, {rect(1, 1, 2, 2)}},
  };
  for (int t = 0; t < 30; ++t) pairs.push_back({{random_star(t % 2 == 1)}, {random_star(t % 2 == 1)}});
  auto union_ = [](bool x, bool y) { return x || y; };
  auto minus = [](bool x, bool y) { return x && !y; };
  std::size_t fewer = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    auto const& [a, b] = pairs[i];
    INFO("pair " << i);
    auto ba = boundary_of(a), bb = boundary_of(b);
    auto A = bsp::build_point_set<K>(ba, true, false, bsp::random_order(i)), B = bsp::build_point_set<K>(bb, true, false, bsp::random_order(i + 99));
    for (int op = 0; op < 2; ++op) {
      auto cut = op == 0 ? bsp::merged_boundary(A, ba, B, bb, union_) : bsp::merged_boundary(A, ba, B, bb, minus);
      auto joined = op == 0 ? bsp::merged_boundary(A, ba, B, bb, union_, true) : bsp::merged_boundary(A, ba, B, bb, minus, true);
      CHECK(joined.size() <= cut.size());
      fewer += joined.size() < cut.size();
      // Both bound the result: the trees built from them have its area.
      auto exact = op == 0 ? bsp::set_union(A, B) : bsp::set_difference(A, B);
      CHECK(laws::size<K>(bsp::build_point_set<K>(joined)) == laws::size<K>(exact));
      CHECK(laws::size<K>(bsp::build_point_set<K>(cut)) == laws::size<K>(exact));
      for (auto const& piece : joined) {
        auto ends = e2::endpoints(piece);
        REQUIRE(ends);
        for (auto const& p : {ends->first, ends->second})
          CHECK((is_vertex(a, p) || is_vertex(b, p) || (on_boundary(a, p) && on_boundary(b, p))));
      }
    }
    if (i == 0) // two overlapping squares: 4 sides whole, 4 cut at the 2 crossings, for the union
      CHECK(bsp::merged_boundary(A, ba, B, bb, union_, true).size() == 8);
  }
  CHECK(fewer > 10); // the trees' cuts, put back together
}

// Plain double: integer vertices in general position.  (With decimal vertices,
// which double cannot hold, the double kernel is not reliable: its predicates
// see rounded constructions.  That is what the exact default is for.)
TEST_CASE("E2 point sets in double on non-degenerate input", "[bsp][e2][double]") {
  using KD = e2::double_kernel;
  using PD = e2::point<double>;
  for (int t = 0; t < 20; ++t) {
    auto ra = random_star(false, true), rb = random_star(false, true);
    auto to_d = [](ring const& r) {
      std::vector<e2::sub_hyperplane<double>> out;
      for (std::size_t i = 0; i < r.size(); ++i) {
        auto const &p = r[i], &q = r[(i + 1) % r.size()];
        out.push_back(e2::segment(PD(q.x().convert_to<double>(), q.y().convert_to<double>()),
                                  PD(p.x().convert_to<double>(), p.y().convert_to<double>())));
      }
      return out;
    };
    auto A = bsp::build_point_set<KD>(to_d(ra)), B = bsp::build_point_set<KD>(to_d(rb));
    auto AQ = bsp::build_point_set<K>(boundary_of({ra})), BQ = bsp::build_point_set<K>(boundary_of({rb}));
    double u = laws::size<KD>(bsp::set_union(A, B)), i = laws::size<KD>(bsp::set_intersection(A, B));
    CHECK(u == Approx(laws::size<K>(bsp::set_union(AQ, BQ)).convert_to<double>()).epsilon(1e-9));
    CHECK(i == Approx(laws::size<K>(bsp::set_intersection(AQ, BQ)).convert_to<double>()).epsilon(1e-9).margin(1e-9));
    CHECK(u + i == Approx(shoelace(ra).convert_to<double>() + shoelace(rb).convert_to<double>()).epsilon(1e-9));
  }
}

} // namespace bsp_e2_sets_tests
