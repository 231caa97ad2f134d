// Replaying a tree's making step by step (bsp/explain.hpp): after every step
// the cells tile the space exactly, a leaf once made keeps its label, each
// node is placed after its parent, and the last step is the finished tree.
// Random inputs with shared ends, touching intervals and repeated lines.
#include "../support.hpp"

#include <bsp/explain.hpp>
#include <bsp/boolean.hpp>
#include <geometry/e1.hpp>
#include <geometry/e2.hpp>
#include <geometry/e2/svg.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <set>

using namespace geometry;
using test::Q;

namespace bsp_explain_tests {

namespace {

using K1 = e1::exact_kernel;
using K2 = e2::exact_kernel;

/// Disjoint random intervals with integer ends; neighbours may touch.
std::vector<e1::sub_hyperplane<Q>> random_intervals(std::vector<std::pair<Q, Q>>& out) {
  std::vector<e1::sub_hyperplane<Q>> b;
  long at = test::uniform(-20, 0);
  for (int i = 0, n = static_cast<int>(test::uniform(1, 6)); i < n; ++i) {
    long lo = at + test::uniform(1, 3), hi = lo + test::uniform(1, 4);
    out.emplace_back(Q(lo), Q(hi));
    b.push_back({e1::hyperplane_at(Q(lo), false)});
    b.push_back({e1::hyperplane_at(Q(hi), true)});
    at = hi;
  }
  return b;
}

/// The cells of a step of an E1 tree tile the line: sorted by their ends, each
/// starts where the one before ends, from −∞ to +∞.
void check_tiling(std::vector<bsp::step_cell<K1>> const& cells) {
  std::vector<std::pair<std::optional<Q>, std::optional<Q>>> ends;
  for (auto const& c : cells) ends.push_back(e1::ends(c.region));
  std::sort(ends.begin(), ends.end(), [](auto const& a, auto const& b) { return !a.first || (b.first && *a.first < *b.first); });
  REQUIRE_FALSE(ends.front().first);
  REQUIRE_FALSE(ends.back().second);
  for (std::size_t i = 1; i < ends.size(); ++i) {
    REQUIRE(ends[i - 1].second);
    REQUIRE(ends[i].first);
    CHECK(*ends[i - 1].second == *ends[i].first);
  }
}

/// The parts of each step's cells inside a window add up to its area exactly.
Q area_in(std::vector<bsp::step_cell<K2>> const& cells, e2::svg_view const& v) {
  Q total(0);
  for (auto const& c : cells)
    if (auto a = e2::area(e2::detail::clip_to(c.region, v))) total += *a;
  return total;
}

/// A leaf made at one step keeps its cell and label at every later step.
template <class G> void check_leaves_stay(bsp::point_set<G, bool> const& t) {
  std::map<std::uint32_t, bool> seen;
  for (std::size_t k = 0; k <= t.interior_count(); ++k) {
    std::set<std::uint32_t> now;
    for (auto const& c : bsp::cells_after(t, k))
      if (!c.pending) {
        now.insert(c.node.index());
        CHECK(t.leaf_data(c.node) == seen.emplace(c.node.index(), t.leaf_data(c.node)).first->second);
      }
    for (auto const& [leaf, label] : seen) CHECK(now.contains(leaf));
  }
}

/// Every interior node hangs under one placed before it.
template <class G> void check_order(bsp::point_set<G, bool> const& t) {
  auto places = bsp::interior_places(t);
  for (std::uint32_t n = 0; n < t.interior_count(); ++n) {
    auto const& p = places[n];
    if (bsp::node_id::interior(n) == t.root()) {
      CHECK_FALSE(p.parent.valid());
      continue;
    }
    REQUIRE(p.parent.valid());
    CHECK(p.parent.index() < n);
    CHECK(t.child(p.parent, p.side) == bsp::node_id::interior(n));
    CHECK(p.depth == places[p.parent.index()].depth + 1);
  }
}

} // namespace

TEST_CASE("E1: every step of building and merging tiles the line", "[bsp][explain]") {
  for (int round = 0; round < 40; ++round) {
    std::vector<std::pair<Q, Q>> ia, ib;
    auto a = bsp::build_point_set<K1>(random_intervals(ia));
    auto b = bsp::build_point_set<K1>(random_intervals(ib));
    for (auto const* t : {&a, &b}) {
      auto first = bsp::state_after(*t, 0);
      REQUIRE(first.cells.size() == 1);
      CHECK(first.cells[0].pending);
      CHECK(first.splits.empty());
      for (std::size_t k = 0; k <= t->interior_count(); ++k) {
        auto s = bsp::state_after(*t, k);
        check_tiling(s.cells);
        CHECK(s.splits.size() == k);
      }
      check_order(*t);
      check_leaves_stay(*t);
    }
    auto x = [](bool p, bool q) { return p != q; };
    auto merged = bsp::merge_unreduced(a, b, x);
    for (std::size_t k = 0; k <= merged.interior_count(); ++k) check_tiling(bsp::cells_after(merged, k));
    check_order(merged);
    check_leaves_stay(merged);
    // The last step is the finished tree, and reducing it gives the merge.
    auto last = bsp::cells_after(merged, merged.interior_count());
    CHECK(last.size() == bsp::cells(merged).size());
    CHECK(std::none_of(last.begin(), last.end(), [](auto const& c) { return c.pending; }));
    CHECK(bsp::measure(bsp::reduce(merged), true) == bsp::measure(bsp::set_symmetric_difference(a, b), true));
  }
}

TEST_CASE("E2: every step of a build covers the plane once, and ends as the tree", "[bsp][explain]") {
  e2::svg_view window{-40, -40, 40, 40, 100};
  Q window_area(80 * 80);
  for (int round = 0; round < 25; ++round) {
    // Random boxes, some sharing edges or corners with others, as separate rings.
    std::vector<e2::sub_hyperplane<Q>> edges;
    Q expected(0);
    std::vector<std::array<long, 4>> boxes;
    for (int i = 0, n = static_cast<int>(test::uniform(1, 4)); i < n; ++i) {
      long x0 = 8 * i - 16 + test::uniform(0, 2), y0 = test::uniform(-10, 10);
      long x1 = x0 + test::uniform(1, 6) + (i % 2 ? 0 : 2), y1 = y0 + test::uniform(1, 6);
      x1 = std::min(x1, 8L * (i + 1) - 16); // neighbours may share an edge, never overlap
      if (x1 <= x0) continue;
      e2::point<Q> p[4] = {{Q(x0), Q(y0)}, {Q(x1), Q(y0)}, {Q(x1), Q(y1)}, {Q(x0), Q(y1)}};
      for (int k = 0; k < 4; ++k) edges.push_back(e2::segment(p[(k + 1) % 4], p[k]));
      expected += Q((x1 - x0) * (y1 - y0));
    }
    if (edges.empty()) continue;
    auto t = bsp::build_point_set<K2>(edges, true, false, bsp::random_order(static_cast<std::uint64_t>(round)));
    for (std::size_t k = 0; k <= t.interior_count(); ++k) {
      auto s = bsp::state_after(t, k);
      CHECK(area_in(s.cells, window) == window_area);
      CHECK(s.splits.size() == k);
    }
    check_order(t);
    check_leaves_stay(t);
    auto last = bsp::cells_after(t, t.interior_count());
    auto direct = bsp::cells(t);
    REQUIRE(last.size() == direct.size());
    Q inside(0);
    for (std::size_t i = 0; i < last.size(); ++i) {
      CHECK(last[i].node == direct[i].leaf);
      if (t.leaf_data(last[i].node)) inside += *e2::area(last[i].region);
    }
    CHECK(inside == expected);
  }
}

} // namespace bsp_explain_tests
