/// @file
/// Predicates of E1.
#pragma once

#include "objects.hpp"

namespace geometry::e1 {

/// Side of `p` with respect to the oriented point `h`.
template <number FT> oriented_side side(hyperplane<FT> const& h, point<FT> const& p) {
  return to_side(dot_sign(h.n, p.homogeneous()));
}

/// Whether `p` lies in the closed interval (`on` at an end).
template <number FT> oriented_side classify(polytope<FT> const& c, point<FT> const& p) {
  return classify_in(c.bounds, [&p](hyperplane<FT> const& b) { return side(b, p); });
}

} // namespace geometry::e1
