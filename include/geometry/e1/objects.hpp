/// @file
/// The Euclidean line E1: points, oriented points as hyperplanes, intervals.
/// E1 is the half w > 0 of the oriented projective line: x is (x, 1) and the
/// point at infinity (0, 1) bounds every cell, so rays are exact.
#pragma once

#include "../common.hpp"

#include <vector>

namespace geometry::e1 {

struct space;

/// A point of E1, kept as homogeneous (x, 1).
template <number FT> class point {
public:
  point() : h_(std::array<FT, 2>{FT(0), FT(1)}) {}
  explicit point(FT x) : h_(std::array<FT, 2>{std::move(x), FT(1)}) {}

  FT const& x() const noexcept { return h_[0]; }
  hvec<FT, 2> const& homogeneous() const noexcept { return h_; }
  friend bool operator==(point const& a, point const& b) { return a.h_ == b.h_; }

private:
  hvec<FT, 2> h_;
};

/// An oriented point `a`: `(1, −a)` is positive above `a`, `(−1, a)` below.
template <number FT> using hyperplane = basic_hyperplane<FT, 2, space>;

/// A sub-hyperplane of E1: its hyperplane's single point.
template <number FT> struct sub_hyperplane {
  hyperplane<FT> support;
};

/// An interval of E1, possibly unbounded: the intersection of the positive
/// sides of `bounds` (the point at infinity among them when unbounded).
template <number FT> struct polytope {
  std::vector<hyperplane<FT>> bounds;
};

} // namespace geometry::e1
