// Shared by the subcommands of genbsp: the bad-input error, whole-or-nothing
// output files, exact numbers as text.
#pragma once

#include <geometry/number.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

namespace genbsp_tool {

using geometry::rational;

/// Bad input: reported as one line, exit status 2.
struct usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Writes `text` to `path` through a temporary file and a rename, so that the
/// file is either complete or untouched; "-" is standard output.
inline void write_file(std::string const& path, std::string const& text) {
  if (path == "-") {
    std::cout << text;
    return;
  }
  std::filesystem::path target(path), tmp = target;
  tmp += ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw usage_error(path + ": cannot write");
    out << text;
    out.flush();
    if (!out) {
      std::filesystem::remove(tmp);
      throw usage_error(path + ": write failed");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, target, ec);
  if (ec) {
    std::filesystem::remove(tmp);
    throw usage_error(path + ": " + ec.message());
  }
}

/// An exact number as text: a decimal when it terminates, else p/q.
inline std::string exact_text(rational const& q) {
  auto den = boost::multiprecision::denominator(q);
  geometry::integer d(den);
  int twos = 0, fives = 0;
  while (d % 2 == 0) d /= 2, ++twos;
  while (d % 5 == 0) d /= 5, ++fives;
  if (d != 1) return q.str();
  int digits = std::max(twos, fives);
  geometry::integer scale = boost::multiprecision::pow(geometry::integer(10), static_cast<unsigned>(digits));
  geometry::integer n = geometry::integer(boost::multiprecision::numerator(q)) * (scale / geometry::integer(den));
  bool neg = n < 0;
  std::string s = (neg ? geometry::integer(-n) : n).str();
  if (digits > 0) {
    if (s.size() <= static_cast<std::size_t>(digits)) s.insert(0, static_cast<std::size_t>(digits) - s.size() + 1, '0');
    s.insert(s.size() - static_cast<std::size_t>(digits), ".");
  }
  return (neg ? "-" : "") + s;
}

} // namespace genbsp_tool
