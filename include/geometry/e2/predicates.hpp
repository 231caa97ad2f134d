/// @file
/// Predicates of E2: signs of dot products and 3 × 3 determinants of
/// input-derived homogeneous vectors, filtered over exact fields.
#pragma once

#include "objects.hpp"

namespace geometry::e2 {

/// Side of `p` with respect to the line `h`.
template <number FT> oriented_side side(hyperplane<FT> const& h, point<FT> const& p) {
  return to_side(dot_sign(h.n, p.homogeneous()));
}

/// Side of the intersection of lines `a` and `b` (the point `a × b`) with respect to `h`.
template <number FT>
oriented_side side_of_vertex(hyperplane<FT> const& a, hyperplane<FT> const& b, hyperplane<FT> const& h) {
  return to_side(det_sign(a.n, b.n, h.n));
}

/// Orientation of three points: positive when counter-clockwise.
template <number FT> sign orientation(point<FT> const& a, point<FT> const& b, point<FT> const& c) {
  return det_sign(a.homogeneous(), b.homogeneous(), c.homogeneous());
}

/// Whether `p` lies in the closed polytope (`on` when on its boundary).
template <number FT> oriented_side classify(polytope<FT> const& c, point<FT> const& p) {
  return classify_in(c.bounds, [&p](hyperplane<FT> const& b) { return side(b, p); });
}

} // namespace geometry::e2
