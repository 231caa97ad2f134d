/// @file
/// The circle of directions S1 (2D visibility, teaching): directions, point
/// pairs as hyperplanes, and arcs.
#pragma once

#include "../common.hpp"

#include <vector>

namespace geometry::s1 {

struct space;

/// A point of S1: an unnormalised direction of the plane.
template <number FT> using point = hvec<FT, 2>;

/// An oriented hyperplane of S1: the two antipodal directions `p` with
/// `n · p = 0`; its positive side is the open half circle `n · p > 0`.
template <number FT> using hyperplane = basic_hyperplane<FT, 2, space>;

/// A sub-hyperplane of S1: the hyperplane's two points `start = (n₁, −n₀)`
/// (where, turning counter-clockwise, one enters the positive side) and
/// `end = −start`, or only one of them once a cell has cut the other away.
template <number FT> struct sub_hyperplane {
  hyperplane<FT> support;
  bool has_start = true;
  bool has_end = true;
};

/// An arc of S1 (a polytope): the intersection of the positive half circles
/// of at most two bounds.  None: the whole circle; one `[b]`: a half circle;
/// two `[b₀, b₁]`: the arc from `start(b₀)` counter-clockwise to `end(b₁)`.
template <number FT> struct polytope {
  std::vector<hyperplane<FT>> bounds;
};

} // namespace geometry::s1
