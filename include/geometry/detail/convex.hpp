/// @file
/// Convex regions of the oriented projective line and plane, described only by
/// their bounding hyperplanes (Stolfi's oriented projective geometry).  Every
/// geometry reduces to these two: S1 and E1 cells are arcs, S2 and E2 cells are
/// polygons, and a sub-hyperplane of S2/E2 (E3) is an arc (a polygon) in the
/// hyperplane's own coordinates after `restrict_to`.
///
/// A region is a list of *bounds*; each bound `b` supplies `b.line()`, the
/// homogeneous vector of a hyperplane whose non-negative side holds the region.
/// Vertices are never stored: the vertex between consecutive bounds `a`, `b`
/// is `a × b` (in the plane) and is only ever tested by a determinant of
/// bounds, so the degree of every predicate is fixed by the degree of the bounds.
#pragma once

#include "../linear.hpp"

#include <optional>
#include <utility>
#include <vector>

namespace geometry::detail {

/// The two parts of a region cut by a hyperplane `h`: the part where `h ≥ 0`
/// (positive) and where `h ≤ 0` (negative); an absent part is empty.
template <class Bound> struct region_split {
  std::optional<std::vector<Bound>> negative, positive;
};

template <class Bound> region_split<Bound> only_positive(std::vector<Bound> const& r) { return {std::nullopt, r}; }
template <class Bound> region_split<Bound> only_negative(std::vector<Bound> const& r) { return {r, std::nullopt}; }

/// @name Arcs: convex regions of the oriented projective line (2 coordinates)
/// An arc has 0 bounds (the whole circle), 1 bound `[b]` (the half circle
/// `b ≥ 0`, from `start(b) = (b₁, −b₀)` counter-clockwise to `−start(b)`) or 2
/// bounds `[b₀, b₁]` (from `start(b₀)` to `end(b₁) = −start(b₁)`, at most a
/// half circle).  `h · start(b) = det(h, b)`.
/// @{

template <class Bound>
region_split<Bound> split_arc(std::vector<Bound> const& arc, Bound const& hp, Bound const& hn) {
  auto const& h = hp.line();
  if (arc.empty()) return {std::vector<Bound>{hn}, std::vector<Bound>{hp}};
  if (arc.size() == 1) {
    auto const& b = arc[0];
    sign par = parallel(b.line(), h);
    if (par == sign::positive) return only_positive(arc);
    if (par == sign::negative) return only_negative(arc);
    if (det_sign(h, b.line()) == sign::positive)
      return {std::vector<Bound>{hn, b}, std::vector<Bound>{b, hp}};
    return {std::vector<Bound>{b, hn}, std::vector<Bound>{hp, b}};
  }
  auto const &b0 = arc[0], &b1 = arc[1];
  // An end whose bound is the splitting hyperplane itself (or its opposite,
  // by shared numbers) lies on it.
  auto on_h = [&hp](Bound const& b) {
    if constexpr (requires { b.original.n; }) return shares_numbers(b.original.n, hp.original.n);
    else return false;
  };
  sign s = on_h(b0) ? sign::zero : det_sign(h, b0.line());  // side of the start point
  sign e = on_h(b1) ? sign::zero : det_sign(b1.line(), h);  // side of the end point
  if (s == sign::zero && e == sign::zero) {
    // A half circle whose both ends lie on h: its midpoint is b₀ itself.
    return dot_sign(h, b0.line()) == sign::positive ? only_positive(arc) : only_negative(arc);
  }
  if (s != sign::negative && e != sign::negative) return only_positive(arc);
  if (s != sign::positive && e != sign::positive) return only_negative(arc);
  if (s == sign::negative) return {std::vector<Bound>{b0, hn}, std::vector<Bound>{hp, b1}};
  return {std::vector<Bound>{hn, b1}, std::vector<Bound>{b0, hp}};
}

/// @}

/// @name Polygons: convex regions of the oriented projective plane (3 coordinates)
/// A polygon has 0 bounds (the whole sphere), 1 (a hemisphere), 2 (a lune) or
/// more, listed counter-clockwise: the vertex between bounds `i` and `i+1` is
/// `Lᵢ × Lᵢ₊₁`, and edge `i` runs on `Lᵢ` from vertex `i−1` to vertex `i`.
/// @{

/// Sign of the coefficient of `b` when `h = α a + β b` lies in the pencil of `a` and `b`.
template <number FT> sign pencil_coefficient(hvec<FT, 3> const& a, hvec<FT, 3> const& b, hvec<FT, 3> const& h) {
  // (a × h)·(a × b) = β |a × b|²  (Binet–Cauchy), degree 4.
  return filtered_sign([](auto const& x, auto const& y, auto const& z) { return dot(x, x) * dot(z, y) - dot(x, y) * dot(z, x); }, a, b, h);
}

/// Where the polygon `poly` lies with respect to the hyperplane `h`: −1 or +1
/// when wholly on that side (touching allowed, as `split_polygon` would put
/// it), 0 when `h` cuts it in two.  `s` receives the sides of the vertices
/// (for two bounds or more; else it is emptied).  Constructs nothing.
template <class Bound, class Line> int polygon_side(std::vector<Bound> const& poly, Line const& h, std::vector<sign>& s) {
  std::size_t const k = poly.size();
  s.clear();
  if (k == 0) return 0;
  if (k == 1) {
    sign par = parallel(poly[0].line(), h);
    return par == sign::positive ? 1 : par == sign::negative ? -1 : 0;
  }
  s.resize(k);
  bool any_pos = false, any_neg = false;
  for (std::size_t i = 0; i < k; ++i) {
    // A lune's two vertices are antipodal: one evaluation decides both, so
    // that even an inexact number type sees them on opposite sides.
    s[i] = (k == 2 && i == 1) ? -s[0] : det_sign(poly[i].line(), poly[(i + 1) % k].line(), h);
    any_pos = any_pos || s[i] == sign::positive;
    any_neg = any_neg || s[i] == sign::negative;
  }
  if (!any_pos && !any_neg) {
    // Only a lune can have every vertex on h: then h is in the pencil of its bounds.
    sign beta = pencil_coefficient(poly[0].line(), poly[1].line(), h);
    sign alpha = pencil_coefficient(poly[1].line(), poly[0].line(), h);
    if (alpha != sign::negative && beta != sign::negative) return 1;
    if (alpha != sign::positive && beta != sign::positive) return -1;
    return 0;
  }
  return !any_neg ? 1 : !any_pos ? -1 : 0;
}

/// The two parts of `poly` cut by `hp` (and its opposite `hn`), when
/// `polygon_side(poly, hp.line(), s)` has given 0 and the signs `s`.
template <class Bound>
region_split<Bound> split_polygon_across(std::vector<Bound> const& poly, Bound const& hp, Bound const& hn,
                                         std::vector<sign> const& s) {
  std::size_t const k = poly.size();
  if (k == 0) return {std::vector<Bound>{hn}, std::vector<Bound>{hp}};
  if (k == 1) return {std::vector<Bound>{poly[0], hn}, std::vector<Bound>{poly[0], hp}};
  bool all_on = true;
  for (sign x : s) all_on = all_on && x == sign::zero;
  if (all_on) {
    // A lune whose vertices lie on h, cut along its length.
    auto const &a = poly[0], &b = poly[1];
    if (pencil_coefficient(b.line(), a.line(), hp.line()) == sign::positive)
      return {std::vector<Bound>{a, hn}, std::vector<Bound>{b, hp}};
    return {std::vector<Bound>{b, hn}, std::vector<Bound>{a, hp}};
  }
  // Sutherland–Hodgman on bounds: keep every edge with a point strictly on the
  // kept side, and put h where the boundary leaves that side.
  auto clip = [&](sign keep, Bound const& hb) {
    std::vector<Bound> out;
    out.reserve(k + 1);
    for (std::size_t i = 0; i < k; ++i) {
      sign prev = s[(i + k - 1) % k] * keep, cur = s[i] * keep, next = s[(i + 1) % k] * keep;
      if (prev != sign::positive && cur != sign::positive) continue;
      out.push_back(poly[i]);
      if (cur == sign::negative || (cur == sign::zero && next != sign::positive)) out.push_back(hb);
    }
    return out;
  };
  return {clip(sign::negative, hn), clip(sign::positive, hp)};
}

/// The parts of `poly` on either side of `hp` (`hn` is its opposite).
/// `signs`, when given, receives the sides of the vertices (for two bounds or more).
template <class Bound>
region_split<Bound> split_polygon(std::vector<Bound> const& poly, Bound const& hp, Bound const& hn,
                                  std::vector<sign>* signs = nullptr) {
  std::vector<sign> local;
  std::vector<sign>& s = signs ? *signs : local;
  int side = polygon_side(poly, hp.line(), s);
  if (side > 0) return only_positive(poly);
  if (side < 0) return only_negative(poly);
  return split_polygon_across(poly, hp, hn, s);
}

/// @}

} // namespace geometry::detail
