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
  oriented_side result = oriented_side::positive;
  for (auto const& b : c.bounds) {
    auto s = side(b, p);
    if (s == oriented_side::negative) return s;
    if (s == oriented_side::on) result = s;
  }
  return result;
}

} // namespace geometry::e1
