/// @file
/// Coverage trees: point-set trees whose leaves are *covered* or *free*, for
/// front-to-back visibility.  Convex pieces arrive front to back and descend
/// the tree (`insert`); a part that reaches a covered leaf is hidden and
/// dropped there, a part that reaches a free leaf is visible, and the caller
/// hangs the piece's bounds under that leaf (`split`) and covers the cell
/// inside (`cover`).  Two covered siblings collapse into one covered leaf, so
/// the tree follows the boundary of what is covered, not everything that was
/// ever visible: later pieces are not cut along edges that lie inside the
/// covered region.
#pragma once

#include "point_set.hpp"
#include "tree.hpp"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace bsp {

/// Where a piece goes at an interior node (`coverage_tree::insert`): wholly
/// to one side (`side` −1 or +1, the piece itself passed on), or split
/// (`side` 0) into the parts on either side, one of which may be empty.
template <class Piece> struct routed {
  int side = 0;
  std::optional<Piece> negative, positive;
};

/// A point-set tree over `G` whose leaves are free, with a payload `L` (a
/// face handle, say), or covered.  Interior nodes know their parents, so that
/// covering a leaf can collapse covered siblings upwards.
template <geometry G, tree_payload L> class coverage_tree {
public:
  using tree_type = tree<G, none, L>;
  using hyperplane = typename G::hyperplane;

  /// Where a node hangs: its parent (invalid for the root) and the side (−1, +1).
  struct place {
    node_id parent;
    int side = 0;
  };

  /// One free leaf, the whole space, with payload `whole`.  With `collapse`
  /// false, covered leaves keep their place and payload (the tree then
  /// partitions the space into every cell ever split, as the paper's V does).
  explicit coverage_tree(L whole = {}, bool collapse = true) : tree_(std::move(whole)), collapse_(collapse) {
    covered_.push_back(0);
  }

  tree_type const& as_tree() const noexcept { return tree_; }
  node_id root() const noexcept { return tree_.root(); }
  bool is_covered(node_id leaf) const { return covered_[leaf.index()] != 0; }

  /// Replaces the free leaf at `at` by an interior node on `h` whose children
  /// are new free leaves with payloads `neg` and `pos`; returns the node.
  node_id split(place at, hyperplane h, L neg, L pos) {
    node_id n = tree_.add_interior(std::move(h), add_leaf(std::move(neg)), add_leaf(std::move(pos)));
    if (up_.size() <= n.index()) up_.resize(n.index() + 1);
    up_[n.index()] = at;
    tree_.attach(at.parent, at.side, n);
    ++interior_;
    if (interior_ > peak_) peak_ = interior_;
    return n;
  }

  /// Marks the leaf `leaf` hanging at `at` covered; while its sibling is a
  /// covered leaf too, their parent is replaced by the one covered leaf.
  void cover(place at, node_id leaf) {
    covered_[leaf.index()] = 1;
    if (!collapse_) return;
    while (at.parent.valid()) {
      node_id sibling = tree_.child(at.parent, -at.side);
      if (!tree_.is_leaf(sibling) || !is_covered(sibling)) break;
      place up = up_[at.parent.index()];
      tree_.attach(up.parent, up.side, leaf);
      --interior_;
      at = up;
    }
  }

  /// Inserts the convex `piece`: from the root, `route(piece, node)` sends it
  /// down each interior node it reaches (a `bsp::routed`); at each free leaf
  /// it reaches, `visit(part, leaf, place)` is called (it may `split` that
  /// leaf and `cover` a leaf hanging there).  Parts on a node's positive side
  /// are visited before those on its negative side.  Returns how many parts
  /// reached covered leaves.
  template <class Piece, class Route, class Visit> std::size_t insert(Piece piece, Route&& route, Visit&& visit) {
    return insert(std::move(piece), route, visit, [](Piece&&) {});
  }

  /// The same, calling `hide(part)` for each part that reaches a covered leaf.
  template <class Piece, class Route, class Visit, class Hide>
  std::size_t insert(Piece piece, Route&& route, Visit&& visit, Hide&& hide) {
    struct work {
      node_id n;
      place at;
      Piece p;
    };
    std::vector<work> stack;
    std::size_t hidden = 0;
    stack.push_back({root(), {}, std::move(piece)});
    while (!stack.empty()) {
      work w = std::move(stack.back());
      stack.pop_back();
      if (!tree_.is_leaf(w.n)) {
        routed<Piece> r = route(w.p, w.n);
        if (r.side != 0) {
          stack.push_back({tree_.child(w.n, r.side), {w.n, r.side}, std::move(w.p)});
          continue;
        }
        if (r.negative) stack.push_back({tree_.negative(w.n), {w.n, -1}, std::move(*r.negative)});
        if (r.positive) stack.push_back({tree_.positive(w.n), {w.n, +1}, std::move(*r.positive)});
        continue;
      }
      if (is_covered(w.n)) {
        ++hidden;
        hide(std::move(w.p));
        continue;
      }
      visit(std::move(w.p), w.n, w.at);
    }
    return hidden;
  }

  /// Inserts `piece` as `insert` does, and reports it cut into as few parts
  /// as the tree allows: `part(p, visible)` for each maximal part of `piece`
  /// that is wholly visible or wholly hidden, where the tree split it at a
  /// node whose parts all turned out alike it is reported unsplit there.
  /// (The parts that `visit` and `hide` see are the tree's cells, many more
  /// where the tree is fine.)  Recursive, to the depth of the tree.  Returns
  /// the number of hidden cells.
  template <class Piece, class Route, class Visit, class Part>
  std::size_t insert_merged(Piece piece, Route&& route, Visit&& visit, Part&& part) {
    std::size_t hidden = 0;
    auto r = merged(root(), place{}, std::move(piece), route, visit, part, hidden);
    if (r.state != 0) part(std::move(*r.piece), r.state > 0);
    return hidden;
  }

  /// Calls `f(leaf, place)` for every leaf reachable from the root.
  template <class F> void for_each_leaf(F&& f) const {
    std::vector<std::pair<node_id, place>> stack{{root(), place{}}};
    while (!stack.empty()) {
      auto [n, at] = stack.back();
      stack.pop_back();
      if (tree_.is_leaf(n)) {
        f(n, at);
        continue;
      }
      stack.push_back({tree_.negative(n), {n, -1}});
      stack.push_back({tree_.positive(n), {n, +1}});
    }
  }

  /// Interior nodes reachable from the root now, and the most there ever were.
  std::size_t interior_nodes() const noexcept { return interior_; }
  std::size_t peak_interior_nodes() const noexcept { return peak_; }

  /// Rebuilds the tree from the boundary of the covered region: Thibault and
  /// Naylor's build in the order `policy` chooses, then `bsp::reduce`.  The
  /// covered set stays the same; the cuts that earlier insertions left
  /// through the free space and through the covered region are gone.  Every
  /// leaf's payload becomes `L{}`, so this is for trees whose free leaves
  /// carry nothing that the caller still needs.
  template <class Policy> void rebuild(Policy policy) {
    point_set<G, bool> labelled(false);
    copy(tree_, labelled, [&](node_id leaf) { return is_covered(leaf); });
    labelled = reduce(labelled);
    if (!labelled.is_leaf(labelled.root()))
      labelled = reduce(build_point_set<G, bool>(oriented_boundary(labelled), true, false, std::move(policy)));
    tree_ = tree_type(L{});
    covered_.assign(1, 0);
    up_.clear();
    interior_ = 0;
    // Top-down, each node hung at its place.
    std::vector<std::pair<node_id, place>> stack{{labelled.root(), place{}}};
    while (!stack.empty()) {
      auto [n, at] = stack.back();
      stack.pop_back();
      if (labelled.is_leaf(n)) {
        node_id leaf = add_leaf(L{});
        covered_[leaf.index()] = labelled.leaf_data(n) ? 1 : 0;
        tree_.attach(at.parent, at.side, leaf);
        continue;
      }
      node_id m = tree_.add_interior(labelled.splitter(n), node_id{}, node_id{});
      if (up_.size() <= m.index()) up_.resize(m.index() + 1);
      up_[m.index()] = at;
      tree_.attach(at.parent, at.side, m);
      ++interior_;
      stack.push_back({labelled.negative(n), {m, -1}});
      stack.push_back({labelled.positive(n), {m, +1}});
    }
    if (interior_ > peak_) peak_ = interior_;
  }

  /// The tree, leaving this one empty.
  tree_type release() && { return std::move(tree_); }

private:
  /// What `merged` leaves to its caller: a part wholly visible (+1) or
  /// wholly hidden (−1), not yet reported, or 0 when its parts are.
  template <class Piece> struct pending {
    int state = 0;
    std::optional<Piece> piece;
  };

  template <class Piece, class Route, class Visit, class Part>
  pending<Piece> merged(node_id n, place at, Piece p, Route& route, Visit& visit, Part& part, std::size_t& hidden) {
    if (tree_.is_leaf(n)) {
      if (is_covered(n)) {
        ++hidden;
        return {-1, std::move(p)};
      }
      Piece kept = p;
      visit(std::move(p), n, at);
      return {+1, std::move(kept)};
    }
    routed<Piece> r = route(p, n);
    if (r.side != 0) return merged(tree_.child(n, r.side), {n, r.side}, std::move(p), route, visit, part, hidden);
    pending<Piece> pos, neg;
    if (r.positive) pos = merged(tree_.positive(n), {n, +1}, std::move(*r.positive), route, visit, part, hidden);
    if (r.negative) neg = merged(tree_.negative(n), {n, -1}, std::move(*r.negative), route, visit, part, hidden);
    // Alike on both sides (or one side empty): the piece whole.
    bool alike = (r.positive ? pos.state : neg.state) != 0 && (!r.positive || !r.negative || pos.state == neg.state);
    if (alike) return {r.positive ? pos.state : neg.state, std::move(p)};
    for (auto* q : {&pos, &neg})
      if (q->state != 0) part(std::move(*q->piece), q->state > 0);
    return {};
  }

  /// Copies the shape of `from` into the empty tree `to`, leaf labels from `label(leaf)`.
  template <class From, class To, class Label> static void copy(From const& from, To& to, Label&& label) {
    std::vector<std::pair<node_id, place>> stack{{from.root(), place{}}};
    while (!stack.empty()) {
      auto [n, at] = stack.back();
      stack.pop_back();
      if (from.is_leaf(n)) {
        to.attach(at.parent, at.side, to.add_leaf(label(n)));
        continue;
      }
      node_id m = to.add_interior(from.splitter(n), node_id{}, node_id{});
      to.attach(at.parent, at.side, m);
      stack.push_back({from.negative(n), {m, -1}});
      stack.push_back({from.positive(n), {m, +1}});
    }
  }

  node_id add_leaf(L d) {
    node_id n = tree_.add_leaf(std::move(d));
    covered_.push_back(0);
    return n;
  }

  tree_type tree_;
  bool collapse_;
  std::vector<char> covered_; // by leaf index
  std::vector<place> up_;     // by interior index
  std::size_t interior_ = 0, peak_ = 0;
};

} // namespace bsp
