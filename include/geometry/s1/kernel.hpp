/// @file
/// `s1::kernel<FT>`: the circle S1 as a `bsp::geometry`, for the generic tree.
#pragma once

#include "constructions.hpp"

#include <bsp/concepts/geometry.hpp>

namespace geometry::s1 {

/// The circle S1 over the number type `FT`, as the generic BSP tree sees it.
template <number FT> struct kernel {
  using number_type = FT;
  using point = s1::point<FT>;
  using hyperplane = s1::hyperplane<FT>;
  using sub_hyperplane = s1::sub_hyperplane<FT>;
  using polytope = s1::polytope<FT>;

  static oriented_side side(hyperplane const& h, point const& p) { return s1::side(h, p); }
  static hyperplane opposite(hyperplane const& h) { return h.opposite(); }
  static sub_hyperplane opposite(sub_hyperplane const& s) { return s1::opposite(s); }
  static polytope whole_space() { return whole_circle<FT>(); }
  static sub_hyperplane whole(hyperplane const& h) { return sub_hyperplane{h, true, true}; }
  static hyperplane const& supporting(sub_hyperplane const& s) { return s.support; }
  static split_result<polytope> split(polytope const& c, hyperplane const& h) { return s1::split(c, h); }
  static split_result<sub_hyperplane> split(sub_hyperplane const& s, hyperplane const& h) { return s1::split(s, h); }
  /// The length of a cell (in double).
  static auto measure(polytope const& c) { return s1::length(c); }
};

/// Exact the circle S1.
using exact_kernel = kernel<rational>;
/// The circle S1 in plain `double`, for teaching and comparison.
using double_kernel = kernel<double>;

} // namespace geometry::s1

template <geometry::number FT> inline constexpr bool bsp::enable_geometry<geometry::s1::kernel<FT>> = true;
