/// @file
/// The concept `bsp::whole_side_geometry`: a cheap test that a sub-hyperplane
/// lies wholly on one side of a hyperplane, so that it passes down a tree unsplit.
#pragma once

#include "geometry.hpp"

namespace bsp {

/// A geometry that can tell cheaply, without constructing anything, that a
/// sub-hyperplane lies wholly on one side of a hyperplane.  The point-set
/// algorithms (`build_point_set`, `merged_boundary`) use it where it exists
/// and call `G::split` otherwise.
///
/// Requirements on a type `G`, in addition to `bsp::geometry`:
/// 1. `G::whole_side(s, h)` returns a `bsp::side_value` (see `bsp::oriented_space`): −1 or +1 only when
///    `G::split(s, h)` would put all of `s` on that side of `h`; 0 when it
///    cannot tell cheaply (then `split` decides).
/// 2. It constructs no object: it only evaluates predicates.
///
/// @see bsp::geometry
template <class G>
concept whole_side_geometry =
    geometry<G> && requires(typename G::sub_hyperplane const& s, typename G::hyperplane const& h) {
      { G::whole_side(s, h) } -> side_value;
    };

} // namespace bsp
