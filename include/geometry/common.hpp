/// @file
/// Vocabulary shared by the five geometries: oriented sides, split results,
/// hyperplanes as homogeneous vectors, and bounds restricted to a hyperplane.
#pragma once

#include "detail/convex.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
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

/// Where a point lies in the closed intersection of the positive sides of
/// some hyperplanes, given `side_of(x)`, its side of the hyperplane of each
/// `x` in `bounds`: `negative` outside, `on` on the boundary, else `positive`.
template <class Range, class SideOf> oriented_side classify_in(Range const& bounds, SideOf&& side_of) {
  oriented_side result = oriented_side::positive;
  for (auto const& b : bounds) {
    oriented_side s = side_of(b);
    if (s == oriented_side::negative) return s;
    if (s == oriented_side::on) result = s;
  }
  return result;
}

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

namespace detail {
/// Calls `f(std::integral_constant<std::size_t, k>{}, std::bool_constant<flip>{})`
/// for `k < N`: the restricted predicates below are written once per
/// eliminated coordinate and orientation, so that their polynomials have
/// no captures and get the filter's static stage.
template <std::size_t N, class F> decltype(auto) with_restriction(std::size_t k, bool flip, F&& f) {
  return [&]<std::size_t... K>(std::index_sequence<K...>) -> decltype(auto) {
    using R = decltype(f(std::integral_constant<std::size_t, 0>{}, std::false_type{}));
    R r{};
    (void)((k == K ? (r = flip ? f(std::integral_constant<std::size_t, K>{}, std::true_type{})
                               : f(std::integral_constant<std::size_t, K>{}, std::false_type{}),
                      true)
                   : false) ||
           ...);
    return r;
  }(std::make_index_sequence<N>{});
}

/// The coordinates other than `K` of an `N`-coordinate vector, in order.
template <std::size_t N, std::size_t K> constexpr std::array<std::size_t, N - 1> kept_coordinates() {
  std::array<std::size_t, N - 1> idx{};
  for (std::size_t i = 0, j = 0; i < N; ++i)
    if (i != K) idx[j++] = i;
  return idx;
}
} // namespace detail

/// Sign of `det(restrict_to(p, k, h), b)` for a 2-coordinate bound `b` on
/// the 3-coordinate hyperplane `p`, without constructing the restriction: the
/// same filtered predicate, so asking it allocates nothing in the common case.
template <number FT>
sign restricted_det_sign(hvec<FT, 3> const& p, std::size_t k, hvec<FT, 3> const& h, hvec<FT, 2> const& b) {
  sign s = detail::with_restriction<3>(k, detail::restriction_flips(p, k), [&](auto kc, auto fc) {
    return filtered_sign(
        [](auto const& P, auto const& H, auto const& B) {
          constexpr std::size_t K = decltype(kc)::value;
          constexpr auto idx = detail::kept_coordinates<3, K>();
          auto v0 = P[K] * H[idx[0]] - H[K] * P[idx[0]];
          auto v1 = P[K] * H[idx[1]] - H[K] * P[idx[1]];
          if constexpr (decltype(fc)::value)
            return -(v0 * B[1]) - v1 * B[0];
          else
            return v0 * B[1] - v1 * B[0];
        },
        p, h, b);
  });
  return p.sign_at(k) == sign::negative ? -s : s;
}

/// Sign of `det(a, b, restrict_to(p, k, h))` for bounds `a`, `b` (3
/// coordinates) on the 4-coordinate hyperplane `p`: the side of `h` of the
/// polygon vertex `a × b`, as `split` sees it, without constructing the
/// restriction.
template <number FT>
sign restricted_det_sign(hvec<FT, 4> const& p, std::size_t k, hvec<FT, 4> const& h, hvec<FT, 3> const& a,
                         hvec<FT, 3> const& b) {
  sign s = detail::with_restriction<4>(k, detail::restriction_flips(p, k), [&](auto kc, auto fc) {
    return filtered_sign(
        [](auto const& P, auto const& H, auto const& A, auto const& B) {
          constexpr std::size_t K = decltype(kc)::value;
          constexpr auto idx = detail::kept_coordinates<4, K>();
          auto r0 = P[K] * H[idx[0]] - H[K] * P[idx[0]];
          auto r1 = P[K] * H[idx[1]] - H[K] * P[idx[1]];
          auto r2 = P[K] * H[idx[2]] - H[K] * P[idx[2]];
          auto c0 = A[1] * B[2] - A[2] * B[1];
          auto c1 = A[2] * B[0] - A[0] * B[2];
          auto c2 = A[0] * B[1] - A[1] * B[0];
          if constexpr (decltype(fc)::value)
            return c1 * r1 + c2 * r2 - c0 * r0;
          else
            return c0 * r0 + c1 * r1 + c2 * r2;
        },
        p, h, a, b);
  });
  return p.sign_at(k) == sign::negative ? -s : s;
}

namespace detail {
/// The polynomial of `restricted_det_sign` on E3 for the first coordinate
/// eliminated, not flipped: every variant has its degrees, weight and depth
/// of roundings, so its static stage's constants serve all of them.
inline constexpr auto restricted_vertex_side = [](auto const& P, auto const& H, auto const& A, auto const& B) {
  auto r0 = P[0] * H[1] - H[0] * P[1];
  auto r1 = P[0] * H[2] - H[0] * P[2];
  auto r2 = P[0] * H[3] - H[0] * P[3];
  auto c0 = A[1] * B[2] - A[2] * B[1];
  auto c1 = A[2] * B[0] - A[0] * B[2];
  auto c2 = A[0] * B[1] - A[1] * B[0];
  return c0 * r0 + c1 * r1 + c2 * r2;
};

/// `restricted_det_sign`'s static stage for many vertices of one polygon
/// against one hyperplane: the restriction of `h`, the same for all, is made
/// once.  The same operations as its polynomial, so the same error bound,
/// and the same exact decision on small integers (`static_stage`).
class restricted_vertex_filter {
public:
  restricted_vertex_filter(approximation<4> const& p, approximation<4> const& h, std::size_t axis, bool flip, bool negated)
      : flip_(flip), negated_(negated), integral_(p.integral && h.integral), bound_(scale * p.norm * h.norm),
        magnitude_(k.weight * p.norm * h.norm) {
    std::array<std::size_t, 3> idx{};
    for (std::size_t i = 0, j = 0; i < 4; ++i)
      if (i != axis) idx[j++] = i;
    for (std::size_t j = 0; j < 3; ++j) r_[j] = p.v[axis] * h.v[idx[j]] - h.v[axis] * p.v[idx[j]];
  }

  /// The side of the vertex a × b, when this stage decides it.
  std::optional<sign> operator()(approximation<3> const& a, approximation<3> const& b) const {
    double const c0 = a.v[1] * b.v[2] - a.v[2] * b.v[1];
    double const c1 = a.v[2] * b.v[0] - a.v[0] * b.v[2];
    double const c2 = a.v[0] * b.v[1] - a.v[1] * b.v[0];
    double const v = flip_ ? c1 * r_[1] + c2 * r_[2] - c0 * r_[0] : c0 * r_[0] + c1 * r_[1] + c2 * r_[2];
    auto signed_as = [this](double x) { return x == 0 ? sign::zero : (x > 0) != negated_ ? sign::positive : sign::negative; };
    if (v > bound_ * a.norm * b.norm || v < -bound_ * a.norm * b.norm) return signed_as(v);
    // Small integers: every operation was exact, zeros included.
    if (integral_ && a.integral && b.integral && magnitude_ * a.norm * b.norm < two_53) return signed_as(v);
    return std::nullopt;
  }

private:
  static constexpr auto k = static_constants_of<decltype(restricted_vertex_side), 4, 4, 3, 3>(std::make_index_sequence<4>{});
  static constexpr double scale = 2.0 * k.depth * (std::numeric_limits<double>::epsilon() / 2) * k.weight;
  bool flip_, negated_, integral_;
  double bound_, magnitude_;
  std::array<double, 3> r_{};
};
} // namespace detail

/// The side of `h` on which a convex polygon of the plane `support`, bounded
/// by `bounds` (three or more), lies wholly, touching allowed, as `split`
/// would put it; `on` when it may cross `h` or lie in it (then `split`
/// decides).  Constructs nothing.  Over an exact field the filter's static
/// stage runs for all vertices at once (`restricted_vertex_filter`); a
/// vertex it leaves undecided goes through the whole predicate.
template <number FT, class Bound>
oriented_side whole_side(hvec<FT, 4> const& support, std::size_t axis, std::vector<Bound> const& bounds,
                         hvec<FT, 4> const& h) {
  std::size_t n = bounds.size();
  if (n < 3 || shares_numbers(support, h)) return oriented_side::on; // in h itself: split tells
  std::optional<detail::restricted_vertex_filter> filter;
  if constexpr (exact_field<FT>)
    if (filter_config().enabled) [[likely]]
      filter.emplace(support.approx(), h.approx(), axis, detail::restriction_flips(support, axis), support.sign_at(axis) == sign::negative);
  bool pos = false, neg = false;
  for (std::size_t i = 0; i < n && !(pos && neg); ++i) {
    auto const &a = bounds[i].line(), &b = bounds[(i + 1) % n].line();
    std::optional<sign> s;
    if constexpr (exact_field<FT>)
      if (filter) {
        if (filter_config().count_evaluations) ++filter_stats().evaluations;
        s = (*filter)(a.approx(), b.approx());
      }
    if (!s) s = restricted_det_sign(support, axis, h, a, b);
    pos = pos || *s == sign::positive;
    neg = neg || *s == sign::negative;
  }
  if (pos && !neg) return oriented_side::positive;
  if (neg && !pos) return oriented_side::negative;
  return oriented_side::on;
}

/// The side of `h` on which an arc of the circle `support` bounded by
/// `bounds` (two of them: a bounded arc or segment) lies wholly, touching
/// allowed, as `split` would put it; `on` when it may cross `h`, lie in it, or
/// is not bounded by two bounds (then `split` decides).  Constructs nothing.
template <number FT, class Bound>
oriented_side whole_side(hvec<FT, 3> const& support, std::size_t axis, std::vector<Bound> const& bounds,
                         hvec<FT, 3> const& h) {
  if (bounds.size() != 2 || shares_numbers(support, h)) return oriented_side::on; // in h itself: split tells
  // An end whose bound is h itself (or its opposite, by shared numbers) lies on h.
  auto on_h = [&h](Bound const& b) {
    if constexpr (requires { b.original.n; }) return shares_numbers(b.original.n, h);
    else return false;
  };
  sign s = on_h(bounds[0]) ? sign::zero : restricted_det_sign(support, axis, h, bounds[0].line());   // side of the start point
  sign e = on_h(bounds[1]) ? sign::zero : -restricted_det_sign(support, axis, h, bounds[1].line()); // side of the end point
  if (s == sign::zero && e == sign::zero) return oriented_side::on;
  if (s != sign::negative && e != sign::negative) return oriented_side::positive;
  if (s != sign::positive && e != sign::positive) return oriented_side::negative;
  return oriented_side::on;
}

} // namespace geometry
