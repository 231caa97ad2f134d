// 2D visibility, exactly: a room with a pillar, seen from a point on its
// wall.  The walls go into a depth-order tree once (svm::wall_index); each
// view is the same front-to-back construction as the 3D map, on the circle
// of directions, and answers which wall is seen in every direction.
#include <svm/visibility2d.hpp>

#include <cstdlib>
#include <iostream>

using namespace geometry;
using Q = rational;
using P = e2::point<Q>;

int main() {
  svm::wall_scene<Q> room;
  room.rings.push_back({P(0, 0), P(12, 0), P(12, 8), P(0, 8)}); // counter-clockwise: the inside on the left
  room.rings.push_back({P(5, 3), P(5, 5), P(7, 5), P(7, 3)});   // a pillar, clockwise: a hole
  svm::wall_index<Q> index(room);

  // From the middle of the left wall the eye looks into the room only.
  P eye(Q(0), Q(4));
  auto view = index.view(eye);
  auto area = svm::area(view, room);
  auto boundary = svm::boundary(view, room);
  std::cout << "seen from (0, 4): " << view.arcs.size() << " arcs, " << boundary->size() << " vertices, area " << *area << "\n";
  for (auto const& a : view.arcs) {
    if (a.wall < 0) continue;
    auto w = room.wall(static_cast<std::size_t>(a.wall));
    auto p = svm::hit_point(eye, a.start(), w), q = svm::hit_point(eye, a.end(), w);
    std::cout << "  wall " << a.wall << ": (" << p.x() << ", " << p.y() << ") to (" << q.x() << ", " << q.y() << ")\n";
  }
  // The pillar hides the quadrilateral between the rays through (5, 3) and
  // (5, 5) beyond its near side, out to the wall x = 12, where they reach
  // y = 8/5 and y = 32/5: (5,3) (12,8/5) (12,32/5) (5,5), of area
  // 7·(2 + 24/5)/2 = 119/5, the pillar itself inside it.  The room is 96.
  if (*area != Q(96) - Q(119, 5)) {
    std::cerr << "expected area 361/5\n";
    return EXIT_FAILURE;
  }
  // Directions out of the room see nothing: the eye is on its wall.
  auto const& behind = svm::locate(view, s1::point<Q>(std::array<Q, 2>{Q(-1), Q(0)}));
  if (behind.wall != svm::behind_boundary) {
    std::cerr << "expected nothing to the left of the wall\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
