/// @file
/// A text picture of a tree, one node a line, indented by depth — for
/// teaching and debugging.
#pragma once

#include "tree.hpp"

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace bsp {

/// Prints `t`: interior nodes as `hyperplane(h)`, leaves as `leaf(data)`,
/// each child under its parent with `-` (negative side) or `+` (positive side).
template <geometry G, class N, class L, class FH, class FL>
void print(std::ostream& out, tree<G, N, L> const& t, FH&& hyperplane, FL&& leaf) {
  struct item {
    node_id n;
    std::size_t depth;
    char side;
  };
  std::vector<item> stack{{t.root(), 0, ' '}};
  while (!stack.empty()) {
    auto [n, d, s] = stack.back();
    stack.pop_back();
    out << std::string(2 * d, ' ') << s << ' ';
    if (t.is_leaf(n)) {
      out << "leaf " << leaf(t.leaf_data(n)) << '\n';
      continue;
    }
    out << "node " << hyperplane(t.splitter(n)) << '\n';
    stack.push_back({t.positive(n), d + 1, '+'});
    stack.push_back({t.negative(n), d + 1, '-'});
  }
}

} // namespace bsp
