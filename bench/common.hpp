// Shared by the benchmark programs: what built them, and JSON strings.
#pragma once

#include <geometry/number.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace bench {

/// The compiler and its version.
inline std::string compiler() {
#if defined(__clang__)
  return "clang " __clang_version__;
#elif defined(__GNUC__)
  return "g++ " __VERSION__;
#else
  return "unknown";
#endif
}

/// Whether the build is optimised.
constexpr bool optimised() {
#if defined(__OPTIMIZE__)
  return true;
#else
  return false;
#endif
}

/// `s` as a JSON string literal.
inline std::string json_string(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

/// The point X,Y,Z (exact numbers, as the command line writes them).
inline std::array<geometry::rational, 3> parse_point(std::string_view text, std::string_view what) {
  std::array<geometry::rational, 3> p;
  std::size_t at = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    std::size_t comma = k < 2 ? text.find(',', at) : text.size();
    if (comma == std::string_view::npos) throw std::invalid_argument(std::string(what) + ": expected X,Y,Z");
    p[k] = geometry::parse_number<geometry::rational>(text.substr(at, comma - at));
    at = comma + 1;
  }
  return p;
}

/// The median wall-clock time of `runs` calls of `f`, in seconds.
template <class F> double median_seconds(int runs, F&& f) {
  std::vector<double> t;
  for (int r = 0; r < runs; ++r) {
    auto t0 = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

} // namespace bench
