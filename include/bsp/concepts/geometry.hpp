/// @file
/// The concept `bsp::geometry`: what a geometry provides to the generic tree.
#pragma once

#include "cell_space.hpp"

namespace bsp {

/// Opt-in: specialise to `true` for a type that models `bsp::geometry`.  The
/// concept has semantic requirements (exactness, partition) that a look-alike
/// type would not meet, so modelling it is a declaration, not an accident.
template <class G> inline constexpr bool enable_geometry = false;

/// The result of splitting a sub-hyperplane: the two parts, and whether it
/// lies in the splitting hyperplane (with the same or the opposite orientation).
template <class R, class T>
concept sub_split_result_of = split_result_of<R, T> && requires(R r) {
  { r.is_coincident() } -> std::convertible_to<bool>;
  { static_cast<int>(r.coincident) } -> std::same_as<int>;
};

/// A geometry the generic BSP tree works in: E1, E2, E3, S1, S2, or yours.
///
/// Requirements on a type `G`, in addition to `bsp::cell_space`:
/// 1. `bsp::enable_geometry<G>` is `true`.
/// 2. `G::sub_hyperplane` is a copyable type: a convex piece of a hyperplane
///    (a point in E1 and S1, a segment in E2, a convex polygon in E3, an arc
///    in S2), possibly the whole hyperplane.
/// 3. `G::whole(h)` is all of the hyperplane `h` as a sub-hyperplane, and
///    `G::supporting(s)` the oriented hyperplane that carries `s`.
/// 4. `G::split(s, h)` returns the parts of `s` on either side of `h`; when
///    `s` lies in `h` both parts are empty and `coincident` is +1 (same
///    orientation as `h`) or −1 (opposite).
/// 5. `G::opposite(s)` is the same piece with the opposite orientation:
///    `supporting(opposite(s)) == opposite(supporting(s))`.
///
/// Every model is checked with `static_assert(bsp::geometry<…>)` in the tests,
/// and `tests/bsp/archetype.hpp` holds the minimal model the whole generic
/// tree compiles against.
///
/// @see bsp::cell_space, bsp::tree
template <class G>
concept geometry = enable_geometry<G> && cell_space<G> &&
                   requires(typename G::sub_hyperplane const& s, typename G::hyperplane const& h) {
                     requires std::copyable<typename G::sub_hyperplane>;
                     { G::whole(h) } -> std::convertible_to<typename G::sub_hyperplane>;
                     { G::supporting(s) } -> std::convertible_to<typename G::hyperplane>;
                     { G::split(s, h) } -> sub_split_result_of<typename G::sub_hyperplane>;
                     { G::opposite(s) } -> std::convertible_to<typename G::sub_hyperplane>;
                   };

} // namespace bsp
