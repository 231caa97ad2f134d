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
  oriented_side result = oriented_side::positive;
  for (auto const& b : c.bounds) {
    auto s = side(b, p);
    if (s == oriented_side::negative) return s;
    if (s == oriented_side::on) result = s;
  }
  return result;
}

} // namespace geometry::s1
