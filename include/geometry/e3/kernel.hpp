/// @file
/// `e3::kernel<FT>`: space E3 as a `bsp::geometry`, for the generic tree.
#pragma once

#include "../detail/kernel.hpp"
#include "constructions.hpp"

#include <bsp/concepts/geometry.hpp>

namespace geometry::e3 {

/// Space E3 over the number type `FT`, as the generic BSP tree sees it.
template <number FT>
struct kernel : detail::kernel_base<FT, e3::point<FT>, e3::hyperplane<FT>, e3::sub_hyperplane<FT>, e3::polytope<FT>> {
  static e3::polytope<FT> whole_space() { return e3::whole_space<FT>(); }
  static e3::sub_hyperplane<FT> whole(e3::hyperplane<FT> const& h) { return whole_plane(h); }
  /// The volume of a cell (exact; nothing when unbounded).
  static auto measure(e3::polytope<FT> const& c) { return e3::volume(c); }
};

/// Exact space E3.
using exact_kernel = kernel<rational>;
/// Space E3 in plain `double`, for teaching and comparison.
using double_kernel = kernel<double>;

} // namespace geometry::e3

template <geometry::number FT> inline constexpr bool bsp::enable_geometry<geometry::e3::kernel<FT>> = true;
