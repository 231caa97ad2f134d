// An exact ray caster for scenes of integer triangles (128-bit integer
// arithmetic on the input, sharing nothing with the library), and boxes made
// of such triangles: the independent truth the visibility map is checked
// against, by the tests and by the map's fuzz target.
#pragma once

#include <geometry/number.hpp>
#include <svm/build.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace test::ray {

__extension__ using i128 = __int128;
using ivec = std::array<long, 3>;
struct triangle {
  std::array<ivec, 3> v;
};

inline ivec sub(ivec a, ivec b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline std::array<i128, 3> cross(std::array<i128, 3> a, std::array<i128, 3> b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline std::array<i128, 3> wide(ivec a) { return {a[0], a[1], a[2]}; }
inline i128 dot(std::array<i128, 3> a, std::array<i128, 3> b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

inline constexpr long ambiguous = -2;

/// The triangle seen first from `o` in direction `d` (two-sided), −1 for none,
/// or `ambiguous` when the answer is not determined: the ray grazes an edge or
/// vertex no farther than the first hit, or two triangles tie there.
inline long cast(std::vector<triangle> const& scene, ivec o, ivec d, bool cull_back = false) {
  struct hit {
    i128 num, den; // t = num / den, den > 0
    bool boundary;
    long id;
  };
  std::vector<hit> hits;
  for (std::size_t i = 0; i < scene.size(); ++i) {
    auto const& t = scene[i].v;
    auto n = cross(wide(sub(t[1], t[0])), wide(sub(t[2], t[0])));
    i128 den = dot(n, wide(d)), num = dot(n, wide(sub(t[0], o)));
    if (den == 0) continue;
    if (cull_back && num > 0) continue; // the eye is behind the triangle's front
    if (den < 0) num = -num, den = -den;
    if (num <= 0) continue;
    int pos = 0, zero = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      auto e = wide(sub(t[(k + 1) % 3], t[k]));
      auto w = wide(sub(o, t[k]));
      std::array<i128, 3> x{den * w[0] + num * d[0], den * w[1] + num * d[1], den * w[2] + num * d[2]};
      i128 s = dot(cross(e, x), n);
      pos += s > 0;
      zero += s == 0;
    }
    if (pos + zero < 3) continue;
    hits.push_back({num, den, zero > 0, static_cast<long>(i)});
  }
  long best = -1;
  hit const* first = nullptr;
  for (auto const& h : hits)
    if (!h.boundary && (!first || h.num * first->den < first->num * h.den)) first = &h, best = h.id;
  for (auto const& h : hits) {
    if (!first) {
      if (h.boundary) return ambiguous;
      continue;
    }
    if (&h == first) continue;
    i128 a = h.num * first->den, b = first->num * h.den;
    if (a < b && h.boundary) return ambiguous;
    if (a == b) return ambiguous;
  }
  return best;
}

inline bool nondegenerate(triangle const& t) {
  auto n = cross(wide(sub(t.v[1], t.v[0])), wide(sub(t.v[2], t.v[0])));
  return n[0] != 0 || n[1] != 0 || n[2] != 0;
}

/// An axis-aligned box [lo, hi] as 12 outward triangles, optionally rotated a
/// quarter turn about z (exact) … or sheared, for boxes not aligned with the axes.
inline void add_box(std::vector<triangle>& s, ivec lo, ivec hi, int turn = 0) {
  auto v = [&](int i, int j, int k) {
    ivec p{i ? hi[0] : lo[0], j ? hi[1] : lo[1], k ? hi[2] : lo[2]};
    if (turn == 1) p = {p[0] + p[2] / 2, p[1] - p[2] / 3, p[2] + p[0] / 2}; // an exact linear map: a slanted box
    return p;
  };
  std::array<std::array<ivec, 4>, 6> q{{{v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0)},
                                        {v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1)},
                                        {v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1)},
                                        {v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0)},
                                        {v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0)},
                                        {v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1)}}};
  for (auto const& f : q) {
    s.push_back({{f[0], f[1], f[2]}});
    s.push_back({{f[0], f[2], f[3]}});
  }
}

inline std::vector<svm::polygon<geometry::rational>> polygons_of(std::vector<triangle> const& s) {
  using Q = geometry::rational;
  std::vector<svm::polygon<Q>> out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    std::vector<geometry::e3::point<Q>> v;
    for (auto const& p : s[i].v) v.emplace_back(Q(p[0]), Q(p[1]), Q(p[2]));
    out.push_back({v, static_cast<std::uint32_t>(i)});
  }
  return out;
}

} // namespace test::ray
