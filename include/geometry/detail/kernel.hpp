/// @file
/// `geometry::detail::kernel_base`: what the five `kernel<FT>`s have in
/// common.  Each geometry's kernel derives from it and adds only what is its
/// own: the whole space, the whole sub-hyperplane of a hyperplane, and the
/// measure of a cell.
#pragma once

#include "split.hpp"

namespace geometry::detail {

/// Calls of a geometry's free functions, found by argument-dependent lookup
/// in the geometry's namespace (a kernel's members of the same names would
/// hide them inside the kernel).
namespace found {
template <class H, class P> oriented_side side_of(H const& h, P const& p) { return side(h, p); }
template <class S> S opposite_of(S const& s) { return opposite(s); }
template <class T, class H> split_result<T> split_of(T const& t, H const& h) { return split(t, h); }
} // namespace found

/// The `bsp::geometry` operations of a geometry with these objects, each the
/// free function of the same name in the objects' namespace.  With
/// sub-hyperplanes that are `restricted_piece`s it is also a
/// `bsp::whole_side_geometry`.
template <number FT, class Point, class Hyperplane, class SubHyperplane, class Polytope> struct kernel_base {
  using number_type = FT;
  using point = Point;
  using hyperplane = Hyperplane;
  using sub_hyperplane = SubHyperplane;
  using polytope = Polytope;

  static oriented_side side(hyperplane const& h, point const& p) { return found::side_of(h, p); }
  static hyperplane opposite(hyperplane const& h) { return h.opposite(); }
  static sub_hyperplane opposite(sub_hyperplane const& s) { return found::opposite_of(s); }
  static hyperplane const& supporting(sub_hyperplane const& s) { return s.support; }
  static split_result<polytope> split(polytope const& c, hyperplane const& h) { return found::split_of(c, h); }
  static split_result<sub_hyperplane> split(sub_hyperplane const& s, hyperplane const& h) { return found::split_of(s, h); }
  /// The side of `h` on which `s` lies wholly (`on`: ask `split`), cheaply.
  static oriented_side whole_side(sub_hyperplane const& s, hyperplane const& h)
    requires restricted_piece<sub_hyperplane>
  {
    return geometry::whole_side(s.support.n, s.axis, s.bounds, h.n);
  }
};

} // namespace geometry::detail
