/// @file
/// Constructions of E1: oriented points, intervals, splitting, lengths.
#pragma once

#include "../detail/split.hpp"
#include "predicates.hpp"

#include <optional>

namespace geometry::e1 {

/// The oriented point at `a`, positive above it (or below when `positive_above` is false).
template <number FT> hyperplane<FT> hyperplane_at(FT const& a, bool positive_above = true, hyperplane_tag tag = no_tag) {
  std::array<FT, 2> n = positive_above ? std::array<FT, 2>{FT(1), FT(-a)} : std::array<FT, 2>{FT(-1), a};
  return hyperplane<FT>(hvec<FT, 2>(n), tag);
}

/// The point at infinity, positive on the whole line.
template <number FT> hyperplane<FT> point_at_infinity() {
  return hyperplane<FT>(hvec<FT, 2>(std::array<FT, 2>{FT(0), FT(1)}));
}

template <number FT> polytope<FT> whole_line() { return {{point_at_infinity<FT>()}}; }

/// The parts of `c` on either side of `h`.
template <number FT> split_result<polytope<FT>> split(polytope<FT> const& c, hyperplane<FT> const& h) {
  return detail::split_cell(c, h, detail::arc_split);
}

/// The closed interval [a, b] (a < b).
template <number FT> polytope<FT> interval(FT const& a, FT const& b) {
  auto c = *split(whole_line<FT>(), hyperplane_at(a, true)).positive;
  return *split(c, hyperplane_at(b, false)).positive;
}

/// The same point with the opposite orientation.
template <number FT> sub_hyperplane<FT> opposite(sub_hyperplane<FT> const& s) { return {s.support.opposite()}; }

/// The parts of the point `s` on either side of `h`, or its coincidence with `h`.
template <number FT> split_result<sub_hyperplane<FT>> split(sub_hyperplane<FT> const& s, hyperplane<FT> const& h) {
  split_result<sub_hyperplane<FT>> out;
  out.coincident = parallel(s.support.n, h.n);
  if (out.is_coincident()) return out;
  // The point of n = (n₀, n₁) is sign(n₀)·(−n₁, n₀); h at it is sign(n₀)·det(n, h).
  sign side = det_sign(s.support.n, h.n) * sign_of(s.support.n[0]);
  (side == sign::positive ? out.positive : out.negative) = s;
  return out;
}

/// The ends of an interval, lower then upper; nothing for an unbounded end.
template <number FT> std::pair<std::optional<FT>, std::optional<FT>> ends(polytope<FT> const& c) {
  std::optional<FT> lo, hi;
  for (auto const& b : c.bounds) {
    if (sign_of(b.n[0]) == sign::zero) continue; // the point at infinity
    FT at = -b.n[1] / b.n[0];
    (sign_of(b.n[0]) == sign::positive ? lo : hi) = at;
  }
  return {lo, hi};
}

/// Length of an interval, exact over exact fields; nothing when unbounded.
template <number FT> std::optional<FT> length(polytope<FT> const& c) {
  auto [lo, hi] = ends(c);
  if (!lo || !hi) return std::nullopt;
  return FT(*hi - *lo);
}

} // namespace geometry::e1
