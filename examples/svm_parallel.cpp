// A parallel view, exactly: a unit cube in front of a square, seen along
// (1, 1, 3) from the point at infinity.  The projective map of
// svm::view_from_infinity makes that point finite; the visibility map from
// it is the parallel view's.  The cube shows the three faces that face the
// viewer; the square shows around it.
#include <svm/parallel.hpp>
#include <svm/query.hpp>
#include <svm/scenes.hpp>

#include <cstdlib>
#include <iostream>
#include <set>
#include <vector>

using namespace geometry;
using Q = rational;
using P = e3::point<Q>;

int main() {
  svm::scenes::scene s;
  svm::scenes::add_box(s, P(0, 0, 2), P(1, 1, 3)); // faces 0 (z = 2) to 5, outward
  s.polygons.push_back({{P(-4, -4, 5), P(-4, 4, 5), P(4, 4, 5), P(4, -4, 5)}, 6}); // a square behind, facing -z
  std::array<Q, 3> along{Q(1), Q(1), Q(3)};
  svm::view_from_infinity<Q> view(s.polygons, {-along[0], -along[1], -along[2]}, P(Q(1, 2), Q(1, 2), Q(5, 2)));
  auto map = svm::build<Q>(view.image(s.polygons), view.eye());

  std::set<std::int64_t> seen;
  for (auto const& f : map.map.faces()) seen.insert(f.label);
  std::cout << "faces seen along (1, 1, 3):";
  for (auto l : seen) std::cout << ' ' << l;
  std::cout << "\n";
  // The cube's faces towards the viewer: z = 2 (0), y = 0 (2), x = 0 (4); the square (6); nothing (-1) around.
  bool ok = seen == std::set<std::int64_t>{-1, 0, 2, 4, 6};
  // Straight along the view through the cube's centre, from any point of
  // that line, the same face: the map's direction towards the image of the
  // point (0.5, 0.5, 1) below the cube is the line's, and it meets face 0.
  auto q = view.image(P(Q(1, 2), Q(1, 2), Q(1)));
  auto e = view.eye();
  auto d = svm::locate(map, s2::point<Q>(std::array<Q, 3>{q.x() - e.x(), q.y() - e.y(), q.z() - e.z()}));
  std::cout << "through the cube's centre: face " << d << "\n";
  ok = ok && d == 0;
  std::cout << (ok ? "ok" : "WRONG") << "\n";
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
