/// @file
/// `e2::kernel<FT>`: the plane E2 as a `bsp::geometry`, for the generic tree.
#pragma once

#include "../detail/kernel.hpp"
#include "constructions.hpp"

#include <bsp/concepts/geometry.hpp>

namespace geometry::e2 {

/// The plane E2 over the number type `FT`, as the generic BSP tree sees it.
template <number FT>
struct kernel : detail::kernel_base<FT, e2::point<FT>, e2::hyperplane<FT>, e2::sub_hyperplane<FT>, e2::polytope<FT>> {
  static e2::polytope<FT> whole_space() { return whole_plane<FT>(); }
  static e2::sub_hyperplane<FT> whole(e2::hyperplane<FT> const& h) { return whole_line(h); }
  /// The area of a cell (exact; nothing when unbounded).
  static auto measure(e2::polytope<FT> const& c) { return e2::area(c); }
};

/// Exact the plane E2.
using exact_kernel = kernel<rational>;
/// The plane E2 in plain `double`, for teaching and comparison.
using double_kernel = kernel<double>;

} // namespace geometry::e2

template <geometry::number FT> inline constexpr bool bsp::enable_geometry<geometry::e2::kernel<FT>> = true;
