/// @file
/// `bsp::tree`: one binary space partitioning tree for every geometry and both
/// uses — hyperplanes at interior nodes, a payload at each interior node
/// (depth order keeps its coincident sub-hyperplanes there) and a payload at
/// each leaf (point sets keep their labels there).
#pragma once

#include "concepts/geometry.hpp"
#include "concepts/label.hpp"

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace bsp {

/// An empty payload.
struct none {
  friend bool operator==(none, none) = default;
};

/// A node of a tree: an index into one of its two arenas.  The high bit tells
/// leaves from interior nodes, so a node costs no more than an index.
class node_id {
public:
  constexpr node_id() = default;
  static constexpr node_id leaf(std::uint32_t i) { return node_id(i | leaf_bit); }
  static constexpr node_id interior(std::uint32_t i) { return node_id(i); }

  constexpr bool valid() const noexcept { return v_ != invalid; }
  constexpr bool is_leaf() const noexcept { return valid() && (v_ & leaf_bit) != 0; }
  constexpr std::uint32_t index() const noexcept { return v_ & ~leaf_bit; }
  friend constexpr bool operator==(node_id, node_id) = default;

private:
  static constexpr std::uint32_t leaf_bit = 0x80000000u, invalid = 0xffffffffu;
  constexpr explicit node_id(std::uint32_t v) : v_(v) {}
  std::uint32_t v_ = invalid;
};

/// Sizes of a tree.
struct tree_statistics {
  std::size_t interior_nodes = 0; ///< reachable interior nodes
  std::size_t leaves = 0;         ///< reachable leaves
  std::size_t depth = 0;          ///< longest root-to-leaf path, in edges
  std::size_t bytes = 0;          ///< arena storage (not counting memory the payloads own)
};

/// A BSP tree over the geometry `G`.  Nodes live in two contiguous arenas
/// (interior nodes, leaves) addressed by `node_id`; copying a tree copies
/// the arenas.  Nodes are added bottom-up (`add_leaf`, `add_interior`) or
/// hung under a parent (`attach`); a tree has one root.
template <geometry G, tree_payload NodeData = none, tree_payload LeafData = none> class tree {
public:
  using geometry_type = G;
  using hyperplane = typename G::hyperplane;
  using node_data_type = NodeData;
  using leaf_data_type = LeafData;

  /// A tree of one leaf: the whole space with one payload.
  explicit tree(LeafData root = {}) { root_ = add_leaf(std::move(root)); }

  node_id root() const noexcept { return root_; }
  void set_root(node_id n) noexcept { root_ = n; }

  /// @name Nodes
  /// @{
  bool is_leaf(node_id n) const noexcept { return n.is_leaf(); }
  hyperplane const& splitter(node_id n) const { return in(n).h; }
  node_id negative(node_id n) const { return in(n).neg; }
  node_id positive(node_id n) const { return in(n).pos; }
  /// The child on the given side (−1: negative, +1: positive).
  node_id child(node_id n, int side) const { return side < 0 ? in(n).neg : in(n).pos; }
  NodeData& node_data(node_id n) { return in(n).data; }
  NodeData const& node_data(node_id n) const { return in(n).data; }
  LeafData& leaf_data(node_id n) { return leaves_[leaf_index(n)].data; }
  LeafData const& leaf_data(node_id n) const { return leaves_[leaf_index(n)].data; }
  /// How many interior nodes were added, reachable or not: each of
  /// `node_id::interior(0)` to `node_id::interior(interior_count() - 1)`.
  std::size_t interior_count() const noexcept { return interiors_.size(); }
  /// @}

  /// @name Building
  /// @{
  node_id add_leaf(LeafData d = {}) {
    leaves_.push_back({std::move(d)});
    return node_id::leaf(static_cast<std::uint32_t>(leaves_.size() - 1));
  }
  node_id add_interior(hyperplane h, node_id neg, node_id pos, NodeData d = {}) {
    interiors_.push_back({std::move(h), neg, pos, std::move(d)});
    return node_id::interior(static_cast<std::uint32_t>(interiors_.size() - 1));
  }
  void set_children(node_id n, node_id neg, node_id pos) {
    in(n).neg = neg;
    in(n).pos = pos;
  }
  /// Makes `child` the child of `parent` on `side` (−1 or +1), or the root when `parent` is invalid.
  void attach(node_id parent, int side, node_id child) {
    if (!parent.valid())
      root_ = child;
    else
      (side < 0 ? in(parent).neg : in(parent).pos) = child;
  }
  /// @}

  /// Node and leaf counts, depth and storage of the part reachable from the root.
  tree_statistics statistics() const {
    tree_statistics s;
    std::vector<std::pair<node_id, std::size_t>> stack{{root_, 0}};
    while (!stack.empty()) {
      auto [n, d] = stack.back();
      stack.pop_back();
      s.depth = std::max(s.depth, d);
      if (n.is_leaf()) {
        ++s.leaves;
        continue;
      }
      ++s.interior_nodes;
      stack.push_back({negative(n), d + 1});
      stack.push_back({positive(n), d + 1});
    }
    s.bytes = interiors_.capacity() * sizeof(interior) + leaves_.capacity() * sizeof(leaf) + sizeof(*this);
    return s;
  }

  /// Number of nodes in the arenas, reachable or not.
  std::size_t arena_size() const noexcept { return interiors_.size() + leaves_.size(); }

private:
  struct interior {
    hyperplane h;
    node_id neg, pos;
    NodeData data;
  };
  interior& in(node_id n) {
    assert(n.valid() && !n.is_leaf());
    return interiors_[n.index()];
  }
  interior const& in(node_id n) const {
    assert(n.valid() && !n.is_leaf());
    return interiors_[n.index()];
  }
  static std::size_t leaf_index(node_id n) {
    assert(n.valid() && n.is_leaf());
    return n.index();
  }

  struct leaf {
    LeafData data; // wrapped: a std::vector<bool> would hand out proxies
  };
  std::vector<interior> interiors_;
  std::vector<leaf> leaves_;
  node_id root_;
};

/// Visits every node reachable from `n` in pre-order with its depth: `f(node, depth)`.
template <class Tree, class F> void for_each_node(Tree const& t, node_id n, F&& f) {
  std::vector<std::pair<node_id, std::size_t>> stack{{n, 0}};
  while (!stack.empty()) {
    auto [m, d] = stack.back();
    stack.pop_back();
    f(m, d);
    if (!t.is_leaf(m)) {
      stack.push_back({t.positive(m), d + 1});
      stack.push_back({t.negative(m), d + 1});
    }
  }
}

} // namespace bsp
