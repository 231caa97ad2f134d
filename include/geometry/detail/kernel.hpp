/// @file
/// `geometry::detail::kernel_base`: what the five `kernel<FT>`s have in
/// common.  Each geometry's kernel derives from it and adds only what is its
/// own: the whole space, the whole sub-hyperplane of a hyperplane, and the
/// measure of a cell.
#pragma once

#include "split.hpp"

#include <optional>
#include <type_traits>

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
/// `bsp::whole_side_geometry`, and with one-dimensional ones (segments,
/// arcs) a `bsp::joining_geometry`.
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
  /// `a` and `b` as one piece when `b` continues `a`: one-dimensional
  /// pieces (segments, arcs) on one support with one orientation, `a`'s end
  /// bound and `b`'s start bound one hyperplane (by shared numbers, without
  /// arithmetic), so `a` ends where `b` starts.  Empty otherwise (which says
  /// nothing).
  static std::optional<sub_hyperplane> join(sub_hyperplane const& a, sub_hyperplane const& b)
    requires restricted_piece<sub_hyperplane> && (std::remove_cvref_t<decltype(a.bounds.front().line())>::size == 2)
  {
    if (a.bounds.size() != 2 || b.bounds.size() != 2 || a.axis != b.axis) return std::nullopt;
    if (!shares_numbers(a.support.n, b.support.n) || a.support.n.sign_at(a.axis) != b.support.n.sign_at(b.axis))
      return std::nullopt;
    if (!shares_numbers(a.bounds.back().original.n, b.bounds.front().original.n)) return std::nullopt;
    return sub_hyperplane{a.support, a.axis, {a.bounds.front(), b.bounds.back()}};
  }
};

} // namespace geometry::detail
