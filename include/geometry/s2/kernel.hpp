/// @file
/// `s2::kernel<FT>`: the sphere S2 as a `bsp::geometry`, for the generic tree.
#pragma once

#include "constructions.hpp"

#include <bsp/concepts/geometry.hpp>

namespace geometry::s2 {

/// The sphere S2 over the number type `FT`, as the generic BSP tree sees it.
template <number FT> struct kernel {
  using number_type = FT;
  using point = s2::point<FT>;
  using hyperplane = s2::hyperplane<FT>;
  using sub_hyperplane = s2::sub_hyperplane<FT>;
  using polytope = s2::polytope<FT>;

  static oriented_side side(hyperplane const& h, point const& p) { return s2::side(h, p); }
  static hyperplane opposite(hyperplane const& h) { return h.opposite(); }
  static sub_hyperplane opposite(sub_hyperplane const& s) { return s2::opposite(s); }
  static polytope whole_space() { return whole_sphere<FT>(); }
  static sub_hyperplane whole(hyperplane const& h) { return whole_circle(h); }
  static hyperplane const& supporting(sub_hyperplane const& s) { return s.support; }
  static split_result<polytope> split(polytope const& c, hyperplane const& h) { return s2::split(c, h); }
  static split_result<sub_hyperplane> split(sub_hyperplane const& s, hyperplane const& h) { return s2::split(s, h); }
  /// The side of `h` on which `s` lies wholly (`on`: ask `split`), cheaply.
  static oriented_side whole_side(sub_hyperplane const& s, hyperplane const& h) {
    return geometry::whole_side(s.support.n, s.axis, s.bounds, h.n);
  }
  /// The area of a cell (in double).
  static auto measure(polytope const& c) { return s2::area(c); }
};

/// Exact the sphere S2.
using exact_kernel = kernel<rational>;
/// The sphere S2 in plain `double`, for teaching and comparison.
using double_kernel = kernel<double>;

} // namespace geometry::s2

template <geometry::number FT> inline constexpr bool bsp::enable_geometry<geometry::s2::kernel<FT>> = true;
