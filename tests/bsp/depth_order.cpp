// Depth order: along sample rays from the eye, no fragment is listed after a
// fragment behind it.  Checked with an independent exact ray test (plain
// rational arithmetic on the fragments' exact vertices) on triangle soups
// with intersecting, coplanar and shared-edge triangles, and segment soups.
#include "../support.hpp"

#include <bsp/bsp.hpp>
#include <catch2/catch.hpp>
#include <geometry/geometry.hpp>

#include <iostream>

using namespace geometry;
using test::Q;

namespace bsp_depth_order_tests {

namespace {

using P3 = e3::point<Q>;
using K3 = e3::exact_kernel;
using V3 = std::array<Q, 3>;

V3 sub(V3 const& a, V3 const& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 v3(P3 const& p) { return {p.x(), p.y(), p.z()}; }

/// The ray parameter where E + t·d meets the convex polygon `poly`, if it
/// meets its interior (boundary hits do not count).
std::optional<Q> hit(std::vector<P3> const& poly, V3 const& e, V3 const& d) {
  V3 n = test::ref_cross(sub(v3(poly[1]), v3(poly[0])), sub(v3(poly[2]), v3(poly[0])));
  Q den = test::ref_dot(n, d);
  if (den == 0) return std::nullopt;
  Q t = test::ref_dot(n, sub(v3(poly[0]), e)) / den;
  if (t <= 0) return std::nullopt;
  V3 x{e[0] + t * d[0], e[1] + t * d[1], e[2] + t * d[2]};
  int s0 = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    V3 c = test::ref_cross(sub(v3(poly[(i + 1) % poly.size()]), v3(poly[i])), sub(x, v3(poly[i])));
    int s = test::ref_dot(c, n).sign();
    if (s == 0) return std::nullopt;
    if (s0 == 0) s0 = s;
    if (s != s0) return std::nullopt;
  }
  return t;
}

P3 rp(long r) { return P3(Q(test::uniform(-r, r)), Q(test::uniform(-r, r)), Q(test::uniform(-r, r))); }

/// Scenes of the families: random, intersecting, coplanar overlapping, and a closed mesh with shared edges.
std::vector<std::vector<P3>> scene(int family) {
  std::vector<std::vector<P3>> tris;
  auto add = [&](P3 a, P3 b, P3 c) {
    auto n = test::ref_cross(sub(v3(b), v3(a)), sub(v3(c), v3(a)));
    if (n[0] != 0 || n[1] != 0 || n[2] != 0) tris.push_back({a, b, c});
  };
  switch (family) {
  case 0: // random triangles, many intersecting
    for (int i = 0; i < 25; ++i) add(rp(10), rp(10), rp(10));
    break;
  case 1: // coplanar overlapping triangles on two planes, both orientations
    for (int i = 0; i < 12; ++i) {
      Q z(i % 2 ? 0 : 3);
      auto p = [&] { return P3(Q(test::uniform(-8, 8)), Q(test::uniform(-8, 8)), z); };
      if (i % 3) add(p(), p(), p());
      else {
        auto a = p(), b = p(), c = p();
        add(c, b, a);
      }
    }
    for (int i = 0; i < 6; ++i) add(rp(10), rp(10), rp(10));
    break;
  case 2: { // the closed mesh of a box (shared edges), and triangles through it
    std::array<Q, 3> lo{-4, -3, -2}, hi{3, 4, 5};
    auto v = [&](int i, int j, int k) { return P3(i ? hi[0] : lo[0], j ? hi[1] : lo[1], k ? hi[2] : lo[2]); };
    std::vector<std::array<P3, 4>> q{{v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0)}, {v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1)},
                                     {v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1)}, {v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0)},
                                     {v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0)}, {v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1)}};
    for (auto const& f : q) add(f[0], f[1], f[2]), add(f[0], f[2], f[3]);
    for (int i = 0; i < 8; ++i) add(rp(8), rp(8), rp(8));
    break;
  }
  }
  return tris;
}

} // namespace

TEST_CASE("E3 depth order: front to back along every sample ray", "[bsp][depth][e3]") {
  int compared = 0, rays = 0;
  for (int t = 0; t < 36; ++t) {
    auto tris = scene(t % 3);
    bsp::fragment_list<K3> input;
    for (std::size_t i = 0; i < tris.size(); ++i) input.push_back({e3::convex_polygon<Q>(tris[i]), i});
    bsp::depth_order_tree<K3> tree;
    if (t % 4 == 0) tree = bsp::build_depth_order<K3>(input);
    else if (t % 4 == 1) tree = bsp::build_depth_order<K3>(input, bsp::random_order(static_cast<std::uint64_t>(t)));
    else tree = bsp::build_depth_order<K3>(input, bsp::least_splits(6, static_cast<std::uint64_t>(t)));
    V3 e{test::random_decimal(2, 12), test::random_decimal(2, 12), test::random_decimal(2, 12)};
    std::vector<std::vector<P3>> order;
    bsp::for_each_front_to_back(tree, P3(e[0], e[1], e[2]), [&](auto const& f) { order.push_back(*e3::vertices(f.piece)); });
    std::vector<std::vector<P3>> back;
    bsp::for_each_back_to_front(tree, P3(e[0], e[1], e[2]), [&](auto const& f) { back.push_back(*e3::vertices(f.piece)); });
    REQUIRE(order.size() == back.size());
    for (int r = 0; r < 50; ++r) {
      // Aim at a random point of a random triangle, so that rays meet the scene.
      auto const& tri = tris[static_cast<std::size_t>(test::uniform(0, static_cast<long>(tris.size()) - 1))];
      Q w0(test::uniform(1, 20)), w1(test::uniform(1, 20)), w2(test::uniform(1, 20)), ws = w0 + w1 + w2;
      V3 target;
      for (std::size_t k = 0; k < 3; ++k) target[k] = (w0 * tri[0][k] + w1 * tri[1][k] + w2 * tri[2][k]) / ws;
      V3 d = sub(target, e);
      if (d[0] == 0 && d[1] == 0 && d[2] == 0) continue;
      ++rays;
      std::optional<Q> nearest_before; // largest t among the fragments listed so far
      for (auto const& poly : order) {
        auto h = hit(poly, e, d);
        if (!h) continue;
        if (nearest_before) {
          CHECK(*nearest_before <= *h); // a fragment listed earlier is never behind a later one
          ++compared;
        }
        if (!nearest_before || *nearest_before < *h) nearest_before = h;
      }
      std::optional<Q> farthest; // back to front: the reverse
      for (auto const& poly : back) {
        auto h = hit(poly, e, d);
        if (!h) continue;
        if (farthest) CHECK(*h <= *farthest);
        if (!farthest || *h < *farthest) farthest = h;
      }
    }
  }
  std::cout << "E3 depth order: " << compared << " ordered pairs of hits checked on " << rays << " rays\n";
  CHECK(compared > 2000);
}

TEST_CASE("E3 depth order on a convex surface: balanced cuts keep the tree shallow", "[bsp][depth][e3]") {
  // Triangles of z = x² + y² over an integer grid: a convex surface, so every
  // triangle's plane has all the others on one side and an autopartition is a chain.
  std::vector<std::vector<P3>> tris;
  int const m = 12;
  auto p = [](int x, int y) { return P3(Q(x), Q(y), Q(x * x + y * y)); };
  for (int x = -m; x < m; ++x)
    for (int y = -m; y < m; ++y) {
      tris.push_back({p(x, y), p(x + 1, y), p(x + 1, y + 1)});
      tris.push_back({p(x, y), p(x + 1, y + 1), p(x, y + 1)});
    }
  bsp::fragment_list<K3> input;
  for (std::size_t i = 0; i < tris.size(); ++i) input.push_back({e3::convex_polygon<Q>(tris[i]), i});
  // The free cut goes through a median vertex coordinate: along a grid line,
  // where it crosses no triangle, with an eighth of them on either side.
  auto cut = e3::axis_median_cut<Q>{}(input);
  REQUIRE(cut);
  std::size_t crossed = 0, below = 0, above = 0;
  for (auto const& f : input) {
    auto r = e3::split(f.piece, *cut);
    crossed += r.negative && r.positive;
    below += r.negative && !r.positive;
    above += r.positive && !r.negative;
  }
  CHECK(crossed == 0);
  CHECK(below * 8 >= input.size());
  CHECK(above * 8 >= input.size());
  auto chain = bsp::build_depth_order<K3>(input, bsp::random_order(3));
  auto shallow = bsp::build_depth_order<K3>(input, bsp::balanced(e3::axis_median_cut<Q>{}, 3, 16));
  auto dc = chain.statistics().depth, ds = shallow.statistics().depth;
  std::cout << "convex surface of " << tris.size() << " triangles: depth " << dc << " (random order), " << ds << " (balanced)\n";
  CHECK(dc >= tris.size() / 2); // coplanar pairs share a node
  CHECK(ds * 8 <= dc);
  // The policy's decisions: on the convex surface a free cut above the
  // threshold, a piece only at or below it, and a valid piece either way.
  auto piece = [](bsp::fragment<K3> const& f) -> K3::sub_hyperplane const& { return f.piece; };
  bsp::balanced policy(e3::axis_median_cut<Q>{}, 3, 16);
  auto many = bsp::decide<K3>(policy, input, piece);
  CHECK(many.cut.has_value());
  CHECK(many.piece < input.size());
  bsp::fragment_list<K3> few(input.begin(), input.begin() + 16);
  auto some = bsp::decide<K3>(policy, few, piece);
  CHECK(!some.cut.has_value());
  CHECK(some.piece < few.size());
  // Front to back from inside the cup, below it and beside it, checked along rays.
  int compared = 0;
  for (V3 e : {V3{Q(1, 3), Q(-2, 7), Q(400)}, V3{Q(5, 2), Q(3), Q(-50)}, V3{Q(30), Q(1), Q(100)}}) {
    std::vector<std::vector<P3>> order;
    bsp::for_each_front_to_back(shallow, P3(e[0], e[1], e[2]), [&](auto const& f) { order.push_back(*e3::vertices(f.piece)); });
    for (int r = 0; r < 300; ++r) {
      // Aim at a point of the surface: rays from outside the cup cross it twice.
      Q x(test::uniform(-4 * m, 4 * m), 4), y(test::uniform(-4 * m, 4 * m), 4);
      V3 d{x - e[0], y - e[1], x * x + y * y - e[2]};
      std::optional<Q> nearest;
      for (auto const& poly : order) {
        auto h = hit(poly, e, d);
        if (!h) continue;
        if (nearest) {
          CHECK(*nearest <= *h);
          ++compared;
        }
        if (!nearest || *nearest < *h) nearest = h;
      }
    }
  }
  std::cout << "convex surface: " << compared << " ordered pairs of hits checked\n";
  CHECK(compared > 100);
}

TEST_CASE("E2 depth order: front to back for segment soups", "[bsp][depth][e2]") {
  using K2 = e2::exact_kernel;
  using P2 = e2::point<Q>;
  int compared = 0;
  for (int t = 0; t < 40; ++t) {
    bsp::fragment_list<K2> input;
    auto p = [] { return P2(Q(test::uniform(-10, 10)), Q(test::uniform(-10, 10))); };
    for (std::size_t i = 0; i < 30; ++i) {
      auto a = p(), b = p();
      if (a == b) continue;
      if (i % 5 == 0) b = P2(a.x() + (b.x() - a.x()) * 2, a.y() + (b.y() - a.y()) * 2); // collinear overlaps
      input.push_back({e2::segment(a, b), i});
      if (i % 7 == 0) input.push_back({e2::segment(b, a), i}); // the same segment reversed
    }
    auto tree = bsp::build_depth_order<K2>(input, bsp::random_order(static_cast<std::uint64_t>(t)));
    std::array<Q, 2> e{test::random_decimal(2, 12), test::random_decimal(2, 12)};
    std::vector<std::pair<P2, P2>> order;
    bsp::for_each_front_to_back(tree, P2(e[0], e[1]), [&](auto const& f) { order.push_back(*e2::endpoints(f.piece)); });
    for (int r = 0; r < 100; ++r) {
      std::array<Q, 2> d{test::random_decimal(2, 1), test::random_decimal(2, 1)};
      if (d[0] == 0 && d[1] == 0) continue;
      std::optional<Q> nearest_before;
      for (auto const& [a, b] : order) {
        // e + t d = a + s (b − a), 0 < s < 1, t > 0: Cramer's rule.
        Q ux = b.x() - a.x(), uy = b.y() - a.y(), wx = a.x() - e[0], wy = a.y() - e[1];
        Q den = d[0] * uy - d[1] * ux;
        if (den == 0) continue;
        Q tt = (wx * uy - wy * ux) / den, s = (wx * d[1] - wy * d[0]) / den;
        if (tt <= 0 || s <= 0 || s >= 1) continue;
        if (nearest_before) {
          CHECK(*nearest_before <= tt);
          ++compared;
        }
        if (!nearest_before || *nearest_before < tt) nearest_before = tt;
      }
    }
  }
  std::cout << "E2 depth order: " << compared << " ordered pairs of hits checked\n";
  CHECK(compared > 2000);
}

} // namespace bsp_depth_order_tests
