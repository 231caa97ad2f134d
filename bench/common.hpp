// Shared by the benchmark programs: what built them, and JSON strings.
#pragma once

#include <geometry/number.hpp>

#include <poll.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
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

/// The median of `v` (the mean of the middle two for an even count; 0 for none).
inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/// How often a case is run: at least `at_least` times (unless a run is
/// long), more while short runs add up to less than `min_total`, at most
/// `at_most` times, and never again after a run of `long_run` seconds.
struct repetition {
  int at_least = 3;
  int at_most = 15;
  double min_total = 0.25;
  double long_run = 10;

  /// Whether another run is due after `runs` (seconds).
  bool another_run(std::vector<double> const& runs) const {
    if (runs.empty()) return true;
    if (runs.back() >= long_run) return false;
    double total = 0;
    for (double s : runs) total += s;
    int n = static_cast<int>(runs.size());
    return n < at_least || (n < at_most && total < min_total);
  }
};

/// Writes all of `s` to `fd` (a measuring child's report), retrying after signals.
inline void write_all(int fd, std::string const& s) {
  std::size_t done = 0;
  while (done < s.size()) {
    ssize_t w = ::write(fd, s.data() + done, s.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return;
    done += static_cast<std::size_t>(w);
  }
}

/// How a measuring child process ended.
struct child_end {
  std::string status; ///< "ok", "not finished" (stopped at the limit), or "error: …"
  bool timed_out = false;
};

/// Runs `body(fd)` in a child process that reports on `fd` one line at a
/// time, and passes each line to `on_line(kind, rest)` (its first word and
/// the rest).  The child's "done" line ends it well, "error MESSAGE" (or an
/// exception out of `body`) badly.  A child silent for longer than `limit`
/// seconds is stopped: "not finished".
template <class Body, class OnLine> child_end run_in_child(double limit, Body body, OnLine on_line) {
  using clock = std::chrono::steady_clock;
  child_end end;
  int fds[2];
  if (::pipe(fds) != 0) return {std::string("error: pipe: ") + std::strerror(errno)};
  std::fflush(stdout);
  std::fflush(stderr);
  pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return {std::string("error: fork: ") + std::strerror(errno)};
  }
  if (pid == 0) {
    ::close(fds[0]);
    try {
      body(fds[1]);
      write_all(fds[1], "done\n");
    } catch (std::exception const& e) {
      std::string msg = e.what();
      std::replace(msg.begin(), msg.end(), '\n', ' ');
      write_all(fds[1], "error " + msg + "\n");
    }
    ::close(fds[1]);
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string buffer;
  bool done = false;
  auto deadline = clock::now() + std::chrono::duration<double>(limit);
  while (!done) {
    double left = std::chrono::duration<double>(deadline - clock::now()).count();
    if (left <= 0) {
      end.timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(std::ceil(std::min(left, 1.0) * 1000))) <= 0) continue; // this poll's time, or a signal
    char chunk[4096];
    ssize_t got = ::read(fds[0], chunk, sizeof chunk);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) {
      end.status = "error: the measuring process ended without a result";
      break;
    }
    buffer.append(chunk, static_cast<std::size_t>(got));
    for (std::size_t nl; (nl = buffer.find('\n')) != std::string::npos;) {
      std::istringstream in(buffer.substr(0, nl));
      buffer.erase(0, nl + 1);
      std::string kind;
      in >> kind;
      if (kind == "done") {
        end.status = "ok", done = true;
      } else if (kind == "error") {
        std::string rest;
        std::getline(in, rest);
        end.status = "error:" + rest, done = true;
      } else {
        on_line(kind, in);
      }
      deadline = clock::now() + std::chrono::duration<double>(limit);
    }
  }
  if (end.timed_out) {
    ::kill(pid, SIGKILL);
    end.status = "not finished";
  }
  ::close(fds[0]);
  int wstatus = 0;
  while (::waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {
  }
  if (!end.timed_out && WIFSIGNALED(wstatus)) end.status = "error: signal " + std::to_string(WTERMSIG(wstatus));
  return end;
}

} // namespace bench
