// Hidden lines against independent truth: every drawn piece, visible or
// hidden, sampled at 20 points and checked with an exact ray cast from the
// eye written here on plain rationals (a visible point is the first thing
// its ray meets; a hidden one has a polygon strictly nearer on its ray);
// pieces cover every drawn edge; line counts of boxes match hand counts.
#include <svm/build.hpp>
#include <svm/camera.hpp>
#include <svm/lines.hpp>
#include <svm/render/lines.hpp>
#include <svm/render/svg.hpp>
#include <svm/scenes.hpp>

#include <catch2/catch.hpp>

#include "support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

using Q = geometry::rational;
using P = geometry::e3::point<Q>;
using R3 = std::array<Q, 3>;

R3 raw(P const& p) { return {p.x(), p.y(), p.z()}; }
R3 sub(R3 const& a, R3 const& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

/// Whether the closed convex polygon `g` meets the open segment from `o` to
/// `x` (exact; the segment may lie in the polygon's plane).
bool meets(std::vector<R3> const& v, R3 const& n, R3 const& o, R3 const& x) {
  Q f0 = test::ref_dot(n, sub(o, v[0])), f1 = test::ref_dot(n, sub(x, v[0]));
  R3 d = sub(x, o);
  // The segment's parameters inside each edge's half plane: α + s·β ≥ 0.
  Q lo(0), hi(1);
  bool lo_open = true, hi_open = true;
  auto clip = [&](Q const& alpha, Q const& beta) {
    if (beta == 0) return alpha >= 0;
    Q s = -alpha / beta;
    if (beta > 0) {
      if (s > lo || (s == lo && lo_open)) lo = s, lo_open = false;
    } else {
      if (s < hi || (s == hi && hi_open)) hi = s, hi_open = false;
    }
    return true;
  };
  if (f0 == 0 && f1 == 0) {
    for (std::size_t k = 0; k < v.size(); ++k) {
      R3 w = test::ref_cross(n, sub(v[(k + 1) % v.size()], v[k]));
      if (!clip(test::ref_dot(w, sub(o, v[k])), test::ref_dot(w, d))) return false;
    }
  } else {
    if (f0 == f1) return false;
    Q s = f0 / (f0 - f1);
    if (!(s > 0 && s < 1)) return false;
    R3 y{o[0] + s * d[0], o[1] + s * d[1], o[2] + s * d[2]};
    for (std::size_t k = 0; k < v.size(); ++k) {
      R3 w = test::ref_cross(sub(v[(k + 1) % v.size()], v[k]), sub(y, v[k]));
      if (test::ref_dot(w, n) < 0) return false;
    }
    return true;
  }
  if (lo < hi) return true;
  return lo == hi && !lo_open && !hi_open && lo > 0 && lo < 1;
}

struct check_result {
  std::size_t samples = 0, wrong = 0, pieces = 0, hidden_pieces = 0, gaps = 0;
  std::size_t intersections = 0; ///< map edges drawn as intersection curves
  std::size_t hidden_whole = 0;  ///< edges found hidden whole from the build's culled back faces
};

/// A polygon for the ray caster, with a double copy of its plane to skip, with
/// a wide error margin, the polygons a segment clearly does not reach.
struct caster_polygon {
  std::vector<R3> vertices;
  R3 normal;
  std::array<double, 3> n, v0;
  double slack;
  std::vector<std::array<double, 3>> v;
};

std::vector<caster_polygon> caster(std::vector<svm::polygon<Q>> const& polygons) {
  std::vector<caster_polygon> out;
  for (auto const& g : polygons) {
    R3 a = raw(g.vertices[0]), n{};
    for (std::size_t k = 2; k < g.vertices.size() && n == R3{}; ++k) n = test::ref_cross(sub(raw(g.vertices[1]), a), sub(raw(g.vertices[k]), a));
    caster_polygon c{{}, n, {}, {}, 0, {}};
    for (auto const& p : g.vertices) c.vertices.push_back(raw(p));
    double size = 0;
    for (int k = 0; k < 3; ++k) {
      c.n[k] = n[static_cast<std::size_t>(k)].convert_to<double>();
      c.v0[k] = a[static_cast<std::size_t>(k)].convert_to<double>();
      size = std::max(size, std::abs(c.n[k]));
    }
    c.slack = size;
    for (auto const& p : g.vertices) c.v.push_back({p.x().convert_to<double>(), p.y().convert_to<double>(), p.z().convert_to<double>()});
    out.push_back(c);
  }
  return out;
}

/// Whether any polygon meets the open segment from `o` to `x`.
bool blocked(std::vector<caster_polygon> const& cs, R3 const& o, R3 const& x) {
  std::array<double, 3> od{o[0].convert_to<double>(), o[1].convert_to<double>(), o[2].convert_to<double>()};
  std::array<double, 3> xd{x[0].convert_to<double>(), x[1].convert_to<double>(), x[2].convert_to<double>()};
  for (auto const& c : cs) {
    double f0 = 0, f1 = 0, m = 0;
    for (int k = 0; k < 3; ++k) {
      f0 += c.n[k] * (od[k] - c.v0[k]);
      f1 += c.n[k] * (xd[k] - c.v0[k]);
      m = std::max({m, std::abs(od[k]) + std::abs(c.v0[k]), std::abs(xd[k]) + std::abs(c.v0[k])});
    }
    double eps = 1e-9 * c.slack * (m + 1);
    if ((f0 > eps && f1 > eps) || (f0 < -eps && f1 < -eps)) continue; // both ends clearly on one side
    if (std::abs(f0) > eps && std::abs(f1) > eps) {
      // Where it crosses the plane, clearly outside an edge?
      double s = f0 / (f0 - f1);
      std::array<double, 3> y{od[0] + s * (xd[0] - od[0]), od[1] + s * (xd[1] - od[1]), od[2] + s * (xd[2] - od[2])};
      bool outside = false, inside = true;
      for (std::size_t k = 0; k < c.v.size() && !outside; ++k) {
        auto const &a = c.v[k], &b = c.v[(k + 1) % c.v.size()];
        std::array<double, 3> e{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{y[0] - a[0], y[1] - a[1], y[2] - a[2]};
        std::array<double, 3> x3{e[1] * w[2] - e[2] * w[1], e[2] * w[0] - e[0] * w[2], e[0] * w[1] - e[1] * w[0]};
        double side = x3[0] * c.n[0] + x3[1] * c.n[1] + x3[2] * c.n[2];
        double mag = (std::abs(e[0]) + std::abs(e[1]) + std::abs(e[2])) * (std::abs(w[0]) + std::abs(w[1]) + std::abs(w[2])) * c.slack;
        if (side < -1e-6 * mag) outside = true;
        if (side < 1e-6 * mag) inside = false;
      }
      if (outside) continue;
      // Clearly across the plane and clearly inside every edge.
      if (inside && std::abs(f0) > 1e3 * eps && std::abs(f1) > 1e3 * eps) return true;
    }
    if (meets(c.vertices, c.normal, o, x)) return true;
  }
  return false;
}

/// Samples every piece of `ls` and checks it with the ray caster.
check_result check_lines(svm::line_set<Q> const& ls, std::vector<svm::polygon<Q>> const& polygons, P const& eye) {
  check_result r;
  R3 o = raw(eye);
  auto cs = caster(polygons);
  // Pieces of each drawn edge, to check they cover it.
  std::map<std::uint32_t, std::vector<std::pair<Q, Q>>> cover;
  for (auto const& p : ls.pieces) {
    ++r.pieces;
    if (p.hidden) ++r.hidden_pieces;
    auto const& e = ls.edges[p.edge];
    cover[p.edge].push_back({p.t0, p.t1});
    R3 a = raw(e.a), ab = sub(raw(e.b), a);
    for (int k = 0; k < 20; ++k) {
      Q t = p.t0 + (p.t1 - p.t0) * (Q(1, 100) + Q(98, 100) * Q(k, 19));
      R3 x{a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]};
      bool hit = blocked(cs, o, x);
      ++r.samples;
      if (hit != p.hidden) {
        if (r.wrong < 5)
          std::cout << "  wrong: edge " << p.edge << " t=" << t.convert_to<double>() << " drawn " << (p.hidden ? "hidden" : "visible")
                    << " (" << svm::name_of(p.cls) << ")\n";
        ++r.wrong;
      }
    }
  }
  // Every edge drawn in any part, other than smooth ones, is drawn whole
  // (the map here has no window).
  for (auto& [ei, list] : cover) {
    auto k = ls.kinds[ei];
    if (k == svm::edge_kind::smooth) continue;
    std::sort(list.begin(), list.end());
    Q at(0);
    for (auto const& [t0, t1] : list) {
      if (t0 != at) ++r.gaps;
      at = t1;
    }
    if (at != 1) ++r.gaps;
  }
  return r;
}

std::vector<svm::polygon<Q>> relabelled(std::vector<svm::polygon<Q>> p) {
  for (std::uint32_t i = 0; i < p.size(); ++i) p[i].face = i;
  return p;
}

check_result run(std::vector<svm::polygon<Q>> const& polys, P const& eye, double crease = 0) {
  auto vm = svm::build<Q>(polys, eye, {});
  auto ls = svm::hidden_lines(vm, eye, polys, {.crease = crease});
  auto r = check_lines(ls, polys, eye);
  for (auto const& ml : ls.map_lines) r.intersections += ml.cls == svm::line_class::intersection;
  r.hidden_whole = ls.stats.hidden_whole;
  return r;
}

/// Counts of scene edges by class and visibility.
std::map<std::string, std::size_t> counts(svm::line_set<Q> const& ls) {
  std::map<std::string, std::set<std::uint32_t>> seen;
  for (auto const& p : ls.pieces) seen[std::string(p.hidden ? "hidden " : "visible ") + std::string(svm::name_of(p.cls))].insert(p.edge);
  std::map<std::string, std::size_t> out;
  for (auto const& [k, v] : seen) out[k] = v.size();
  return out;
}

std::map<std::string, std::size_t> counts_of(std::vector<svm::polygon<Q>> const& polys, P const& eye) {
  auto vm = svm::build<Q>(polys, eye, {});
  return counts(svm::hidden_lines(vm, eye, polys));
}

using counted = std::map<std::string, std::size_t>;

/// `polys` with every other quadrilateral (from `first`) cut in two between
/// the midpoints of two opposite sides: T-junctions where a neighbour keeps
/// those sides whole.  Polygons are labelled by their indices.
std::vector<svm::polygon<Q>> split_quads(std::vector<svm::polygon<Q>> const& polys, std::size_t first) {
  std::vector<svm::polygon<Q>> out;
  auto mid = [](P const& a, P const& b) { return P((a.x() + b.x()) / 2, (a.y() + b.y()) / 2, (a.z() + b.z()) / 2); };
  for (std::size_t i = 0; i < polys.size(); ++i) {
    auto const& v = polys[i].vertices;
    if (v.size() != 4 || i % 2 != first) {
      out.push_back(polys[i]);
      continue;
    }
    P m01 = mid(v[0], v[1]), m23 = mid(v[2], v[3]);
    out.push_back({{v[0], m01, m23, v[3]}, 0});
    out.push_back({{m01, v[1], v[2], m23}, 0});
  }
  return relabelled(out);
}

/// The drawn length of each class, visible and hidden, in a 400 × 300 view.
std::vector<double> drawn_lengths(std::vector<svm::polygon<Q>> const& polys, P const& eye, svm::camera cam) {
  svm::projector pr(cam, svm::projection::perspective);
  auto vm = svm::build<Q>(polys, eye, pr.window_options());
  auto ls = svm::hidden_lines(vm, eye, polys);
  svm::render::line_drawing_summary s;
  svm::render::draw_lines(ls, vm, eye, pr, {.hidden = svm::render::hidden_style::dashed}, &s);
  std::vector<double> out;
  for (auto const& c : s.visible) out.push_back(c.length);
  for (auto const& c : s.hidden) out.push_back(c.length);
  return out;
}

} // namespace

TEST_CASE("hidden lines: line counts of boxes match hand counts", "[lines]") {
  svm::scenes::scene cube;
  svm::scenes::add_box(cube, P(Q(-1), Q(-1), Q(-1)), P(Q(1), Q(1), Q(1)));
  SECTION("a cube seen from near a corner: 6 silhouette and 3 crease edges visible, 3 hidden") {
    CHECK(counts_of(cube.polygons, P(Q(3), Q(4), Q(5))) == counted{{"visible silhouette", 6}, {"visible crease", 3}, {"hidden crease", 3}});
  }
  SECTION("a cube seen face on: the front face's 4 edges; the 8 others hidden behind it, all creases") {
    // A side edge, (1, 1, z) say, has its faces x = 1 and y = 1 on either
    // side of its image (the diagonal x = y): a crease, not a fold.
    CHECK(counts_of(cube.polygons, P(Q(0), Q(0), Q(5))) == counted{{"visible silhouette", 4}, {"hidden crease", 8}});
  }
  SECTION("a cube seen from the plane of its top face: the top face edge-on") {
    // The eye in the top face's plane: the top face has no area in the view,
    // and its far edges lie behind its near ones in that plane.
    auto c = counts_of(cube.polygons, P(Q(5), Q(3), Q(1)));
    std::size_t total_visible = 0;
    for (auto const& [k, v] : c)
      if (k.starts_with("visible")) total_visible += v;
    CHECK(total_visible == 7);
    auto r = run(cube.polygons, P(Q(5), Q(3), Q(1)));
    CHECK(r.wrong == 0);
    CHECK(r.gaps == 0);
  }
  SECTION("an open box (no top) seen from above: its rim is boundary") {
    auto polys = cube.polygons;
    polys.erase(polys.begin() + 1); // the top, z = 1
    polys = relabelled(polys);
    auto c = counts_of(polys, P(Q(3), Q(4), Q(5)));
    // The rim's 4 edges are visible; inside, the floor's 4 edges and the
    // 4 vertical edges are visible creases, but 2 vertical edges are
    // hidden in part behind the near walls.
    CHECK(c["visible boundary"] == 4);
    auto r = run(polys, P(Q(3), Q(4), Q(5)));
    CHECK(r.wrong == 0);
    CHECK(r.gaps == 0);
  }
  SECTION("faces cut in two, their neighbours' sides whole (T-junctions), draw the same lines") {
    // Every other face of the cube cut in two: two of its sides meet two
    // sides of neighbours each.
    P eye(Q(3), Q(4), Q(5));
    svm::camera cam;
    cam.forward = {-3, -4, -5};
    cam.up = {0, 0, 1};
    cam.width = 400, cam.height = 300;
    auto plain = drawn_lengths(cube.polygons, eye, cam);
    for (std::size_t first : {0, 1}) {
      auto cut = split_quads(cube.polygons, first);
      auto lengths = drawn_lengths(cut, eye, cam);
      REQUIRE(lengths.size() == plain.size());
      for (std::size_t k = 0; k < plain.size(); ++k) {
        INFO("cut from " << first << ", class " << svm::name_of(static_cast<svm::line_class>(k % svm::line_class_count)) << (k < svm::line_class_count ? " visible" : " hidden"));
        CHECK(lengths[k] == Approx(plain[k]).margin(1e-6));
      }
      auto c = counts_of(cut, eye);
      CHECK(c.count("visible boundary") == 0);
      CHECK(c.count("hidden boundary") == 0);
      auto r = run(cut, eye);
      CHECK(r.wrong == 0);
      CHECK(r.gaps == 0);
    }
  }
  SECTION("a square cut into two triangles: the diagonal is never drawn") {
    std::vector<svm::polygon<Q>> polys{{{P(Q(0), Q(0), Q(0)), P(Q(1), Q(0), Q(0)), P(Q(1), Q(1), Q(0))}, 0},
                                       {{P(Q(0), Q(0), Q(0)), P(Q(1), Q(1), Q(0)), P(Q(0), Q(1), Q(0))}, 1}};
    CHECK(counts_of(polys, P(Q(1, 3), Q(1, 5), Q(3))) == counted{{"visible boundary", 4}});
  }
  SECTION("a box on a floor: its bottom edges are outlines against the floor where seen") {
    svm::scenes::scene s;
    s.polygons.push_back({{P(Q(-10), Q(-10), Q(0)), P(Q(10), Q(-10), Q(0)), P(Q(10), Q(10), Q(0)), P(Q(-10), Q(10), Q(0))}, 0});
    svm::scenes::add_box(s, P(Q(-1), Q(-1), Q(0)), P(Q(1), Q(1), Q(2)));
    s.polygons.erase(s.polygons.begin() + 1); // the box's bottom lies on the floor
    auto polys = relabelled(s.polygons);
    P eye(Q(6), Q(8), Q(10));
    auto c = counts_of(polys, eye);
    CHECK(c["visible boundary"] == 4 + 2); // the floor's 4 sides; the box's 2 bottom edges on the near side (open box)
    CHECK(c["hidden boundary"] == 2);      // the 2 far bottom edges
    auto r = run(polys, eye);
    CHECK(r.wrong == 0);
    CHECK(r.gaps == 0);
  }
  SECTION("two squares crossing: their intersection is drawn where seen") {
    std::vector<svm::polygon<Q>> polys{{{P(Q(-2), Q(-2), Q(0)), P(Q(2), Q(-2), Q(0)), P(Q(2), Q(2), Q(0)), P(Q(-2), Q(2), Q(0))}, 0},
                                       {{P(Q(-1), Q(0), Q(-1)), P(Q(1), Q(0), Q(-1)), P(Q(1), Q(0), Q(1)), P(Q(-1), Q(0), Q(1))}, 1}};
    P eye(Q(3), Q(-7), Q(5));
    auto vm = svm::build<Q>(polys, eye, {});
    auto ls = svm::hidden_lines(vm, eye, polys);
    std::size_t crossings = 0;
    for (auto const& ml : ls.map_lines) {
      CHECK(ml.cls == svm::line_class::intersection);
      // On the line y = 0, z = 0, seen from the eye: its circle's normal is
      // perpendicular to (1, 0, 0) and to the eye's offset.
      auto n = vm.map.circles()[vm.map.half_edges()[ml.half_edge].circle].n.exact();
      CHECK(n[0] == 0);
      CHECK(n[1] * Q(7) + n[2] * Q(-5) == 0);
      ++crossings;
    }
    CHECK(crossings >= 1);
    CHECK(check_lines(ls, polys, eye).wrong == 0);
  }
}

TEST_CASE("hidden lines agree with an exact ray cast at sampled points", "[lines]") {
  check_result total;
  std::size_t scenes = 0;
  // `crossing`: whether polygons may cross (elsewhere no intersection curve may be drawn).
  auto add = [&](std::string const& name, std::vector<svm::polygon<Q>> const& polys, P const& eye, double crease = 0, bool crossing = true) {
    auto r = run(relabelled(polys), eye, crease);
    INFO(name);
    CHECK(r.wrong == 0);
    if (!crossing) CHECK(r.intersections == 0);
    CHECK(r.gaps == 0);
    CHECK(r.pieces > 0);
    total.samples += r.samples, total.wrong += r.wrong, total.pieces += r.pieces, total.hidden_pieces += r.hidden_pieces, total.gaps += r.gaps;
    total.hidden_whole += r.hidden_whole;
    ++scenes;
  };
  for (std::size_t n : {2, 4, 6}) {
    auto b = svm::scenes::bricks(n);
    add("bricks " + std::to_string(n), b.polygons, b.eye, 0, false);
    auto h = svm::scenes::hidden_bricks(n);
    add("hidden bricks " + std::to_string(n), h.polygons, h.eye);
    auto p = svm::scenes::platforms(n);
    add("platforms " + std::to_string(n), p.polygons, p.eye);
    auto r = svm::scenes::random_cubes(n, n);
    add("random " + std::to_string(n), r.polygons, r.eye);
  }
  auto room = svm::scenes::room();
  add("room", room.polygons, room.eye);
  add("room, creases over 30 degrees", room.polygons, room.eye, 30);
  auto sphere = svm::scenes::sphere(5);
  add("sphere (closed mesh)", sphere.polygons, sphere.eye);
  add("sphere, smooth", sphere.polygons, sphere.eye, 40);
  auto terrain = svm::scenes::terrain(6);
  add("terrain (open mesh)", terrain.polygons, terrain.eye);

  // Degenerate families: unit cubes stacked on an integer grid (shared
  // edges and faces, coplanar neighbours), seen from eyes on their planes,
  // on their edges' lines and at generic points.
  for (int seed = 0; seed < 24; ++seed) {
    svm::scenes::scene s;
    std::set<std::array<int, 3>> cells;
    while (cells.size() < 6) cells.insert({static_cast<int>(test::uniform(0, 2)), static_cast<int>(test::uniform(0, 2)), static_cast<int>(test::uniform(0, 1))});
    for (auto const& c : cells) svm::scenes::add_box(s, P(Q(c[0]), Q(c[1]), Q(c[2])), P(Q(c[0] + 1), Q(c[1] + 1), Q(c[2] + 1)));
    std::array<P, 4> eyes{P(Q(5), Q(-3), Q(1)),                  // in the plane z = 1 of faces
                          P(Q(-2), Q(-2), Q(2)),                  // on the line of an edge direction (x = y) and a plane z = 2
                          P(Q(-4), Q(1), Q(1)),                   // on the line y = 1, z = 1 of edges
                          P(Q(7, 2), Q(-13, 3), Q(11, 5))};        // generic
    add("grid cubes " + std::to_string(seed), s.polygons, eyes[static_cast<std::size_t>(seed) % 4], 0, false);
    // The same with T-junctions: every other quadrilateral cut in two.
    add("grid cubes with T-junctions " + std::to_string(seed), split_quads(s.polygons, static_cast<std::size_t>(seed) % 2),
        eyes[static_cast<std::size_t>(seed) % 4], 0, false);
  }
  std::cout << "hidden lines: " << scenes << " scenes, " << total.pieces << " pieces (" << total.hidden_pieces << " hidden), "
            << total.samples << " samples checked by ray casting, " << total.wrong << " wrong, " << total.gaps << " gaps; "
            << total.hidden_whole << " edges hidden whole between culled back faces\n";
  CHECK(total.wrong == 0);
  CHECK(total.hidden_whole > 50);
  CHECK(total.hidden_pieces > 0);
}

TEST_CASE("hidden lines: edges between culled back faces come out as the two-sided map gives them", "[lines][cull]") {
  // Scenes of closed convex solids, with and without a narrow window around
  // the direction of the scene's centre: the pieces (edge, interval,
  // visibility, class) read off the map built without the culled back faces
  // equal those of the two-sided map, and some edges take the short way.
  std::size_t shortcut = 0, windowed = 0, compared = 0;
  auto check_scene = [&](std::string const& name, svm::scenes::scene const& sc) {
    auto polys = relabelled(sc.polygons);
    std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (auto const& p : polys)
      for (auto const& v : p.vertices)
        for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k].convert_to<double>()), hi[k] = std::max(hi[k], v[k].convert_to<double>());
    std::array<double, 3> f{};
    for (std::size_t k = 0; k < 3; ++k) f[k] = (lo[k] + hi[k]) / 2 - sc.eye[k].convert_to<double>();
    double fl = std::hypot(f[0], f[1], f[2]);
    for (auto& x : f) x /= fl;
    std::array<double, 3> u = std::abs(f[2]) < 0.9 ? std::array<double, 3>{-f[1], f[0], 0} : std::array<double, 3>{0, -f[2], f[1]};
    double ul = std::hypot(u[0], u[1], u[2]);
    for (auto& x : u) x /= ul;
    std::array<double, 3> v{f[1] * u[2] - f[2] * u[1], f[2] * u[0] - f[0] * u[2], f[0] * u[1] - f[1] * u[0]};
    for (bool narrow : {false, true}) {
      INFO(name << (narrow ? ", narrow window" : ""));
      svm::build_options o;
      if (narrow)
        for (auto [w, s] : {std::pair{u, 1.0}, {u, -1.0}, {v, 1.0}, {v, -1.0}})
          o.window.push_back({0.3 * f[0] + s * w[0], 0.3 * f[1] + s * w[1], 0.3 * f[2] + s * w[2]});
      auto culled = svm::build<Q>(polys, sc.eye, o);
      o.cull_convex_solids = false;
      auto two_sided = svm::build<Q>(polys, sc.eye, o);
      CHECK(culled.stats.convex_solids > 0);
      auto a = svm::hidden_lines(culled, sc.eye, polys), b = svm::hidden_lines(two_sided, sc.eye, polys);
      CHECK(b.stats.hidden_whole == 0);
      shortcut += a.stats.hidden_whole;
      if (narrow) windowed += a.stats.hidden_whole;
      REQUIRE(a.pieces.size() == b.pieces.size());
      for (std::size_t i = 0; i < a.pieces.size(); ++i) {
        auto const &x = a.pieces[i], &y = b.pieces[i];
        CHECK((x.edge == y.edge && x.t0 == y.t0 && x.t1 == y.t1 && x.hidden == y.hidden && x.cls == y.cls));
      }
      compared += a.pieces.size();
    }
  };
  for (std::size_t n : {3, 8}) {
    check_scene("random " + std::to_string(n), svm::scenes::random_cubes(n, n + 1));
    check_scene("bricks " + std::to_string(n), svm::scenes::bricks(n));
    check_scene("platforms " + std::to_string(n), svm::scenes::platforms(n));
  }
  std::cout << "hidden lines with culled back faces: " << compared << " pieces compared, " << shortcut << " edges hidden whole ("
            << windowed << " in a narrow window)\n";
  CHECK(shortcut > 40);
  CHECK(windowed > 5);
}

TEST_CASE("pen-travel ordering: the grid search picks what a scan of every line picks", "[lines][render]") {
  using svm::pixel;
  for (int seed = 0; seed < 6; ++seed) {
    // Integer ends on a small board (many ties), or spread wide, or all on one point.
    std::vector<std::vector<pixel>> lines;
    std::size_t n = seed == 5 ? 40 : 300 + 200 * static_cast<std::size_t>(seed);
    for (std::size_t i = 0; i < n; ++i) {
      auto at = [&] {
        if (seed == 5) return pixel{7, 7};
        long span = seed % 2 ? 5000 : 40;
        return pixel{static_cast<double>(test::uniform(-span / 4, span)), static_cast<double>(test::uniform(0, span))};
      };
      lines.push_back({at(), at()});
    }
    // The plain greedy order, O(n²).
    std::vector<std::vector<pixel>> expected, copy = lines;
    std::vector<char> done(n, 0);
    pixel pen{0, 0};
    for (std::size_t k = 0; k < n; ++k) {
      std::size_t best = 0;
      bool reverse = false;
      double bd = HUGE_VAL;
      for (std::size_t i = 0; i < n; ++i) {
        if (done[i]) continue;
        double a = std::hypot(copy[i].front().x - pen.x, copy[i].front().y - pen.y);
        double b = std::hypot(copy[i].back().x - pen.x, copy[i].back().y - pen.y);
        if (a < bd) bd = a, best = i, reverse = false;
        if (b < bd) bd = b, best = i, reverse = true;
      }
      done[best] = 1;
      if (reverse) std::reverse(copy[best].begin(), copy[best].end());
      pen = copy[best].back();
      expected.push_back(copy[best]);
    }
    std::vector<std::vector<pixel>> got;
    svm::render::detail::order_for_travel(lines, got);
    REQUIRE(got.size() == expected.size());
    std::size_t same = 0;
    for (std::size_t k = 0; k < n; ++k)
      same += got[k].front().x == expected[k].front().x && got[k].front().y == expected[k].front().y &&
              got[k].back().x == expected[k].back().x && got[k].back().y == expected[k].back().y;
    INFO("seed " << seed);
    CHECK(same == n);
  }
}

TEST_CASE("hidden-line drawings: layers, dashes, pen travel", "[lines][render]") {
  svm::scenes::scene cube;
  svm::scenes::add_box(cube, P(Q(-1), Q(-1), Q(-1)), P(Q(1), Q(1), Q(1)));
  P eye(Q(3), Q(4), Q(5));
  svm::camera cam;
  cam.forward = {-3, -4, -5};
  cam.up = {0, 0, 1};
  cam.width = 400, cam.height = 300;
  svm::projector pr(cam, svm::projection::perspective);
  auto vm = svm::build<Q>(cube.polygons, eye, pr.window_options());
  auto ls = svm::hidden_lines(vm, eye, cube.polygons);
  svm::render::line_drawing_summary s;
  auto d = svm::render::draw_lines(ls, vm, eye, pr, {.hidden = svm::render::hidden_style::dashed}, &s);
  std::map<std::string, std::size_t> segments;
  for (auto const& l : d.layers)
    for (auto const& line : l.lines) segments[l.name] += line.size() - 1;
  // The silhouette joined into one closed hexagon; creases meet at corners.
  CHECK(segments == std::map<std::string, std::size_t>{{"hidden-crease", 3}, {"visible-crease", 3}, {"visible-silhouette", 6}});
  CHECK(s.visible[static_cast<std::size_t>(svm::line_class::silhouette)].polylines == 1);
  CHECK(d.edges == 9); // the visible ones
  for (auto const& l : d.layers) CHECK(l.edges == (l.name == "visible-silhouette" ? 6u : 3u));
  CHECK(s.travel_after <= s.travel_before);
  for (auto const& l : d.layers) CHECK(l.dash.empty() == l.name.starts_with("visible"));
  auto svg = svm::render::to_svg(d);
  CHECK(svg.find("inkscape:groupmode=\"layer\"") != std::string::npos);
  CHECK(svg.find("stroke-dasharray") != std::string::npos);
  // Hidden lines left out, or on hidden layers.
  auto none = svm::render::draw_lines(ls, vm, eye, pr, {.hidden = svm::render::hidden_style::none});
  for (auto const& l : none.layers) CHECK(l.name.starts_with("visible"));
  auto layer = svm::render::draw_lines(ls, vm, eye, pr, {.hidden = svm::render::hidden_style::layer});
  for (auto const& l : layer.layers) CHECK(l.shown == l.name.starts_with("visible"));
  CHECK(svm::render::to_svg(layer).find("display:none") != std::string::npos);
  // The window clips: a view of part of the cube draws only what it shows.
  cam.hfov = 10;
  svm::projector narrow(cam, svm::projection::perspective);
  auto vn = svm::build<Q>(cube.polygons, eye, narrow.window_options());
  auto ln = svm::hidden_lines(vn, eye, cube.polygons);
  auto dn = svm::render::draw_lines(ln, vn, eye, narrow, {.hidden = svm::render::hidden_style::dashed});
  for (auto const& l : dn.layers)
    for (auto const& line : l.lines)
      for (auto const& p : line) {
        CHECK(p.x >= -1e-6);
        CHECK(p.x <= 400 + 1e-6);
        CHECK(p.y >= -1e-6);
        CHECK(p.y <= 300 + 1e-6);
      }
}
