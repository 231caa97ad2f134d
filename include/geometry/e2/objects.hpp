/// @file
/// The Euclidean plane E2: points, lines, segments, convex polygons (possibly
/// unbounded).  E2 is the open upper hemisphere w > 0 of the oriented
/// projective plane: a point (x, y) is (x, y, 1), a line a·x + b·y + c = 0 is
/// the circle (a, b, c), and the line at infinity (0, 0, 1) bounds every cell,
/// so unbounded cells are exact, with no bounding box.
#pragma once

#include "../common.hpp"

#include <cmath>
#include <vector>

namespace geometry::detail {

/// Whether the homogeneous point `h` of E2 has integer coordinates below 2^40 in
/// magnitude (w = 1 in primitive form), read from its cached doubles: then
/// a product of two coordinates, or of their differences, is below 2^82,
/// and sums of many such terms fit in 128 bits.  Input vertices usually are.
template <number FT> bool small_plane_point(hvec<FT, 3> const& h) {
  auto const& a = h.approx();
  return a.integral && a.v[2] == 1 && std::fabs(a.v[0]) < 0x1p40 && std::fabs(a.v[1]) < 0x1p40;
}

} // namespace geometry::detail

namespace geometry::e2 {

struct space;

/// A point of E2, kept as homogeneous (x, y, 1).
template <number FT> class point {
public:
  point() : h_(std::array<FT, 3>{FT(0), FT(0), FT(1)}) {}
  point(FT x, FT y) : h_(std::array<FT, 3>{std::move(x), std::move(y), FT(1)}) {}

  /// The point of homogeneous coordinates `h` (exact fields only; h[2] > 0):
  /// the same point as (h[0]/h[2], h[1]/h[2]), made from `h`'s integers
  /// without rational arithmetic; its coordinates are divided out only when
  /// first read.
  static point from_homogeneous(hvec<FT, 3> const& h)
    requires exact_field<FT>
  {
    point p;
    p.h_ = hvec<FT, 3>::from_point_integers(h.integer_view());
    return p;
  }

  FT const& x() const noexcept { return h_[0]; }
  FT const& y() const noexcept { return h_[1]; }
  hvec<FT, 3> const& homogeneous() const noexcept { return h_; }

  friend bool operator==(point const& a, point const& b) { return a.h_ == b.h_; }

private:
  hvec<FT, 3> h_;
};

/// An oriented line `a·x + b·y + c = 0`; its positive side is `a·x + b·y + c > 0`.
template <number FT> using hyperplane = basic_hyperplane<FT, 3, space>;

/// A bound of a segment: a line restricted to the segment's line.
template <number FT> using segment_bound = restricted_bound<hyperplane<FT>, FT, 2>;

/// A piece of a line (a sub-hyperplane of E2): a segment, a ray or the whole
/// line, as the line `support` cut by bounding lines (the line at infinity
/// among them for rays and lines).
template <number FT> struct sub_hyperplane {
  hyperplane<FT> support;
  std::size_t axis = 0;                 ///< coordinate eliminated by `restrict_to`
  std::vector<segment_bound<FT>> bounds;
};

/// A convex region of E2, possibly unbounded: the intersection of the
/// positive sides of `bounds`, listed counter-clockwise; the line at infinity
/// is one of them when the region is unbounded.  Vertex `i` is
/// `bounds[i].n × bounds[i+1].n` (at infinity when its w is 0).
template <number FT> struct polytope {
  std::vector<hyperplane<FT>> bounds;
};

} // namespace geometry::e2
