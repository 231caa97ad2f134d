/// @file
/// Vocabulary shared by the five geometries: oriented sides, split results,
/// hyperplanes as homogeneous vectors, and bounds restricted to a hyperplane.
#pragma once

#include "detail/convex.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace geometry {

/// Where a point lies with respect to an oriented hyperplane.
enum class oriented_side : signed char { negative = -1, on = 0, positive = 1 };

inline constexpr oriented_side to_side(sign s) noexcept { return static_cast<oriented_side>(static_cast<int>(s)); }

/// The parts of an object split by a hyperplane `h`: the part on `h`'s negative
/// side, the part on its positive side (either absent when empty), and, for a
/// sub-hyperplane lying in `h` itself, `coincident` = +1 when it has `h`'s
/// orientation and −1 when it has the opposite one (both parts are then absent).
template <class T> struct split_result {
  std::optional<T> negative;
  std::optional<T> positive;
  sign coincident = sign::zero;

  bool is_coincident() const noexcept { return coincident != sign::zero; }
};

/// Identifies where a hyperplane came from (an input edge, a scene line …);
/// carried unchanged through splits.
using hyperplane_tag = std::uint32_t;
inline constexpr hyperplane_tag no_tag = ~hyperplane_tag{0};

/// An oriented hyperplane of a space with `N` homogeneous coordinates: the
/// points `x` with `n · x = 0`; its positive side is `n · x > 0`.  `Space`
/// makes the hyperplanes of different geometries different types.
template <number FT, std::size_t N, class Space> struct basic_hyperplane {
  hvec<FT, N> n;
  hyperplane_tag tag = no_tag;

  basic_hyperplane() = default;
  explicit basic_hyperplane(hvec<FT, N> v, hyperplane_tag t = no_tag) : n(std::move(v)), tag(t) {}

  hvec<FT, N> const& line() const noexcept { return n; }
  /// The same hyperplane with the opposite orientation (and the same tag).
  basic_hyperplane opposite() const { return basic_hyperplane(-n, tag); }
  /// Same point set and orientation (tags are not compared).
  friend bool operator==(basic_hyperplane const& a, basic_hyperplane const& b) { return parallel(a.n, b.n) == sign::positive; }
};

/// A hyperplane `original` seen inside another hyperplane: `line()` is its
/// restriction to that hyperplane's coordinates (see `restrict_to`).
template <class Hyperplane, number FT, std::size_t M> struct restricted_bound {
  Hyperplane original;
  hvec<FT, M> restricted;

  hvec<FT, M> const& line() const noexcept { return restricted; }
};

/// The bounds of a restricted region seen from the opposite hyperplane: the
/// restricted coordinates are mirrored (see `mirror`), which reverses the
/// counter-clockwise order.
template <class Hyperplane, number FT, std::size_t M>
std::vector<restricted_bound<Hyperplane, FT, M>> mirrored(std::vector<restricted_bound<Hyperplane, FT, M>> const& bounds) {
  std::vector<restricted_bound<Hyperplane, FT, M>> out;
  for (auto it = bounds.rbegin(); it != bounds.rend(); ++it) out.push_back({it->original, mirror(it->restricted)});
  return out;
}

} // namespace geometry
