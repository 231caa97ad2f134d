/// @file
/// Set operations by tree merging (Naylor, Amanatides and Thibault, "Merging
/// BSP trees yields polyhedral set operations", SIGGRAPH 1990), generic over
/// the geometry and the label type.
///
/// `merge(a, b, op)` keeps the structure of `a` and grafts, at each leaf of
/// `a`, the part of `b` inside that leaf's cell: `b`'s nodes whose hyperplane
/// does not cut the cell are skipped (the cell is split exactly by the
/// geometry), so the result has no empty cells.  Leaf labels become
/// `op(label of a, label of b)`; the result is then reduced.
#pragma once

#include "concepts/join.hpp"
#include "point_set.hpp"

#include <cstddef>
#include <functional>
#include <optional>
#include <tuple>
#include <vector>
#include <type_traits>

namespace bsp {

/// `merge` before its result is reduced: every node of `a` that cuts the
/// region, then under each leaf of `a` the nodes of `b` that cut that leaf's
/// cell, added to the result in the order the merge decides them (so that
/// `bsp::cells_after` replays it step by step).
template <geometry G, label LA, label LB, class Op, class R = std::invoke_result_t<Op&, LA const&, LB const&>>
  requires label<R>
point_set<G, R> merge_unreduced(point_set<G, LA> const& a, point_set<G, LB> const& b, Op op) {
  using P = typename G::polytope;
  point_set<G, R> out;
  // Work items: a node of `a` with its cell, or a node of `b` inside the cell
  // of a leaf of `a` (whose label is `la`); each builds a node of `out` and
  // attaches it under `parent` on `side`.
  struct item {
    bool in_b;
    node_id n;
    P cell;
    node_id parent;
    int side;
    LA la;
  };
  std::vector<item> stack;
  stack.push_back({false, a.root(), G::whole_space(), node_id{}, 0, LA{}});
  while (!stack.empty()) {
    item w = std::move(stack.back());
    stack.pop_back();
    if (!w.in_b && a.is_leaf(w.n)) {
      LA la = a.leaf_data(w.n);
      if constexpr (std::is_same_v<LB, bool>) {
        // A label that decides the result alone (union with inside …) ends here.
        R f = op(la, false), t = op(la, true);
        if (f == t) {
          out.attach(w.parent, w.side, out.add_leaf(f));
          continue;
        }
      }
      stack.push_back({true, b.root(), std::move(w.cell), w.parent, w.side, std::move(la)});
      continue;
    }
    if (w.in_b && b.is_leaf(w.n)) {
      out.attach(w.parent, w.side, out.add_leaf(op(w.la, b.leaf_data(w.n))));
      continue;
    }
    auto const& tr = w.in_b ? b.splitter(w.n) : a.splitter(w.n);
    node_id neg = w.in_b ? b.negative(w.n) : a.negative(w.n);
    node_id pos = w.in_b ? b.positive(w.n) : a.positive(w.n);
    auto r = G::split(w.cell, tr);
    if (!r.negative || !r.positive) {
      // The hyperplane misses the cell: only one side matters here.
      stack.push_back({w.in_b, r.negative ? neg : pos, std::move(r.negative ? *r.negative : *r.positive), w.parent,
                       w.side, std::move(w.la)});
      continue;
    }
    node_id n = out.add_interior(tr, node_id{}, node_id{});
    out.attach(w.parent, w.side, n);
    stack.push_back({w.in_b, neg, std::move(*r.negative), n, -1, w.la});
    stack.push_back({w.in_b, pos, std::move(*r.positive), n, +1, std::move(w.la)});
  }
  return out;
}

/// Merges two labellings of the same space: each point gets `op(a(p), b(p))`.
template <geometry G, label LA, label LB, class Op, class R = std::invoke_result_t<Op&, LA const&, LB const&>>
  requires label<R>
point_set<G, R> merge(point_set<G, LA> const& a, point_set<G, LB> const& b, Op op) {
  return reduce(merge_unreduced(a, b, op));
}

namespace detail {

/// Joins the pieces `out[first..]` where one continues another with the same
/// labels (`G::join`), until none does; skipped past `limit` pieces, where
/// the pairs to try would cost more than the pieces they save.
template <geometry G, class R>
void join_runs(std::vector<std::pair<typename G::sub_hyperplane, R>>& out, std::size_t first, std::size_t limit = 64) {
  if constexpr (joining_geometry<G>) {
    if (out.size() - first < 2 || out.size() - first > limit) return;
    for (std::size_t i = first; i < out.size(); ++i)
      for (std::size_t j = first; j < out.size();) {
        std::optional<typename G::sub_hyperplane> u;
        if (j != i && out[j].second == out[i].second) {
          u = G::join(out[i].first, out[j].first);
          if (!u) u = G::join(out[j].first, out[i].first);
        }
        if (!u) {
          ++j;
          continue;
        }
        out[i].first = std::move(*u);
        if (j != out.size() - 1) out[j] = std::move(out.back());
        if (i == out.size() - 1) i = j; // the joined piece moved into j's place
        out.pop_back();
        j = first; // the longer piece may continue another
      }
  }
}

/// The pieces of `s` with the labels of tree `t` on their negative and
/// positive sides (where `s` runs along a node's hyperplane both children are
/// looked at, as in `boundary`).
///
/// Both sides of a piece go down together while it stays off the hyperplanes
/// it meets; where it lies in one (at node m), they part: the piece goes down
/// the child on its negative side, and each part that comes out goes down the
/// other child from m.  Without descending twice from the root.  With
/// `rejoin`, parts of a split whose labels agree are put back together
/// (`rejoiner`), so a piece comes out cut only where a label on one of its
/// sides changes, or where a neighbouring part was cut.
template <geometry G, class N, label L>
void labels_across(tree<G, N, L> const& t, typename G::sub_hyperplane s,
                   std::vector<std::pair<typename G::sub_hyperplane, std::pair<L, L>>>& out, bool rejoin) {
  std::size_t const first = out.size();
  using S = typename G::sub_hyperplane;
  using J = rejoiner<S, std::pair<L, L>>;
  J parts(out, rejoin);
  std::vector<rejoin_work<S>> stack; // parts of split pieces, both sides still together
  std::vector<std::pair<S, L>> below, across;
  stack.push_back({std::move(s), t.root(), J::none, 0});
  while (!stack.empty()) {
    auto w = std::move(stack.back());
    stack.pop_back();
    for (;;) {
      if (t.is_leaf(w.m)) {
        auto const& l = t.leaf_data(w.m);
        parts.whole(w.record, w.side, std::move(w.piece), {l, l});
        break;
      }
      if (int side = whole_side<G>(w.piece, t.splitter(w.m))) {
        w.m = t.child(w.m, side);
        continue;
      }
      auto r = G::split(w.piece, t.splitter(w.m));
      if (r.is_coincident()) {
        int c = static_cast<int>(r.coincident); // +1: the piece faces as m's hyperplane does
        below.clear();
        push_down(t, std::move(w.piece), t.child(w.m, -c), -1, below, rejoin);
        if (below.size() == 1) {
          across.clear();
          push_down(t, std::move(below.front().first), t.child(w.m, c), +1, across, rejoin);
          if (across.size() == 1) { // whole, one label on each side
            parts.whole(w.record, w.side, std::move(across.front().first), {below.front().second, across.front().second});
            break;
          }
          for (auto& [q, lpos] : across) parts.emit(std::move(q), {below.front().second, lpos});
        } else {
          for (auto& [part, lneg] : below) {
            across.clear();
            push_down(t, std::move(part), t.child(w.m, c), +1, across, rejoin);
            for (auto& [q, lpos] : across) parts.emit(std::move(q), {lneg, lpos});
          }
        }
        parts.broken(w.record, w.side);
        break;
      }
      if (!follow_split<G>(t, r, w, stack, parts)) break;
    }
  }
  if (rejoin) join_runs<G>(out, first);
}

} // namespace detail

/// The boundary of `op(a, b)` (`op` on labels `bool × bool → bool`) without
/// building the merged tree: the pieces of the two operands' boundaries,
/// classified against both trees, where the result's label changes across
/// them.  `a_boundary` must cover the boundary of `a` (for instance the
/// pieces `a` was built from) and `b_boundary` that of `b`; pieces along
/// which the operand's own label does not change are dropped, so two input
/// pieces meeting back to back (a shared edge inside one operand) vanish.
/// Where the two boundaries run together, the piece is taken once (from `a`).
/// Each output piece has the result on its negative side, like
/// `oriented_boundary`.
///
/// Each input piece is pushed down both trees, so the cost grows with the
/// number of input pieces times the cells they cross, and not with the size
/// of the merged tree, which can be much larger.
///
/// With `rejoin`, the parts of an input piece that a tree's hyperplanes cut
/// where no label changes are put back together: the output pieces end only
/// at the input pieces' ends and where a label changes, so there are fewer
/// of them and fewer ends to construct.  Where the result's boundary touches
/// itself inside a piece (a hole's corner on its outer ring's edge), that
/// piece may then pass through the point where the others end: a caller
/// that joins pieces by their ends must accept such a T-junction.  Without
/// it, every cut stays.
template <geometry G, class Op>
std::vector<typename G::sub_hyperplane> merged_boundary(point_set<G, bool> const& a,
                                                        std::vector<typename G::sub_hyperplane> const& a_boundary,
                                                        point_set<G, bool> const& b,
                                                        std::vector<typename G::sub_hyperplane> const& b_boundary, Op op,
                                                        bool rejoin = false) {
  using S = typename G::sub_hyperplane;
  std::vector<S> out;
  std::vector<std::pair<S, std::pair<bool, bool>>> first, second;
  for (int from = 0; from < 2; ++from) {
    auto const& own = from == 0 ? a : b;
    auto const& other = from == 0 ? b : a;
    for (auto const& s : from == 0 ? a_boundary : b_boundary) {
      first.clear();
      detail::labels_across(own, s, first, rejoin);
      for (auto& [p, own] : first) {
        auto [own_neg, own_pos] = own;
        if (own_neg == own_pos) continue; // not on this operand's boundary
        second.clear();
        detail::labels_across(other, std::move(p), second, rejoin);
        for (auto& [q, other] : second) {
          auto [other_neg, other_pos] = other;
          if (from == 1 && other_neg != other_pos) continue; // on both boundaries: taken from a
          bool neg = from == 0 ? op(own_neg, other_neg) : op(other_neg, own_neg);
          bool pos = from == 0 ? op(own_pos, other_pos) : op(other_pos, own_pos);
          if (neg == pos) continue;
          out.push_back(neg ? std::move(q) : G::opposite(q));
        }
      }
    }
  }
  return out;
}

/// @name Set operations on regular sets (`true` inside)
/// @{
template <geometry G> point_set<G, bool> set_union(point_set<G, bool> const& a, point_set<G, bool> const& b) {
  return merge(a, b, [](bool x, bool y) { return x || y; });
}
template <geometry G> point_set<G, bool> set_intersection(point_set<G, bool> const& a, point_set<G, bool> const& b) {
  return merge(a, b, [](bool x, bool y) { return x && y; });
}
template <geometry G> point_set<G, bool> set_difference(point_set<G, bool> const& a, point_set<G, bool> const& b) {
  return merge(a, b, [](bool x, bool y) { return x && !y; });
}
template <geometry G>
point_set<G, bool> set_symmetric_difference(point_set<G, bool> const& a, point_set<G, bool> const& b) {
  return merge(a, b, [](bool x, bool y) { return x != y; });
}
/// The same tree with every label replaced by `f(label)`.
template <geometry G, label L, class F, class R = std::invoke_result_t<F&, L const&>>
point_set<G, R> relabel(point_set<G, L> const& t, F f) {
  return merge(t, point_set<G, bool>(false), [&](L const& x, bool) { return f(x); });
}
/// Everything not in `a`.
template <geometry G> point_set<G, bool> complement(point_set<G, bool> const& a) {
  return relabel(a, [](bool x) { return !x; });
}
/// @}

} // namespace bsp
