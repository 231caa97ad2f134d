// S1: arcs of the circle of directions.  Directions are exact (unnormalised
// integer vectors), so the arcs' ends are decided exactly; lengths are angles,
// not rational, and come out in double, checked to 1e-12.
#include <bsp/bsp.hpp>
#include <bsp/print.hpp>
#include <geometry/s1.hpp>

#include <cmath>
#include <iostream>
#include <numbers>
#include <sstream>
#include <utility>
#include <vector>

using namespace geometry;
using Q = rational;
using K = s1::exact_kernel;
using D = s1::point<Q>;

namespace {
D dir(int x, int y) { return D(std::array<Q, 2>{Q(x), Q(y)}); }

/// The boundary of the arc from `a` counter-clockwise to `b` (less than a half
/// circle): the point `a` of the hyperplane starting at `a`, reversed so the
/// arc is on its negative side, and the point `b` of the hyperplane starting at `b`.
std::vector<s1::sub_hyperplane<Q>> boundary_of(D const& a, D const& b) {
  return {s1::opposite(s1::sub_hyperplane<Q>{s1::hyperplane_at(a), true, false}),
          s1::sub_hyperplane<Q>{s1::hyperplane_at(b), true, false}};
}
/// A node's pair of directions ±(n₁, −n₀) as the open half circle of its
/// positive child: counter-clockwise from (n₁, −n₀).
std::string positive_half(s1::hyperplane<Q> const& h) {
  std::ostringstream s;
  s << "half circle from (" << h.n[1] << ", " << -h.n[0] << ")";
  return s.str();
}
char const* in_out(bool in) { return in ? "in" : "out"; }
} // namespace

int main() {
  constexpr double pi = std::numbers::pi;
  auto A = bsp::build_point_set<K>(boundary_of(dir(1, 0), dir(0, 1)));  // 0° to 90°
  auto B = bsp::build_point_set<K>(boundary_of(dir(1, 1), dir(-1, 0))); // 45° to 180°
  auto U = bsp::set_union(A, B);
  auto X = bsp::set_symmetric_difference(A, B);

  // By hand: A ∪ B runs from 0° to 180°: π.  A △ B is [0°, 45°] ∪ [90°, 180°]:
  // π/4 + π/2 = 3π/4.  (A's start and B's end lie on one hyperplane, y = 0.)
  double u = bsp::measure(U, true), x = bsp::measure(X, true);
  std::cout.precision(17);
  std::cout << "|A u B| = " << u << " (pi), |A ^ B| = " << x << " (3 pi/4)\n";
  if (std::abs(u - pi) > 1e-12 || std::abs(x - 3 * pi / 4) > 1e-12) {
    std::cerr << "s1_arcs: wrong length, expected pi and 3 pi/4\n";
    return 1;
  }

  std::cout << "tree of A ^ B:\n";
  bsp::print(std::cout, X, positive_half, in_out);
  return 0;
}
