// Shadows: a triangle floats over a floor under a lamp and under the sun.
// The floor's pieces that no light reaches are the triangle's shadow: its
// area is exactly that of the triangle projected from the lamp (scaled by
// 9 / (9 − 3) about the lamp's foot), and, under the sun, of its translate.
#include <svm/shadow.hpp>

#include <cstdlib>
#include <iostream>
#include <vector>

using namespace geometry;
using Q = rational;
using P = e3::point<Q>;

namespace {
/// The area, in the floor's plane, of the floor's pieces that no light reaches.
Q shadow_on_floor(svm::shadows<Q> const& sh) {
  Q area(0);
  for (auto const& p : sh.pieces)
    if (p.polygon == 0 && p.lights == 0) area += *e3::projected_area(p.shape, 2);
  return area;
}
} // namespace

int main() {
  std::vector<svm::polygon<Q>> scene{
      {{P(-50, -50, 0), P(50, -50, 0), P(50, 50, 0), P(-50, 50, 0)}, 0}, // the floor, facing up
      {{P(1, 2, 3), P(4, 1, 3), P(2, 5, 3)}, 1}};                       // a triangle at height 3, facing up
  Q triangle = *e3::projected_area(e3::convex_polygon<Q>(scene[1].vertices), 2);

  auto lamp = svm::compute_shadows<Q>(scene, {P(0, 0, 9)});
  auto sun = svm::compute_shadows<Q>(scene, {svm::light_source<Q>::sun({Q(1), Q(-2), Q(5)})});
  Q scale = Q(9) / Q(6);
  std::cout << "triangle " << triangle << ", its shadow under the lamp " << shadow_on_floor(lamp) << " (expected "
            << triangle * scale * scale << "), under the sun " << shadow_on_floor(sun) << "\n";
  bool ok = shadow_on_floor(lamp) == triangle * scale * scale && shadow_on_floor(sun) == triangle;
  // The triangle itself faces both lights and nothing is above it: lit whole.
  for (auto const& sh : {lamp, sun})
    for (auto const& p : sh.pieces)
      if (p.polygon == 1) ok = ok && p.lights == 1;
  std::cout << (ok ? "ok" : "WRONG") << "\n";
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
