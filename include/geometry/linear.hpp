/// @file
/// Small polynomial building blocks over `std::array<T, N>` — dot and cross
/// products, determinants — written with `+ − ×` only so that one definition
/// serves `double`, the filter's tracked doubles and exact rationals.  And the
/// predicates and constructions shared by every geometry, on `hvec`.
#pragma once

#include "filter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>

namespace geometry {

template <class T, std::size_t N> constexpr T dot(std::array<T, N> const& a, std::array<T, N> const& b) {
  T s = a[0] * b[0];
  for (std::size_t i = 1; i < N; ++i) s = s + a[i] * b[i];
  return s;
}

template <class T> constexpr std::array<T, 3> cross(std::array<T, 3> const& a, std::array<T, 3> const& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <class T> constexpr T det2(std::array<T, 2> const& a, std::array<T, 2> const& b) { return a[0] * b[1] - a[1] * b[0]; }

template <class T> constexpr T det3(std::array<T, 3> const& a, std::array<T, 3> const& b, std::array<T, 3> const& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/// The 4 × 4 determinant `|a b c d|`, by the 2 × 2 minors of its first two rows.
template <class T>
constexpr T det4(std::array<T, 4> const& a, std::array<T, 4> const& b, std::array<T, 4> const& c, std::array<T, 4> const& d) {
  auto m = [](std::array<T, 4> const& x, std::array<T, 4> const& y, std::size_t i, std::size_t j) { return x[i] * y[j] - x[j] * y[i]; };
  return m(a, b, 0, 1) * m(c, d, 2, 3) - m(a, b, 0, 2) * m(c, d, 1, 3) + m(a, b, 0, 3) * m(c, d, 1, 2) +
         m(a, b, 1, 2) * m(c, d, 0, 3) - m(a, b, 1, 3) * m(c, d, 0, 2) + m(a, b, 2, 3) * m(c, d, 0, 1);
}

/// @name Predicates on homogeneous vectors (filtered over exact fields)
/// @{

/// Sign of `a · b`: the side of a point `b` of a hyperplane `a`.
template <number FT, std::size_t N> sign dot_sign(hvec<FT, N> const& a, hvec<FT, N> const& b) {
  return filtered_sign([](auto const& x, auto const& y) { return dot(x, y); }, a, b);
}

/// Sign of the 2 × 2 determinant `|a b|`.
template <number FT> sign det_sign(hvec<FT, 2> const& a, hvec<FT, 2> const& b) {
  return filtered_sign([](auto const& x, auto const& y) { return det2(x, y); }, a, b);
}

/// Sign of the 3 × 3 determinant `|a b c|`.
template <number FT> sign det_sign(hvec<FT, 3> const& a, hvec<FT, 3> const& b, hvec<FT, 3> const& c) {
  return filtered_sign([](auto const& x, auto const& y, auto const& z) { return det3(x, y, z); }, a, b, c);
}

/// Whether `a` and `b` are positive (+1) or negative (−1) multiples of each
/// other, or independent (0).  Both must be non-zero.  Over an exact field,
/// one vector or opposite ones (shared numbers) are told without
/// arithmetic, and where the first minor vanishes the primitive integer
/// coordinates, equal or opposite exactly for parallel vectors, decide.
template <number FT, std::size_t N> sign parallel(hvec<FT, N> const& a, hvec<FT, N> const& b) {
  if constexpr (exact_field<FT>) {
    if (shares_numbers(a, b)) {
      std::size_t k = 0;
      while (k + 1 < N && a.sign_at(k) == sign::zero) ++k;
      return a.sign_at(k) == b.sign_at(k) ? sign::positive : sign::negative;
    }
    if (filtered_sign([](auto const& x, auto const& y) { return x[0] * y[1] - x[1] * y[0]; }, a, b) != sign::zero)
      return sign::zero;
    if (a.integer_view() == b.integer_view()) return sign::positive;
    if (a.integer_view() == (-b).integer_view()) return sign::negative;
    return sign::zero;
  }
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j) {
      auto minor = [i, j](auto const& x, auto const& y) { return x[i] * y[j] - x[j] * y[i]; };
      if (filtered_sign(minor, a, b) != sign::zero) return sign::zero;
    }
  return dot_sign(a, b);
}

/// @}

/// @name Exact constructions on homogeneous vectors
/// @{

/// The vector of the values of `f` on `v...`, for a result that means the
/// same up to a positive factor (a hyperplane, a direction, a homogeneous
/// point): `f` is a polynomial map over `std::array<T, N>` arguments with
/// `+ − ×` only, homogeneous in each argument, returning a
/// `std::array<T, M>`.  Over an exact field it is evaluated on the
/// arguments' integer coordinates (positive multiples of theirs, so the
/// result is a positive multiple of the true one), in 128-bit integers when
/// the bound allows and in GMP integers otherwise, never in rationals; over
/// `double`, on the doubles.
template <std::size_t M, class F, number FT, std::size_t... N> hvec<FT, M> construct(F const& f, hvec<FT, N> const&... v) {
  if constexpr (exact_field<FT>)
    return hvec<FT, M>::from_integers(detail::integer_construction<M>(f, v.integer_view()...));
  else
    return hvec<FT, M>(f(v.exact()...));
}

template <number FT> hvec<FT, 3> cross(hvec<FT, 3> const& a, hvec<FT, 3> const& b) {
  return construct<3>([](auto const& x, auto const& y) { return cross(x, y); }, a, b);
}

/// The coordinate eliminated when restricting to the hyperplane `p`: the one
/// where `|p[k]|` is largest, so that the restriction is well conditioned.
template <number FT, std::size_t N> std::size_t dominant_axis(hvec<FT, N> const& p) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < N; ++i)
    if (p.abs_greater(i, k)) k = i;
  return k;
}

namespace detail {
/// Whether dropping coordinate `k` of the hyperplane `p` reverses orientation:
/// then the first restricted coordinate is negated, so that for points `vᵢ` on
/// `p`, `det(drop(v₁), …) ` has the sign of `det(p, v₁, …)` — counter-clockwise
/// in restricted coordinates is counter-clockwise seen from `p`'s positive side.
template <number FT, std::size_t N> bool restriction_flips(hvec<FT, N> const& p, std::size_t k) {
  return (p.sign_at(k) == sign::negative) != (k % 2 == 1);
}
} // namespace detail

/// A hyperplane `b` of an N-coordinate space restricted to the hyperplane `p`,
/// as a hyperplane of `p`'s own N−1 coordinates (coordinate `k` eliminated,
/// orientation kept).  For every point `x` on `p`,
/// `sign(restrict_to(p, k, b) · drop(p, k, x)) = sign(b · x)`.  Its degree is
/// `deg p + deg b`: restricting input-derived hyperplanes keeps every
/// predicate of bounded degree.
template <number FT, std::size_t N>
hvec<FT, N - 1> restrict_to(hvec<FT, N> const& p, std::size_t k, hvec<FT, N> const& b) {
  bool neg = p.sign_at(k) == sign::negative, flip = detail::restriction_flips(p, k);
  return construct<N - 1>(
      [k, neg, flip](auto const& P, auto const& B) {
        std::array<std::remove_cvref_t<decltype(P[0])>, N - 1> r;
        for (std::size_t i = 0, j = 0; i < N; ++i) {
          if (i == k) continue;
          auto v = P[k] * B[i] - B[k] * P[i];
          r[j++] = neg ? -v : v;
        }
        if (flip) r[0] = -r[0];
        return r;
      },
      p, b);
}

/// The restricted coordinates of a point `x` on the hyperplane `p` (see `restrict_to`).
template <number FT, std::size_t N> hvec<FT, N - 1> drop(hvec<FT, N> const& p, std::size_t k, hvec<FT, N> const& x) {
  bool flip = detail::restriction_flips(p, k);
  return construct<N - 1>(
      [k, flip](auto const& X) {
        std::array<std::remove_cvref_t<decltype(X[0])>, N - 1> r;
        for (std::size_t i = 0, j = 0; i < N; ++i)
          if (i != k) r[j++] = X[i];
        if (flip) r[0] = -r[0];
        return r;
      },
      x);
}

namespace detail {
/// The values of `lift` on coordinates of any arithmetic type (integers,
/// bit counters, doubles for estimates): `P` the hyperplane's N coordinates,
/// `X` the N − 1 restricted ones, `flip` and `neg` as `restrict_to` sets them.
template <std::size_t N, class PA, class XA> auto lift_values(PA const& P, std::size_t k, bool flip, bool neg, XA const& X) {
  using T = std::remove_cvref_t<decltype(P[0])>;
  std::array<T, N> r;
  T s{};
  for (std::size_t i = 0, j = 0; i < N; ++i) {
    if (i == k) continue;
    T xj = (flip && j == 0) ? T(-X[j]) : T(X[j]);
    r[i] = neg ? T(-(P[k] * xj)) : T(P[k] * xj);
    s = s + P[i] * xj;
    ++j;
  }
  r[k] = neg ? s : T(-s);
  return r;
}
} // namespace detail

/// The point of the hyperplane `p` whose restricted coordinates are `x`: the
/// inverse of `drop`, up to a positive factor.
template <number FT, std::size_t N> hvec<FT, N> lift(hvec<FT, N> const& p, std::size_t k, hvec<FT, N - 1> const& x) {
  bool flip = detail::restriction_flips(p, k), neg = p.sign_at(k) == sign::negative;
  return construct<N>([k, flip, neg](auto const& P, auto const& X) { return detail::lift_values<N>(P, k, flip, neg, X); }, p, x);
}

/// The same, for restricted coordinates given as numbers.
template <number FT, std::size_t N> hvec<FT, N> lift(hvec<FT, N> const& p, std::size_t k, std::array<FT, N - 1> x) {
  return lift(p, k, hvec<FT, N - 1>(std::move(x)));
}

/// A restricted vector seen from the opposite hyperplane `-p`: its first
/// coordinate changes sign (see `restrict_to`).
template <number FT, std::size_t M> hvec<FT, M> mirror(hvec<FT, M> const& r) {
  return construct<M>(
      [](auto const& X) {
        auto c = X;
        c[0] = -c[0];
        return c;
      },
      r);
}

/// @}

namespace detail {
/// `v` in doubles, scaled by a positive factor so that its largest
/// coordinate is 1 in magnitude; nothing when it is zero or when the
/// filter's approximation has no double for an entry (tiny beside the
/// others: see `approximate`).
template <number FT, std::size_t N> std::optional<std::array<double, N>> unit_doubles(hvec<FT, N> const& v) {
  std::array<double, N> d;
  if constexpr (exact_field<FT>) {
    d = v.approx().v;
  } else {
    for (std::size_t i = 0; i < N; ++i) d[i] = v[i];
  }
  double m = 0;
  for (double x : d) {
    if (std::isnan(x)) return std::nullopt;
    m = std::max(m, std::fabs(x));
  }
  if (!(m > 0) || !std::isfinite(m)) return std::nullopt;
  for (double& x : d) x /= m;
  return d;
}

} // namespace detail

} // namespace geometry
