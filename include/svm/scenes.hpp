/// @file
/// The paper's four scene families (section 3.3), with exact integer
/// coordinates, and the suggested eye for each: Bricks, Hidden Bricks,
/// Platforms, Random; a terrain mesh and a sphere for large inputs; and a
/// furnished room with colours, for pictures.
#pragma once

#include "build.hpp"

#include <array>
#include <cstdint>
#include <numbers>
#include <optional>
#include <random>
#include <string>

namespace svm::scenes {

/// A scene: convex quadrilaterals (counter-clockwise seen from outside their
/// solid) and the eye the family is meant to be seen from.
struct scene {
  std::vector<polygon<geometry::rational>> polygons;
  geometry::e3::point<geometry::rational> eye;
  /// Colours (0..255) by polygon, when the scene has them (empty otherwise).
  std::vector<std::array<std::uint8_t, 3>> colours;
};

using Q = geometry::rational;
using P = geometry::e3::point<Q>;

/// Adds the six faces of the box [lo, hi], each as one quadrilateral, outward.
inline void add_box(scene& s, P const& lo, P const& hi) {
  auto v = [&](int i, int j, int k) { return P(i ? hi.x() : lo.x(), j ? hi.y() : lo.y(), k ? hi.z() : lo.z()); };
  std::uint32_t f = static_cast<std::uint32_t>(s.polygons.size());
  std::array<std::array<P, 4>, 6> q{{{v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0)},
                                     {v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1)},
                                     {v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1)},
                                     {v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0)},
                                     {v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0)},
                                     {v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1)}}};
  for (auto const& face : q) s.polygons.push_back({{face[0], face[1], face[2], face[3]}, f++});
  if (!s.colours.empty()) s.colours.resize(s.polygons.size(), {200, 200, 200});
}

/// Bricks: n/2 long bars in front, n/2 perpendicular bars behind them and a
/// back wall; through the gaps of the front row the eye sees Θ(n²) pieces.
inline scene bricks(std::size_t n) {
  scene s;
  long h = static_cast<long>(std::max<std::size_t>(n / 2, 1));
  for (long i = 0; i < h; ++i) // front: bars along x, gaps in y
    add_box(s, P(Q(-2 * h), Q(4 * i - 2 * h), Q(10)), P(Q(2 * h), Q(4 * i - 2 * h + 2), Q(11)));
  for (long j = 0; j < h; ++j) // behind: bars along y, gaps in x
    add_box(s, P(Q(4 * j - 2 * h), Q(-2 * h), Q(20)), P(Q(4 * j - 2 * h + 2), Q(2 * h), Q(21)));
  add_box(s, P(Q(-4 * h), Q(-4 * h), Q(30)), P(Q(4 * h), Q(4 * h), Q(31))); // the wall behind
  s.eye = P(Q(1, 3), Q(1, 7), Q(0));
  return s;
}

/// Hidden Bricks: Bricks, all behind one larger box nearer the eye.
inline scene hidden_bricks(std::size_t n) {
  scene s = bricks(n);
  long h = static_cast<long>(std::max<std::size_t>(n / 2, 1));
  std::vector<polygon<Q>> front;
  scene blocker;
  add_box(blocker, P(Q(-8 * h), Q(-8 * h), Q(4)), P(Q(8 * h), Q(8 * h), Q(5)));
  // The blocker first, so that face indices start with what is visible.
  for (auto& p : s.polygons) p.face += 6;
  blocker.polygons.insert(blocker.polygons.end(), s.polygons.begin(), s.polygons.end());
  blocker.eye = s.eye;
  return blocker;
}

/// Platforms: n square slabs, each farther and larger than the one before as
/// seen from the eye, so that every slab shows a ring around the nearer ones.
inline scene platforms(std::size_t n) {
  scene s;
  for (long i = 1; i <= static_cast<long>(n); ++i) {
    long r = i * i + i, z = 4 * i;
    add_box(s, P(Q(-r), Q(-r), Q(z)), P(Q(r), Q(r), Q(z + 1)));
  }
  s.eye = P(Q(1, 5), Q(1, 9), Q(0));
  return s;
}

/// Random: n cubes of side 2 turned by random exact rotations (quaternions
/// with small integer components give rational rotation matrices), at random
/// places in a box; they may intersect one another.
inline scene random_cubes(std::size_t n, std::uint64_t seed = 1) {
  scene s;
  std::mt19937_64 rng(seed);
  auto uni = [&](long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); };
  long extent = 4 + static_cast<long>(std::cbrt(static_cast<double>(n)) * 4);
  for (std::size_t c = 0; c < n; ++c) {
    long a = uni(1, 4), b = uni(-4, 4), cc = uni(-4, 4), d = uni(-4, 4);
    Q w(a * a + b * b + cc * cc + d * d);
    // Rotation matrix of the quaternion (a, b, c, d), divided by its norm.
    std::array<std::array<Q, 3>, 3> R{{{Q(a * a + b * b - cc * cc - d * d) / w, Q(2 * (b * cc - a * d)) / w, Q(2 * (b * d + a * cc)) / w},
                                       {Q(2 * (b * cc + a * d)) / w, Q(a * a - b * b + cc * cc - d * d) / w, Q(2 * (cc * d - a * b)) / w},
                                       {Q(2 * (b * d - a * cc)) / w, Q(2 * (cc * d + a * b)) / w, Q(a * a - b * b - cc * cc + d * d) / w}}};
    P centre(Q(uni(-extent, extent)), Q(uni(-extent, extent)), Q(uni(6, 6 + 2 * extent)));
    scene cube;
    add_box(cube, P(Q(-1), Q(-1), Q(-1)), P(Q(1), Q(1), Q(1)));
    for (auto& p : cube.polygons) {
      for (auto& v : p.vertices) {
        std::array<Q, 3> x{v.x(), v.y(), v.z()}, y;
        for (std::size_t i = 0; i < 3; ++i) y[i] = R[i][0] * x[0] + R[i][1] * x[1] + R[i][2] * x[2];
        v = P(Q(y[0] + centre.x()), Q(y[1] + centre.y()), Q(y[2] + centre.z()));
      }
      p.face += static_cast<std::uint32_t>(s.polygons.size());
    }
    s.polygons.insert(s.polygons.end(), cube.polygons.begin(), cube.polygons.end());
  }
  s.eye = P(Q(1, 3), Q(1, 7), Q(0));
  return s;
}

/// A terrain: a `k` × `k` grid of integer heights, two triangles per cell
/// (2k² triangles), seen from above.
inline scene terrain(std::size_t k, std::uint64_t seed = 1) {
  scene s;
  std::mt19937_64 rng(seed);
  std::vector<long> h((k + 1) * (k + 1));
  for (std::size_t i = 0; i <= k; ++i)
    for (std::size_t j = 0; j <= k; ++j) {
      double x = static_cast<double>(i) / static_cast<double>(k), y = static_cast<double>(j) / static_cast<double>(k);
      h[i * (k + 1) + j] = std::lround(20 * std::sin(7 * x) * std::cos(5 * y) + 6 * std::sin(23 * x * y)) +
                           std::uniform_int_distribution<long>(0, 2)(rng);
    }
  auto p = [&](std::size_t i, std::size_t j) { return P(Q(static_cast<long>(i)), Q(static_cast<long>(j)), Q(h[i * (k + 1) + j])); };
  std::uint32_t f = 0;
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < k; ++j) {
      s.polygons.push_back({{p(i, j), p(i + 1, j), p(i + 1, j + 1)}, f++});
      s.polygons.push_back({{p(i, j), p(i + 1, j + 1), p(i, j + 1)}, f++});
    }
  long c = static_cast<long>(k) / 2;
  s.eye = P(Q(c) + Q(1, 3), Q(-static_cast<long>(k) / 3) + Q(1, 7), Q(60));
  return s;
}

/// A closed sphere of 4k(k − 1) triangles with integer vertices (radius
/// 100000, latitude–longitude grid, rounded), outward, seen from outside.
inline scene sphere(std::size_t k) {
  scene s;
  k = std::max<std::size_t>(k, 3);
  double const R = 100000, pi = std::numbers::pi;
  std::vector<std::array<long, 3>> v{{0, 0, static_cast<long>(R)}};
  for (std::size_t i = 1; i < k; ++i)
    for (std::size_t j = 0; j < 2 * k; ++j) {
      double t = pi * static_cast<double>(i) / static_cast<double>(k), p = pi * static_cast<double>(j) / static_cast<double>(k);
      v.push_back({std::lround(R * std::sin(t) * std::cos(p)), std::lround(R * std::sin(t) * std::sin(p)), std::lround(R * std::cos(t))});
    }
  v.push_back({0, 0, -static_cast<long>(R)});
  auto ring = [&](std::size_t i, std::size_t j) { return 1 + (i - 1) * 2 * k + j % (2 * k); };
  std::uint32_t f = 0;
  auto tri = [&](std::size_t a, std::size_t b, std::size_t c) {
    auto const &A = v[a], &B = v[b], &C = v[c];
    // Outward: the normal points away from the centre.
    std::array<long, 3> u{B[0] - A[0], B[1] - A[1], B[2] - A[2]}, w{C[0] - A[0], C[1] - A[1], C[2] - A[2]};
    double n0 = double(u[1]) * double(w[2]) - double(u[2]) * double(w[1]), n1 = double(u[2]) * double(w[0]) - double(u[0]) * double(w[2]),
           n2 = double(u[0]) * double(w[1]) - double(u[1]) * double(w[0]);
    bool out = n0 * double(A[0] + B[0] + C[0]) + n1 * double(A[1] + B[1] + C[1]) + n2 * double(A[2] + B[2] + C[2]) > 0;
    auto P3 = [&](std::size_t i) { return P(Q(v[i][0]), Q(v[i][1]), Q(v[i][2])); };
    s.polygons.push_back({out ? std::vector<P>{P3(a), P3(b), P3(c)} : std::vector<P>{P3(a), P3(c), P3(b)}, f++});
  };
  std::size_t south = v.size() - 1;
  for (std::size_t j = 0; j < 2 * k; ++j) {
    tri(0, ring(1, j), ring(1, j + 1));
    tri(south, ring(k - 1, j + 1), ring(k - 1, j));
    for (std::size_t i = 1; i + 1 < k; ++i) {
      tri(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1));
      tri(ring(i, j), ring(i + 1, j + 1), ring(i, j + 1));
    }
  }
  s.eye = P(Q(250000) + Q(1, 3), Q(120000) + Q(1, 7), Q(90000));
  return s;
}

/// A furnished room, 6 m × 5 m × 2.8 m in centimetres, with colours: walls,
/// floor and ceiling facing inwards, a window and a door, a table with four
/// chairs, a sofa, a bookcase with books, a rug, a lamp and a picture; seen
/// from a standing eye by the door.  Boxes only (some touching, some
/// sharing planes): a scene that looks like something and is full of the
/// degenerate contacts real models have.
inline scene room() {
  scene s;
  s.colours.reserve(512);
  using rgb8 = std::array<std::uint8_t, 3>;
  auto box = [&](long x0, long y0, long z0, long x1, long y1, long z1, rgb8 c) {
    std::size_t first = s.polygons.size();
    add_box(s, P(Q(x0), Q(y0), Q(z0)), P(Q(x1), Q(y1), Q(z1)));
    s.colours.resize(s.polygons.size(), c);
    for (std::size_t i = first; i < s.polygons.size(); ++i) s.colours[i] = c;
  };
  // An inward quadrilateral (counter-clockwise seen from inside the room).
  auto quad = [&](std::array<std::array<long, 3>, 4> const& v, rgb8 c) {
    std::vector<P> ps;
    for (auto const& a : v) ps.push_back(P(Q(a[0]), Q(a[1]), Q(a[2])));
    s.polygons.push_back({std::move(ps), static_cast<std::uint32_t>(s.polygons.size())});
    s.colours.push_back(c);
  };
  rgb8 const wall{236, 228, 212}, floor{170, 120, 78}, ceiling{248, 248, 244}, wood{139, 94, 60}, dark{92, 64, 44},
      fabric{70, 110, 150}, white{245, 245, 240}, rug{160, 52, 58}, frame{60, 60, 60};
  long const X = 600, Y = 500, Z = 280;
  quad({{{0, 0, 0}, {X, 0, 0}, {X, Y, 0}, {0, Y, 0}}}, floor);
  quad({{{0, 0, Z}, {0, Y, Z}, {X, Y, Z}, {X, 0, Z}}}, ceiling);
  quad({{{0, 0, 0}, {0, Y, 0}, {0, Y, Z}, {0, 0, Z}}}, wall);         // x = 0
  quad({{{0, 0, 0}, {0, 0, Z}, {X, 0, Z}, {X, 0, 0}}}, wall);         // y = 0
  quad({{{0, Y, 0}, {X, Y, 0}, {X, Y, Z}, {0, Y, Z}}}, wall);         // y = Y
  // The wall x = X with a window 200 × 120 at height 90: four pieces around it.
  quad({{{X, 0, 0}, {X, 0, Z}, {X, 150, Z}, {X, 150, 0}}}, wall);
  quad({{{X, 350, 0}, {X, 350, Z}, {X, Y, Z}, {X, Y, 0}}}, wall);
  quad({{{X, 150, 0}, {X, 150, 90}, {X, 350, 90}, {X, 350, 0}}}, wall);
  quad({{{X, 150, 210}, {X, 150, Z}, {X, 350, Z}, {X, 350, 210}}}, wall);
  box(X - 8, 146, 86, X + 4, 354, 90, white); // sill and frame of the window
  box(X - 8, 146, 210, X + 4, 354, 214, white);
  box(X - 8, 146, 90, X + 4, 150, 210, white);
  box(X - 8, 350, 90, X + 4, 354, 210, white);
  box(X - 4, 248, 90, X + 2, 252, 210, white);
  box(X + 120, -200, -50, X + 130, 700, 400, {150, 190, 225}); // the sky beyond the window
  box(20, -4, 0, 110, 4, 210, wood);                             // the door, in the wall y = 0
  box(95, 4, 100, 101, 10, 106, {200, 170, 60});                 // its handle
  // The rug, the table and four chairs.
  box(200, 150, 0, 460, 350, 1, rug);
  box(250, 205, 72, 410, 295, 77, wood);
  for (auto [x, y] : std::array<std::array<long, 2>, 4>{{{255, 210}, {399, 210}, {255, 284}, {399, 284}}}) box(x, y, 0, x + 6, y + 6, 72, dark);
  auto chair = [&](long x, long y, int facing) { // facing: +1 looks towards +y, −1 towards −y
    box(x, y, 44, x + 44, y + 44, 48, wood);
    for (auto [dx, dy] : std::array<std::array<long, 2>, 4>{{{0, 0}, {40, 0}, {0, 40}, {40, 40}}}) box(x + dx, y + dy, 0, x + dx + 4, y + dy + 4, 44, dark);
    long by = facing > 0 ? y : y + 40;
    box(x, by, 48, x + 44, by + 4, 95, wood);
  };
  chair(280, 150, +1);
  chair(338, 150, +1);
  chair(280, 306, -1);
  chair(338, 306, -1);
  // The sofa against the wall y = Y.
  box(150, 410, 0, 390, 490, 42, fabric);
  box(150, 470, 42, 390, 490, 90, fabric);
  box(150, 410, 42, 170, 470, 62, fabric);
  box(370, 410, 42, 390, 470, 62, fabric);
  // The bookcase against the wall x = 0, with books of many colours.
  box(2, 300, 0, 40, 304, 200, wood);
  box(2, 476, 0, 40, 480, 200, wood);
  box(0, 300, 0, 2, 480, 200, dark);
  std::mt19937_64 rng(7);
  auto uni = [&](long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); };
  for (long z = 0; z <= 200; z += 40) {
    box(2, 304, z, 40, 476, z + 3, wood);
    if (z == 200) break;
    for (long y = 306; y < 470;) {
      long w = uni(3, 7), h = uni(24, 34);
      if (y + w > 474) break;
      rgb8 c{static_cast<std::uint8_t>(uni(40, 220)), static_cast<std::uint8_t>(uni(40, 200)), static_cast<std::uint8_t>(uni(40, 200))};
      box(6, y, z + 3, 34, y + w, z + 3 + h, c);
      y += w + uni(0, 2);
    }
  }
  // A standing lamp and a picture on the wall y = Y.
  box(520, 420, 0, 550, 450, 3, frame);
  box(533, 433, 3, 537, 437, 150, frame);
  box(515, 415, 150, 555, 455, 185, {250, 225, 160});
  box(180, Y - 3, 130, 360, Y, 230, frame);
  box(190, Y - 4, 140, 350, Y - 3, 220, {90, 140, 110});
  s.eye = P(Q(80) + Q(1, 3), Q(60) + Q(1, 7), Q(165) + Q(1, 11));
  return s;
}

} // namespace svm::scenes
