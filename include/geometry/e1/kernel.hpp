/// @file
/// `e1::kernel<FT>`: the line E1 as a `bsp::geometry`, for the generic tree.
#pragma once

#include "../detail/kernel.hpp"
#include "constructions.hpp"

#include <bsp/concepts/geometry.hpp>

namespace geometry::e1 {

/// The line E1 over the number type `FT`, as the generic BSP tree sees it.
template <number FT>
struct kernel : detail::kernel_base<FT, e1::point<FT>, e1::hyperplane<FT>, e1::sub_hyperplane<FT>, e1::polytope<FT>> {
  static e1::polytope<FT> whole_space() { return whole_line<FT>(); }
  static e1::sub_hyperplane<FT> whole(e1::hyperplane<FT> const& h) { return e1::sub_hyperplane<FT>{h}; }
  /// The length of a cell (exact; nothing when unbounded).
  static auto measure(e1::polytope<FT> const& c) { return e1::length(c); }
};

/// Exact the line E1.
using exact_kernel = kernel<rational>;
/// The line E1 in plain `double`, for teaching and comparison.
using double_kernel = kernel<double>;

} // namespace geometry::e1

template <geometry::number FT> inline constexpr bool bsp::enable_geometry<geometry::e1::kernel<FT>> = true;
