/// @file
/// `s1::kernel<FT>`: the circle S1 as a `bsp::geometry`, for the generic tree.
#pragma once

#include "../detail/kernel.hpp"
#include "constructions.hpp"

#include <bsp/concepts/geometry.hpp>

namespace geometry::s1 {

/// The circle S1 over the number type `FT`, as the generic BSP tree sees it.
template <number FT>
struct kernel : detail::kernel_base<FT, s1::point<FT>, s1::hyperplane<FT>, s1::sub_hyperplane<FT>, s1::polytope<FT>> {
  static s1::polytope<FT> whole_space() { return whole_circle<FT>(); }
  static s1::sub_hyperplane<FT> whole(s1::hyperplane<FT> const& h) { return s1::sub_hyperplane<FT>{h, true, true}; }
  /// The length of a cell (in double).
  static auto measure(s1::polytope<FT> const& c) { return s1::length(c); }
};

/// Exact the circle S1.
using exact_kernel = kernel<rational>;
/// The circle S1 in plain `double`, for teaching and comparison.
using double_kernel = kernel<double>;

} // namespace geometry::s1

template <geometry::number FT> inline constexpr bool bsp::enable_geometry<geometry::s1::kernel<FT>> = true;
