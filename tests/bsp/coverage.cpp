// Coverage trees and partitions rebuilt from their boundaries, in E2, against
// brute force on a grid: rectangles with integer corners inserted front to
// back (shared edges, repeats, nesting, touching corners), the visible area of
// each and of all against counted grid cells, membership of points off the
// grid lines, and the collapse of covered siblings; a labelled grid read back
// by `build_partition`.
#include "../support.hpp"

#include <bsp/coverage.hpp>
#include <bsp/point_set.hpp>
#include <catch2/catch.hpp>
#include <geometry/e2.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace geometry;
using test::Q;

namespace bsp_coverage_tests {

namespace {

using K = e2::exact_kernel;
using P = e2::point<Q>;
using cell = e2::polytope<Q>;
using cover_tree = bsp::coverage_tree<K, cell>;

struct rect {
  long x0, y0, x1, y1;
  bool contains(Q const& x, Q const& y) const { return Q(x0) < x && x < Q(x1) && Q(y0) < y && y < Q(y1); }
};

cell polygon_of(rect const& r) {
  return e2::convex_polygon<Q>({P(Q(r.x0), Q(r.y0)), P(Q(r.x1), Q(r.y0)), P(Q(r.x1), Q(r.y1)), P(Q(r.x0), Q(r.y1))});
}

/// How a piece goes down `t`: split where a node's line crosses it.
auto router(cover_tree const& t) {
  return [&t](cell& piece, bsp::node_id n) -> bsp::routed<cell> {
    auto r = K::split(piece, t.as_tree().splitter(n));
    if (!r.negative) return {+1, std::nullopt, std::nullopt};
    if (!r.positive) return {-1, std::nullopt, std::nullopt};
    return {0, std::move(r.negative), std::move(r.positive)};
  };
}

/// Hangs the bounds of `piece` (which reached the free `leaf` at `at`)
/// under that leaf; `leaf` and `at` become the piece's own leaf; returns its cell.
cell hang(cover_tree& t, cell const& piece, bsp::node_id& leaf, cover_tree::place& at) {
  cell here = t.as_tree().leaf_data(leaf);
  for (auto const& b : piece.bounds) {
    auto r = K::split(here, b);
    if (!r.negative || !r.positive) continue;
    bsp::node_id n = t.split(at, b, *r.negative, *r.positive);
    at = {n, +1};
    leaf = t.as_tree().positive(n);
    here = *r.positive;
  }
  return here;
}

/// Inserts `c` front to back: returns the area that reached free leaves (of
/// the bounded parts), and covers it.  Free leaves carry their cell.
Q insert(cover_tree& t, cell const& c, std::size_t& hidden) {
  Q visible(0);
  auto route = router(t);
  auto visit = [&](cell&& piece, bsp::node_id leaf, cover_tree::place at) {
    auto area = K::measure(piece);
    if (area) visible += *area;
    cell here = hang(t, piece, leaf, at);
    CHECK(K::measure(here) == area); // the leaf is now the piece
    t.cover(at, leaf);
  };
  hidden += t.insert(c, route, visit);
  return visible;
}

/// Inserts `c` as `insert` does, through `insert_merged`: returns the area
/// of the parts reported visible and of those reported hidden, and how many
/// of each.
struct merged_areas {
  Q visible{0}, hidden{0};
  std::size_t visible_parts = 0, hidden_parts = 0, cells = 0;
};
merged_areas insert_merged(cover_tree& t, cell const& c) {
  merged_areas m;
  auto route = router(t);
  auto visit = [&](cell&& piece, bsp::node_id leaf, cover_tree::place at) {
    ++m.cells;
    hang(t, piece, leaf, at);
    t.cover(at, leaf);
  };
  auto part = [&](cell&& p, bool visible) {
    (visible ? m.visible : m.hidden) += *K::measure(p);
    ++(visible ? m.visible_parts : m.hidden_parts);
  };
  m.cells += t.insert_merged(c, route, visit, part);
  return m;
}

bool covered_at(cover_tree const& t, P const& p) {
  auto const& tr = t.as_tree();
  bsp::node_id n = tr.root();
  while (!tr.is_leaf(n)) n = tr.child(n, K::side(tr.splitter(n), p) == oriented_side::negative ? -1 : +1);
  return t.is_covered(n);
}

std::vector<rect> random_rects(int count) {
  std::vector<rect> out;
  while (static_cast<int>(out.size()) < count) {
    int kind = static_cast<int>(test::uniform(0, 9));
    if (kind == 0 && !out.empty()) { // a repeat
      out.push_back(out[static_cast<std::size_t>(test::uniform(0, static_cast<long>(out.size()) - 1))]);
      continue;
    }
    if (kind == 1 && !out.empty()) { // sharing an edge with an earlier one
      rect r = out[static_cast<std::size_t>(test::uniform(0, static_cast<long>(out.size()) - 1))];
      long w = r.x1 - r.x0;
      out.push_back({r.x1, r.y0, r.x1 + w, r.y1});
      continue;
    }
    long x0 = test::uniform(-8, 7), y0 = test::uniform(-8, 7);
    out.push_back({x0, y0, x0 + test::uniform(1, 6), y0 + test::uniform(1, 6)});
  }
  return out;
}

} // namespace

TEST_CASE("a coverage tree covers exactly what was inserted, front to back", "[bsp][coverage]") {
  for (int trial = 0; trial < 40; ++trial) {
    bool collapse = trial % 4 != 3;
    INFO("trial " << trial << (collapse ? "" : ", without collapse"));
    auto rects = random_rects(static_cast<int>(test::uniform(1, 24)));
    cover_tree t(e2::whole_plane<Q>(), collapse);
    std::size_t hidden = 0;
    Q total(0);
    for (std::size_t i = 0; i < rects.size(); ++i) {
      Q visible = insert(t, polygon_of(rects[i]), hidden);
      // Brute force: the unit cells of rectangle i that no earlier rectangle covers.
      long cells = 0;
      auto const& r = rects[i];
      for (long x = r.x0; x < r.x1; ++x)
        for (long y = r.y0; y < r.y1; ++y) {
          Q cx = Q(2 * x + 1) / 2, cy = Q(2 * y + 1) / 2;
          bool before = false;
          for (std::size_t j = 0; j < i && !before; ++j) before = rects[j].contains(cx, cy);
          cells += !before;
        }
      CHECK(visible == Q(cells));
      total += visible;
      CHECK(t.interior_nodes() == t.as_tree().statistics().interior_nodes);
    }
    // Union area, and membership at points off every grid line.
    long union_cells = 0, lo = 0, hi = 0;
    for (auto const& r : rects) lo = std::min({lo, r.x0, r.y0}), hi = std::max({hi, r.x1, r.y1});
    for (long x = lo; x < hi; ++x)
      for (long y = lo; y < hi; ++y) {
        Q cx = Q(2 * x + 1) / 2, cy = Q(2 * y + 1) / 2;
        bool in = false;
        for (auto const& r : rects) in = in || r.contains(cx, cy);
        union_cells += in;
      }
    CHECK(total == Q(union_cells));
    for (int k = 0; k < 200; ++k) {
      // Odd over even: never on a grid line.
      Q x = Q(2 * test::uniform(-900, 1300) + 1) / 194, y = Q(2 * test::uniform(-900, 1300) + 1) / 178;
      bool in = false;
      for (auto const& r : rects) in = in || r.contains(x, y);
      CHECK(covered_at(t, P(x, y)) == in);
    }
    CHECK(t.peak_interior_nodes() >= t.interior_nodes());
    // The two half-planes x ≤ 0 and x ≥ 0 cover the rest: with collapse, one covered leaf is left.
    e2::hyperplane<Q> vertical(hvec<Q, 3>(std::array<Q, 3>{Q(1), Q(0), Q(0)}));
    auto halves = K::split(e2::whole_plane<Q>(), vertical);
    insert(t, *halves.negative, hidden);
    insert(t, *halves.positive, hidden);
    for (int k = 0; k < 20; ++k) CHECK(covered_at(t, P(Q(test::uniform(-99, 99)) / 7, Q(test::uniform(-99, 99)) / 5)));
    if (collapse) {
      CHECK(t.as_tree().is_leaf(t.root()));
      CHECK(t.interior_nodes() == 0);
    } else {
      CHECK(t.interior_nodes() == t.peak_interior_nodes());
    }
  }
}

TEST_CASE("collapsing covered siblings drops the pieces hidden behind them sooner", "[bsp][coverage]") {
  // The outside of the unit square as four half-planes, then the square:
  // everything is covered, and a larger square behind meets one leaf.
  auto half = [](long a, long b, long c) {
    return *K::split(e2::whole_plane<Q>(), e2::hyperplane<Q>(hvec<Q, 3>(std::array<Q, 3>{Q(a), Q(b), Q(c)}))).positive;
  };
  std::vector<cell> front{half(-1, 0, 0), half(1, 0, -1), half(0, -1, 0), half(0, 1, -1), polygon_of({0, 0, 1, 1})};
  std::size_t hidden_collapsed = 0, hidden_kept = 0;
  cover_tree a(e2::whole_plane<Q>(), true), b(e2::whole_plane<Q>(), false);
  for (auto const& c : front) {
    insert(a, c, hidden_collapsed);
    insert(b, c, hidden_kept);
  }
  CHECK(a.as_tree().is_leaf(a.root()));
  CHECK(a.is_covered(a.root()));
  CHECK(a.interior_nodes() == 0);
  CHECK(a.peak_interior_nodes() >= 4);
  CHECK(b.interior_nodes() == b.peak_interior_nodes());
  CHECK(b.interior_nodes() >= 4);
  std::size_t before_collapsed = hidden_collapsed, before_kept = hidden_kept;
  CHECK(insert(a, polygon_of({-1, -1, 2, 2}), hidden_collapsed) == Q(0));
  CHECK(insert(b, polygon_of({-1, -1, 2, 2}), hidden_kept) == Q(0));
  CHECK(hidden_collapsed - before_collapsed == 1);
  CHECK(hidden_kept - before_kept >= 5); // the square and pieces of the four half-planes
}

TEST_CASE("build_partition reads a labelled grid back from the boundaries between its cells", "[bsp][partition]") {
  for (int trial = 0; trial < 20; ++trial) {
    long n = test::uniform(1, 7);
    // Labels of the n × n unit cells; 0 outside.  Neighbours often agree.
    std::vector<std::uint32_t> label(static_cast<std::size_t>(n * n));
    for (auto& l : label) l = static_cast<std::uint32_t>(test::uniform(1, 3));
    auto at = [&](long x, long y) -> std::uint32_t {
      return (x < 0 || y < 0 || x >= n || y >= n) ? 0u : label[static_cast<std::size_t>(y * n + x)];
    };
    std::vector<bsp::boundary_piece<K, std::uint32_t>> pieces;
    // A unit edge between the cells a (on its left, going from p to q) and b.
    auto edge = [&](P p, P q, std::uint32_t left, std::uint32_t right, P left_point) {
      if (left == right) return;
      auto s = e2::segment(p, q);
      bool left_positive = K::side(K::supporting(s), left_point) == oriented_side::positive;
      pieces.push_back({s, left_positive ? right : left, left_positive ? left : right});
    };
    for (long x = 0; x <= n; ++x)
      for (long y = 0; y < n; ++y) // vertical edge at x, cells (x-1, y) | (x, y)
        edge(P(Q(x), Q(y)), P(Q(x), Q(y + 1)), at(x - 1, y), at(x, y), P(Q(2 * x - 1) / 2, Q(2 * y + 1) / 2));
    for (long y = 0; y <= n; ++y)
      for (long x = 0; x < n; ++x) // horizontal edge at y, cells (x, y) | (x, y-1)
        edge(P(Q(x), Q(y)), P(Q(x + 1), Q(y)), at(x, y), at(x, y - 1), P(Q(2 * x + 1) / 2, Q(2 * y + 1) / 2));
    auto t = bsp::build_partition<K, std::uint32_t>(pieces, 0u, bsp::random_order(static_cast<std::uint64_t>(trial)));
    CHECK(t.statistics().interior_nodes <= 2 * pieces.size() * (pieces.size() + 1));
    for (int k = 0; k < 300; ++k) {
      Q x = Q(2 * test::uniform(-300, 1000) + 1) / 194, y = Q(2 * test::uniform(-300, 1000) + 1) / 178;
      long cx = static_cast<long>(std::floor(x.convert_to<double>())), cy = static_cast<long>(std::floor(y.convert_to<double>()));
      auto l = bsp::classify(t, P(x, y));
      REQUIRE(l.has_value());
      CHECK(*l == at(cx, cy));
    }
  }
  // No pieces: one leaf with the label given.
  auto empty = bsp::build_partition<K, std::uint32_t>({}, 7u);
  CHECK(empty.is_leaf(empty.root()));
  CHECK(empty.leaf_data(empty.root()) == 7u);
}

TEST_CASE("insert_merged reports a piece in maximal visible and hidden parts", "[bsp][coverage]") {
  std::size_t fewer = 0;
  for (int trial = 0; trial < 40; ++trial) {
    INFO("trial " << trial);
    auto rects = random_rects(static_cast<int>(test::uniform(2, 24)));
    cover_tree a(e2::whole_plane<Q>()), b(e2::whole_plane<Q>());
    std::size_t hidden = 0;
    for (auto const& r : rects) {
      Q visible = insert(a, polygon_of(r), hidden);
      auto m = insert_merged(b, polygon_of(r));
      // The same visible area as cell by cell, and the parts tile the piece.
      CHECK(m.visible == visible);
      CHECK(m.visible + m.hidden == *K::measure(polygon_of(r)));
      CHECK(m.visible_parts + m.hidden_parts <= m.cells);
      CHECK((m.visible_parts > 0) == (visible > 0));
      fewer += m.visible_parts + m.hidden_parts < m.cells;
    }
    CHECK(b.interior_nodes() == a.interior_nodes());
  }
  CHECK(fewer > 0);
}

} // namespace bsp_coverage_tests
