/// @file
/// Predicates of S2.  Each is the sign of a small determinant of
/// input-derived vectors, filtered over exact fields.
#pragma once

#include "objects.hpp"

namespace geometry::s2 {

/// Side of the direction `p` with respect to the circle `h`: the sign of `h · p`.
template <number FT> oriented_side side(hyperplane<FT> const& h, point<FT> const& p) {
  return to_side(dot_sign(h.n, p));
}

/// Side of the intersection point `a × b` of two circles with respect to `h`:
/// the sign of `det(a, b, h)`, degree 3 in the circles' normals.
template <number FT>
oriented_side side_of_vertex(hyperplane<FT> const& a, hyperplane<FT> const& b, hyperplane<FT> const& h) {
  return to_side(det_sign(a.n, b.n, h.n));
}

/// Turn of three directions: the sign of `det(a, b, c)`; positive when `c` lies
/// to the left of the circle from `a` to `b`.
template <number FT> sign orientation(point<FT> const& a, point<FT> const& b, point<FT> const& c) {
  return det_sign(a, b, c);
}

/// Whether the direction `p` lies in the closed polytope (`on` when on its boundary).
template <number FT> oriented_side classify(polytope<FT> const& c, point<FT> const& p) {
  return classify_in(c.bounds, [&p](hyperplane<FT> const& b) { return side(b, p); });
}

} // namespace geometry::s2
