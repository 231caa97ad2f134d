// Shared by the benchmark programs: what built them, and JSON strings.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

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

} // namespace bench
