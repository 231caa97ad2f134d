/// @file
/// Filtered predicates: a predicate is written once, as a generic polynomial of
/// the coordinates of a few homogeneous vectors, and evaluated first in
/// `double` with a proven error bound; only when the sign is not certain is it
/// evaluated again in exact arithmetic.
///
/// Every predicate here is the sign of a polynomial that is homogeneous in
/// each argument vector (a projective predicate), so each exact vector may be
/// replaced by any positive multiple.  Each `hvec` over an exact field keeps
/// its *primitive integer* multiple (its coordinates times the least common
/// multiple of their denominators, divided by the greatest common divisor of
/// the results) and the `double`s of it, which gives two stages:
///
/// 1. **Exact in double.**  When every input coordinate is an integer below
///    2^53 and so is `m` below (the polynomial evaluated on absolute values,
///    see 2), every intermediate value is an integer below 2^53: the double
///    evaluation is exact, zero included.
/// 2. **Semi-static bound** (in the manner of Shewchuk and of CGAL's static
///    filters, derived mechanically from the expression).  With unit roundoff
///    `u = 2^-53` and `d` the number of roundings on the longest path of the
///    expression — counted by evaluating it on counters, which the optimiser
///    folds to a constant, each input counting two (its
///    conversion truncates, with relative error below 2u) — the computed value
///    `v` satisfies `|v − exact| ≤ γ_d · m ≤ 2·d·u·m` (Higham, *Accuracy and
///    Stability of Numerical Algorithms*, §3.1).  Inputs are filtered only when
///    their integer multiple is below 2^190 (others become NaN, which fails
///    every comparison), and a predicate multiplies at most five coordinates,
///    so nothing overflows; integers are at least 1, so nothing underflows.
///    When `m == 0` every monomial is exactly zero, and so is the sign.
///
/// Only when both stages fail is the polynomial evaluated in exact arithmetic,
/// on those integers, in the narrowest width that a bound on its values
/// allows: 128-bit integers, 256- or 512-bit `wide_integer`s on the stack,
/// else GMP integers (see `detail::integer_sign`).
#pragma once

#include "number.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <atomic>
#include <optional>
#include <type_traits>
#include <utility>

namespace geometry {

/// Counters of filtered predicate evaluations on this thread.
struct filter_statistics {
  std::uint64_t evaluations = 0;  ///< filtered predicates evaluated (when counted, see `filter_settings`)
  std::uint64_t fallbacks = 0;    ///< of these, how many needed exact arithmetic
  std::size_t max_exact_bits = 0; ///< largest bit length seen by an exact evaluation (when tracked)
};

/// Switches of the filter on this thread (benchmarks and tests turn them).
struct filter_settings {
  bool enabled = true;     ///< false: every predicate is evaluated exactly ("always exact")
  bool track_bits = false; ///< true: record the bit length of every exact input
  /// Over `double`: true (the default) gives the exact sign of the
  /// polynomial of the given doubles, filtered; false evaluates it once in
  /// floating point ("plain double", whose signs may contradict each other).
  bool exact_double_signs = true;
  /// false: the exact stage skips its fixed-width rungs (128, 256 and 512
  /// bits on the stack) and evaluates in GMP integers, and constructions
  /// skip their 128-bit rung (for comparison).
  bool fixed_width = true;
  /// true: count every filtered predicate in `filter_stats().evaluations`.
  /// Off by default: a counter written at every call makes each call wait
  /// for the previous one's store, which costs as much as the filter.
  /// Fallbacks are always counted.
  bool count_evaluations = false;
};

/// This thread's counters.
inline filter_statistics& filter_stats() noexcept {
  thread_local filter_statistics s;
  return s;
}

/// This thread's settings.
inline filter_settings& filter_config() noexcept {
  thread_local filter_settings s;
  return s;
}

namespace detail {

/// A double with the magnitude of the semi-static filter.
struct sfloat {
  double v; ///< value computed in double
  double m; ///< the polynomial evaluated on absolute values
};
inline sfloat operator+(sfloat a, sfloat b) noexcept { return {a.v + b.v, a.m + b.m}; }
inline sfloat operator-(sfloat a, sfloat b) noexcept { return {a.v - b.v, a.m + b.m}; }
inline sfloat operator*(sfloat a, sfloat b) noexcept { return {a.v * b.v, a.m * b.m}; }
inline sfloat operator-(sfloat a) noexcept { return {-a.v, a.m}; }

struct no_approximation {
  friend bool operator==(no_approximation, no_approximation) = default;
};

/// The filter's view of an exact vector: the doubles of its integer multiple.
template <std::size_t N> struct approximation {
  std::array<double, N> v{};
  double norm = 0;      ///< the largest |v[i]| (NaN when one is)
  bool integral = true; ///< every double is its integer exactly
  friend bool operator==(approximation const&, approximation const&) = default;
};

__extension__ using int128 = __int128; ///< exact when no value exceeds 2^126
__extension__ using uint128 = unsigned __int128;

/// The bit length of |v|: the least b with |v| < 2^b.
inline int bit_length128(int128 v) noexcept {
  uint128 m = v < 0 ? -static_cast<uint128>(v) : static_cast<uint128>(v);
  auto hi = static_cast<std::uint64_t>(m >> 64), lo = static_cast<std::uint64_t>(m);
  return hi ? 128 - __builtin_clzll(hi) : lo ? 64 - __builtin_clzll(lo) : 0;
}

inline void set_integer(integer& z, int128 v);

/// A value made on first use, at most once kept, by any thread: a thread
/// that finds it absent makes one and publishes it with a compare-exchange;
/// a thread that loses the race drops its own.  No lock and no system call
/// (`std::call_once` wakes waiters with one at every first call).
template <class T> class lazy_value {
public:
  lazy_value() = default;
  explicit lazy_value(std::unique_ptr<T> v) : p_(v.release()) {}
  lazy_value(lazy_value const&) = delete;
  lazy_value& operator=(lazy_value const&) = delete;
  /// Moves are for values no other thread sees yet.
  lazy_value(lazy_value&& o) noexcept : p_(o.p_.exchange(nullptr, std::memory_order_relaxed)) {}
  lazy_value& operator=(lazy_value&& o) noexcept {
    if (this != &o) delete p_.exchange(o.p_.exchange(nullptr, std::memory_order_relaxed), std::memory_order_relaxed);
    return *this;
  }
  ~lazy_value() { delete p_.load(std::memory_order_relaxed); }
  /// The value, when it has been made.
  T const* get_if() const noexcept { return p_.load(std::memory_order_acquire); }

  /// The value, made by `make()` (returning a `std::unique_ptr<T>`) when absent.
  template <class Make> T const& get(Make&& make) const {
    if (T* p = p_.load(std::memory_order_acquire)) return *p;
    std::unique_ptr<T> fresh = make();
    T* expected = nullptr;
    if (p_.compare_exchange_strong(expected, fresh.get(), std::memory_order_acq_rel, std::memory_order_acquire))
      return *fresh.release();
    return *expected;
  }

private:
  mutable std::atomic<T*> p_{nullptr};
};

/// Integer coordinates as the exact stages read them: the largest bit
/// length among them, a 64-bit copy when every one is below 2^63 and a
/// 128-bit one below 2^126, so that a predicate's rung is chosen and fed
/// without asking GMP.  Coordinates of 126 bits or fewer have no GMP
/// integers until something asks for them (`big`): a construction whose
/// result fits 128 bits allocates nothing.
template <std::size_t N> struct integer_vector {
  int bits = 0;                        ///< every |z[i]| < 2^bits
  std::array<std::int64_t, N> z64{};   ///< the values, when bits <= 63
  std::array<int128, N> z128{};        ///< the values, when bits <= 126

  integer_vector() = default;
  explicit integer_vector(std::array<integer, N> v) {
    for (auto const& x : v)
      if (mpz_sgn(x.backend().data()) != 0) bits = std::max(bits, static_cast<int>(mpz_sizeinbase(x.backend().data(), 2)));
    if (mid())
      for (std::size_t i = 0; i < N; ++i) {
        mpz_srcptr p = v[i].backend().data();
        uint128 m = 0;
        for (std::size_t k = mpz_size(p); k-- > 0;) m = (m << 64) | mpz_getlimbn(p, static_cast<mp_size_t>(k));
        z128[i] = mpz_sgn(p) < 0 ? -static_cast<int128>(m) : static_cast<int128>(m);
        z64[i] = static_cast<std::int64_t>(z128[i]);
      }
    big_ = lazy_value<std::array<integer, N>>(std::make_unique<std::array<integer, N>>(std::move(v)));
  }
  /// Values below 2^126 in magnitude.
  explicit integer_vector(std::array<int128, N> const& v) : z128(v) {
    for (auto x : v) bits = std::max(bits, bit_length128(x));
    for (std::size_t i = 0; i < N; ++i) z64[i] = static_cast<std::int64_t>(v[i]);
  }
  integer_vector(integer_vector const& o) : bits(o.bits), z64(o.z64), z128(o.z128) {
    if (!o.mid()) big_ = lazy_value<std::array<integer, N>>(std::make_unique<std::array<integer, N>>(o.big()));
  }
  integer_vector(integer_vector&&) noexcept = default;
  integer_vector& operator=(integer_vector o) noexcept {
    bits = o.bits, z64 = o.z64, z128 = o.z128, big_ = std::move(o.big_);
    return *this;
  }

  bool small() const noexcept { return bits <= 63; }
  bool mid() const noexcept { return bits <= 126; }

  /// The values as GMP integers (made on first use when they fit 128 bits).
  std::array<integer, N> const& big() const {
    return big_.get([this] {
      auto z = std::make_unique<std::array<integer, N>>();
      for (std::size_t i = 0; i < N; ++i) set_integer((*z)[i], z128[i]);
      return z;
    });
  }
  sign sign_at(std::size_t i) const {
    if (mid()) return z128[i] < 0 ? sign::negative : z128[i] > 0 ? sign::positive : sign::zero;
    return static_cast<sign>(mpz_sgn(big()[i].backend().data()));
  }
  /// Whether |z[i]| > |z[j]|.
  bool abs_greater(std::size_t i, std::size_t j) const {
    if (mid()) {
      auto abs = [](int128 x) { return x < 0 ? -static_cast<uint128>(x) : static_cast<uint128>(x); };
      return abs(z128[i]) > abs(z128[j]);
    }
    return mpz_cmpabs(big()[i].backend().data(), big()[j].backend().data()) > 0;
  }
  friend bool operator==(integer_vector const& a, integer_vector const& b) {
    if (a.bits != b.bits) return false;
    if (a.mid()) return a.z128 == b.z128;
    return a.big() == b.big();
  }
  integer_vector operator-() const {
    if (mid()) {
      std::array<int128, N> r;
      for (std::size_t i = 0; i < N; ++i) r[i] = -z128[i];
      return integer_vector(r);
    }
    std::array<integer, N> r;
    for (std::size_t i = 0; i < N; ++i) r[i] = -big()[i];
    return integer_vector(std::move(r));
  }

private:
  lazy_value<std::array<integer, N>> big_;
};

/// The coordinates of a vector and of its opposite, kept once and shared by
/// every copy of either (they are never changed after construction).  A
/// vector always has its *integer* coordinates: the primitive integer
/// multiple of its rational coordinates (their least common denominator
/// times them, divided by the greatest common divisor of the results: a
/// positive factor, so every projective sign is kept), which is what the
/// exact predicates read.  A vector made from integers (a construction on
/// integer coordinates, see `hvec::from_integers`) has as rational
/// coordinates those integers, made the first time they are asked for.  The
/// opposite's numbers too are made when first asked for, so turning a vector
/// round (`-v`) costs no number at all.
template <std::size_t N> class exact_pair {
public:
  exact_pair() : c_(std::make_unique<std::array<rational, N>>()) {}
  exact_pair(std::array<rational, N> c, integer_vector<N> z)
      : z_(std::move(z)), c_(std::make_unique<std::array<rational, N>>(std::move(c))) {}
  explicit exact_pair(integer_vector<N> z) : z_(std::move(z)) {}
  /// A point's homogeneous integer coordinates (the last positive): its
  /// rational coordinates are these divided by the last, made when first
  /// asked for.
  struct point_tag {};
  exact_pair(integer_vector<N> z, point_tag) : z_(std::move(z)), point_(true) {}

  integer_vector<N> const& integers(bool negated) const {
    if (!negated) return z_;
    return negative_z_.get([this] { return std::make_unique<integer_vector<N>>(-z_); });
  }

  std::array<rational, N> const& rationals(bool negated) const {
    auto const& c = c_.get([this] {
      auto c = std::make_unique<std::array<rational, N>>();
      auto const& z = z_.big();
      for (std::size_t i = 0; i < N; ++i) mpq_set_z((*c)[i].backend().data(), z[i].backend().data());
      if (point_) { // divided by the last, which becomes 1
        for (std::size_t i = 0; i + 1 < N; ++i) mpq_div((*c)[i].backend().data(), (*c)[i].backend().data(), (*c)[N - 1].backend().data());
        mpq_set_ui((*c)[N - 1].backend().data(), 1, 1);
      }
      return c;
    });
    if (!negated) return c;
    return negative_c_.get([&c] {
      auto m = std::make_unique<std::array<rational, N>>();
      for (std::size_t i = 0; i < N; ++i) (*m)[i] = -c[i];
      return m;
    });
  }

private:
  // What is made on demand is held by pointer: an absent part costs 8 bytes.
  integer_vector<N> z_;
  lazy_value<std::array<rational, N>> c_;
  lazy_value<integer_vector<N>> negative_z_;
  lazy_value<std::array<rational, N>> negative_c_;
  bool point_ = false;
};

/// Below this, integers and every sum and product of them are exact in double.
inline constexpr double two_53 = 0x1p53;

/// Divides `z` by the greatest common divisor of its entries (when not 0).
template <std::size_t M> void make_primitive(std::array<integer, M>& z) {
  integer g(0);
  std::size_t i = 0;
  if constexpr (M >= 2) // the first two at once: no copy of the first into g
    mpz_gcd(g.backend().data(), z[0].backend().data(), z[1].backend().data()), i = 2;
  for (; i < M; ++i) {
    if (mpz_cmp_ui(g.backend().data(), 1) == 0) return; // the usual case, found before the last entry
    mpz_gcd(g.backend().data(), g.backend().data(), z[i].backend().data());
  }
  if (mpz_cmp_ui(g.backend().data(), 1) > 0)
    for (auto& x : z) mpz_divexact(x.backend().data(), x.backend().data(), g.backend().data());
}

/// The primitive integer multiple of `c` (see `exact_pair`).
template <std::size_t N> std::array<integer, N> integer_multiple(std::array<rational, N> const& c) {
  integer scale(1);
  for (auto const& x : c) {
    auto const* den = mpq_denref(x.backend().data());
    if (mpz_cmp_ui(den, 1) != 0) mpz_lcm(scale.backend().data(), scale.backend().data(), den);
  }
  std::array<integer, N> r;
  for (std::size_t i = 0; i < N; ++i) {
    auto const* q = c[i].backend().data();
    mpz_divexact(r[i].backend().data(), scale.backend().data(), mpq_denref(q));
    mpz_mul(r[i].backend().data(), r[i].backend().data(), mpq_numref(q));
  }
  make_primitive(r);
  return r;
}

/// Fills `a` from the integers `z`.  Past 190 bits the doubles are those of
/// z / 2^s, with s the largest entry's bit length less 190: a positive
/// multiple, which every predicate reads as the same vector (they are
/// homogeneous in each argument, as on the integer multiples themselves),
/// with the entries in the range that integers of at most 190 bits give,
/// [1, 2^190), so no sum or product of them underflows or overflows where it
/// would not for such integers.  A non-zero entry that would fall below 1
/// there is NaN, and the filter leaves the vector to the exact stages.
template <std::size_t N> void approximate(std::array<integer, N> const& z, approximation<N>& a) {
  a.integral = true;
  std::array<std::size_t, N> bits{};
  std::size_t top = 0;
  for (std::size_t i = 0; i < N; ++i) {
    mpz_srcptr num = z[i].backend().data();
    bits[i] = mpz_sgn(num) == 0 ? 0 : mpz_sizeinbase(num, 2);
    top = std::max(top, bits[i]);
  }
  std::size_t const shift = top > 190 ? top - 190 : 0;
  for (std::size_t i = 0; i < N; ++i) {
    mpz_srcptr num = z[i].backend().data();
    if (shift == 0 || bits[i] == 0) {
      a.v[i] = mpz_get_d(num); // truncates: relative error below 2u
      a.integral = a.integral && bits[i] <= 53;
    } else if (bits[i] <= shift) {
      a.v[i] = std::numeric_limits<double>::quiet_NaN();
      a.integral = false;
    } else {
      long e = 0;
      double m = mpz_get_d_2exp(&e, num); // truncates too
      a.v[i] = std::ldexp(m, static_cast<int>(e - static_cast<long>(shift)));
      a.integral = false;
    }
  }
  a.norm = 0;
  for (double x : a.v) a.norm = std::isnan(x) ? x : std::max(a.norm, std::fabs(x));
}

/// The same from integer coordinates, without GMP when they fit 128 bits.
template <std::size_t N> void approximate(integer_vector<N> const& z, approximation<N>& a) {
  if (!z.mid()) return approximate(z.big(), a);
  a.integral = true;
  a.norm = 0;
  for (std::size_t i = 0; i < N; ++i) {
    a.v[i] = static_cast<double>(z.z128[i]); // rounds to nearest: relative error at most u
    a.integral = a.integral && bit_length128(z.z128[i]) <= 53;
    a.norm = std::max(a.norm, std::fabs(a.v[i]));
  }
}


/// Bounds the bit length of an expression's values: inputs below 2^b.
struct bits_counter {
  int b = 0;
};
constexpr bits_counter operator+(bits_counter a, bits_counter b) { return {std::max(a.b, b.b) + 1}; }
constexpr bits_counter operator-(bits_counter a, bits_counter b) { return {std::max(a.b, b.b) + 1}; }
constexpr bits_counter operator*(bits_counter a, bits_counter b) { return {a.b + b.b}; }
constexpr bits_counter operator-(bits_counter a) { return a; }

template <std::size_t N> std::array<bits_counter, N> bits_of(integer_vector<N> const& a) {
  std::array<bits_counter, N> r;
  r.fill({a.bits});
  return r;
}
template <std::size_t N> std::array<int128, N> to_int128(integer_vector<N> const& a) {
  std::array<int128, N> r;
  for (std::size_t i = 0; i < N; ++i) r[i] = a.z64[i];
  return r;
}

/// A signed integer of 64·L bits in two's complement, on the stack, with
/// `+ − ×` modulo 2^(64·L).  Those operations are ring homomorphisms from
/// the integers, so the result of a polynomial is exact whenever its true
/// value lies in [−2^(64·L−1), 2^(64·L−1)), whatever its intermediate values
/// do; `integer_sign` proves that bound before it chooses this rung.
/// (Boost.Multiprecision's fixed-width `cpp_int` was measured here too: no
/// faster than GMP's integers on these predicates, see docs/benchmarks.md.)
template <std::size_t L> struct wide_integer {
  std::array<std::uint64_t, L> w{}; ///< limbs, least significant first

  wide_integer() = default;
  /// The value of a GMP integer below 2^(64·L−1) in magnitude.
  explicit wide_integer(integer const& z) {
    mpz_srcptr p = z.backend().data();
    for (std::size_t k = 0; k < mpz_size(p) && k < L; ++k) w[k] = mpz_getlimbn(p, static_cast<mp_size_t>(k));
    if (mpz_sgn(p) < 0) *this = -*this;
  }
  /// The value of a 128-bit integer.
  explicit wide_integer(int128 v) noexcept {
    auto u = static_cast<uint128>(v);
    w[0] = static_cast<std::uint64_t>(u);
    if constexpr (L > 1) w[1] = static_cast<std::uint64_t>(u >> 64);
    for (std::size_t k = 2; k < L; ++k) w[k] = v < 0 ? ~std::uint64_t(0) : 0;
  }

  friend wide_integer operator+(wide_integer const& a, wide_integer const& b) noexcept {
    wide_integer r;
    uint128 carry = 0;
    for (std::size_t i = 0; i < L; ++i) {
      carry += static_cast<uint128>(a.w[i]) + b.w[i];
      r.w[i] = static_cast<std::uint64_t>(carry);
      carry >>= 64;
    }
    return r;
  }
  friend wide_integer operator-(wide_integer const& a) noexcept {
    wide_integer r;
    uint128 carry = 1;
    for (std::size_t i = 0; i < L; ++i) {
      carry += ~a.w[i];
      r.w[i] = static_cast<std::uint64_t>(carry);
      carry >>= 64;
    }
    return r;
  }
  friend wide_integer operator-(wide_integer const& a, wide_integer const& b) noexcept { return a + (-b); }
  /// The product modulo 2^(64·L): the schoolbook product of the low limbs.
  friend wide_integer operator*(wide_integer const& a, wide_integer const& b) noexcept {
    wide_integer r;
    for (std::size_t i = 0; i < L; ++i) {
      if (a.w[i] == 0) continue;
      uint128 carry = 0;
      for (std::size_t j = 0; i + j < L; ++j) {
        carry += static_cast<uint128>(a.w[i]) * b.w[j] + r.w[i + j];
        r.w[i + j] = static_cast<std::uint64_t>(carry);
        carry >>= 64;
      }
    }
    return r;
  }
  /// The sign of the value in two's complement.
  int sign() const noexcept {
    if (w[L - 1] >> 63) return -1;
    for (auto x : w)
      if (x) return 1;
    return 0;
  }
};

/// `a` as wide integers; every value must be below 2^(64·L−1) in magnitude.
template <class T, std::size_t N> std::array<T, N> to_fixed(integer_vector<N> const& a) {
  std::array<T, N> r;
  if (a.mid())
    for (std::size_t i = 0; i < N; ++i) r[i] = T(a.z128[i]);
  else
    for (std::size_t i = 0; i < N; ++i) r[i] = T(a.big()[i]);
  return r;
}

/// The widths of the fixed-width rungs of `integer_sign`, in bits of magnitude.
inline constexpr int int128_bits = 126, fixed256_bits = 255, fixed512_bits = 511;

/// The exact sign of `f` on integer vectors, on the first rung of a ladder
/// whose width provably holds every intermediate value (the bound comes from
/// the expression itself, evaluated on bit counts): 128-bit integers, then
/// 256 and 512 bits on the stack (`wide_integer`), and GMP integers only past
/// 2^511.
template <class F, std::size_t... N> sign integer_sign(F const& f, integer_vector<N> const&... a) {
  int const bits = f(bits_of(a)...).b;
  auto sign_of_value = [](auto const& x) { return x < 0 ? sign::negative : (x > 0 ? sign::positive : sign::zero); };
  if (filter_config().fixed_width) [[likely]] {
    if (bits <= int128_bits && (a.small() && ...)) return sign_of_value(f(to_int128(a)...));
    if (bits <= fixed256_bits) return to_sign(f(to_fixed<wide_integer<4>>(a)...).sign());
    if (bits <= fixed512_bits) return to_sign(f(to_fixed<wide_integer<8>>(a)...).sign());
  }
  return sign_of(f(a.big()...));
}
template <class F, std::size_t... N> sign integer_sign(F const& f, std::array<integer, N> const&... a) {
  return integer_sign(f, integer_vector<N>(a)...);
}

/// `v` as a GMP integer.
inline void set_integer(integer& z, int128 v) {
  if (v >= std::numeric_limits<std::int64_t>::min() && v <= std::numeric_limits<std::int64_t>::max()) {
    mpz_set_si(z.backend().data(), static_cast<long>(v));
    return;
  }
  uint128 m = v < 0 ? -static_cast<uint128>(v) : static_cast<uint128>(v);
  std::array<std::uint64_t, 2> limbs{static_cast<std::uint64_t>(m), static_cast<std::uint64_t>(m >> 64)};
  mpz_import(z.backend().data(), 2, -1, sizeof(std::uint64_t), 0, 0, limbs.data());
  if (v < 0) mpz_neg(z.backend().data(), z.backend().data());
}

/// The greatest common divisor of two 64-bit numbers, both non-zero (binary).
inline std::uint64_t gcd64(std::uint64_t a, std::uint64_t b) noexcept {
  int shift = __builtin_ctzll(a | b);
  a >>= __builtin_ctzll(a);
  do {
    b >>= __builtin_ctzll(b);
    if (a > b) std::swap(a, b);
    b -= a;
  } while (b != 0);
  return a << shift;
}

/// The greatest common divisor of two 128-bit numbers.  Binary, on 64-bit
/// words as soon as both fit; a number below 2^64 first reduces the other
/// by one division, so that a small common factor is found in a few steps.
inline uint128 gcd(uint128 a, uint128 b) noexcept {
  if (a == 0) return b;
  if (b == 0) return a;
  if (a > b) std::swap(a, b);
  if (static_cast<std::uint64_t>(a >> 64) == 0) {
    auto a64 = static_cast<std::uint64_t>(a);
    auto b64 = static_cast<std::uint64_t>(static_cast<std::uint64_t>(b >> 64) == 0 ? b : b % a64);
    return b64 == 0 ? a64 : gcd64(a64, b64);
  }
  auto ctz = [](uint128 x) {
    auto lo = static_cast<std::uint64_t>(x);
    return lo ? __builtin_ctzll(lo) : 64 + __builtin_ctzll(static_cast<std::uint64_t>(x >> 64));
  };
  int shift = std::min(ctz(a), ctz(b));
  a >>= ctz(a);
  while (b != 0) {
    b >>= ctz(b);
    if (a > b) std::swap(a, b);
    b -= a;
    if (static_cast<std::uint64_t>(b >> 64) == 0 && static_cast<std::uint64_t>(a >> 64) == 0) {
      auto b64 = static_cast<std::uint64_t>(b);
      return (b64 == 0 ? a : uint128{gcd64(static_cast<std::uint64_t>(a), b64)}) << shift;
    }
  }
  return a << shift;
}

/// The primitive integer vector of the values of `f` on integer vectors:
/// `f` is a polynomial map written over `std::array<T, N>` arguments with
/// `+ − ×` only, returning a `std::array<T, M>`.  It is evaluated on the
/// first rung that holds every intermediate value (the bound comes from `f`
/// itself, evaluated on bit counts): 128-bit integers, else GMP integers.
template <std::size_t M, class F, std::size_t... N>
integer_vector<M> integer_construction(F const& f, integer_vector<N> const&... a) {
  std::array<bits_counter, M> const bound = f(bits_of(a)...);
  int bits = 0;
  for (auto b : bound) bits = std::max(bits, b.b);
  if (bits <= int128_bits && (a.small() && ...) && filter_config().fixed_width) {
    std::array<int128, M> r = f(to_int128(a)...);
    uint128 g = 0;
    for (auto x : r)
      if (g != 1) g = gcd(g, x < 0 ? -static_cast<uint128>(x) : static_cast<uint128>(x));
    if (g > 1)
      for (auto& x : r) x /= static_cast<int128>(g);
    return integer_vector<M>(r);
  }
  std::array<integer, M> z = f(a.big()...);
  make_primitive(z);
  return integer_vector<M>(std::move(z));
}

/// Counts the filter's roundings of an expression at compile time.
struct depth_counter {
  int d = 2; ///< an input: its conversion to double
};
constexpr depth_counter operator+(depth_counter a, depth_counter b) { return {std::max(a.d, b.d) + 1}; }
constexpr depth_counter operator-(depth_counter a, depth_counter b) { return {std::max(a.d, b.d) + 1}; }
constexpr depth_counter operator*(depth_counter a, depth_counter b) { return {a.d + b.d + 1}; }
constexpr depth_counter operator-(depth_counter a) { return a; }

} // namespace detail

/// A vector of `N` homogeneous coordinates — a point, a direction or a
/// hyperplane's coefficients.  Over an exact field its exact coordinates
/// and their primitive integer multiple live once, shared by every copy (a
/// copy costs a reference count, never a number), and each copy carries the
/// `double` approximations the filter starts from.
template <number FT, std::size_t N> class hvec {
  static constexpr bool is_exact = exact_field<FT>;
  using shared = detail::exact_pair<N>;

public:
  using value_type = FT;
  static constexpr std::size_t size = N;

  hvec() {
    if constexpr (is_exact) s_ = zero();
  }
  explicit hvec(std::array<FT, N> c) {
    if constexpr (is_exact) {
      auto z = detail::integer_multiple(c);
      detail::approximate(z, a_);
      s_ = std::make_shared<shared const>(std::move(c), detail::integer_vector<N>(std::move(z)));
    } else {
      c_ = std::move(c);
    }
  }

  /// The vector whose integer coordinates are `z` (exact fields only): a
  /// construction's result, computed on integer coordinates, for objects that
  /// mean the same up to a positive factor (hyperplanes, directions,
  /// homogeneous points).  Its rational coordinates are those integers.
  static hvec from_integers(detail::integer_vector<N> z)
    requires is_exact
  {
    hvec r;
    detail::approximate(z, r.a_);
    r.s_ = std::make_shared<shared const>(std::move(z));
    return r;
  }

  /// The point whose homogeneous integer coordinates are `z` (exact fields
  /// only; the last coordinate positive, `z` primitive).  Unlike
  /// `from_integers`, its rational coordinates are those of the point, `z`
  /// divided by its last coordinate (made when first asked for).
  static hvec from_point_integers(detail::integer_vector<N> z)
    requires is_exact
  {
    hvec r;
    detail::approximate(z, r.a_);
    r.s_ = std::make_shared<shared const>(std::move(z), typename shared::point_tag{});
    return r;
  }

  /// The sign of coordinate `i`, read without making rationals: from its
  /// double (a nonzero integer's is nonzero, of the same sign; NaN when too
  /// long for a double), else from the integer.
  sign sign_at(std::size_t i) const {
    if constexpr (is_exact) {
      double v = a_.v[i];
      if (v > 0) return sign::positive;
      if (v < 0) return sign::negative;
      if (v == 0) return sign::zero;
      auto s = s_->integers(false).sign_at(i);
      return negated_ ? -s : s;
    } else {
      return sign_of(c_[i]);
    }
  }
  /// Whether `|v[i]| > |v[j]|`, read without making rationals: the doubles
  /// decide when they differ (rounding keeps order), the integers otherwise.
  bool abs_greater(std::size_t i, std::size_t j) const {
    if constexpr (is_exact) {
      double x = std::fabs(a_.v[i]), y = std::fabs(a_.v[j]);
      if (x > y) return true;
      if (x < y) return false;
      return s_->integers(false).abs_greater(i, j);
    } else {
      using std::abs;
      return abs(c_[i]) > abs(c_[j]);
    }
  }

  FT const& operator[](std::size_t i) const { return exact()[i]; }
  std::array<FT, N> const& exact() const {
    if constexpr (is_exact)
      return s_->rationals(negated_);
    else
      return c_;
  }

  /// The cached approximation (exact fields only).
  detail::approximation<N> const& approx() const noexcept
    requires is_exact
  {
    return a_;
  }

  /// The primitive integer multiple of the coordinates (exact fields only).
  std::array<integer, N> const& integers() const
    requires is_exact
  {
    return s_->integers(negated_).big();
  }
  /// The same, with its bit length, as the exact stages read it.
  detail::integer_vector<N> const& integer_view() const
    requires is_exact
  {
    return s_->integers(negated_);
  }

  /// Over an exact field: the address of the numbers this vector shares
  /// with its copies and with their opposites (the same for `v` and `-v`,
  /// whatever their values; default-constructed zero vectors all share
  /// one).  Tells, without arithmetic, that two vectors are one object or
  /// opposite ones; equal vectors made apart have different ones.
  void const* identity() const noexcept
    requires is_exact
  {
    return s_.get();
  }

  /// The opposite vector; over an exact field it shares this one's numbers.
  hvec operator-() const {
    hvec r(*this);
    if constexpr (is_exact) {
      r.negated_ = !negated_;
      for (auto& v : r.a_.v) v = -v;
    } else {
      for (auto& x : r.c_) x = -x;
    }
    return r;
  }

  bool is_zero() const {
    auto const& c = exact();
    return std::all_of(c.begin(), c.end(), [](FT const& x) { return sign_of(x) == sign::zero; });
  }

  /// Over an exact field: the same vector up to a positive factor (the same
  /// primitive integer coordinates), as every homogeneous object means it.
  friend bool operator==(hvec const& a, hvec const& b) {
    if constexpr (is_exact) {
      if (a.s_ == b.s_ && a.negated_ == b.negated_) return true;
      return a.integer_view() == b.integer_view();
    } else {
      return a.c_ == b.c_;
    }
  }

private:
  /// The zero vector's coordinates, shared by every default-constructed vector.
  static std::shared_ptr<shared const> const& zero()
    requires is_exact
  {
    static std::shared_ptr<shared const> const z = std::make_shared<shared const>();
    return z;
  }

  struct none {
    friend bool operator==(none, none) = default;
  };
  [[no_unique_address]] std::conditional_t<is_exact, none, std::array<FT, N>> c_{};
  [[no_unique_address]] std::conditional_t<is_exact, std::shared_ptr<shared const>, none> s_{};
  [[no_unique_address]] std::conditional_t<is_exact, detail::approximation<N>, detail::no_approximation> a_{};
  struct no_flag {};
  /// Exact fields: this is the opposite of the shared vector.
  [[no_unique_address]] std::conditional_t<is_exact, bool, no_flag> negated_{};
};

/// Whether `a` and `b` are one vector or opposite ones by the numbers they
/// share (`hvec::identity`), decided without arithmetic: over an exact field
/// each non-zero one then lies in the other's hyperplane; over double,
/// never.  False says nothing.
template <number FT, std::size_t N> bool shares_numbers(hvec<FT, N> const& a, hvec<FT, N> const& b) noexcept {
  if constexpr (exact_field<FT>) {
    return a.identity() == b.identity();
  } else {
    return false;
  }
}

namespace detail {

template <std::size_t N> std::array<sfloat, N> to_sfloat(approximation<N> const& a) noexcept {
  std::array<sfloat, N> r;
  for (std::size_t i = 0; i < N; ++i) r[i] = {a.v[i], std::fabs(a.v[i])};
  return r;
}

template <std::size_t N> std::array<sfloat, N> to_sfloat(std::array<double, N> const& a) noexcept {
  std::array<sfloat, N> r;
  for (std::size_t i = 0; i < N; ++i) r[i] = {a[i], std::fabs(a[i])};
  return r;
}

template <std::size_t N> void track_bits(std::array<rational, N> const& c) {
  auto& s = filter_stats();
  for (auto const& x : c) s.max_exact_bits = std::max(s.max_exact_bits, bit_length(x));
}

} // namespace detail

namespace detail {

/// The rest of a filtered predicate once the fast comparison failed: certain
/// zeros, the exact-in-double stage, then exact arithmetic.
template <class F, std::size_t... N>
[[gnu::noinline]] sign filtered_slow(F const& f, sfloat r, hvec<rational, N> const&... v) {
  auto& stats = filter_stats();
  if (filter_config().enabled) {
    if (r.m == 0.0) return sign::zero;
    if ((v.approx().integral && ...) && r.m < two_53) return sign_of(r.v);
  }
  ++stats.fallbacks;
  if (filter_config().track_bits) (track_bits(v.exact()), ...);
  // The cached integer multiples: integer arithmetic needs no gcd, unlike rationals.
  return integer_sign(f, v.integer_view()...);
}

/// The semi-static stage: `f` in double with its error bound (from the
/// polynomial's depth, a constant the optimiser folds).
struct stage_result {
  bool certain;
  sign s;
  sfloat r;
};

/// The degree of an expression in each of its `K` arguments.
template <std::size_t K> struct degree_counter {
  std::array<int, K> d{};
};
template <std::size_t K> constexpr degree_counter<K> operator+(degree_counter<K> a, degree_counter<K> b) {
  for (std::size_t i = 0; i < K; ++i) a.d[i] = std::max(a.d[i], b.d[i]);
  return a;
}
template <std::size_t K> constexpr degree_counter<K> operator-(degree_counter<K> a, degree_counter<K> b) { return a + b; }
template <std::size_t K> constexpr degree_counter<K> operator*(degree_counter<K> a, degree_counter<K> b) {
  for (std::size_t i = 0; i < K; ++i) a.d[i] += b.d[i];
  return a;
}
template <std::size_t K> constexpr degree_counter<K> operator-(degree_counter<K> a) { return a; }

/// The polynomial on absolute values at all-ones inputs: `+` and `−` add, `×` multiplies.
struct weight_counter {
  double c = 1;
};
constexpr weight_counter operator+(weight_counter a, weight_counter b) { return {a.c + b.c}; }
constexpr weight_counter operator-(weight_counter a, weight_counter b) { return {a.c + b.c}; }
constexpr weight_counter operator*(weight_counter a, weight_counter b) { return {a.c * b.c}; }
constexpr weight_counter operator-(weight_counter a) { return a; }

/// What the static stage needs of a polynomial `F` (a lambda without
/// captures) of vectors of sizes `N...`: its degree in each argument, the
/// weight `C` of its polynomial on absolute values (its value at all-ones
/// inputs) and its depth of roundings.  Since that polynomial has
/// non-negative coefficients, on inputs no larger than the norms `nᵢ` it is
/// at most `C · Π nᵢ^degᵢ`.
template <std::size_t K> struct static_constants {
  std::array<int, K> degree{};
  double weight = 0;
  int depth = 0;
};
template <class F, std::size_t... N, std::size_t... I>
constexpr static_constants<sizeof...(N)> static_constants_of(std::index_sequence<I...>) {
  constexpr std::size_t K = sizeof...(N);
  auto unit = [](std::size_t i) {
    degree_counter<K> e;
    e.d[i] = 1;
    return e;
  };
  auto filled = []<std::size_t M, class T>(T x) {
    std::array<T, M> a;
    a.fill(x);
    return a;
  };
  F f{};
  static_constants<K> out;
  out.degree = f(filled.template operator()<N>(unit(I))...).d;
  out.weight = f(filled.template operator()<N>(weight_counter{})...).c;
  out.depth = f(std::array<depth_counter, N>{}...).d;
  return out;
}

/// The static stage, for polynomials without captures: `f` in plain
/// double, its error bound from the inputs' norms (`C · Π nᵢ^degᵢ`, constant
/// but for the norms), so no tracking of magnitudes.  Looser than the
/// semi-static stage, which takes over when this one cannot decide.
template <class F, std::size_t... N> stage_result static_stage(F const& f, approximation<N> const&... a) {
  static constexpr auto k = static_constants_of<F, N...>(std::make_index_sequence<sizeof...(N)>{});
  constexpr double u = std::numeric_limits<double>::epsilon() / 2;
  static constexpr double scale = 2.0 * k.depth * u * k.weight;
  double const v = f(a.v...);
  double bound = scale;
  std::size_t i = 0;
  auto times_power = [&bound](double n, int d) {
    for (int j = 0; j < d; ++j) bound *= n;
  };
  (times_power(a.norm, k.degree[i++]), ...);
  if (v > bound) return {true, sign::positive, {}};
  if (v < -bound) return {true, sign::negative, {}};
  // Integers whose polynomial on absolute values stays below 2^53
  // (`bound / scale · weight`): every operation was exact, zeros included.
  if ((a.integral && ...) && bound * (k.weight / scale) < two_53) return {true, sign_of(v), {}};
  return {false, sign::zero, {}};
}
template <class F, std::size_t... N> stage_result semi_static(F const& f, std::array<sfloat, N> const&... a) {
  int const depth = f(std::array<depth_counter, N>{}...).d;
  constexpr double u = std::numeric_limits<double>::epsilon() / 2;
  sfloat r = f(a...);
  double bound = (2.0 * depth * u) * r.m;
  if (r.v > bound) return {true, sign::positive, r};
  if (r.v < -bound) return {true, sign::negative, r};
  return {false, sign::zero, r};
}

/// Over double, once the fast comparison failed: a certain zero, else the
/// exact sign of the polynomial of the doubles' exact values.
template <class F, std::size_t... N>
[[gnu::noinline]] sign double_slow(F const& f, sfloat r, hvec<double, N> const&... v) {
  if (r.m == 0.0) return sign::zero;
  // Infinities and NaNs have no exact value: their floating-point sign it is.
  if (!std::isfinite(r.m)) return sign_of(r.v);
  ++filter_stats().fallbacks;
  // A vector of doubles times 2^−e (e: the least exponent among its
  // entries' integer mantissas) is a vector of integers: a positive
  // multiple, made without rationals or gcds.
  auto exact = [](auto const& c) {
    constexpr std::size_t M = std::tuple_size_v<std::remove_cvref_t<decltype(c)>>;
    std::array<std::int64_t, M> mantissa{};
    std::array<int, M> exponent{};
    int least = std::numeric_limits<int>::max();
    for (std::size_t i = 0; i < M; ++i) {
      if (c[i] == 0) continue;
      int e = 0;
      mantissa[i] = static_cast<std::int64_t>(std::ldexp(std::frexp(c[i], &e), 53));
      exponent[i] = e - 53;
      least = std::min(least, exponent[i]);
    }
    std::array<integer, M> z;
    for (std::size_t i = 0; i < M; ++i) {
      if (mantissa[i] == 0) continue;
      mpz_set_si(z[i].backend().data(), static_cast<long>(mantissa[i]));
      mpz_mul_2exp(z[i].backend().data(), z[i].backend().data(), static_cast<mp_bitcnt_t>(exponent[i] - least));
    }
    return z;
  };
  return integer_sign(f, exact(v.exact())...);
}

/// The filter's stages after the static one, over an exact field: the
/// semi-static stage, then the exact ladder (or the exact ladder alone when
/// the filter is off).
template <class F, number FT, std::size_t... N> sign semi_static_then_exact(F const& f, hvec<FT, N> const&... v) {
  if (filter_config().enabled) [[likely]] {
    auto q = semi_static(f, to_sfloat(v.approx())...);
    return q.certain ? q.s : filtered_slow(f, q.r, v...);
  }
  return filtered_slow(f, sfloat{0.0, std::numeric_limits<double>::quiet_NaN()}, v...);
}
/// The same, out of line, where the static stage came first and failed.
template <class F, number FT, std::size_t... N>
[[gnu::noinline]] sign after_static_stage(F const& f, hvec<FT, N> const&... v) {
  return semi_static_then_exact(f, v...);
}

} // namespace detail

/// The sign of `f(v...)`, where `f` is a lambda computing a polynomial,
/// homogeneous in each argument, written generically over `std::array<T, N>`
/// arguments with `+ − ×` only.  It is filtered, then exact: over an exact
/// field, the exact value's sign; over `double`, the exact sign of the
/// polynomial of the given doubles (the objects are rounded, the signs are
/// not).
template <class F, number FT, std::size_t... N>
sign filtered_sign(F&& f, hvec<FT, N> const&... v) {
  if constexpr (!exact_field<FT>) {
    // Over double the objects are rounded, but their signs are not: the
    // polynomial is filtered, then evaluated exactly over the doubles'
    // rational values.  So every predicate on one set of double objects
    // tells the same story (three circles rounded apart from a common point
    // meet in a tiny triangle, consistently), which is what keeps a map built
    // over double a valid map.
    if (!filter_config().exact_double_signs) return sign_of(f(v.exact()...));
    if (filter_config().count_evaluations) ++filter_stats().evaluations;
    auto q = detail::semi_static(f, detail::to_sfloat(v.exact())...);
    return q.certain ? q.s : detail::double_slow(f, q.r, v...);
  } else {
    if (filter_config().count_evaluations) ++filter_stats().evaluations;
    if constexpr (std::is_empty_v<std::remove_cvref_t<F>> && std::is_default_constructible_v<std::remove_cvref_t<F>>) {
      // The static stage inline, everything after it out of line: the
      // common case is a few multiplications and a comparison at the caller.
      if (filter_config().enabled) [[likely]] {
        auto p = detail::static_stage(f, v.approx()...);
        if (p.certain) return p.s;
      }
      return detail::after_static_stage(f, v...);
    } else {
      return detail::semi_static_then_exact(f, v...);
    }
  }
}

} // namespace geometry
