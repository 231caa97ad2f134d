/// @file
/// Predicates of S1, filtered over exact fields.
#pragma once

#include "objects.hpp"

namespace geometry::s1 {

/// Side of the direction `p` with respect to `h`: the sign of `h · p`.
template <number FT> oriented_side side(hyperplane<FT> const& h, point<FT> const& p) {
  return to_side(dot_sign(h.n, p));
}

/// Whether `p` lies in the closed arc (`on` at an endpoint).
template <number FT> oriented_side classify(polytope<FT> const& c, point<FT> const& p) {
  return classify_in(c.bounds, [&p](hyperplane<FT> const& b) { return side(b, p); });
}

} // namespace geometry::s1
