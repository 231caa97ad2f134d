/// @file
/// Constructions of S2: circles from directions, arcs and polygons, splitting
/// by a circle, and evaluation of implicit vertices for output.
#pragma once

#include "../detail/split.hpp"
#include "predicates.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace geometry::s2 {

/// The circle through `a` and `b`, oriented from `a` to `b` along the minor
/// arc (its positive side is to the left).  `a` and `b` must be independent.
template <number FT> hyperplane<FT> circle_through(point<FT> const& a, point<FT> const& b, hyperplane_tag tag = no_tag) {
  return hyperplane<FT>(cross(a, b), tag);
}

/// @name Polytopes
/// @{

template <number FT> polytope<FT> whole_sphere() { return {}; }
template <number FT> polytope<FT> hemisphere(hyperplane<FT> const& h) { return {{h}}; }

/// The convex polygon with the given vertices, counter-clockwise seen from
/// outside the sphere (each vertex strictly left of the circle through the
/// previous two).  Throws `std::invalid_argument` otherwise.
template <number FT> polytope<FT> convex_polygon(std::vector<point<FT>> const& v) {
  std::size_t n = v.size();
  if (n < 3) throw std::invalid_argument("s2::convex_polygon needs at least 3 vertices");
  polytope<FT> p;
  for (std::size_t i = 0; i < n; ++i) {
    if (orientation(v[i], v[(i + 1) % n], v[(i + 2) % n]) != sign::positive)
      throw std::invalid_argument("s2::convex_polygon: vertices are not strictly convex and counter-clockwise");
    p.bounds.push_back(circle_through(v[i], v[(i + 1) % n]));
  }
  return p;
}

/// The parts of `c` on either side of `h`.
template <number FT> split_result<polytope<FT>> split(polytope<FT> const& c, hyperplane<FT> const& h) {
  return detail::split_cell(c, h, detail::polygon_split);
}

/// The vertices of `c` (none for the sphere and a hemisphere), exact and unnormalised.
template <number FT> std::vector<point<FT>> vertices(polytope<FT> const& c) {
  std::vector<point<FT>> out;
  std::size_t k = c.bounds.size();
  if (k < 2) return out;
  for (std::size_t i = 0; i < k; ++i) out.push_back(cross(c.bounds[i].n, c.bounds[(i + 1) % k].n));
  return out;
}

/// @}

/// @name Arcs
/// @{

/// The whole circle `h` as a sub-hyperplane.
template <number FT> sub_hyperplane<FT> whole_circle(hyperplane<FT> const& h) {
  return {h, dominant_axis(h.n), {}};
}

/// The same point set with the opposite orientation.
template <number FT> sub_hyperplane<FT> opposite(sub_hyperplane<FT> const& s) { return detail::opposite_piece(s); }

/// The parts of the arc `s` on either side of `h`, or its coincidence with `h`.
template <number FT> split_result<sub_hyperplane<FT>> split(sub_hyperplane<FT> const& s, hyperplane<FT> const& h) {
  return detail::split_piece(s, h, detail::arc_split);
}

/// `restrict_to(p, k, p × x)` for a direction `x` on the circle `p`
/// (`sign` +1), or of `x × p` (`sign` −1), from `x` alone: the minor of p
/// and p × x on coordinates k and i is ∓|p|²·x_m (m the third index; minus
/// when i follows k cyclically), since p × (p × x) = −|p|²·x.  A positive
/// multiple of `restrict_to`'s vector, of x's degree instead of three times
/// p's, and the same signs as `restrict_to` takes (`neg`, `flip`).
template <number FT> hvec<FT, 2> restricted_through(hvec<FT, 3> const& p, std::size_t k, hvec<FT, 3> const& x, int sign) {
  bool negate = (p.sign_at(k) == geometry::sign::negative) != (sign < 0), flip = geometry::detail::restriction_flips(p, k);
  return construct<2>(
      [k, negate, flip](auto const& X) {
        std::array<std::remove_cvref_t<decltype(X[0])>, 2> r;
        for (std::size_t i = 0, j = 0; i < 3; ++i) {
          if (i == k) continue;
          auto const& v = X[3 - k - i];
          bool minus = (i == (k + 1) % 3) != negate;
          r[j++] = minus ? -v : v;
        }
        if (flip) r[0] = -r[0];
        return r;
      },
      x);
}

/// The minor arc from `a` to `b` on their circle `c` (`circle_through(a,
/// b)`), bounded at `a` by the circle `at_a` and at `b` by `at_b`: circles
/// through those points other than `c`, each with the arc on its positive
/// side (the circles of a loop's neighbouring arcs, say).  The bounds are
/// restricted to `c` from the points (`restricted_through`), so they are
/// those of `arc(a, b)`; the circles are kept as the bounds' originals.
template <number FT>
sub_hyperplane<FT> arc_bounded_by(hyperplane<FT> c, point<FT> const& a, point<FT> const& b, hyperplane<FT> at_a,
                                  hyperplane<FT> at_b) {
  std::size_t k = dominant_axis(c.n);
  auto ra = restricted_through(c.n, k, a, +1), rb = restricted_through(c.n, k, b, -1);
  return {std::move(c), k, {{std::move(at_a), std::move(ra)}, {std::move(at_b), std::move(rb)}}};
}

/// The circle through the point `x` of the circle `c`, perpendicular to it,
/// positive on the side `c` runs to from `x` (`sign` +1) or comes from (−1).
template <number FT> hyperplane<FT> perpendicular_through(hyperplane<FT> const& c, point<FT> const& x, int sign) {
  return hyperplane<FT>(sign > 0 ? cross(c.n, x) : cross(x, c.n));
}

/// The minor arc from `a` to `b` (independent directions), on
/// `circle_through(a, b)`: bounded by the circles through a and through b
/// perpendicular to it, each restricted to it from its point
/// (`restricted_through`), as splitting the whole circle by them
/// would bound it.
template <number FT> sub_hyperplane<FT> arc(point<FT> const& a, point<FT> const& b, hyperplane_tag tag = no_tag) {
  auto c = circle_through(a, b, tag);
  auto at_a = perpendicular_through(c, a, +1), at_b = perpendicular_through(c, b, -1);
  return arc_bounded_by(std::move(c), a, b, std::move(at_a), std::move(at_b));
}

/// The start (`end` false) or the end of an arc that has a bound: where
/// its first or last bound meets its circle (exact, unnormalised).
template <number FT> point<FT> endpoint(sub_hyperplane<FT> const& s, bool end) {
  if (!end) {
    auto const& b = s.bounds.front().line();
    return lift(s.support.n, s.axis, {b[1], FT(-b[0])});
  }
  auto const& b = s.bounds.back().line();
  return lift(s.support.n, s.axis, {FT(-b[1]), b[0]});
}

/// The endpoints of an arc: none for a whole circle, else start and end
/// (exact, unnormalised; for a half circle they are antipodal).
template <number FT> std::vector<point<FT>> endpoints(sub_hyperplane<FT> const& s) {
  if (s.bounds.empty()) return {};
  return {endpoint(s, false), endpoint(s, true)};
}

/// @}

/// @name Measures and output (double)
/// @{

/// A unit vector of `p`, in double, for output.
template <number FT> std::array<double, 3> to_unit(point<FT> const& p) {
  std::array<double, 3> d{to_double(p[0]), to_double(p[1]), to_double(p[2])};
  double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return {d[0] / l, d[1] / l, d[2] / l};
}

/// Angle between two directions, well conditioned at 0 and π.
inline double angle_between(std::array<double, 3> const& a, std::array<double, 3> const& b) {
  auto c = cross(a, b);
  return std::atan2(std::sqrt(dot(c, c)), dot(a, b));
}

/// Area of the polytope in steradians (Gauss–Bonnet: 2π minus the turning angles).
template <number FT> double area(polytope<FT> const& c) {
  std::size_t k = c.bounds.size();
  if (k == 0) return 4 * std::numbers::pi;
  double turn = 0;
  for (std::size_t i = 0; i < k; ++i)
    if (k > 1) turn += angle_between(to_unit(c.bounds[i].n), to_unit(c.bounds[(i + 1) % k].n));
  return 2 * std::numbers::pi - turn;
}

/// Length of the arc in radians.
template <number FT> double length(sub_hyperplane<FT> const& s) {
  if (s.bounds.empty()) return 2 * std::numbers::pi;
  if (s.bounds.size() == 1) return std::numbers::pi;
  auto e = endpoints(s);
  return angle_between(to_unit(e[0]), to_unit(e[1]));
}

/// @}

} // namespace geometry::s2
