/// @file
/// Predicates of E3, filtered over exact fields.
#pragma once

#include "objects.hpp"

namespace geometry::e3 {

/// Side of `p` with respect to the plane `h`.
template <number FT> oriented_side side(hyperplane<FT> const& h, point<FT> const& p) {
  return to_side(dot_sign(h.n, p.homogeneous()));
}

/// Whether `p` lies in the closed polytope (`on` when on its boundary).
template <number FT> oriented_side classify(polytope<FT> const& c, point<FT> const& p) {
  oriented_side result = oriented_side::positive;
  for (auto const& f : c.faces) {
    auto s = side(f.support, p);
    if (s == oriented_side::negative) return s;
    if (s == oriented_side::on) result = s;
  }
  return result;
}

} // namespace geometry::e3
