/// @file
/// Depth-order trees: sub-hyperplanes (polygons in E3, segments in E2) kept at
/// the nodes whose hyperplane carries them, so that a traversal from any point
/// lists them front to back (Fuchs, Kedem and Naylor 1980).
#pragma once

#include "concepts/label.hpp"
#include "splitter.hpp"
#include "tree.hpp"

#include <optional>
#include <utility>
#include <vector>

namespace bsp {

/// A piece of an input object in a depth-order tree: what is left of input
/// `id` in one cell.
template <geometry G, class Id = std::size_t> struct fragment {
  typename G::sub_hyperplane piece;
  Id id;
};

/// The fragments lying in one node's hyperplane (both orientations).
template <geometry G, class Id = std::size_t> using fragment_list = std::vector<fragment<G, Id>>;

template <geometry G, class Id> inline constexpr bool enable_depth_order_payload<fragment_list<G, Id>> = true;

/// A depth-order tree: fragments at interior nodes, nothing at the leaves.
template <geometry G, class Id = std::size_t>
  requires depth_order_payload<fragment_list<G, Id>>
using depth_order_tree = tree<G, fragment_list<G, Id>, none>;

/// Autopartition: every node's hyperplane supports one of the input pieces
/// left in its cell (chosen by `policy`); pieces crossing it are split, pieces
/// lying in it stay at the node.  A `bsp::cutting_policy` may answer with a
/// free cut instead, which the node then uses (see `balanced`).
template <geometry G, class Id = std::size_t, splitting_policy<G, fragment<G, Id>> Policy = input_order>
depth_order_tree<G, Id> build_depth_order(fragment_list<G, Id> input, Policy policy = {}) {
  depth_order_tree<G, Id> t;
  struct work {
    fragment_list<G, Id> pieces;
    node_id parent;
    int side;
  };
  std::vector<work> stack;
  stack.push_back({std::move(input), node_id{}, 0});
  auto piece = [](fragment<G, Id> const& f) -> typename G::sub_hyperplane const& { return f.piece; };
  while (!stack.empty()) {
    work w = std::move(stack.back());
    stack.pop_back();
    if (w.pieces.empty()) {
      t.attach(w.parent, w.side, t.add_leaf());
      continue;
    }
    auto d = decide<G>(policy, w.pieces, piece);
    typename G::hyperplane h = d.cut ? std::move(*d.cut) : G::supporting(w.pieces[d.piece].piece);
    fragment_list<G, Id> here, neg, pos;
    for (auto& f : w.pieces) {
      if (int side = detail::whole_side<G>(f.piece, h)) {
        (side < 0 ? neg : pos).push_back(std::move(f));
        continue;
      }
      auto r = G::split(f.piece, h);
      if (r.is_coincident()) {
        here.push_back(std::move(f));
        continue;
      }
      if (r.negative) neg.push_back({std::move(*r.negative), f.id});
      if (r.positive) pos.push_back({std::move(*r.positive), f.id});
    }
    node_id n = t.add_interior(h, node_id{}, node_id{}, std::move(here));
    t.attach(w.parent, w.side, n);
    stack.push_back({std::move(neg), n, -1});
    stack.push_back({std::move(pos), n, +1});
  }
  return t;
}

namespace detail {
template <geometry G, class Id, class F, class Enter, class Stop>
void depth_order_traverse(depth_order_tree<G, Id> const& t, typename G::point const& eye, F&& f, bool front_first, Enter&& enter,
                          Stop&& stop) {
  struct item {
    node_id n;
    bool emit; ///< list the node's own fragments now
  };
  std::vector<item> stack{{t.root(), false}};
  while (!stack.empty() && !stop()) {
    auto [n, emit] = stack.back();
    stack.pop_back();
    if (t.is_leaf(n)) continue;
    if (emit) {
      for (auto const& fr : t.node_data(n)) f(fr);
      continue;
    }
    if (!enter(n)) continue;
    // The eye's side is in front; from a point on the hyperplane either order is right.
    int s = static_cast<int>(G::side(t.splitter(n), eye));
    node_id front = s >= 0 ? t.positive(n) : t.negative(n);
    node_id back = s >= 0 ? t.negative(n) : t.positive(n);
    node_id first = front_first ? front : back, last = front_first ? back : front;
    stack.push_back({last, false});
    stack.push_back({n, true});
    stack.push_back({first, false});
  }
}
} // namespace detail

/// Calls `f(fragment)` for every fragment, front to back as seen from `eye`:
/// no fragment is listed after one that hides part of it.
template <geometry G, class Id, class F>
void for_each_front_to_back(depth_order_tree<G, Id> const& t, typename G::point const& eye, F&& f) {
  detail::depth_order_traverse<G, Id>(t, eye, f, true, [](node_id) { return true; }, [] { return false; });
}

/// The same, for callers that know what cannot matter any more: the
/// subtree at interior node `n` is left out when `enter(n)` is false (its
/// cell is hidden, say), and the traversal ends once `stop()` is true.
template <geometry G, class Id, class Enter, class F, class Stop>
void for_each_front_to_back(depth_order_tree<G, Id> const& t, typename G::point const& eye, Enter&& enter, F&& f, Stop&& stop) {
  detail::depth_order_traverse<G, Id>(t, eye, f, true, enter, stop);
}

/// Calls `f(fragment)` for every fragment, back to front (the painter's order).
template <geometry G, class Id, class F>
void for_each_back_to_front(depth_order_tree<G, Id> const& t, typename G::point const& eye, F&& f) {
  detail::depth_order_traverse<G, Id>(t, eye, f, false, [](node_id) { return true; }, [] { return false; });
}

} // namespace bsp
