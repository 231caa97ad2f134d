// Test support: seeded random inputs and an independent exact reference.
// The reference computes with plain GMP rationals on raw coordinates and does
// not use the library's vectors, filters or predicates.
#pragma once

#include <geometry/number.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

namespace test {

using geometry::rational;
using Q = rational;

/// The seeded generator of one test case.
inline std::mt19937_64& rng() {
  static std::mt19937_64 g(20261122);
  return g;
}

inline long uniform(long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng()); }

/// A random integer in [-bound, bound].
inline Q random_integer(long bound = 1000) { return Q(uniform(-bound, bound)); }

/// A random decimal with `digits` digits after the point, read from its text
/// exactly, as a user's file would give it.
inline Q random_decimal(int digits = 4, long bound = 100) {
  long scale = 1;
  for (int i = 0; i < digits; ++i) scale *= 10;
  long k = uniform(-bound * scale, bound * scale);
  char text[64];
  std::snprintf(text, sizeof text, "%s%ld.%0*ld", k < 0 ? "-" : "", std::labs(k) / scale, digits, std::labs(k) % scale);
  std::string s = text;
  return geometry::parse_number<Q>(s);
}

/// `x` in the number type `FT` (nearest double for double).
template <class FT> FT as(Q const& x) {
  if constexpr (std::is_same_v<FT, double>)
    return x.convert_to<double>();
  else
    return x;
}

/// The exact rational value of a number of type FT (doubles are dyadic rationals).
template <class FT> Q exact(FT const& x) {
  if constexpr (std::is_same_v<FT, double>)
    return Q(x);
  else
    return x;
}

inline int sgn(Q const& x) { return x.sign(); }

/// Reference determinants on raw rationals.
inline Q ref_det2(Q a, Q b, Q c, Q d) { return a * d - b * c; }
inline Q ref_det3(std::array<Q, 3> const& a, std::array<Q, 3> const& b, std::array<Q, 3> const& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}
inline std::array<Q, 3> ref_cross(std::array<Q, 3> const& a, std::array<Q, 3> const& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Q ref_dot(std::array<Q, 3> const& a, std::array<Q, 3> const& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// The next double above / below.
inline double up(double x, int n = 1) {
  for (int i = 0; i < n; ++i) x = std::nextafter(x, INFINITY);
  return x;
}
inline double down(double x, int n = 1) {
  for (int i = 0; i < n; ++i) x = std::nextafter(x, -INFINITY);
  return x;
}

} // namespace test
