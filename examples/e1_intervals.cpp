// E1: unions of intervals with decimal ends, combined exactly.  No double is
// exactly 0.1, 0.3, …; read from text as rationals they are, so the lengths
// below come out as exactly 4/5 and 1/5 and can be compared with ==.
#include <bsp/bsp.hpp>
#include <bsp/print.hpp>
#include <geometry/e1.hpp>

#include <iostream>
#include <string>
#include <utility>
#include <vector>

using namespace geometry;
using Q = rational;
using K = e1::exact_kernel;

namespace {
/// The boundary of disjoint intervals [a, b]: at each end the oriented point
/// whose negative side holds the interval (an outward normal, as
/// bsp::build_point_set wants it).
std::vector<e1::sub_hyperplane<Q>> boundary_of(std::vector<std::pair<char const*, char const*>> const& intervals) {
  std::vector<e1::sub_hyperplane<Q>> out;
  for (auto const& [a, b] : intervals) {
    out.push_back({e1::hyperplane_at(parse_number<Q>(a), false)}); // positive below a
    out.push_back({e1::hyperplane_at(parse_number<Q>(b), true)});  // positive above b
  }
  return out;
}

/// A node's oriented point n₀·x + n₁ = 0 as the side its positive child holds.
std::string positive_side(e1::hyperplane<Q> const& h) {
  Q at = -h.n[1] / h.n[0];
  return (h.n[0] > 0 ? "x > " : "x < ") + at.str();
}
} // namespace

int main() {
  auto A = bsp::build_point_set<K>(boundary_of({{"0.1", "0.3"}, {"0.6", "0.9"}}));
  auto B = bsp::build_point_set<K>(boundary_of({{"0.2", "0.7"}}));
  auto U = bsp::set_union(A, B);
  auto I = bsp::set_intersection(A, B);

  // By hand: A ∪ B = [0.1, 0.9], length 0.8;
  //          A ∩ B = [0.2, 0.3] ∪ [0.6, 0.7], length 0.1 + 0.1 = 0.2.
  auto u = bsp::measure(U, true), i = bsp::measure(I, true); // empty optional: an unbounded set
  std::cout << "|A u B| = " << (u ? u->str() : "unbounded") << '\n'
            << "|A n B| = " << (i ? i->str() : "unbounded") << '\n';
  if (!u || *u != parse_number<Q>("0.8") || !i || *i != parse_number<Q>("0.2")) {
    std::cerr << "e1_intervals: wrong length, expected 4/5 and 1/5\n";
    return 1;
  }

  // The reduced tree of A ∩ B: each node cuts the line at one end.
  std::cout << "tree of A n B:\n";
  bsp::print(std::cout, I, positive_side, [](bool in) { return in ? "in" : "out"; });
  return 0;
}
