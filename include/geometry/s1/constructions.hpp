/// @file
/// Constructions of S1: splitting arcs and point pairs, endpoints, lengths.
#pragma once

#include "../detail/split.hpp"
#include "predicates.hpp"

#include <cmath>
#include <numbers>

namespace geometry::s1 {

/// The hyperplane whose start point is `p`: the half circle counter-clockwise from `p`.
template <number FT> hyperplane<FT> hyperplane_at(point<FT> const& p, hyperplane_tag tag = no_tag) {
  return hyperplane<FT>(point<FT>(std::array<FT, 2>{FT(-p[1]), p[0]}), tag);
}

/// The start point of a hyperplane `n`: `(n₁, −n₀)`.
template <number FT> point<FT> start_point(hyperplane<FT> const& h) {
  return point<FT>(std::array<FT, 2>{h.n[1], FT(-h.n[0])});
}

template <number FT> polytope<FT> whole_circle() { return {}; }

/// The arc from `a` counter-clockwise to `b` (at most a half circle; `a ≠ b`).
template <number FT> polytope<FT> arc(point<FT> const& a, point<FT> const& b) {
  return {{hyperplane_at(a), hyperplane_at(b).opposite()}};
}

/// The parts of `c` on either side of `h`.
template <number FT> split_result<polytope<FT>> split(polytope<FT> const& c, hyperplane<FT> const& h) {
  return detail::split_cell(c, h, detail::arc_split);
}

/// The same points with the opposite orientation: the start of `−n` is the end of `n`.
template <number FT> sub_hyperplane<FT> opposite(sub_hyperplane<FT> const& s) {
  return {s.support.opposite(), s.has_end, s.has_start};
}

/// The parts of the point pair `s` on either side of `h`, or its coincidence with `h`.
template <number FT> split_result<sub_hyperplane<FT>> split(sub_hyperplane<FT> const& s, hyperplane<FT> const& h) {
  split_result<sub_hyperplane<FT>> out;
  out.coincident = parallel(s.support.n, h.n);
  if (out.is_coincident()) return out;
  bool start_positive = det_sign(h.n, s.support.n) == sign::positive; // h · start(s)
  sub_hyperplane<FT> pos{s.support, false, false}, neg{s.support, false, false};
  (start_positive ? pos : neg).has_start = s.has_start;
  (start_positive ? neg : pos).has_end = s.has_end;
  if (pos.has_start || pos.has_end) out.positive = pos;
  if (neg.has_start || neg.has_end) out.negative = neg;
  return out;
}

/// The endpoints of an arc, start then end; none for the whole circle.
template <number FT> std::vector<point<FT>> endpoints(polytope<FT> const& c) {
  if (c.bounds.empty()) return {};
  auto e = start_point(c.bounds.back());
  return {start_point(c.bounds.front()), -e};
}

/// Length of an arc in radians.
template <number FT> double length(polytope<FT> const& c) {
  if (c.bounds.empty()) return 2 * std::numbers::pi;
  if (c.bounds.size() == 1) return std::numbers::pi;
  auto e = endpoints(c);
  double ax = to_double(e[0][0]), ay = to_double(e[0][1]), bx = to_double(e[1][0]), by = to_double(e[1][1]);
  return std::atan2(ax * by - ay * bx, ax * bx + ay * by); // ≤ π: arcs are at most half circles
}

} // namespace geometry::s1
