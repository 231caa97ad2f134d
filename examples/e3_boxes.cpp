// E3: two boxes, one with decimal heights, combined exactly.  B overlaps A
// around its vertical edge x = y = 2, so A \ B is a box with a notch cut
// out of that edge — not convex, yet its volume is exact.
#include <bsp/bsp.hpp>
#include <bsp/print.hpp>
#include <geometry/e3.hpp>

#include <array>
#include <iostream>
#include <sstream>
#include <vector>

using namespace geometry;
using Q = rational;
using K = e3::exact_kernel;
using P = e3::point<Q>;

namespace {
/// The closed mesh of the box [lo, hi]: six quadrilaterals, counter-clockwise
/// seen from outside, so that the box is on the negative side of each face.
std::vector<e3::sub_hyperplane<Q>> boundary_of(P const& lo, P const& hi) {
  auto v = [&](int i, int j, int k) { return P(i ? hi.x() : lo.x(), j ? hi.y() : lo.y(), k ? hi.z() : lo.z()); };
  std::vector<std::array<P, 4>> faces{
      {v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0)}, {v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1)},
      {v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1)}, {v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0)},
      {v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0)}, {v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1)}};
  std::vector<e3::sub_hyperplane<Q>> out;
  for (auto const& f : faces) out.push_back(e3::convex_polygon<Q>({f[0], f[1], f[2], f[3]}));
  return out;
}
/// A node's plane as the inequality that holds in its positive child.
std::string equation(e3::hyperplane<Q> const& h) {
  std::ostringstream s;
  s << h.n[0] << "x + " << h.n[1] << "y + " << h.n[2] << "z + " << h.n[3] << " > 0";
  return s.str();
}
char const* in_out(bool in) { return in ? "in" : "out"; }
} // namespace

int main() {
  Q half = parse_number<Q>("0.5"), one_and_a_half = parse_number<Q>("1.5");
  auto A = bsp::build_point_set<K>(boundary_of(P(0, 0, 0), P(2, 2, 2)));
  auto B = bsp::build_point_set<K>(boundary_of(P(1, 1, half), P(3, 3, one_and_a_half)));
  auto U = bsp::set_union(A, B);
  auto D = bsp::set_difference(A, B);

  // By hand: |A| = 2·2·2 = 8, |B| = 2·2·1 = 4, A ∩ B = [1, 2] × [1, 2] × [0.5, 1.5]
  // of volume 1.  So |A ∪ B| = 8 + 4 − 1 = 11 and |A \ B| = 8 − 1 = 7.
  auto u = bsp::measure(U, true), d = bsp::measure(D, true);
  std::cout << "|A u B| = " << (u ? u->str() : "unbounded") << ", |A \\ B| = " << (d ? d->str() : "unbounded") << '\n';
  if (!u || *u != 11 || !d || *d != 7) {
    std::cerr << "e3_boxes: wrong volume, expected 11 and 7\n";
    return 1;
  }

  // A's six faces come first (merging keeps A's structure), then B's where they cut A.
  std::cout << "tree of A \\ B:\n";
  bsp::print(std::cout, D, equation, in_out);
  return 0;
}
