/// @file
/// `s2::kernel<FT>`: the sphere S2 as a `bsp::geometry`, for the generic tree.
#pragma once

#include "../detail/kernel.hpp"
#include "constructions.hpp"

#include <bsp/concepts/geometry.hpp>

namespace geometry::s2 {

/// The sphere S2 over the number type `FT`, as the generic BSP tree sees it.
template <number FT>
struct kernel : detail::kernel_base<FT, s2::point<FT>, s2::hyperplane<FT>, s2::sub_hyperplane<FT>, s2::polytope<FT>> {
  static s2::polytope<FT> whole_space() { return whole_sphere<FT>(); }
  static s2::sub_hyperplane<FT> whole(s2::hyperplane<FT> const& h) { return whole_circle(h); }
  /// The area of a cell (in double).
  static auto measure(s2::polytope<FT> const& c) { return s2::area(c); }
};

/// Exact the sphere S2.
using exact_kernel = kernel<rational>;
/// The sphere S2 in plain `double`, for teaching and comparison.
using double_kernel = kernel<double>;

} // namespace geometry::s2

template <geometry::number FT> inline constexpr bool bsp::enable_geometry<geometry::s2::kernel<FT>> = true;
