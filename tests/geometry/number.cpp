#include "support.hpp"

#include <catch2/catch.hpp>
#include <geometry/number.hpp>

#include <random>
#include <string>

using geometry::parse_error;
using geometry::parse_number;
using geometry::rational;

namespace geometry_number_tests {

TEST_CASE("decimal text is read exactly", "[number]") {
  CHECK(parse_number<rational>("-0.1") == rational(-1, 10));
  CHECK(parse_number<rational>("1e-3") == rational(1, 1000));
  CHECK(parse_number<rational>("2.5E+10") == rational(25000000000LL));
  CHECK(parse_number<rational>("+7") == rational(7));
  CHECK(parse_number<rational>(".5") == rational(1, 2));
  CHECK(parse_number<rational>("5.") == rational(5));
  CHECK(parse_number<rational>("7/3") == rational(7, 3));
  CHECK(parse_number<rational>("-14/6") == rational(-7, 3));
  CHECK(parse_number<rational>("0.000") == rational(0));
  CHECK(parse_number<rational>("0.0593") == rational(593, 10000)); // leading zeros are not octal
  CHECK(parse_number<rational>("0019/0007") == rational(19, 7));
  CHECK(parse_number<rational>("1.25e-2") == rational(1, 80));
  // An integer longer than any machine word.
  auto big = parse_number<rational>("123456789012345678901234567890123456789");
  CHECK(big == rational(boost::multiprecision::mpz_int("123456789012345678901234567890123456789")));
  // 0.1 is not the double 0.1.
  CHECK(parse_number<rational>("0.1") != rational(0.1));
}

TEST_CASE("short decimals read on machine words equal the general reading", "[number]") {
  // parse_rational reads up to 18 digits in machine words and longer or
  // other numbers through GMP; both must give the same canonical rational.
  auto expected = [](bool negative, std::string const& digits, int after_point) {
    boost::multiprecision::mpz_int n = 0, d = 1; // digit by digit: a leading zero is not octal
    for (char c : digits) n = n * 10 + (c - '0');
    for (int k = 0; k < after_point; ++k) d *= 10;
    rational r(n, d);
    return negative ? rational(-r) : r;
  };
  std::mt19937_64 random(20261206);
  for (int i = 0; i < 20000; ++i) {
    int length = 1 + static_cast<int>(random() % 21); // 1 to 21 digits: both sides of 18
    std::string digits;
    for (int k = 0; k < length; ++k) digits += static_cast<char>('0' + random() % 10);
    if (i % 7 == 0) digits = std::string(static_cast<std::size_t>(length), '9'); // the largest of each length
    int after_point = static_cast<int>(random() % static_cast<unsigned>(length + 1));
    bool negative = random() % 2 == 1;
    auto split = digits.size() - static_cast<std::size_t>(after_point);
    std::string text;
    if (negative) text += '-';
    else if (random() % 4 == 0) text += '+';
    text.append(digits, 0, split);
    if (after_point > 0 || random() % 5 == 0) text.append(1, '.').append(digits, split);
    INFO("input: '" << text << "'");
    rational got = parse_number<rational>(text), want = expected(negative, digits, after_point);
    REQUIRE(got == want);
    // Canonical: the same numerator and denominator, not only equal values.
    REQUIRE(boost::multiprecision::numerator(got) == boost::multiprecision::numerator(want));
    REQUIRE(boost::multiprecision::denominator(got) == boost::multiprecision::denominator(want));
  }
  CHECK(parse_number<rational>("999999999999999999") == rational(999999999999999999LL));
  CHECK(parse_number<rational>("-0.000000000000000001") == rational(-1, 1000000000000000000LL));
  CHECK(parse_number<rational>("-0") == rational(0));
}

TEST_CASE("garbage is rejected with a reason, never read as 0", "[number]") {
  for (char const* bad : {"", "-", "+", ".", "abc", "1.2.3", "1e", "1e+", "e5", "1x", "0x10", " 1", "1 ", "inf", "nan",
                          "1/0", "/3", "3/", "1/-2", "1,5", "--1", "1e99999999999"}) {
    INFO("input: '" << bad << "'");
    CHECK_THROWS_AS(parse_number<rational>(bad), parse_error);
    CHECK_THROWS_AS(parse_number<double>(bad), parse_error);
  }
  try {
    parse_number<rational>("1.2.3");
    FAIL("no exception");
  } catch (parse_error const& e) {
    CHECK(std::string(e.what()).find("1.2.3") != std::string::npos);
  }
}

TEST_CASE("double parsing rounds correctly", "[number]") {
  CHECK(parse_number<double>("0.1") == 0.1);
  CHECK(parse_number<double>("-2.5E+10") == -2.5e10);
  CHECK(parse_number<double>("1/3") == Approx(1.0 / 3.0).epsilon(1e-16));
  CHECK(parse_number<double>("123456789012345678901234567890") == 123456789012345678901234567890.0);
  CHECK_THROWS_AS(parse_number<double>("1e400"), parse_error);
}

TEST_CASE("bit length grows with the number", "[number]") {
  CHECK(geometry::bit_length(rational(1)) == 2);
  CHECK(geometry::bit_length(rational(255, 2)) == 10);
}

} // namespace geometry_number_tests
