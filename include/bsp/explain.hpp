/// @file
/// Replaying how a tree was built, step by step, for teaching and for
/// `genbsp explain`.  The builders of this library (`build_point_set`,
/// `build_partition`, `merge_unreduced`) add each interior node when they
/// decide it, so a tree's arena order is the order of its steps: after step
/// `k` the interior nodes `0 … k−1` are placed, and every other interior node
/// is a cell still waiting for its pieces.  Nothing is recorded while building:
/// the replay reads the finished tree, so a teaching picture cannot disagree
/// with the algorithm it shows.
#pragma once

#include "point_set.hpp"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace bsp {

/// A cell of a tree after some steps: the region of a leaf, or of a subtree
/// whose root is not placed yet (`pending`).
template <geometry G> struct step_cell {
  typename G::polytope region;
  node_id node;         ///< the leaf, or the pending subtree's root
  bool pending = false; ///< the subtree is still to be built
};

/// Where a node hangs: its parent (invalid for the root), the side it is on
/// (−1, +1; 0 for the root) and its depth.
struct node_place {
  node_id parent;
  int side = 0;
  std::size_t depth = 0;
};

/// The place of every interior node reachable from the root, indexed by its
/// arena index (`node_id::index()`); unreachable ones keep a default place.
template <geometry G, class N, class L> std::vector<node_place> interior_places(tree<G, N, L> const& t) {
  std::vector<node_place> out(t.interior_count());
  for_each_node(t, t.root(), [&](node_id n, std::size_t depth) {
    if (t.is_leaf(n)) return;
    out[n.index()].depth = depth;
    for (int side : {-1, +1}) {
      node_id c = t.child(n, side);
      if (!t.is_leaf(c)) out[c.index()] = {n, side, depth + 1};
    }
  });
  return out;
}

/// A tree after some of its steps: its cells, and each placed node with the
/// cell its hyperplane splits, in pre-order.
template <geometry G> struct step_state {
  std::vector<step_cell<G>> cells;
  std::vector<std::pair<node_id, typename G::polytope>> splits;
};

/// The tree `t` after its first `placed` interior nodes (in arena order):
/// leaves under placed nodes, and pending cells where an unplaced interior
/// node hangs.  Cells without interior are left out, as `cells` does.  With
/// `placed == t.interior_count()` the cells are those of `cells(t)`.
template <geometry G, class N, class L> step_state<G> state_after(tree<G, N, L> const& t, std::size_t placed) {
  step_state<G> out;
  std::vector<std::pair<node_id, typename G::polytope>> stack;
  stack.emplace_back(t.root(), G::whole_space());
  while (!stack.empty()) {
    auto [n, c] = std::move(stack.back());
    stack.pop_back();
    if (t.is_leaf(n) || n.index() >= placed) {
      out.cells.push_back({std::move(c), n, !t.is_leaf(n)});
      continue;
    }
    auto r = G::split(c, t.splitter(n));
    out.splits.emplace_back(n, std::move(c));
    if (r.negative) stack.emplace_back(t.negative(n), std::move(*r.negative));
    if (r.positive) stack.emplace_back(t.positive(n), std::move(*r.positive));
  }
  return out;
}

/// The cells of `t` after its first `placed` interior nodes (see `state_after`).
template <geometry G, class N, class L> std::vector<step_cell<G>> cells_after(tree<G, N, L> const& t, std::size_t placed) {
  return state_after(t, placed).cells;
}

} // namespace bsp
