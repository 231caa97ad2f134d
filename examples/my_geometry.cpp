// My own geometry: the integer line E1 written from scratch as a bsp::geometry,
// two sets built from their ends (each interval on the negative side of its ends)
// and merged, the results checked pointwise and by inclusion–exclusion of lengths.
#include <bsp/bsp.hpp>

#include <iostream>
#include <optional>

struct MyLine {
  using point = long long;
  struct hyperplane { // an oriented point
    point at;
    bool up; // the positive side is x > at when up, x < at otherwise
  };
  using sub_hyperplane = hyperplane; // a hyperplane of the line is its only piece
  struct polytope {
    std::optional<point> lo, hi; // an open interval; an absent end is infinite
  };
  template <class T> struct parts {
    std::optional<T> negative, positive;
    int coincident = 0;
    bool is_coincident() const { return coincident != 0; }
  };
  static int side(hyperplane h, point p) { return ((p > h.at) - (p < h.at)) * (h.up ? 1 : -1); }
  static hyperplane opposite(hyperplane h) { return {h.at, !h.up}; }
  static polytope whole_space() { return {}; }
  static hyperplane whole(hyperplane h) { return h; }
  static hyperplane supporting(hyperplane s) { return s; }
  static parts<polytope> split(polytope const& c, hyperplane h) {
    std::optional<polytope> below, above;
    if (!c.lo || *c.lo < h.at) below = polytope{c.lo, c.hi && *c.hi < h.at ? c.hi : h.at};
    if (!c.hi || h.at < *c.hi) above = polytope{c.lo && *c.lo > h.at ? c.lo : h.at, c.hi};
    return h.up ? parts<polytope>{below, above} : parts<polytope>{above, below};
  }
  static parts<hyperplane> split(hyperplane s, hyperplane h) {
    if (s.at == h.at) return {std::nullopt, std::nullopt, s.up == h.up ? 1 : -1};
    return side(h, s.at) > 0 ? parts<hyperplane>{std::nullopt, s} : parts<hyperplane>{s, std::nullopt};
  }
  static std::optional<point> measure(polytope c) { return c.lo && c.hi ? std::optional(*c.hi - *c.lo) : std::nullopt; }
};
template <> inline constexpr bool bsp::enable_geometry<MyLine> = true;
static_assert(bsp::geometry<MyLine> && bsp::measured_space<MyLine>);

int main() {
  auto A = bsp::build_point_set<MyLine>({{0, false}, {3, true}, {6, false}, {9, true}}); // [0, 3] ∪ [6, 9]
  auto B = bsp::build_point_set<MyLine>({{3, false}, {7, true}});                        // [3, 7]
  auto U = bsp::set_union(A, B), I = bsp::set_intersection(A, B);
  bool ok = true; // off both boundaries, U(x) = A(x) or B(x) and I(x) = A(x) and B(x)
  for (long long x = -2; x <= 11; ++x)
    if (auto a = bsp::classify(A, x), b = bsp::classify(B, x); a && b)
      ok = ok && bsp::classify(U, x) == (*a || *b) && bsp::classify(I, x) == (*a && *b);
  auto len = [](auto const& t) { return bsp::measure(t, true).value_or(-1); }; // -1: unbounded
  std::cout << "|A| + |B| = " << len(A) + len(B) << ", |A u B| = " << len(U) << ", |A n B| = " << len(I) << '\n';
  if (!ok || len(U) != 9 || len(I) != 1 || len(A) + len(B) != len(U) + len(I)) { // A u B = [0, 9], A n B = [6, 7]
    std::cerr << "my_geometry: union or intersection disagrees with the hand check\n";
    return 1;
  }
  return 0;
}
