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
  return classify_in(c.faces, [&p](sub_hyperplane<FT> const& f) { return side(f.support, p); });
}

} // namespace geometry::e3
