// The minimal bsp::geometry: the integer line with half-integer splits, just
// enough for the whole generic tree to compile and run against it.  Points
// are even integers, hyperplanes sit at odd integers, so no point is ever on
// a hyperplane and nothing needs exact arithmetic.
#pragma once

#include <bsp/concepts/geometry.hpp>

#include <optional>

namespace archetype {

struct line {
  using point = long; ///< even
  struct hyperplane {
    long at; ///< odd
    bool up; ///< positive side above `at`
    friend bool operator==(hyperplane const&, hyperplane const&) = default;
  };
  struct sub_hyperplane {
    hyperplane h;
  };
  struct polytope {
    std::optional<long> lo, hi; ///< open interval; absent ends are infinite
  };
  template <class T> struct split_result {
    std::optional<T> negative, positive;
    int coincident = 0;
    bool is_coincident() const { return coincident != 0; }
  };

  static int side(hyperplane const& h, point p) { return (p > h.at) == h.up ? 1 : -1; }
  static hyperplane opposite(hyperplane const& h) { return {h.at, !h.up}; }
  static sub_hyperplane opposite(sub_hyperplane const& s) { return {opposite(s.h)}; }
  static polytope whole_space() { return {}; }
  static sub_hyperplane whole(hyperplane const& h) { return {h}; }
  static hyperplane supporting(sub_hyperplane const& s) { return s.h; }
  static split_result<polytope> split(polytope const& c, hyperplane const& h) {
    bool inside = (!c.lo || *c.lo < h.at) && (!c.hi || h.at < *c.hi);
    if (!inside) {
      bool above = c.lo && *c.lo >= h.at;
      return (above == h.up) ? split_result<polytope>{std::nullopt, c} : split_result<polytope>{c, std::nullopt};
    }
    polytope below{c.lo, h.at}, above{h.at, c.hi};
    return h.up ? split_result<polytope>{below, above} : split_result<polytope>{above, below};
  }
  static split_result<sub_hyperplane> split(sub_hyperplane const& s, hyperplane const& h) {
    if (s.h.at == h.at) return {std::nullopt, std::nullopt, s.h.up == h.up ? 1 : -1};
    bool pos = (s.h.at > h.at) == h.up;
    return pos ? split_result<sub_hyperplane>{std::nullopt, s} : split_result<sub_hyperplane>{s, std::nullopt};
  }
  static std::optional<long> measure(polytope const& c) {
    if (!c.lo || !c.hi) return std::nullopt;
    return *c.hi - *c.lo;
  }
};

} // namespace archetype

template <> inline constexpr bool bsp::enable_geometry<archetype::line> = true;
