/// @file
/// The concept `bsp::label`: what point-set trees keep at their leaves.
#pragma once

#include <concepts>
#include <type_traits>

namespace bsp {

/// Opt-in: specialise to `true` for a type used as a point-set label.
/// `bool` and the integer types are labels already.
template <class L> inline constexpr bool enable_label = std::is_integral_v<L>;

/// A leaf label of a point-set tree: inside/outside (`bool`), a colour, a
/// polygon index.
///
/// Requirements on a type `L`:
/// 1. `bsp::enable_label<L>` is `true`.
/// 2. `L` is `std::regular`: copyable, default-constructible and comparable
///    with `==` — so that siblings with equal labels can be collapsed and
///    boundaries found where labels differ.
///
/// @see bsp::point_set
template <class L>
concept label = enable_label<L> && std::regular<L>;

/// What a tree keeps at a node or a leaf (`bsp::tree`'s `NodeData` and
/// `LeafData`).
///
/// Requirements on a type `T`:
/// 1. `T` is `std::semiregular`: default-constructible (a new leaf or node
///    starts with `T{}`) and copyable (copying a tree copies its payloads,
///    `reduce` keeps one of two equal labels).
template <class T>
concept tree_payload = std::semiregular<T>;

/// Opt-in: specialise to `true` for a node payload of a depth-order tree.
template <class N> inline constexpr bool enable_depth_order_payload = false;

/// What a depth-order tree keeps at its interior nodes: the sub-hyperplanes
/// lying in the node's hyperplane (coincident polygons in E3, segments in E2).
///
/// Requirements on a type `N`:
/// 1. `bsp::enable_depth_order_payload<N>` is `true`.
/// 2. `N` is default-constructible and copyable.
template <class N>
concept depth_order_payload = enable_depth_order_payload<N> && std::semiregular<N>;

} // namespace bsp
