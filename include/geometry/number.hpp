/// @file
/// Number types of genbsp: the exact rational (the default) and `double`, the
/// exact text → number parser, and conversion to `double` for output.
#pragma once

#include <boost/multiprecision/gmp.hpp>

#include <charconv>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

namespace geometry {

/// The exact number type: a GMP rational without expression templates, so that
/// `auto` in generic code holds a value, never a lazy expression.
using rational = boost::multiprecision::number<boost::multiprecision::gmp_rational,
                                               boost::multiprecision::et_off>;

/// Exact integers, without expression templates (see `rational`).
using integer = boost::multiprecision::number<boost::multiprecision::gmp_int, boost::multiprecision::et_off>;

/// Opt-in trait: arithmetic on `T` is exact (no rounding in + − ×).
template <class T> inline constexpr bool is_exact_field_v = false;
template <> inline constexpr bool is_exact_field_v<rational> = true;

/// A number type genbsp computes with: an ordered field closed under + − ×
/// and constructible from `int`.
template <class T>
concept number = std::regular<T> && std::totally_ordered<T> && requires(T a, T b) {
  { a + b } -> std::convertible_to<T>;
  { a - b } -> std::convertible_to<T>;
  { a * b } -> std::convertible_to<T>;
  { -a } -> std::convertible_to<T>;
  T(0);
};

/// A number type whose arithmetic is exact: predicates over it return the true sign.
template <class T>
concept exact_field = number<T> && is_exact_field_v<T>;

/// The sign of a value, as predicates return it.
enum class sign : signed char { negative = -1, zero = 0, positive = 1 };

/// `sign` of an integer-like comparison result.
constexpr sign to_sign(int s) noexcept {
  return s < 0 ? sign::negative : (s > 0 ? sign::positive : sign::zero);
}
constexpr sign operator-(sign s) noexcept { return static_cast<sign>(-static_cast<int>(s)); }
constexpr sign operator*(sign a, sign b) noexcept {
  return static_cast<sign>(static_cast<int>(a) * static_cast<int>(b));
}

/// The sign of a number.
template <number T> sign sign_of(T const& x) {
  if constexpr (std::is_same_v<T, rational> || std::is_same_v<T, integer>)
    return to_sign(x.sign());
  else
    return x < T(0) ? sign::negative : (T(0) < x ? sign::positive : sign::zero);
}

/// Thrown for text that is not a number; `what()` says why, in one line.
struct parse_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

namespace detail {

/// Largest decimal exponent accepted, so that `1e999999999` cannot exhaust memory.
inline constexpr long max_decimal_exponent = 4000;

inline bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }

/// A non-empty string of decimal digits as an integer (always base 10: a
/// leading zero does not mean octal).
inline integer decimal_integer(std::string_view digits) {
  integer n;
  std::string s(digits);
  mpz_set_str(n.backend().data(), s.c_str(), 10);
  return n;
}

/// `[+-]digits[.digits]` with at most 18 digits in all, as a numerator and
/// a power of ten in machine words; `false` for anything else (exponents,
/// fractions, longer numbers, bad text), which `parse_rational` then reads.
inline bool short_decimal(std::string_view text, std::int64_t& numerator, std::int64_t& denominator) noexcept {
  std::size_t i = 0;
  bool negative = false;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
  std::int64_t n = 0, d = 1; // below 10^18 < 2^63
  std::size_t digits = 0;
  bool point = false;
  for (; i < text.size(); ++i) {
    char c = text[i];
    if (is_digit(c)) {
      if (++digits > 18) return false;
      n = n * 10 + (c - '0');
      if (point) d *= 10;
    } else if (c == '.' && !point) {
      point = true;
    } else {
      return false;
    }
  }
  if (digits == 0) return false;
  numerator = negative ? -n : n;
  denominator = d;
  return true;
}

/// Parses `[+-]digits[.digits][(e|E)[+-]digits]` or `[+-]digits/digits` exactly.
inline rational parse_rational(std::string_view text) {
  // Integers and short decimals, the common coordinates, without GMP's text
  // conversion (a mesh's reading was mostly that).
  if (std::int64_t n = 0, d = 1; short_decimal(text, n, d)) return d == 1 ? rational(n) : rational(n, d);
  auto fail = [&](char const* why) -> rational {
    throw parse_error("not a number '" + std::string(text) + "': " + why);
  };
  if (text.empty()) return fail("empty");
  std::size_t i = 0;
  bool negative = false;
  if (text[i] == '+' || text[i] == '-') negative = text[i++] == '-';
  std::string digits; // integer and fraction digits, the point removed
  long scale = 0;     // value = digits × 10^scale
  std::size_t int_digits = 0, frac_digits = 0;
  while (i < text.size() && is_digit(text[i])) digits += text[i++], ++int_digits;
  if (i < text.size() && text[i] == '/') {
    if (int_digits == 0) return fail("missing numerator");
    std::size_t j = ++i;
    while (i < text.size() && is_digit(text[i])) ++i;
    if (i == j) return fail("missing denominator");
    if (i != text.size()) return fail("unexpected character after denominator");
    auto den = decimal_integer(text.substr(j));
    if (den == 0) return fail("zero denominator");
    rational r = rational(decimal_integer(digits)) / rational(den);
    return negative ? rational(-r) : r;
  }
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && is_digit(text[i])) digits += text[i++], ++frac_digits;
    scale = -static_cast<long>(frac_digits);
  }
  if (int_digits + frac_digits == 0) return fail("no digits");
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool eneg = false;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) eneg = text[i++] == '-';
    std::size_t j = i;
    long e = 0;
    while (i < text.size() && is_digit(text[i])) {
      if (e > max_decimal_exponent) return fail("exponent out of range");
      e = e * 10 + (text[i++] - '0');
    }
    if (i == j) return fail("missing exponent digits");
    if (e > max_decimal_exponent) return fail("exponent out of range");
    scale += eneg ? -e : e;
  }
  if (i != text.size()) return fail("unexpected character");
  auto n = decimal_integer(digits);
  long a = scale < 0 ? -scale : scale;
  integer p = boost::multiprecision::pow(integer(10), static_cast<unsigned>(a));
  rational r = scale < 0 ? rational(rational(n) / rational(p)) : rational(n * p);
  return negative ? rational(-r) : r;
}

} // namespace detail

/// Reads a number written as an integer of any length, a decimal (`-0.1`,
/// `1e-3`, `2.5E+10`) or a fraction (`7/3`).  Exact for `rational`; for
/// `double` the correctly rounded nearest value.  Throws `parse_error` for
/// anything else (never a silent 0).
template <number T> T parse_number(std::string_view text) {
  rational exact = detail::parse_rational(text);
  if constexpr (std::is_same_v<T, rational>) {
    return exact;
  } else {
    if (text.find('/') == std::string_view::npos) {
      double d = 0;
      auto first = text.data() + (text.starts_with('+') ? 1 : 0);
      auto [ptr, ec] = std::from_chars(first, text.data() + text.size(), d);
      if (ec == std::errc() && ptr == text.data() + text.size()) return T(d);
      if (ec == std::errc::result_out_of_range)
        throw parse_error("not a number '" + std::string(text) + "': out of the range of double");
    }
    return T(exact.template convert_to<double>());
  }
}

/// Nearest-ish `double` of a number, for output only (never fed back into predicates).
template <number T> double to_double(T const& x) {
  if constexpr (std::is_same_v<T, rational>)
    return x.template convert_to<double>();
  else
    return static_cast<double>(x);
}

/// Bits needed for numerator plus denominator: how large an exact number has grown.
inline std::size_t bit_length(rational const& x) {
  return mpz_sizeinbase(mpq_numref(x.backend().data()), 2) +
         mpz_sizeinbase(mpq_denref(x.backend().data()), 2);
}

} // namespace geometry
