/// @file
/// Constructions of E2: lines through points, segments and convex polygons,
/// splitting by a line, and exact evaluation of implicit vertices.
#pragma once

#include "../detail/split.hpp"
#include "predicates.hpp"

#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>

namespace geometry::e2 {

/// The line through `p` and `q`, oriented from `p` to `q`: its positive side is on the left.
template <number FT> hyperplane<FT> line_through(point<FT> const& p, point<FT> const& q, hyperplane_tag tag = no_tag) {
  return hyperplane<FT>(cross(p.homogeneous(), q.homogeneous()), tag);
}

/// The line at infinity, positive on the whole plane (made once; a copy
/// shares its numbers).
template <number FT> hyperplane<FT> line_at_infinity() {
  static hyperplane<FT> const inf(hvec<FT, 3>(std::array<FT, 3>{FT(0), FT(0), FT(1)}));
  return inf;
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
    // A triangle of three points of integer coordinates below 2^40 (w = 1
    // in primitive form: input vertices, most of a cell's) adds an integer
    // below 2^83, summed in 128 bits; the others add rationals.
    auto small = [](hvec<FT, 3> const& x) { return detail::small_plane_point(x); };
    auto const& ho = h[0];
    bool o_small = small(ho);
    detail::int128 z = 0;
    FT twice(0);
    for (std::size_t i = 1; i + 1 < h.size(); ++i) {
      if (o_small && small(h[i]) && small(h[i + 1])) {
        auto const &o = ho.approx().v, &a = h[i].approx().v, &b = h[i + 1].approx().v;
        auto d = [](double u, double v) { return static_cast<detail::int128>(static_cast<std::int64_t>(u) - static_cast<std::int64_t>(v)); };
        z += d(a[0], o[0]) * d(b[1], o[1]) - d(a[1], o[1]) * d(b[0], o[0]);
        continue;
      }
      auto const &o = ho.integers(), &a = h[i].integers(), &b = h[i + 1].integers();
      integer n = det3(o, a, b);
      if (n != 0) twice += FT(n, integer(o[2] * a[2] * b[2]));
    }
    if (z != 0) {
      integer w;
      detail::set_integer(w, z);
      twice += FT(w);
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
  // A steep line is cut by a horizontal one.  On p's homogeneous (X, Y, W),
  // W > 0: the line W·y − Y = 0, or W·x − X = 0, made on integers.
  bool horizontal = !support.n.abs_greater(1, 0);
  auto line = [horizontal](auto const& P) {
    using T = std::remove_cvref_t<decltype(P[0])>;
    return horizontal ? std::array<T, 3>{T{}, P[2], -P[1]} : std::array<T, 3>{P[2], T{}, -P[0]};
  };
  hyperplane<FT> b{construct<3>(line, p.homogeneous())};
  return side(b, toward) == oriented_side::negative ? b.opposite() : b;
}

/// The segment from `p` to `q` (distinct points) on `line_through(p, q)`:
/// the line cut by `cross_line(l, p, q)` at its start and `cross_line(l, q,
/// p)` at its end, in that order (what splitting the whole line by the two
/// would give, without the splits).
template <number FT> sub_hyperplane<FT> segment(point<FT> const& p, point<FT> const& q, hyperplane_tag tag = no_tag) {
  auto l = line_through(p, q, tag);
  std::size_t k = dominant_axis(l.n);
  auto start = cross_line(l, p, q), end = cross_line(l, q, p);
  auto rs = restrict_to(l.n, k, start.n), re = restrict_to(l.n, k, end.n);
  return {std::move(l), k, {segment_bound<FT>{std::move(start), std::move(rs)}, segment_bound<FT>{std::move(end), std::move(re)}}};
}

/// The endpoints of `s` in homogeneous coordinates, start then end (w = 0 at infinity); none for a whole line.
template <number FT> std::vector<hvec<FT, 3>> homogeneous_endpoints(sub_hyperplane<FT> const& s) {
  std::vector<hvec<FT, 3>> out;
  if (s.bounds.size() < 2) return out;
  // The restricted point of a bound (b₀, b₁) is (b₁, −b₀) at the start and
  // its opposite at the end, lifted to the support line: one construction
  // on integers each.
  auto const& p = s.support.n;
  std::size_t k = s.axis;
  bool flip = detail::restriction_flips(p, k), neg = p.sign_at(k) == sign::negative;
  auto end = [&](hvec<FT, 2> const& b, bool start) {
    return construct<3>(
        [k, flip, neg, start](auto const& P, auto const& B) {
          using T = std::remove_cvref_t<decltype(P[0])>;
          std::array<T, 2> x = start ? std::array<T, 2>{B[1], -B[0]} : std::array<T, 2>{-B[1], B[0]};
          return detail::lift_values<3>(P, k, flip, neg, x);
        },
        p, b);
  };
  out.reserve(2);
  out.push_back(end(s.bounds.front().line(), true));
  out.push_back(end(s.bounds.back().line(), false));
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
