// libFuzzer target for the visibility map.  The input's bytes make a tiny
// scene: the eye and up to 8 triangles or boxes, every coordinate an integer
// in [−4, 4], so that shared edges, coplanar and crossing polygons, eyes on
// planes and on edges' lines are the usual case.  The map is built exact,
// unsimplified and simplified, and checked on every input:
//   * its invariants (`svm::check_invariants`: twins, cycles, minor arcs,
//     Euler's formula), and face areas summing to 4π;
//   * `svm::locate` against the tests' exact ray caster (128-bit integers on
//     the input triangles) in the directions of every vertex, of every
//     edge's midpoint and of 16 directions from the input, wherever the ray
//     caster's answer is determined.
// Any failed check aborts, with the reason on standard error.
#include "input.hpp"

#include <svm/build.hpp>
#include <svm/dcel.hpp>
#include <svm/query.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

using namespace test::ray;
using Q = geometry::rational;

namespace {

[[noreturn]] void fail(char const* what, long a = 0, long b = 0) {
  fuzz::fail("fuzz_map", std::string(what) + " (" + std::to_string(a) + ", " + std::to_string(b) + ")");
}

void check(std::vector<triangle> const& tris, ivec eye, std::vector<ivec> const& directions) {
  auto polys = polygons_of(tris);
  geometry::e3::point<Q> e{Q(eye[0]), Q(eye[1]), Q(eye[2])};
  for (bool simplify : {false, true}) {
    auto vm = svm::build<Q>(polys, e, {.simplify = simplify});
    auto problems = svm::check_invariants(vm.map);
    if (!problems.empty()) {
      fuzz::fail("fuzz_map", problems.front());
    }
    double sum = 0;
    for (double a : svm::face_areas(vm.map)) {
      if (a < -1e-9) fail("a face of negative area");
      sum += a;
    }
    if (std::abs(sum - 4 * std::numbers::pi) > 1e-9 * 4 * std::numbers::pi) fail("face areas do not sum to 4 pi");
    for (auto const& d : directions) {
      if (d == ivec{0, 0, 0}) continue;
      long truth = cast(tris, eye, d);
      if (truth == ambiguous) continue;
      long got = svm::locate(vm, geometry::s2::point<Q>(std::array<Q, 3>{Q(d[0]), Q(d[1]), Q(d[2])}));
      if (got != truth) fail("locate disagrees with the ray caster (map, ray caster)", got, truth);
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(std::uint8_t const* data, std::size_t size) {
  fuzz::input in(data, size);
  auto [eye, tris] = fuzz::read_scene(in);
  if (tris.empty()) return 0;
  std::vector<ivec> directions;
  for (auto const& t : tris)
    for (std::size_t k = 0; k < 3; ++k) {
      auto const &a = t.v[k], &b = t.v[(k + 1) % 3];
      directions.push_back(sub(a, eye));
      directions.push_back({a[0] + b[0] - 2 * eye[0], a[1] + b[1] - 2 * eye[1], a[2] + b[2] - 2 * eye[2]});
    }
  for (int k = 0; k < 16; ++k) directions.push_back({in.in(-8, 8), in.in(-8, 8), in.in(-8, 8)});
  check(tris, eye, directions);
  return 0;
}
