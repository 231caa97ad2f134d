// Shared by the subcommands of genbsp: the bad-input error, whole-or-nothing
// output files, exact numbers as text.
#pragma once

#include <geometry/number.hpp>

#include "version.hpp"

#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace genbsp_tool {

using geometry::rational;

/// What ran: the version and the source revision (git describe), as
/// `genbsp --version` prints it and every JSON summary carries it.
inline std::string version() { return GENBSP_VERSION " (" GENBSP_REVISION ")"; }

/// Where a subcommand writes what it prints (standard output unless a
/// caller, such as `genbsp batch` or the Python module, captures it for the
/// running thread).
inline std::ostream*& output_stream() {
  thread_local std::ostream* s = &std::cout;
  return s;
}
inline std::ostream& out() { return *output_stream(); }

/// Whether this thread runs the jobs of a batch: subcommands then report no
/// progress of their own.
inline bool& batch_worker() {
  thread_local bool b = false;
  return b;
}

/// Whether `run` only checks its command line (a batch checks every job's
/// before running any).
inline bool& parse_only() {
  thread_local bool b = false;
  return b;
}

/// Whether `run` serves the genbsp program (set by `run_main`), which owns
/// its process: only then may `--max-memory` limit the process's memory.
inline bool& program_owns_process() {
  static bool b = false;
  return b;
}

/// The memory limit the program runs under (`--max-memory`), as given; empty
/// when none.  Named in the out-of-memory message.
inline std::string& memory_limit_text() {
  static std::string s;
  return s;
}

/// "out of memory", with the limit it ran under when there is one:
/// "out of memory (--max-memory 1G)".
inline std::string out_of_memory_text() {
  return "out of memory" + (memory_limit_text().empty() ? std::string() : " (--max-memory " + memory_limit_text() + ")");
}

/// Thrown, when `parse_only()`, by a command that has checked all it can
/// check without reading its scene.
struct options_checked {};

/// Bad input: reported as one line, exit status 2.
struct usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A file that cannot be opened or written: bad input to the program (status
/// 2) like any other, told apart for callers that answer it differently
/// (Python raises OSError).  `code` is the `errno` value, 0 when unknown.
struct file_error : usage_error {
  int code = 0;
  file_error(std::string const& text, int error_code) : usage_error(text), code(error_code) {}
};

/// Writes `text` to `path` through a temporary file and a rename, so that the
/// file is either complete or untouched; "-" is standard output.
inline void write_file(std::string const& path, std::string const& text) {
  if (path == "-") {
    out() << text;
    return;
  }
  std::filesystem::path target(path), tmp = target;
  tmp += ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) {
      int code = errno;
      throw file_error(path + ": cannot write", code);
    }
    out << text;
    out.flush();
    if (!out) {
      std::filesystem::remove(tmp);
      throw file_error(path + ": write failed", EIO);
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, target, ec);
  if (ec) {
    std::filesystem::remove(tmp);
    throw file_error(path + ": " + ec.message(), ec.value());
  }
}

/// "A,B,…" read exactly as `count` numbers.
inline std::vector<rational> parse_numbers(std::string const& text, std::size_t count, std::string const& option, std::string const& form) {
  std::vector<rational> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i < count; ++i) {
    std::size_t end = text.find(',', start);
    if ((i + 1 < count) != (end != std::string::npos)) throw usage_error(option + ": expected " + form + ", got '" + text + "'");
    try {
      out.push_back(geometry::parse_number<rational>(text.substr(start, end == std::string::npos ? std::string::npos : end - start)));
    } catch (geometry::parse_error const& e) {
      throw usage_error(option + ": " + e.what());
    }
    start = end + 1;
  }
  return out;
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

/// The extension of `path`, lower case, with its dot.
inline std::string extension(std::string const& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (auto& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

/// A line of numbers read from a file, and its number.
struct number_line {
  std::size_t line;
  std::vector<rational> values;
};

/// The lines of `count` numbers of a file ("-": standard input), read
/// exactly; "#" starts a comment, blank lines are skipped, commas count as
/// spaces.  Bad input is a `usage_error` naming the file and line; `form`
/// names what a line should hold ("'dx dy dz'").
inline std::vector<number_line> read_number_lines(std::string const& path, std::size_t count, std::string const& form) {
  std::ifstream file;
  std::istream* in = &std::cin;
  if (path != "-") {
    file.open(path);
    if (!file) {
      int code = errno;
      throw file_error(path + ": cannot open", code);
    }
    in = &file;
  }
  std::string name = path == "-" ? "<stdin>" : path;
  std::vector<number_line> out;
  std::string line;
  for (std::size_t number = 1; std::getline(*in, line); ++number) {
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    for (auto& c : line)
      if (c == ',') c = ' ';
    std::istringstream words(line);
    std::vector<std::string> w{std::istream_iterator<std::string>(words), {}};
    if (w.empty()) continue;
    if (w.size() != count) throw usage_error(name + ":" + std::to_string(number) + ": expected " + form);
    number_line l{number, {}};
    for (auto const& x : w) try {
        l.values.push_back(geometry::parse_number<rational>(x));
      } catch (geometry::parse_error const& e) {
        throw usage_error(name + ":" + std::to_string(number) + ": " + e.what());
      }
    out.push_back(std::move(l));
  }
  return out;
}

} // namespace genbsp_tool
