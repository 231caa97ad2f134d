/// @file
/// `e2::kernel<FT>`: the plane E2 as a `bsp::geometry`, for the generic tree.
#pragma once

#include "constructions.hpp"

#include <bsp/concepts/geometry.hpp>

namespace geometry::e2 {

/// The plane E2 over the number type `FT`, as the generic BSP tree sees it.
template <number FT> struct kernel {
  using number_type = FT;
  using point = e2::point<FT>;
  using hyperplane = e2::hyperplane<FT>;
  using sub_hyperplane = e2::sub_hyperplane<FT>;
  using polytope = e2::polytope<FT>;

  static oriented_side side(hyperplane const& h, point const& p) { return e2::side(h, p); }
  static hyperplane opposite(hyperplane const& h) { return h.opposite(); }
  static sub_hyperplane opposite(sub_hyperplane const& s) { return e2::opposite(s); }
  static polytope whole_space() { return whole_plane<FT>(); }
  static sub_hyperplane whole(hyperplane const& h) { return whole_line(h); }
  static hyperplane const& supporting(sub_hyperplane const& s) { return s.support; }
  static split_result<polytope> split(polytope const& c, hyperplane const& h) { return e2::split(c, h); }
  static split_result<sub_hyperplane> split(sub_hyperplane const& s, hyperplane const& h) { return e2::split(s, h); }
  /// The side of `h` on which `s` lies wholly (`on`: ask `split`), cheaply.
  static oriented_side whole_side(sub_hyperplane const& s, hyperplane const& h) {
    return geometry::whole_side(s.support.n, s.axis, s.bounds, h.n);
  }
  /// The area of a cell (exact; nothing when unbounded).
  static auto measure(polytope const& c) { return e2::area(c); }
};

/// Exact the plane E2.
using exact_kernel = kernel<rational>;
/// The plane E2 in plain `double`, for teaching and comparison.
using double_kernel = kernel<double>;

} // namespace geometry::e2

template <geometry::number FT> inline constexpr bool bsp::enable_geometry<geometry::e2::kernel<FT>> = true;
