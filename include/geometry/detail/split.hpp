/// @file
/// The splitting and turning of cells and sub-hyperplanes, written once for
/// the geometries whose objects are lists of bounds (see `convex.hpp`): each
/// geometry's `split` and `opposite` name the region split it uses and are
/// otherwise these functions.
#pragma once

#include "../common.hpp"

#include <utility>

namespace geometry::detail {

/// The parts of the cell `c` (a `Polytope` with `bounds`, a list of
/// hyperplanes) on either side of `h`, by the region split `split_region`
/// (`split_arc` or `split_polygon`).
template <class Polytope, class Hyperplane, class SplitRegion>
split_result<Polytope> split_cell(Polytope const& c, Hyperplane const& h, SplitRegion split_region) {
  auto r = split_region(c.bounds, h, h.opposite());
  split_result<Polytope> out;
  if (r.negative) out.negative = Polytope{std::move(*r.negative)};
  if (r.positive) out.positive = Polytope{std::move(*r.positive)};
  return out;
}

/// A sub-hyperplane kept as its `support`, the coordinate `axis` that
/// `restrict_to` eliminates, and `bounds` in the support's own coordinates.
template <class S>
concept restricted_piece = requires(S const& s) {
  s.support.opposite();
  { s.axis } -> std::convertible_to<std::size_t>;
  mirrored(s.bounds);
};

/// The same point set as `s` with the opposite orientation.
template <restricted_piece S> S opposite_piece(S const& s) { return {s.support.opposite(), s.axis, mirrored(s.bounds)}; }

/// The parts of `s` on either side of `h`, or its coincidence with `h`: `h`
/// restricted to the support is a bound of `s`'s region, split there by
/// `split_region` (`split_arc` for segments and arcs, `split_polygon` for
/// polygons).
template <restricted_piece S, class Hyperplane, class SplitRegion>
split_result<S> split_piece(S const& s, Hyperplane const& h, SplitRegion split_region) {
  using bound = typename decltype(s.bounds)::value_type;
  split_result<S> out;
  out.coincident = parallel(s.support.n, h.n);
  if (out.is_coincident()) return out;
  auto r = restrict_to(s.support.n, s.axis, h.n);
  bound hp{h, r}, hn{h.opposite(), -r};
  auto parts = split_region(s.bounds, hp, hn);
  if (parts.negative) out.negative = S{s.support, s.axis, std::move(*parts.negative)};
  if (parts.positive) out.positive = S{s.support, s.axis, std::move(*parts.positive)};
  return out;
}

/// `split_arc` and `split_polygon` as function objects, to pass to the functions above.
inline constexpr auto arc_split = [](auto const& region, auto const& hp, auto const& hn) { return split_arc(region, hp, hn); };
inline constexpr auto polygon_split = [](auto const& region, auto const& hp, auto const& hn) {
  return split_polygon(region, hp, hn);
};

} // namespace geometry::detail
