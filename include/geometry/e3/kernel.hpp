/// @file
/// `e3::kernel<FT>`: space E3 as a `bsp::geometry`, for the generic tree.
#pragma once

#include "constructions.hpp"

#include <bsp/concepts/geometry.hpp>

namespace geometry::e3 {

/// Space E3 over the number type `FT`, as the generic BSP tree sees it.
template <number FT> struct kernel {
  using number_type = FT;
  using point = e3::point<FT>;
  using hyperplane = e3::hyperplane<FT>;
  using sub_hyperplane = e3::sub_hyperplane<FT>;
  using polytope = e3::polytope<FT>;

  static oriented_side side(hyperplane const& h, point const& p) { return e3::side(h, p); }
  static hyperplane opposite(hyperplane const& h) { return h.opposite(); }
  static sub_hyperplane opposite(sub_hyperplane const& s) { return e3::opposite(s); }
  static polytope whole_space() { return e3::whole_space<FT>(); }
  static sub_hyperplane whole(hyperplane const& h) { return whole_plane(h); }
  static hyperplane const& supporting(sub_hyperplane const& s) { return s.support; }
  static split_result<polytope> split(polytope const& c, hyperplane const& h) { return e3::split(c, h); }
  static split_result<sub_hyperplane> split(sub_hyperplane const& s, hyperplane const& h) { return e3::split(s, h); }
  /// The side of `h` on which `s` lies wholly (`on`: ask `split`), cheaply.
  static oriented_side whole_side(sub_hyperplane const& s, hyperplane const& h) {
    return geometry::whole_side(s.support.n, s.axis, s.bounds, h.n);
  }
  /// The volume of a cell (exact; nothing when unbounded).
  static auto measure(polytope const& c) { return e3::volume(c); }
};

/// Exact space E3.
using exact_kernel = kernel<rational>;
/// Space E3 in plain `double`, for teaching and comparison.
using double_kernel = kernel<double>;

} // namespace geometry::e3

template <geometry::number FT> inline constexpr bool bsp::enable_geometry<geometry::e3::kernel<FT>> = true;
