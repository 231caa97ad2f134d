/// @file
/// Constructions of E2: lines through points, segments and convex polygons,
/// splitting by a line, and exact evaluation of implicit vertices.
#pragma once

#include "../detail/split.hpp"
#include "predicates.hpp"

#include <optional>
#include <stdexcept>

namespace geometry::e2 {

/// The line through `p` and `q`, oriented from `p` to `q`: its positive side is on the left.
template <number FT> hyperplane<FT> line_through(point<FT> const& p, point<FT> const& q, hyperplane_tag tag = no_tag) {
  return hyperplane<FT>(cross(p.homogeneous(), q.homogeneous()), tag);
}

/// The line at infinity, positive on the whole plane.
template <number FT> hyperplane<FT> line_at_infinity() {
  return hyperplane<FT>(hvec<FT, 3>(std::array<FT, 3>{FT(0), FT(0), FT(1)}));
}

/// @name Polytopes
/// @{

/// The whole plane.
template <number FT> polytope<FT> whole_plane() { return {{line_at_infinity<FT>()}}; }

/// The parts of `c` on either side of `h`.
template <number FT> split_result<polytope<FT>> split(polytope<FT> const& c, hyperplane<FT> const& h) {
  return detail::split_cell(c, h, detail::polygon_split);
}

/// The convex polygon with the given vertices in counter-clockwise order
/// (strictly convex).  Throws `std::invalid_argument` otherwise.
template <number FT> polytope<FT> convex_polygon(std::vector<point<FT>> const& v) {
  std::size_t n = v.size();
  if (n < 3) throw std::invalid_argument("e2::convex_polygon needs at least 3 vertices");
  polytope<FT> p;
  for (std::size_t i = 0; i < n; ++i) {
    if (orientation(v[i], v[(i + 1) % n], v[(i + 2) % n]) != sign::positive)
      throw std::invalid_argument("e2::convex_polygon: vertices are not strictly convex and counter-clockwise");
    p.bounds.push_back(line_through(v[i], v[(i + 1) % n]));
  }
  return p;
}

/// The homogeneous vertices of `c` (w = 0 for vertices at infinity).
template <number FT> std::vector<hvec<FT, 3>> homogeneous_vertices(polytope<FT> const& c) {
  std::vector<hvec<FT, 3>> out;
  std::size_t k = c.bounds.size();
  if (k < 2) return out;
  for (std::size_t i = 0; i < k; ++i) out.push_back(cross(c.bounds[i].n, c.bounds[(i + 1) % k].n));
  return out;
}

/// The vertices of a bounded polytope, exact; nothing when it is unbounded.
template <number FT> std::optional<std::vector<point<FT>>> vertices(polytope<FT> const& c) {
  std::vector<point<FT>> out;
  auto hv = homogeneous_vertices(c);
  if (hv.empty()) return std::nullopt;
  for (auto const& v : hv) {
    if (v.sign_at(2) != sign::positive) return std::nullopt;
    if constexpr (exact_field<FT>) {
      auto const& z = v.integers(); // one canonical fraction a coordinate
      out.emplace_back(FT(z[0], z[2]), FT(z[1], z[2]));
    } else {
      out.emplace_back(FT(v[0] / v[2]), FT(v[1] / v[2]));
    }
  }
  return out;
}

/// Area of a polytope, exact over exact fields; nothing when it is unbounded.
template <number FT> std::optional<FT> area(polytope<FT> const& c) {
  if constexpr (exact_field<FT>) {
    // On the vertices' integer homogeneous coordinates: the fan triangle
    // (o, a, b) has twice the area det3(o, a, b) / (w_o·w_a·w_b).
    auto h = homogeneous_vertices(c);
    if (h.empty()) return std::nullopt;
    for (auto const& x : h)
      if (x.sign_at(2) != sign::positive) return std::nullopt;
    auto const& o = h[0].integers();
    FT twice(0);
    for (std::size_t i = 1; i + 1 < h.size(); ++i) {
      auto const &a = h[i].integers(), &b = h[i + 1].integers();
      integer n = det3(o, a, b);
      if (n != 0) twice += FT(n, integer(o[2] * a[2] * b[2]));
    }
    return FT(twice / FT(2));
  }
  auto v = vertices(c);
  if (!v) return std::nullopt;
  FT twice(0);
  for (std::size_t i = 0; i < v->size(); ++i) {
    auto const &a = (*v)[i], &b = (*v)[(i + 1) % v->size()];
    twice = twice + (a.x() * b.y() - a.y() * b.x());
  }
  return FT(twice / FT(2));
}

/// @}

/// @name Segments, rays and lines
/// @{

/// The whole line `h` as a sub-hyperplane.
template <number FT> sub_hyperplane<FT> whole_line(hyperplane<FT> const& h) {
  std::size_t k = dominant_axis(h.n);
  auto inf = line_at_infinity<FT>();
  return {h, k, {segment_bound<FT>{inf, restrict_to(h.n, k, inf.n)}}};
}

/// The same point set with the opposite orientation.
template <number FT> sub_hyperplane<FT> opposite(sub_hyperplane<FT> const& s) { return detail::opposite_piece(s); }

/// The parts of `s` on either side of `h`, or its coincidence with `h`.
template <number FT> split_result<sub_hyperplane<FT>> split(sub_hyperplane<FT> const& s, hyperplane<FT> const& h) {
  return detail::split_piece(s, h, detail::arc_split);
}

/// A line through `p`, transverse to `support`, parallel to a coordinate axis
/// (degree 1 in `p`), oriented so that `toward` is on its positive side.
template <number FT> hyperplane<FT> cross_line(hyperplane<FT> const& support, point<FT> const& p, point<FT> const& toward) {
  using std::abs;
  bool horizontal = abs(support.n[0]) >= abs(support.n[1]); // a steep line is cut by a horizontal one
  std::array<FT, 3> c = horizontal ? std::array<FT, 3>{FT(0), FT(1), FT(-p.y())} : std::array<FT, 3>{FT(1), FT(0), FT(-p.x())};
  hyperplane<FT> b{hvec<FT, 3>(c)};
  return side(b, toward) == oriented_side::negative ? b.opposite() : b;
}

/// The segment from `p` to `q` (distinct points) on `line_through(p, q)`.
template <number FT> sub_hyperplane<FT> segment(point<FT> const& p, point<FT> const& q, hyperplane_tag tag = no_tag) {
  auto l = line_through(p, q, tag);
  auto s = split(whole_line(l), cross_line(l, p, q)).positive;
  return *split(*s, cross_line(l, q, p)).positive;
}

/// The endpoints of `s` in homogeneous coordinates, start then end (w = 0 at infinity); none for a whole line.
template <number FT> std::vector<hvec<FT, 3>> homogeneous_endpoints(sub_hyperplane<FT> const& s) {
  std::vector<hvec<FT, 3>> out;
  if (s.bounds.size() < 2) return out;
  auto const& b0 = s.bounds.front().line();
  auto const& b1 = s.bounds.back().line();
  out.push_back(lift(s.support.n, s.axis, {b0[1], FT(-b0[0])}));
  out.push_back(lift(s.support.n, s.axis, {FT(-b1[1]), b1[0]}));
  return out;
}

/// The endpoints of a bounded segment, exact; nothing for rays and lines.
template <number FT> std::optional<std::pair<point<FT>, point<FT>>> endpoints(sub_hyperplane<FT> const& s) {
  auto h = homogeneous_endpoints(s);
  if (h.empty() || sign_of(h[0][2]) != sign::positive || sign_of(h[1][2]) != sign::positive) return std::nullopt;
  return std::pair{point<FT>(FT(h[0][0] / h[0][2]), FT(h[0][1] / h[0][2])),
                   point<FT>(FT(h[1][0] / h[1][2]), FT(h[1][1] / h[1][2]))};
}

/// @}

} // namespace geometry::e2
