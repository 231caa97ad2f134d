/// @file
/// The sphere of directions S2: points, great circles, arcs, convex spherical polygons.
#pragma once

#include "../common.hpp"

#include <vector>

namespace geometry::s2 {

struct space;

/// A point of S2: an unnormalised direction.  Only its direction matters;
/// predicates never normalise it, so exact coordinates stay exact.
template <number FT> using point = hvec<FT, 3>;

/// An oriented great circle: the plane through the centre with normal `n`;
/// its positive side is the open hemisphere `n · p > 0`, to the left of an
/// observer walking along the circle on the outside of the sphere.
template <number FT> using hyperplane = basic_hyperplane<FT, 3, space>;

/// A bound of an arc: a great circle restricted to the arc's circle.
template <number FT> using arc_bound = restricted_bound<hyperplane<FT>, FT, 2>;

/// An arc of a great circle (a sub-hyperplane of S2): the circle `support`
/// cut by at most two bounding circles (none: the whole circle; one: a half
/// circle).  Its endpoints are implicit: intersections of `support` with a bound.
template <number FT> struct sub_hyperplane {
  hyperplane<FT> support;
  std::size_t axis = 0;                ///< coordinate eliminated by `restrict_to`
  std::vector<arc_bound<FT>> bounds;   ///< the arc in `support`'s own coordinates
};

/// A convex region of S2 (a polytope): the intersection of the positive
/// hemispheres of `bounds`, listed counter-clockwise.  No bounds: the whole
/// sphere; one: a hemisphere; two: a lune; more: a convex polygon.  Vertex `i`
/// is `bounds[i].n × bounds[i+1].n`.
template <number FT> struct polytope {
  std::vector<hyperplane<FT>> bounds;
};

} // namespace geometry::s2
