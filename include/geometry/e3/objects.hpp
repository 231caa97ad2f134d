/// @file
/// Euclidean space E3: points, planes, convex polygons and convex polyhedra
/// (possibly unbounded).  E3 is the half w > 0 of oriented projective 3-space:
/// a point is (x, y, z, 1), a plane a·x + b·y + c·z + d = 0 is (a, b, c, d),
/// and the plane at infinity (0, 0, 0, 1) implicitly bounds every cell.
#pragma once

#include "../common.hpp"

#include <vector>

namespace geometry::e3 {

struct space;

/// A point of E3, kept as homogeneous (x, y, z, 1).
template <number FT> class point {
public:
  point() : h_(std::array<FT, 4>{FT(0), FT(0), FT(0), FT(1)}) {}
  point(FT x, FT y, FT z) : h_(std::array<FT, 4>{std::move(x), std::move(y), std::move(z), FT(1)}) {}
  /// The point of homogeneous integer coordinates `h` (exact fields only;
  /// h[3] > 0): the same point as (h[0]/h[3], h[1]/h[3], h[2]/h[3]), whose
  /// coordinates are divided out only when first read.
  static point from_homogeneous(std::array<integer, 4> h)
    requires exact_field<FT>
  {
    detail::make_primitive(h);
    point p;
    p.h_ = hvec<FT, 4>::from_point_integers(detail::integer_vector<4>(std::move(h)));
    return p;
  }

  FT const& x() const noexcept { return h_[0]; }
  FT const& y() const noexcept { return h_[1]; }
  FT const& z() const noexcept { return h_[2]; }
  FT const& operator[](std::size_t i) const noexcept { return h_[i]; }
  hvec<FT, 4> const& homogeneous() const noexcept { return h_; }

  friend bool operator==(point const& a, point const& b) { return a.h_ == b.h_; }

private:
  hvec<FT, 4> h_;
};

/// An oriented plane `a·x + b·y + c·z + d = 0`, positive where the expression is positive.
template <number FT> using hyperplane = basic_hyperplane<FT, 4, space>;

/// A bound of a convex polygon: a plane restricted to the polygon's plane.
template <number FT> using polygon_bound = restricted_bound<hyperplane<FT>, FT, 3>;

/// A convex polygon (a sub-hyperplane of E3), possibly unbounded: the plane
/// `support` cut by bounding planes, listed counter-clockwise in `support`'s
/// restricted coordinates.  Its vertices are implicit: each is the meeting
/// point of `support` and two consecutive bounding planes.
template <number FT> struct sub_hyperplane {
  hyperplane<FT> support;
  std::size_t axis = 0;                 ///< coordinate eliminated by `restrict_to`
  std::vector<polygon_bound<FT>> bounds;
};

/// A convex polyhedron, possibly unbounded: its faces, each a convex polygon
/// whose supporting plane has the polyhedron on its positive side.  No faces:
/// the whole space.
template <number FT> struct polytope {
  std::vector<sub_hyperplane<FT>> faces;
};

} // namespace geometry::e3
