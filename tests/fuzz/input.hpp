// Helpers shared by the fuzz targets: the input's bytes read as small
// numbers (zero once they run out), and the tiny scenes that the map and
// rendering targets build from them.
#pragma once

#include "../svm/ray_cast.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace fuzz {

/// The input's bytes, read one at a time.
class input {
public:
  input(std::uint8_t const* data, std::size_t size) : data_(data), size_(size) {}
  /// The next byte, 0 once the input is used up.
  long byte() { return at_ < size_ ? data_[at_++] : 0; }
  /// An integer in [lo, hi] from the next byte.
  long in(long lo, long hi) { return lo + byte() % (hi - lo + 1); }
  bool done() const { return at_ >= size_; }

private:
  std::uint8_t const* data_;
  std::size_t size_, at_ = 0;
};

/// Reports a failed check on standard error and aborts: libFuzzer keeps the input.
[[noreturn]] inline void fail(char const* target, std::string const& what) {
  std::fprintf(stderr, "%s: %s\n", target, what.c_str());
  std::abort();
}

/// A tiny scene: the eye and up to 8 triangles or boxes (some slanted), every
/// coordinate an integer in [−4, 4], so that shared edges, coplanar and
/// crossing polygons, eyes on planes and on edges' lines are the usual case.
struct tiny_scene {
  test::ray::ivec eye;
  std::vector<test::ray::triangle> triangles;
};

inline tiny_scene read_scene(input& in) {
  using namespace test::ray;
  auto point = [&] { return ivec{in.in(-4, 4), in.in(-4, 4), in.in(-4, 4)}; };
  tiny_scene s{point(), {}};
  for (long k = 0, shapes = in.in(1, 8); k < shapes && !in.done(); ++k) {
    if (in.byte() % 4 == 0) {
      ivec lo = point(), hi{lo[0] + in.in(1, 4), lo[1] + in.in(1, 4), lo[2] + in.in(1, 4)};
      add_box(s.triangles, lo, hi, static_cast<int>(in.byte() % 2));
    } else {
      triangle t{{point(), point(), point()}};
      s.triangles.push_back(t);
    }
  }
  std::erase_if(s.triangles, [](triangle const& t) { return !nondegenerate(t); }); // a slanted box's faces may fold flat
  return s;
}

} // namespace fuzz
