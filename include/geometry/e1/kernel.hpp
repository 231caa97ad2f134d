/// @file
/// `e1::kernel<FT>`: the line E1 as a `bsp::geometry`, for the generic tree.
#pragma once

#include "constructions.hpp"

#include <bsp/concepts/geometry.hpp>

namespace geometry::e1 {

/// The line E1 over the number type `FT`, as the generic BSP tree sees it.
template <number FT> struct kernel {
  using number_type = FT;
  using point = e1::point<FT>;
  using hyperplane = e1::hyperplane<FT>;
  using sub_hyperplane = e1::sub_hyperplane<FT>;
  using polytope = e1::polytope<FT>;

  static oriented_side side(hyperplane const& h, point const& p) { return e1::side(h, p); }
  static hyperplane opposite(hyperplane const& h) { return h.opposite(); }
  static sub_hyperplane opposite(sub_hyperplane const& s) { return e1::opposite(s); }
  static polytope whole_space() { return whole_line<FT>(); }
  static sub_hyperplane whole(hyperplane const& h) { return sub_hyperplane{h}; }
  static hyperplane const& supporting(sub_hyperplane const& s) { return s.support; }
  static split_result<polytope> split(polytope const& c, hyperplane const& h) { return e1::split(c, h); }
  static split_result<sub_hyperplane> split(sub_hyperplane const& s, hyperplane const& h) { return e1::split(s, h); }
  /// The length of a cell (exact; nothing when unbounded).
  static auto measure(polytope const& c) { return e1::length(c); }
};

/// Exact the line E1.
using exact_kernel = kernel<rational>;
/// The line E1 in plain `double`, for teaching and comparison.
using double_kernel = kernel<double>;

} // namespace geometry::e1

template <geometry::number FT> inline constexpr bool bsp::enable_geometry<geometry::e1::kernel<FT>> = true;
