// Point sets in E1, S1, S2 and E3: the laws on random and degenerate inputs,
// against exact lengths and volumes (spherical measures within 1e-12) and
// independent membership tests.
#include "../support.hpp"
#include "laws.hpp"

#include <geometry/geometry.hpp>

#include <numbers>

using namespace geometry;
using test::Q;

namespace bsp_sets_tests {

namespace {
constexpr double pi = std::numbers::pi;
}

// ---------------------------------------------------------------- E1

namespace {
using interval = std::pair<Q, Q>;
std::vector<e1::sub_hyperplane<Q>> boundary_of(std::vector<interval> const& set) {
  std::vector<e1::sub_hyperplane<Q>> out;
  for (auto const& [a, b] : set) {
    out.push_back({e1::hyperplane_at(a, false)}); // outward: below a
    out.push_back({e1::hyperplane_at(b, true)});  // outward: above b
  }
  return out;
}
int in_intervals(std::vector<interval> const& set, Q const& x) {
  for (auto const& [a, b] : set) {
    if (x == a || x == b) return 0;
    if (a < x && x < b) return 1;
  }
  return -1;
}
/// Up to three disjoint random intervals (possibly touching) with decimal ends.
std::vector<interval> random_intervals() {
  std::vector<Q> ends;
  int n = static_cast<int>(test::uniform(1, 3));
  for (int i = 0; i < 2 * n; ++i) ends.push_back(test::random_decimal(1, 10));
  std::sort(ends.begin(), ends.end());
  std::vector<interval> out;
  for (int i = 0; i < n; ++i)
    if (ends[2 * i] < ends[2 * i + 1]) out.push_back({ends[2 * i], ends[2 * i + 1]});
  if (out.empty()) out.push_back({Q(0), Q(1)});
  return out;
}
} // namespace

TEST_CASE("E1 point sets: the laws, exactly", "[bsp][e1]") {
  using K = e1::exact_kernel;
  int compared = 0;
  std::vector<std::pair<std::vector<interval>, std::vector<interval>>> cases{
      {{{0, 1}}, {{1, 2}}},           // touching
      {{{0, 2}}, {{0, 2}}},           // identical
      {{{0, 3}}, {{1, 2}}},           // nested
      {{{0, 1}, {2, 3}}, {{1, 2}}},   // filling the gap
  };
  for (int t = 0; t < 60; ++t) cases.push_back({random_intervals(), random_intervals()});
  for (auto const& [a, b] : cases) {
    auto A = bsp::build_point_set<K>(boundary_of(a)), B = bsp::build_point_set<K>(boundary_of(b));
    Q la(0);
    for (auto const& [x, y] : a) la += y - x;
    CHECK(laws::size<K>(A) == la);
    std::vector<e1::point<Q>> pts;
    for (int i = 0; i < 100; ++i) pts.emplace_back(test::random_decimal(2, 11));
    for (auto const& [x, y] : a) pts.emplace_back(x), pts.emplace_back((x + y) / 2);
    laws::check_all<K>(A, B, [&](auto const& p) { return in_intervals(a, p.x()); },
                       [&](auto const& p) { return in_intervals(b, p.x()); }, pts, compared);
  }
  CHECK(compared > 10000);
}

// ---------------------------------------------------------------- S1

namespace {
using arc_set = std::vector<std::pair<s1::point<Q>, s1::point<Q>>>; // counter-clockwise arcs, each < π
std::vector<s1::sub_hyperplane<Q>> boundary_of(arc_set const& set) {
  std::vector<s1::sub_hyperplane<Q>> out;
  for (auto const& [a, b] : set) {
    out.push_back(s1::opposite(s1::sub_hyperplane<Q>{s1::hyperplane_at(a), true, false})); // a, outward
    out.push_back({s1::hyperplane_at(b), true, false});                                     // b, outward
  }
  return out;
}
int det2(s1::point<Q> const& a, s1::point<Q> const& b) { return (a[0] * b[1] - a[1] * b[0]).sign(); }
int in_arcs(arc_set const& set, s1::point<Q> const& p) {
  for (auto const& [a, b] : set) {
    int sa = det2(a, p), sb = det2(p, b);
    bool same_dir_a = sa == 0 && (a[0] * p[0] + a[1] * p[1]) > 0, same_dir_b = sb == 0 && (b[0] * p[0] + b[1] * p[1]) > 0;
    if (same_dir_a || same_dir_b) return 0;
    if (sa > 0 && sb > 0) return 1;
  }
  return -1;
}
s1::point<Q> dir(double t) {
  return s1::point<Q>(std::array<Q, 2>{Q(std::lround(1000 * std::cos(t)), 1000), Q(std::lround(1000 * std::sin(t)), 1000)});
}
} // namespace

TEST_CASE("S1 point sets: the laws", "[bsp][s1]") {
  using K = s1::exact_kernel;
  int compared = 0;
  for (int t = 0; t < 60; ++t) {
    auto random_arcs = [&] {
      double a0 = static_cast<double>(test::uniform(0, 3000)) / 1000, a1 = a0 + static_cast<double>(test::uniform(100, 3000)) / 1000;
      arc_set s{{dir(a0), dir(a1)}};
      if (t % 2) s.push_back({dir(a1 + 0.5), dir(a1 + 1.5)});
      return s;
    };
    arc_set a = random_arcs(), b = t % 7 == 0 ? a : random_arcs();
    auto A = bsp::build_point_set<K>(boundary_of(a)), B = bsp::build_point_set<K>(boundary_of(b));
    double la = 0;
    for (auto const& [x, y] : a) la += s1::length(s1::arc(x, y));
    CHECK(laws::size<K>(A) == Approx(la).epsilon(1e-12));
    std::vector<s1::point<Q>> pts;
    for (int i = 0; i < 100; ++i) pts.push_back(dir(static_cast<double>(test::uniform(0, 6283)) / 1000));
    for (auto const& [x, y] : a) pts.push_back(x);
    laws::check_all<K>(A, B, [&](auto const& p) { return in_arcs(a, p); }, [&](auto const& p) { return in_arcs(b, p); },
                       pts, compared);
  }
  CHECK(compared > 5000);
}

// ---------------------------------------------------------------- S2

namespace {
using SP = s2::point<Q>;
using spherical_polygon = std::vector<SP>; // convex, counter-clockwise
SP sdir(Q x, Q y, Q z) { return SP(std::array<Q, 3>{x, y, z}); }
std::vector<s2::sub_hyperplane<Q>> boundary_of(spherical_polygon const& v) {
  std::vector<s2::sub_hyperplane<Q>> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back(s2::arc(v[(i + 1) % v.size()], v[i]));
  return out;
}
int in_spherical(spherical_polygon const& v, SP const& p) {
  int r = 1;
  for (std::size_t i = 0; i < v.size(); ++i) {
    auto const &a = v[i], &b = v[(i + 1) % v.size()];
    int s = test::ref_det3({a[0], a[1], a[2]}, {b[0], b[1], b[2]}, {p[0], p[1], p[2]}).sign();
    if (s < 0) return -1;
    if (s == 0) r = 0;
  }
  return r;
}
spherical_polygon random_spherical_triangle() {
  for (;;) {
    Q cx = test::random_decimal(1, 1), cy = test::random_decimal(1, 1);
    auto near = [&] { return sdir(cx + test::random_decimal(1, 1), cy + test::random_decimal(1, 1), Q(1)); };
    spherical_polygon v{near(), near(), near()};
    int o = test::ref_det3({v[0][0], v[0][1], v[0][2]}, {v[1][0], v[1][1], v[1][2]}, {v[2][0], v[2][1], v[2][2]}).sign();
    if (o == 0) continue;
    if (o < 0) std::swap(v[1], v[2]);
    return v;
  }
}
} // namespace

TEST_CASE("S2 point sets: the laws, areas within 1e-12", "[bsp][s2]") {
  using K = s2::exact_kernel;
  int compared = 0;
  auto X = sdir(1, 0, 0), Y = sdir(0, 1, 0), Z = sdir(0, 0, 1), W = sdir(1, 1, -1);
  std::vector<std::pair<spherical_polygon, spherical_polygon>> cases{
      {{X, Y, Z}, {Y, X, sdir(0, 0, -1)}},           // octants sharing an edge
      {{X, Y, Z}, {X, Y, Z}},                        // identical
      {{X, Y, Z}, {Z, sdir(-1, 0, 1), sdir(0, -1, 1)}}, // touching at a vertex
      {{X, Y, Z}, {X, W, Y}},                        // sharing an edge, opposite sides
  };
  for (int t = 0; t < 50; ++t) cases.push_back({random_spherical_triangle(), random_spherical_triangle()});
  for (auto const& [a, b] : cases) {
    auto A = bsp::build_point_set<K>(boundary_of(a)), B = bsp::build_point_set<K>(boundary_of(b));
    CHECK(laws::size<K>(A) == Approx(s2::area(s2::convex_polygon(a))).epsilon(1e-12));
    std::vector<SP> pts;
    for (int i = 0; i < 100; ++i) pts.push_back(sdir(test::random_decimal(2, 2), test::random_decimal(2, 2), test::random_decimal(2, 2)));
    for (auto const& p : a) pts.push_back(p);
    laws::check_all<K>(A, B, [&](SP const& p) { return in_spherical(a, p); }, [&](SP const& p) { return in_spherical(b, p); },
                       pts, compared);
  }
  // The octant and its complement: areas sum to 4π.
  auto O = bsp::build_point_set<K>(boundary_of({X, Y, Z}));
  CHECK(laws::size<K>(O) + laws::size<K>(bsp::complement(O)) == Approx(4 * pi).epsilon(1e-12));
  // A hemisphere: its boundary is a whole circle.
  auto H = bsp::build_point_set<K>({s2::whole_circle(s2::hyperplane<Q>(sdir(0, 0, -1)))});
  CHECK(laws::size<K>(H) == Approx(2 * pi).epsilon(1e-12));
  CHECK(bsp::classify(H, Z) == true);
  CHECK(compared > 5000);
}

// ---------------------------------------------------------------- E3

namespace {
using P3 = e3::point<Q>;
struct box_shape {
  std::array<Q, 3> lo, hi;
};
/// The closed mesh of a union of disjoint boxes: quadrilaterals counter-clockwise seen from outside.
std::vector<e3::sub_hyperplane<Q>> boundary_of(std::vector<box_shape> const& boxes) {
  std::vector<e3::sub_hyperplane<Q>> out;
  for (auto const& b : boxes) {
    auto v = [&](int i, int j, int k) { return P3(i ? b.hi[0] : b.lo[0], j ? b.hi[1] : b.lo[1], k ? b.hi[2] : b.lo[2]); };
    std::vector<std::array<P3, 4>> faces{{v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0)}, {v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1)},
                                         {v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1)}, {v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0)},
                                         {v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0)}, {v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1)}};
    for (auto const& f : faces) out.push_back(e3::convex_polygon<Q>({f[0], f[1], f[2], f[3]}));
  }
  return out;
}
int in_boxes(std::vector<box_shape> const& boxes, P3 const& p) {
  for (auto const& b : boxes) {
    bool inside = true, closed = true;
    for (std::size_t k = 0; k < 3; ++k) {
      inside = inside && b.lo[k] < p[k] && p[k] < b.hi[k];
      closed = closed && b.lo[k] <= p[k] && p[k] <= b.hi[k];
    }
    if (inside) return 1;
    if (closed) return 0;
  }
  return -1;
}
box_shape random_box() {
  box_shape b;
  for (std::size_t k = 0; k < 3; ++k) {
    long a = test::uniform(-10, 8);
    b.lo[k] = Q(a);
    b.hi[k] = Q(a + test::uniform(1, 8));
  }
  return b;
}
Q volume_of(std::vector<box_shape> const& boxes) {
  Q v(0);
  for (auto const& b : boxes) v += (b.hi[0] - b.lo[0]) * (b.hi[1] - b.lo[1]) * (b.hi[2] - b.lo[2]);
  return v;
}
} // namespace

TEST_CASE("E3 point sets: the laws on boxes, exactly", "[bsp][e3]") {
  using K = e3::exact_kernel;
  int compared = 0;
  auto bx = [](Q a, Q b, Q c, Q d, Q e, Q f) { return box_shape{{a, b, c}, {d, e, f}}; };
  std::vector<std::pair<std::vector<box_shape>, std::vector<box_shape>>> cases{
      {{bx(0, 0, 0, 2, 2, 2)}, {bx(2, 0, 0, 4, 2, 2)}},                    // sharing a face
      {{bx(0, 0, 0, 2, 2, 2)}, {bx(2, 2, 0, 4, 4, 2)}},                    // sharing an edge
      {{bx(0, 0, 0, 2, 2, 2)}, {bx(2, 2, 2, 4, 4, 4)}},                    // sharing a vertex
      {{bx(0, 0, 0, 2, 2, 2)}, {bx(0, 0, 0, 2, 2, 2)}},                    // identical
      {{bx(0, 0, 0, 4, 4, 1)}, {bx(1, 1, 0, 3, 3, 1)}},                    // coplanar faces, nested
      {{bx(0, 0, 0, 2, 2, 2), bx(2, 2, 2, 3, 3, 3)}, {bx(1, 1, 1, 3, 3, 3)}}, // a non-manifold union
      {{bx(Q(1, 10), 0, 0, Q(7, 10), 1, 1)}, {bx(Q(3, 10), Q(1, 2), 0, 1, 2, Q(1, 3))}},
  };
  for (int t = 0; t < 30; ++t) cases.push_back({{random_box()}, {random_box()}});
  for (auto const& [a, b] : cases) {
    auto A = bsp::build_point_set<K>(boundary_of(a)), B = bsp::build_point_set<K>(boundary_of(b));
    CHECK(laws::size<K>(A) == volume_of(a));
    std::vector<P3> pts;
    for (int i = 0; i < 60; ++i) pts.emplace_back(test::random_decimal(1, 12), test::random_decimal(1, 12), test::random_decimal(1, 12));
    laws::check_all<K>(A, B, [&](P3 const& p) { return in_boxes(a, p); }, [&](P3 const& p) { return in_boxes(b, p); }, pts,
                       compared);
  }
  // Hand-computed volumes.
  auto cube = [&](Q a, Q b, Q c, Q s) { return bsp::build_point_set<K>(boundary_of({bx(a, b, c, a + s, b + s, c + s)})); };
  CHECK(laws::size<K>(bsp::set_union(cube(0, 0, 0, 2), cube(1, 1, 1, 2))) == 15);
  CHECK(laws::size<K>(bsp::set_difference(cube(0, 0, 0, 2), cube(1, 1, 1, 2))) == 7);
  CHECK(laws::size<K>(bsp::set_intersection(cube(0, 0, 0, 2), cube(2, 0, 0, 2))) == 0);
  CHECK(compared > 5000);
}

TEST_CASE("E3 point sets from boxes meeting face to face: every splitting order gives the exact volume", "[bsp][e3]") {
  // Two boxes in one boundary, the second against the first's x = 2 face,
  // sharing part of it (their faces lie in one plane, opposite ways round):
  // both sides of that plane are inside, whichever face cuts there first.
  using K = e3::exact_kernel;
  int compared = 0;
  // The second box's y0, z0 and sizes: two that once lost volume (orders 6 and 1), then random ones.
  std::vector<std::array<long, 5>> second{{0, 1, 1, 2, 1}, {1, -1, 2, 1, 3}};
  for (int t = 0; t < 12; ++t)
    second.push_back({test::uniform(-1, 1), test::uniform(-1, 1), test::uniform(1, 3), test::uniform(1, 3), test::uniform(1, 3)});
  for (auto [y0, z0, w, h, d] : second) {
    std::vector<box_shape> boxes{{{Q(0), Q(0), Q(0)}, {Q(2), Q(2), Q(2)}}};
    boxes.push_back({{Q(2), Q(y0), Q(z0)}, {Q(2 + w), Q(y0 + h), Q(z0 + d)}});
    for (std::uint64_t seed = 0; seed < 12; ++seed) {
      auto a = bsp::build_point_set<K>(boundary_of(boxes), true, false, bsp::random_order(seed));
      CHECK(laws::size<K>(a) == volume_of(boxes));
      for (int k = 0; k < 30; ++k) {
        P3 p(Q(test::uniform(-5, 55), 10), Q(test::uniform(-15, 45), 10), Q(test::uniform(-15, 45), 10));
        int truth = in_boxes(boxes, p);
        if (truth == 0) continue;
        CHECK(bsp::classify(a, p) == std::optional<bool>(truth > 0));
        ++compared;
      }
    }
  }
  CHECK(compared > 2000);
}

} // namespace bsp_sets_tests
