/// @file
/// The concept `bsp::oriented_space`: points and oriented hyperplanes.
#pragma once

#include <concepts>
#include <type_traits>

namespace bsp {

/// Where a point lies with respect to an oriented hyperplane, as the tree
/// sees it: the sign of the hyperplane's equation at the point.
template <class S>
concept side_value = requires(S s) {
  { static_cast<int>(s) } -> std::same_as<int>;
};

/// A space of points and oriented hyperplanes.
///
/// Requirements on a type `G`:
/// 1. `G::point` and `G::hyperplane` are copyable types.
/// 2. `G::side(h, p)` returns a value whose `static_cast<int>` is −1, 0 or +1:
///    `p` lies on the negative side of `h`, on `h`, or on its positive side.
///    It must be exact: the tree's structure is decided by it.
/// 3. `G::opposite(h)` is the same hyperplane with its sides exchanged:
///    `side(opposite(h), p) == −side(h, p)` for every `p`.
///
/// @see bsp::cell_space, bsp::geometry
template <class G>
concept oriented_space = requires(typename G::hyperplane const& h, typename G::point const& p) {
  requires std::copyable<typename G::point>;
  requires std::copyable<typename G::hyperplane>;
  { G::side(h, p) } -> side_value;
  { G::opposite(h) } -> std::convertible_to<typename G::hyperplane>;
};

} // namespace bsp
