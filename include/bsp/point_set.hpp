/// @file
/// Point-set trees: regular sets (and labelled partitions) as BSP trees with
/// labels at the leaves.  Build from a boundary (Thibault and Naylor 1987),
/// classify points, list the cells, extract the boundary, reduce.
#pragma once

#include "concepts/label.hpp"
#include "concepts/measure.hpp"
#include "concepts/whole_side.hpp"
#include "splitter.hpp"
#include "tree.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace bsp {

/// A point-set tree over `G` with labels `L` at its leaves.
template <geometry G, label L = bool> using point_set = tree<G, none, L>;

/// Builds the point-set tree of a region from its boundary: sub-hyperplanes
/// oriented with the region on their *negative* side (outward normals), as a
/// closed polygon mesh has them when its faces turn counter-clockwise seen from
/// outside.  Cells behind a boundary piece get `inside`, the others `outside`.
/// The boundary must be closed and consistently oriented; pieces may touch and
/// share vertices, edges and faces.  Where two parts of the region meet back
/// to back (pieces lying in one hyperplane, opposite ways round, as where two
/// polygons share part of an edge), both sides are inside.  The same pieces
/// also arise where the region lies on neither side (a hole sharing part of
/// an edge with its outer ring, a cavity part of a face with the outer
/// shell); that case is not told apart yet, and the side in front of such a
/// cut is labelled inside.  A `bsp::cutting_policy` that offers free
/// cuts, as `balanced` does, keeps the tree shallow on convex surfaces.
template <geometry G, label L = bool, splitting_policy<G> Policy = input_order>
point_set<G, L> build_point_set(std::vector<typename G::sub_hyperplane> boundary, L inside = L(true),
                                L outside = L(false), Policy policy = {}) {
  using S = typename G::sub_hyperplane;
  point_set<G, L> t(outside);
  struct work {
    std::vector<S> pieces;
    node_id parent;
    int side;
    L empty;
  };
  std::vector<work> stack;
  stack.push_back({std::move(boundary), node_id{}, 0, outside});
  while (!stack.empty()) {
    work w = std::move(stack.back());
    stack.pop_back();
    if (w.pieces.empty()) {
      t.attach(w.parent, w.side, t.add_leaf(w.empty));
      continue;
    }
    auto piece = [](S const& s) -> S const& { return s; };
    std::vector<S> neg, pos;
    std::optional<typename G::hyperplane> h;
    // A free cut (from a `bsp::cutting_policy` such as `balanced`) is taken
    // only when it leaves pieces on both sides, so no leaf hangs under it:
    // every leaf still lies just behind or in front of a boundary piece.
    // Pieces lying in the cut go to the side the region is on.
    auto d = decide<G>(policy, w.pieces, piece);
    if (d.cut) {
      for (auto const& s : w.pieces) {
        auto r = G::split(s, *d.cut);
        if (r.is_coincident())
          (static_cast<int>(r.coincident) > 0 ? neg : pos).push_back(s);
        if (r.negative) neg.push_back(std::move(*r.negative));
        if (r.positive) pos.push_back(std::move(*r.positive));
      }
      if (!neg.empty() && !pos.empty())
        h = std::move(*d.cut);
      else
        neg.clear(), pos.clear();
    }
    bool free = h.has_value();
    // A piece lying in the chosen hyperplane the other way round (the region
    // on its positive side: two regions meeting there, back to back) makes
    // the positive side inside too.
    bool inside_in_front = false;
    if (!free) {
      h = G::supporting(w.pieces[d.piece]);
      for (auto& s : w.pieces) {
        if (int side = detail::whole_side<G>(s, *h)) {
          (side < 0 ? neg : pos).push_back(std::move(s));
          continue;
        }
        auto r = G::split(s, *h);
        if (r.is_coincident()) inside_in_front = inside_in_front || static_cast<int>(r.coincident) < 0;
        if (r.negative) neg.push_back(std::move(*r.negative));
        if (r.positive) pos.push_back(std::move(*r.positive));
      }
    }
    node_id n = t.add_interior(std::move(*h), node_id{}, node_id{});
    t.attach(w.parent, w.side, n);
    stack.push_back({std::move(neg), n, -1, free ? w.empty : inside});
    stack.push_back({std::move(pos), n, +1, free ? w.empty : inside_in_front ? inside : outside});
  }
  return t;
}

template <geometry G, label L> struct boundary_piece;

/// Builds a tree that labels the cells of a partition (a map's faces, say)
/// from the pieces of their common boundaries: each piece lies between a cell
/// labelled `negative` and one labelled `positive` on those sides of its
/// hyperplane.  Every node's hyperplane supports a piece (an autopartition in
/// the order `policy` chooses), and a leaf takes the label on its side of the
/// last piece split there: that piece lies on the leaf's boundary, and no
/// piece crosses the leaf.  With no pieces the tree is one leaf labelled
/// `whole`.  Pieces lying in a node's hyperplane end there.  Classification
/// of a point on a piece gives the label of the node's positive side.
template <geometry G, label L, splitting_policy<G, boundary_piece<G, L>> Policy = input_order>
point_set<G, L> build_partition(std::vector<boundary_piece<G, L>> pieces, L whole, Policy policy = {}) {
  using B = boundary_piece<G, L>;
  point_set<G, L> t(whole);
  struct work {
    std::vector<B> pieces;
    node_id parent;
    int side;
    L label;
  };
  std::vector<work> stack;
  stack.push_back({std::move(pieces), node_id{}, 0, whole});
  auto piece = [](B const& b) -> typename G::sub_hyperplane const& { return b.piece; };
  while (!stack.empty()) {
    work w = std::move(stack.back());
    stack.pop_back();
    if (w.pieces.empty()) {
      t.attach(w.parent, w.side, t.add_leaf(std::move(w.label)));
      continue;
    }
    auto d = decide<G>(policy, w.pieces, piece);
    typename G::hyperplane h = G::supporting(w.pieces[d.piece].piece);
    L below = w.pieces[d.piece].negative, above = w.pieces[d.piece].positive;
    std::vector<B> neg, pos;
    for (auto& b : w.pieces) {
      if (int side = detail::whole_side<G>(b.piece, h)) {
        (side < 0 ? neg : pos).push_back(std::move(b));
        continue;
      }
      auto r = G::split(b.piece, h);
      if (r.negative) neg.push_back({std::move(*r.negative), b.negative, b.positive});
      if (r.positive) pos.push_back({std::move(*r.positive), b.negative, b.positive});
    }
    node_id n = t.add_interior(std::move(h), node_id{}, node_id{});
    t.attach(w.parent, w.side, n);
    stack.push_back({std::move(neg), n, -1, std::move(below)});
    stack.push_back({std::move(pos), n, +1, std::move(above)});
  }
  return t;
}

/// The label at `p`, or nothing when `p` lies on the boundary between
/// differently labelled cells.
template <geometry G, class N, label L>
std::optional<L> classify(tree<G, N, L> const& t, typename G::point const& p, node_id from) {
  node_id n = from;
  while (!t.is_leaf(n)) {
    int s = static_cast<int>(G::side(t.splitter(n), p));
    if (s == 0) {
      auto a = classify(t, p, t.negative(n));
      auto b = classify(t, p, t.positive(n));
      return a == b ? a : std::nullopt;
    }
    n = t.child(n, s);
  }
  return t.leaf_data(n);
}

template <geometry G, class N, label L> std::optional<L> classify(tree<G, N, L> const& t, typename G::point const& p) {
  return classify(t, p, t.root());
}

/// A leaf's cell: a convex polytope and the leaf.
template <geometry G> struct cell {
  typename G::polytope region;
  node_id leaf;
};

namespace detail {

/// Calls `f(cell, leaf)` for the cell of every leaf reachable from the root
/// through nodes `descend(node)` accepts (leaves whose cell has no interior
/// are left out), in the order of `cells`, until `f` returns false.
template <geometry G, class N, class L, class Descend, class F> void visit_cells(tree<G, N, L> const& t, Descend descend, F f) {
  if (!descend(t.root())) return;
  std::vector<std::pair<node_id, typename G::polytope>> stack;
  stack.emplace_back(t.root(), G::whole_space());
  while (!stack.empty()) {
    auto [n, c] = std::move(stack.back());
    stack.pop_back();
    if (t.is_leaf(n)) {
      if (!f(std::move(c), n)) return;
      continue;
    }
    node_id neg = t.negative(n), pos = t.positive(n);
    auto r = G::split(c, t.splitter(n));
    if (r.negative && descend(neg)) stack.emplace_back(neg, std::move(*r.negative));
    if (r.positive && descend(pos)) stack.emplace_back(pos, std::move(*r.positive));
  }
}

} // namespace detail

/// The cells of all leaves reachable from the root (leaves whose cell has no
/// interior are left out).
template <geometry G, class N, class L> std::vector<cell<G>> cells(tree<G, N, L> const& t) {
  std::vector<cell<G>> out;
  detail::visit_cells(t, [](node_id) { return true; }, [&](typename G::polytope c, node_id n) {
    out.push_back({std::move(c), n});
    return true;
  });
  return out;
}

namespace detail {

/// The number a measure adds up to: `M`, or the value an optional `M` holds.
template <class M, bool partial> struct sum_of {
  using type = M;
};
template <class M> struct sum_of<M, true> {
  using type = typename M::value_type;
};

/// For each interior node of `t` (by index), whether its subtree holds a
/// reachable leaf labelled `which`.
template <geometry G, class N, label L> std::vector<char> subtrees_holding(tree<G, N, L> const& t, L const& which) {
  std::vector<char> holds(t.interior_count(), 0);
  auto has = [&](node_id n) { return t.is_leaf(n) ? t.leaf_data(n) == which : holds[n.index()] != 0; };
  if (t.is_leaf(t.root())) return holds;
  std::vector<std::pair<node_id, bool>> stack{{t.root(), false}}; // (node, children done)
  while (!stack.empty()) {
    auto [n, done] = stack.back();
    stack.pop_back();
    if (done) {
      holds[n.index()] = has(t.negative(n)) || has(t.positive(n));
      continue;
    }
    stack.emplace_back(n, true);
    for (node_id c : {t.negative(n), t.positive(n)})
      if (!t.is_leaf(c)) stack.emplace_back(c, false);
  }
  return holds;
}

} // namespace detail

/// The total measure (length, area, volume …, as `G::measure` gives it) of the
/// cells labelled `which`; nothing when one of them is unbounded.  Only the
/// subtrees that hold such a cell are descended, and cells are measured as
/// they are reached, in the order of `cells`, so a sum of doubles is the same.
template <geometry G, class N, label L>
  requires measured_space<G>
measure_t<G> measure(tree<G, N, L> const& t, L const& which) {
  using M = measure_t<G>;
  constexpr bool partial = partial_measure<M>;
  typename detail::sum_of<M, partial>::type sum(0);
  auto holds = detail::subtrees_holding(t, which);
  [[maybe_unused]] bool bounded = true;
  detail::visit_cells(
      t, [&](node_id n) { return t.is_leaf(n) ? t.leaf_data(n) == which : holds[n.index()] != 0; },
      [&](typename G::polytope const& c, node_id) {
        if constexpr (partial) {
          auto m = G::measure(c);
          if (!m) return bounded = false;
          sum = sum + *m;
        } else {
          sum = sum + G::measure(c);
        }
        return true;
      });
  if constexpr (partial)
    if (!bounded) return std::nullopt;
  return sum;
}

/// A piece of the boundary between differently labelled cells: it lies in a
/// node's hyperplane and keeps that orientation; `negative` and `positive` are
/// the labels on its two sides.
template <geometry G, label L> struct boundary_piece {
  typename G::sub_hyperplane piece;
  L negative, positive;
};

namespace detail {

/// Collects the parts of one piece pushed down a tree, each with the result
/// `R` its leaf gave, and puts split pieces back together: where both parts
/// of a split come out whole with equal results, the piece before the split
/// comes out instead (with that result).  So a piece cut only by hyperplanes
/// across which its result does not change comes out whole, and the parts
/// that do come out end where the result changes or where a neighbouring
/// part was cut.  Nothing is constructed: the kept pieces are the ones the
/// splits started from.
///
/// Each split is a record waiting for its two parts; a part reports to the
/// record of the split that made it (`none` for the piece pushed down).
/// Switched off (`enabled` false), it keeps no record and every part goes
/// out as it comes.
template <class S, class R> class rejoiner {
public:
  static constexpr std::size_t none = static_cast<std::size_t>(-1);

  rejoiner(std::vector<std::pair<S, R>>& out, bool enabled) : out_(out), enabled_(enabled) {}

  /// Records the split of `piece` (a part of `parent`'s side `side`); its
  /// parts report to the returned record, the negative one as side 0.
  std::size_t split(S piece, std::size_t parent, int side) {
    if (!enabled_) return none;
    records_.push_back({std::move(piece), parent, side, {}, 0, false});
    return records_.size() - 1;
  }
  /// A part that came out whole with `result`.
  void whole(std::size_t record, int side, S piece, R result) {
    report(record, side, std::optional<std::pair<S, R>>(std::in_place, std::move(piece), std::move(result)));
  }
  /// A part that came out in several pieces (already given to `emit`).
  void broken(std::size_t record, int side) { report(record, side, std::nullopt); }
  /// A piece for the output that is no split's part.
  void emit(S piece, R result) { out_.emplace_back(std::move(piece), std::move(result)); }

private:
  struct record {
    S piece;
    std::size_t parent;
    int side;
    std::array<std::optional<std::pair<S, R>>, 2> part;
    int arrived;
    bool broken;
  };

  void report(std::size_t at, int side, std::optional<std::pair<S, R>> part) {
    while (at != none) {
      auto& r = records_[at];
      if (part) r.part[side] = std::move(part);
      else r.broken = true;
      if (++r.arrived < 2) return;
      if (!r.broken && r.part[0]->second == r.part[1]->second) {
        part.emplace(std::move(r.piece), std::move(r.part[0]->second));
      } else {
        for (auto& p : r.part)
          if (p) out_.push_back(std::move(*p));
        part.reset();
      }
      at = r.parent, side = r.side;
    }
    if (part) out_.push_back(std::move(*part));
  }

  std::vector<std::pair<S, R>>& out_;
  bool enabled_;
  std::vector<record> records_;
};

/// A piece on its way down a tree for a `rejoiner`: at node `m`, a part of
/// the split `record`'s side `side`.
template <class S> struct rejoin_work {
  S piece;
  node_id m;
  std::size_t record;
  int side;
};

/// Follows `r`, the split of `w.piece` by the hyperplane at `w.m` (not
/// coincident): two parts go on `stack` as the parts of a new record of
/// `parts`; a single part (the piece touches the hyperplane) becomes `w`'s
/// piece in the child on its side, and true is returned, to go on with it;
/// nothing left is reported to `parts` as a broken part.
template <class G, class Tree, class R, class J>
bool follow_split(Tree const& t, R& r, rejoin_work<typename G::sub_hyperplane>& w,
                  std::vector<rejoin_work<typename G::sub_hyperplane>>& stack, J& parts) {
  if (r.negative && r.positive) {
    auto k = parts.split(std::move(w.piece), w.record, w.side);
    stack.push_back({std::move(*r.negative), t.negative(w.m), k, 0});
    stack.push_back({std::move(*r.positive), t.positive(w.m), k, 1});
    return false;
  }
  if (!r.negative && !r.positive) { // nothing left of it
    parts.broken(w.record, w.side);
    return false;
  }
  w.piece = std::move(r.negative ? *r.negative : *r.positive);
  w.m = t.child(w.m, r.negative ? -1 : +1);
  return true;
}

/// The pieces of `s` (lying in a hyperplane h) as seen from the side `probe`
/// (−1, +1) of h, pushed down the subtree at `n`, with the labels they meet.
/// With `rejoin`, split parts that meet equal labels are put back together
/// (`rejoiner`): a piece whose label does not change then comes out whole,
/// as one part.
template <geometry G, class N, label L>
void push_down(tree<G, N, L> const& t, typename G::sub_hyperplane s, node_id n, int probe,
               std::vector<std::pair<typename G::sub_hyperplane, L>>& out, bool rejoin = false) {
  using S = typename G::sub_hyperplane;
  using J = rejoiner<S, L>;
  J parts(out, rejoin);
  std::vector<rejoin_work<S>> stack;
  stack.push_back({std::move(s), n, J::none, 0});
  while (!stack.empty()) {
    auto w = std::move(stack.back());
    stack.pop_back();
    for (;;) {
      if (t.is_leaf(w.m)) {
        parts.whole(w.record, w.side, std::move(w.piece), t.leaf_data(w.m));
        break;
      }
      if (int side = detail::whole_side<G>(w.piece, t.splitter(w.m))) {
        w.m = t.child(w.m, side);
        continue;
      }
      auto r = G::split(w.piece, t.splitter(w.m));
      if (r.is_coincident()) {
        w.m = t.child(w.m, probe * static_cast<int>(r.coincident));
        continue;
      }
      if (!follow_split<G>(t, r, w, stack, parts)) break;
    }
  }
}

} // namespace detail

/// The boundary of the labelling: every piece of a node's hyperplane, within
/// the node's cell, whose two sides carry different labels.
template <geometry G, class N, label L> std::vector<boundary_piece<G, L>> boundary(tree<G, N, L> const& t) {
  using S = typename G::sub_hyperplane;
  using H = typename G::hyperplane;
  std::vector<boundary_piece<G, L>> out;
  // Each node with the hyperplanes of its ancestors, oriented towards it.
  std::vector<std::pair<node_id, std::vector<H>>> stack{{t.root(), {}}};
  while (!stack.empty()) {
    auto [n, path] = std::move(stack.back());
    stack.pop_back();
    if (t.is_leaf(n)) continue;
    auto const& h = t.splitter(n);
    std::optional<S> section = G::whole(h);
    for (auto const& g : path) {
      // Wholly on one side: kept or gone without a split (no construction).
      if (int w = detail::whole_side<G>(*section, g)) {
        if (w < 0) section.reset();
        if (!section) break;
        continue;
      }
      auto r = G::split(*section, g);
      section = r.positive;
      if (!section) break;
    }
    if (section) {
      std::vector<std::pair<S, L>> below, across;
      detail::push_down(t, std::move(*section), t.negative(n), -1, below);
      for (auto& [piece, lneg] : below) {
        across.clear();
        detail::push_down(t, std::move(piece), t.positive(n), +1, across);
        for (auto& [p, lpos] : across)
          if (!(lneg == lpos)) out.push_back({std::move(p), lneg, lpos});
      }
    }
    auto neg_path = path;
    neg_path.push_back(G::opposite(h));
    path.push_back(h);
    stack.emplace_back(t.negative(n), std::move(neg_path));
    stack.emplace_back(t.positive(n), std::move(path));
  }
  return out;
}

/// The boundary of a set (`true` inside) as sub-hyperplanes with the set on
/// their negative side: the input form of `build_point_set`.
template <geometry G, class N> std::vector<typename G::sub_hyperplane> oriented_boundary(tree<G, N, bool> const& t) {
  std::vector<typename G::sub_hyperplane> out;
  for (auto& b : boundary(t)) out.push_back(b.negative ? std::move(b.piece) : G::opposite(b.piece));
  return out;
}

/// The same labelling with every interior node whose two children are leaves
/// with equal labels collapsed into one leaf, repeatedly; unreachable nodes are dropped.
template <geometry G, class N, label L> tree<G, N, L> reduce(tree<G, N, L> const& t) {
  tree<G, N, L> out;
  // Post-order: the new node of each old node, built after both children.
  struct item {
    node_id old;
    bool expanded;
  };
  std::vector<item> stack{{t.root(), false}};
  std::vector<node_id> built; // results, as a stack
  while (!stack.empty()) {
    auto [n, expanded] = stack.back();
    stack.pop_back();
    if (t.is_leaf(n)) {
      built.push_back(out.add_leaf(t.leaf_data(n)));
      continue;
    }
    if (!expanded) {
      stack.push_back({n, true});
      stack.push_back({t.positive(n), false});
      stack.push_back({t.negative(n), false});
      continue;
    }
    node_id pos = built.back();
    built.pop_back();
    node_id neg = built.back();
    built.pop_back();
    if (out.is_leaf(neg) && out.is_leaf(pos) && out.leaf_data(neg) == out.leaf_data(pos))
      built.push_back(neg);
    else
      built.push_back(out.add_interior(t.splitter(n), neg, pos, t.node_data(n)));
  }
  out.set_root(built.back());
  return out;
}

} // namespace bsp
