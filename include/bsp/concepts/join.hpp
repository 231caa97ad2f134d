/// @file
/// The concept `bsp::joining_geometry`: two parts of a cut piece put back
/// together without constructing anything.
#pragma once

#include "geometry.hpp"

#include <concepts>
#include <optional>

namespace bsp {

/// A geometry that can tell cheaply that the piece `b` continues the piece
/// `a` across the point where a hyperplane cut them apart (one-dimensional
/// pieces: segments, arcs), and give the piece they make together.
/// `bsp::merged_boundary` uses it, where it exists, to put back together the
/// parts of a piece that its trees cut where no label changes.
///
/// Requirements on a type `G`, in addition to `bsp::geometry`:
/// 1. `G::join(a, b)` returns a `std::optional<G::sub_hyperplane>`: when it
///    has a value, `a` and `b` lie on one hyperplane with one orientation,
///    `a` ends where `b` starts, and the value is the piece from `a`'s start
///    to `b`'s end (their union); empty when it cannot tell cheaply.
/// 2. It evaluates no predicate that could need exact arithmetic and
///    constructs no coordinate.
template <class G>
concept joining_geometry =
    geometry<G> && requires(typename G::sub_hyperplane const& a, typename G::sub_hyperplane const& b) {
      { G::join(a, b) } -> std::same_as<std::optional<typename G::sub_hyperplane>>;
    };

} // namespace bsp
