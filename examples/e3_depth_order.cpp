// E3 depth order: three stacked triangles, two of them slightly tilted, given
// out of order.  The tree is built once; any eye then gets them front to back
// by one traversal, with no sorting — the order changes with the eye.
#include <bsp/bsp.hpp>
#include <bsp/print.hpp>
#include <geometry/e3.hpp>

#include <iostream>
#include <sstream>
#include <vector>

using namespace geometry;
using Q = rational;
using K = e3::exact_kernel;
using P = e3::point<Q>;

namespace {
/// The ids of the fragments seen from `eye`, front to back.
std::vector<std::size_t> front_to_back(bsp::depth_order_tree<K> const& t, P const& eye) {
  std::vector<std::size_t> ids;
  bsp::for_each_front_to_back(t, eye, [&](bsp::fragment<K> const& f) { ids.push_back(f.id); });
  return ids;
}
/// A node's plane as the inequality that holds in its positive child.
std::string equation(e3::hyperplane<Q> const& h) {
  std::ostringstream s;
  s << h.n[0] << "x + " << h.n[1] << "y + " << h.n[2] << "z + " << h.n[3] << " > 0";
  return s.str();
}
char const* empty(bsp::none) { return "empty"; }
} // namespace

int main() {
  // All three over the same (x, y) triangle (−1, −1), (1, −1), (0, 1), at heights
  // z = 1 (id 0, the middle), z = x/10 (id 1, the bottom), z = 2 − y/10 (id 2, the top).
  // The tilted planes meet z = 1 and each other only at x = 10, y = 10 or x + y = 20,
  // far outside the triangles, so no triangle is split and each id is listed once.
  Q tenth = parse_number<Q>("0.1");
  auto tri = [](auto z) { return e3::convex_polygon<Q>({P(-1, -1, z(-1, -1)), P(1, -1, z(1, -1)), P(0, 1, z(0, 1))}); };
  bsp::fragment_list<K> input{{tri([](Q, Q) { return Q(1); }), 0},
                              {tri([&](Q x, Q) { return Q(x * tenth); }), 1},
                              {tri([&](Q, Q y) { return Q(2 - y * tenth); }), 2}};
  auto tree = bsp::build_depth_order<K>(input);

  // From above the top triangle comes first; from below the bottom one.
  auto above = front_to_back(tree, P(0, 0, 10)), below = front_to_back(tree, P(0, 0, -10));
  auto show = [](char const* from, std::vector<std::size_t> const& ids) {
    std::cout << "front to back from " << from << ':';
    for (auto id : ids) std::cout << ' ' << id;
    std::cout << '\n';
  };
  show("(0, 0, 10)", above);
  show("(0, 0, -10)", below);
  if (above != std::vector<std::size_t>{2, 0, 1} || below != std::vector<std::size_t>{1, 0, 2}) {
    std::cerr << "e3_depth_order: wrong order, expected 2 0 1 and 1 0 2\n";
    return 1;
  }

  // The root is the first input's plane (the input order decides); the other
  // two triangles lie one on each side of it.
  std::cout << "tree:\n";
  bsp::print(std::cout, tree, equation, empty);
  return 0;
}
