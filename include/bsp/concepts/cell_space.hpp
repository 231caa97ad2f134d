/// @file
/// The concept `bsp::cell_space`: convex cells that hyperplanes split.
#pragma once

#include "oriented_space.hpp"

#include <optional>

namespace bsp {

/// The result of splitting `T` by a hyperplane: optional negative and positive parts.
template <class R, class T>
concept split_result_of = requires(R r) {
  { r.negative } -> std::convertible_to<std::optional<T>>;
  { r.positive } -> std::convertible_to<std::optional<T>>;
};

/// A space whose convex cells (polytopes) can be split by hyperplanes.
///
/// Requirements on a type `G`, in addition to `bsp::oriented_space`:
/// 1. `G::polytope` is a copyable type: a convex region, possibly unbounded.
/// 2. `G::whole_space()` is the polytope of the whole space: the root cell.
/// 3. `G::split(c, h)` returns the parts of `c` on the negative and positive
///    sides of `h` (each a `std::optional<polytope>`, empty when that part has
///    no interior).  The parts' interiors partition the interior of `c` minus `h`.
///
/// @see bsp::oriented_space, bsp::geometry
template <class G>
concept cell_space = oriented_space<G> && requires(typename G::polytope const& c, typename G::hyperplane const& h) {
  requires std::copyable<typename G::polytope>;
  { G::whole_space() } -> std::convertible_to<typename G::polytope>;
  { G::split(c, h) } -> split_result_of<typename G::polytope>;
};

} // namespace bsp
