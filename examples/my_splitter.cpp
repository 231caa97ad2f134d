// My own splitter policy: the longest segment first, a bsp::choosing_policy written
// outside the library, on a crown-shaped polygon in E2 whose ring starts with short
// edges.  The tree changes with the policy, the set does not: the exact area is the
// same as with bsp::input_order and as the shoelace formula gives.
#include <bsp/bsp.hpp>
#include <geometry/e2.hpp>

#include <cstddef>
#include <iostream>
#include <vector>

using namespace geometry;
using Q = rational;
using K = e2::exact_kernel;
using P = e2::point<Q>;

namespace {
/// The bounded segment of greatest squared length (exact), the first of equals; the first piece when there is none.
struct longest_first {
  template <class G, class Item, class Piece> std::size_t choose(std::vector<Item> const& items, Piece&& piece) {
    std::size_t best = 0;
    Q best_length(0);
    for (std::size_t i = 0; i < items.size(); ++i)
      if (auto e = e2::endpoints(piece(items[i]))) {
        Q dx = e->second.x() - e->first.x(), dy = e->second.y() - e->first.y(), length = dx * dx + dy * dy;
        if (length > best_length) best = i, best_length = length;
      }
    return best;
  }
};
static_assert(bsp::splitting_policy<longest_first, K>);

/// The boundary of a counter-clockwise ring: each edge reversed, the polygon on its negative side.
std::vector<e2::sub_hyperplane<Q>> boundary_of(std::vector<P> const& ring) {
  std::vector<e2::sub_hyperplane<Q>> out;
  for (std::size_t i = 0; i < ring.size(); ++i) out.push_back(e2::segment(ring[(i + 1) % ring.size()], ring[i]));
  return out;
}
} // namespace

int main() {
  std::vector<P> crown{P(7, 2), P(5, 6), P(4, 2), P(2, 5), P(1, 1), P(0, 8), P(0, 0), P(9, 0), P(9, 7)};
  Q area(0); // by the shoelace formula
  for (std::size_t i = 0, n = crown.size(); i < n; ++i)
    area += (crown[i].x() * crown[(i + 1) % n].y() - crown[i].y() * crown[(i + 1) % n].x()) / 2;
  auto by_input = bsp::build_point_set<K>(boundary_of(crown));
  auto by_length = bsp::build_point_set<K>(boundary_of(crown), true, false, longest_first{});
  auto si = by_input.statistics(), sl = by_length.statistics();
  // An unbounded set would have the area -1.
  auto ai = bsp::measure(by_input, true).value_or(Q(-1)), al = bsp::measure(by_length, true).value_or(Q(-1));
  std::cout << "input_order:   " << si.interior_nodes << " nodes, depth " << si.depth << ", area " << ai.str() << '\n'
            << "longest_first: " << sl.interior_nodes << " nodes, depth " << sl.depth << ", area " << al.str() << '\n'
            << "shoelace:                          area " << area.str() << '\n';
  if (ai != area || al != area) {
    std::cerr << "my_splitter: a tree's area differs from the shoelace area\n";
    return 1;
  }
  return 0;
}
