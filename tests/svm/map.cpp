// The spherical visibility map against an independent exact ray caster (128-bit
// integer arithmetic on the input triangles, sharing nothing with the library),
// on scene families with the degeneracies the map must treat as normal input;
// and the map's invariants: half-edge consistency, minor arcs, Euler's formula,
// face areas summing to 4π, no adjacent faces with one label after simplifying.
#include "../support.hpp"
#include "ray_cast.hpp"

#include <catch2/catch.hpp>
#include <svm/camera.hpp>
#include <svm/query.hpp>
#include <svm/graph.hpp>
#include <svm/parallel.hpp>
#include <svm/scenes.hpp>

#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>

using namespace geometry;
using test::Q;

namespace {

using namespace test::ray;

ivec rp(long r) { return {test::uniform(-r, r), test::uniform(-r, r), test::uniform(-r, r)}; }

struct scene_case {
  std::vector<triangle> tris;
  ivec eye;
  bool closed = false; ///< closed, outward-oriented solids: culling backfaces changes nothing
};

scene_case make_scene(int family) {
  scene_case c;
  auto& s = c.tris;
  c.eye = rp(3);
  switch (family) {
  case 0: // random triangles, intersecting
    for (int i = 0, n = static_cast<int>(test::uniform(1, 40)); i < n; ++i) s.push_back({{rp(12), rp(12), rp(12)}});
    break;
  case 1: // random boxes, some slanted: closed meshes with shared edges
    for (int i = 0, n = static_cast<int>(test::uniform(1, 4)); i < n; ++i) {
      ivec lo{test::uniform(-12, 6), test::uniform(-12, 6), test::uniform(4, 8)};
      ivec hi{lo[0] + test::uniform(1, 6), lo[1] + test::uniform(1, 6), lo[2] + test::uniform(1, 6)};
      if (i % 2) lo[2] = -lo[2] - 8, hi[2] = lo[2] + test::uniform(1, 6);
      add_box(s, lo, hi, static_cast<int>(test::uniform(0, 1)));
    }
    c.eye = {test::uniform(-2, 2), test::uniform(-2, 2), 0};
    c.closed = true;
    break;
  case 2: // coplanar overlapping triangles, both orientations
    for (int i = 0; i < 20; ++i) {
      long z = i % 2 ? 6 : -5;
      auto p = [&] { return ivec{test::uniform(-10, 10), test::uniform(-10, 10), z}; };
      auto a = p(), b = p(), d = p();
      s.push_back(i % 3 ? triangle{{a, b, d}} : triangle{{d, b, a}});
    }
    break;
  case 3: { // T-junctions: a fan of triangles whose edges end inside other edges
    long z = 7;
    for (int i = 0; i < 6; ++i) {
      long x = 2 * i - 6;
      s.push_back({{ivec{x, 0, z}, ivec{x + 2, 0, z}, ivec{x + 1, 4, z}}});
      s.push_back({{ivec{x, 0, z}, ivec{x + 4, -3, z + 1}, ivec{x + 2, 0, z}}});
    }
    for (int i = 0; i < 8; ++i) s.push_back({{rp(10), rp(10), rp(10)}});
    break;
  }
  case 4: { // the eye in the plane of some polygons and on the lines of some edges
    for (int i = 0; i < 15; ++i) s.push_back({{rp(10), rp(10), rp(10)}});
    c.eye = {1, 2, 0};
    s.push_back({{ivec{-5, -5, 0}, ivec{5, -5, 0}, ivec{0, 7, 0}}});     // plane through the eye
    s.push_back({{ivec{3, 6, 4}, ivec{5, 10, 8}, ivec{-2, 9, 3}}});      // edge on a line through the eye
    s.push_back({{ivec{-1, -2, 0}, ivec{-3, -6, 0}, ivec{4, -3, 5}}});  // another one
    break;
  }
  case 5: { // triangles touching at a vertex seen head-on, and a closed octahedron
    ivec apex{2, 3, 9};
    for (int i = 0; i < 6; ++i) {
      ivec a = rp(10), b = rp(10);
      a[2] = b[2] = 12;
      s.push_back({{apex, a, b}});
    }
    c.eye = {0, 0, 0}; // the apex is seen head-on along (2, 3, 9)
    ivec o{-6, 4, -7};
    auto P = [&](long x, long y, long z) { return ivec{o[0] + x, o[1] + y, o[2] + z}; };
    std::array<ivec, 6> v{P(3, 0, 0), P(-3, 0, 0), P(0, 3, 0), P(0, -3, 0), P(0, 0, 3), P(0, 0, -3)};
    int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (auto const& f : faces) s.push_back({{v[f[0]], v[f[1]], v[f[2]]}});
    break;
  }
  }
  std::vector<triangle> ok;
  for (auto const& t : s)
    if (nondegenerate(t)) ok.push_back(t);
  s = ok;
  return c;
}

template <class FT> void check_map(svm::visibility_map<FT> const& vm, bool simplified) {
  auto problems = svm::check_invariants(vm.map);
  INFO((problems.empty() ? std::string() : problems.front()));
  CHECK(problems.empty());
  double sum = 0;
  for (double a : svm::face_areas(vm.map)) {
    CHECK(a > -1e-9);
    sum += a;
  }
  CHECK(sum == Approx(4 * std::numbers::pi).epsilon(1e-9));
  if (simplified)
    for (svm::index e = 0; e < vm.map.half_edges().size(); ++e)
      CHECK(vm.map.faces()[vm.map.face_of(e)].label != vm.map.faces()[vm.map.face_of(vm.map.twin(e))].label);
}

} // namespace

TEST_CASE("the visibility map agrees with an exact ray caster", "[svm]") {
  long compared = 0, skipped = 0;
  std::size_t solids = 0;
  int scenes = 0;
  for (int t = 0; t < 204; ++t) {
    int family = t % 6;
    auto sc = make_scene(family);
    if (sc.tris.empty()) continue;
    ++scenes;
    INFO("scene " << t << ", family " << family);
    auto polys = polygons_of(sc.tris);
    e3::point<Q> eye(Q(sc.eye[0]), Q(sc.eye[1]), Q(sc.eye[2]));
    auto raw = svm::build<Q>(polys, eye, {.simplify = false, .cull_convex_solids = false});
    auto simple = svm::build<Q>(polys, eye); // back faces of convex solids proven hidden, culled
    solids += simple.stats.convex_solids;
    check_map(raw, false);
    check_map(simple, true);
    std::optional<svm::visibility_map<Q>> culled;
    if (sc.closed) culled = svm::build<Q>(polys, eye, {.cull_backfaces = true});
    for (int r = 0; r < 1000; ++r) {
      ivec d = rp(1000);
      if (d == ivec{0, 0, 0}) continue;
      s2::point<Q> dq(std::array<Q, 3>{Q(d[0]), Q(d[1]), Q(d[2])});
      long a = svm::locate(raw, dq), b = svm::locate(simple, dq);
      long truth = cast(sc.tris, sc.eye, d);
      if (truth == ambiguous) {
        ++skipped;
        continue;
      }
      ++compared;
      CHECK(a == truth);
      CHECK(b == truth);
      if (culled) CHECK(svm::locate(*culled, dq) == truth);
    }
  }
  std::cout << "visibility map: " << scenes << " scenes, " << compared << " directions compared with the ray caster, "
            << skipped << " skipped (on an edge or a tie); " << solids << " convex solids culled\n";
  CHECK(scenes >= 200);
  CHECK(solids > 60); // the boxes and octahedra
  CHECK(compared > 150000);
}

TEST_CASE("parallel views agree with an exact parallel ray caster", "[svm][parallel]") {
  // The map of the scene's image from the finite eye of view_from_infinity
  // (svm/parallel.hpp), located along lines parallel to the view, against
  // the exact ray caster started far behind on each line.
  long compared = 0, skipped = 0;
  std::size_t solids = 0;
  int scenes = 0;
  for (int t = 0; t < 102; ++t) {
    int family = t % 6;
    auto sc = make_scene(family);
    if (sc.tris.empty()) continue;
    ++scenes;
    INFO("scene " << t << ", family " << family);
    ivec d = rp(5);
    if (d == ivec{0, 0, 0}) d = {1, 2, 3};
    if (t % 5 == 0) d = {0, 0, t % 2 ? 1 : -1}; // along an axis: faces edge-on, vertices in line
    std::vector<ivec> points;
    for (int r = 0; r < 300; ++r) points.push_back(rp(16));
    std::vector<e3::point<Q>> also;
    for (auto const& p : points) also.emplace_back(Q(p[0]), Q(p[1]), Q(p[2]));
    auto polys = polygons_of(sc.tris);
    svm::view_from_infinity<Q> view(polys, {Q(-d[0]), Q(-d[1]), Q(-d[2])}, e3::point<Q>(Q(1, 3), Q(-1, 7), Q(1, 5)), also);
    auto vm = svm::build<Q>(view.image(polys), view.eye());
    solids += vm.stats.convex_solids;
    check_map(vm, true);
    for (std::size_t r = 0; r < points.size(); ++r) {
      auto const& p = points[r];
      ivec o{p[0] - 1000 * d[0], p[1] - 1000 * d[1], p[2] - 1000 * d[2]};
      long truth = cast(sc.tris, o, d);
      if (truth == ambiguous) {
        ++skipped;
        continue;
      }
      ++compared;
      CHECK(svm::locate(vm, view.direction_of(also[r])) == truth);
    }
  }
  std::cout << "parallel views: " << scenes << " scenes, " << compared << " lines compared with the ray caster, " << skipped
            << " skipped (on an edge or a tie); " << solids << " convex solids culled\n";
  CHECK(scenes >= 100);
  CHECK(solids > 30); // the images of the boxes and octahedra
  CHECK(compared > 20000);
}

TEST_CASE("a parallel view's image points, made on integers, are the projective map's", "[svm][parallel]") {
  // view_from_infinity::image makes each image point from homogeneous
  // integers; the map is x -> c + s (x - c) / (s + e.(x - c)) in rationals.
  int checked = 0;
  for (int t = 0; t < 200; ++t) {
    auto q = [&](long r) { return Q(test::uniform(-r, r), test::uniform(1, 9)); };
    std::vector<e3::point<Q>> pts;
    for (int k = 0; k < 6; ++k) pts.emplace_back(q(50), q(50), q(50));
    std::array<Q, 3> e{q(4), q(4), q(4)};
    if (e[0] == 0 && e[1] == 0 && e[2] == 0) e[2] = Q(1, 3);
    e3::point<Q> c(q(5), q(5), q(5));
    svm::view_from_infinity<Q> view({svm::polygon<Q>{pts, 0}}, e, c);
    auto const& s = view.s();
    Q m(0);
    for (auto const& x : pts) m = std::max(m, abs(e[0] * (x.x() - c.x()) + e[1] * (x.y() - c.y()) + e[2] * (x.z() - c.z())));
    Q twice = 2 * m;
    integer floor;
    mpz_fdiv_q(floor.backend().data(), mpq_numref(twice.backend().data()), mpq_denref(twice.backend().data()));
    CHECK(s == Q(floor) + 1); // an integer over twice the largest |e.(x - c)|
    CHECK(s > m);
    for (auto const& x : pts) {
      Q w = s + e[0] * (x.x() - c.x()) + e[1] * (x.y() - c.y()) + e[2] * (x.z() - c.z());
      e3::point<Q> want(c.x() + s * (x.x() - c.x()) / w, c.y() + s * (x.y() - c.y()) / w, c.z() + s * (x.z() - c.z()) / w);
      auto got = view.image(x);
      CHECK(got == want);
      CHECK(got.x() == want.x());
      CHECK(got.y() == want.y());
      CHECK(got.z() == want.z());
      CHECK(got[3] == Q(1));
      ++checked;
    }
  }
  CHECK(checked == 1200);
  // A point from homogeneous integers, not primitive: the same point.
  auto p = e3::point<Q>::from_homogeneous({integer(-6), integer(4), integer(10), integer(4)});
  CHECK(p == e3::point<Q>(Q(-3, 2), Q(1), Q(5, 2)));
  CHECK(p.x() == Q(-3, 2));
  CHECK(p.z() == Q(5, 2));
}

TEST_CASE("the coverage tree and the map's locator answer as the paper's tree V does", "[svm][locate]") {
  // The same scenes built twice: in two passes (a coverage tree that is
  // rebuilt from its covered boundary finds the visible pieces, then the map
  // is made of them) with a locator built from the final map, and in the
  // paper's one pass with its tree V kept as the locator.  Every direction
  // must see the same polygon, except where it lies exactly on an edge
  // between the two answers; simplified, the two maps have the same size.
  long compared = 0, on_edges = 0;
  std::size_t hidden_new = 0, hidden_old = 0, nodes_new = 0, nodes_old = 0;
  auto check_scene = [&](std::vector<svm::polygon<Q>> const& polys, e3::point<Q> const& eye, bool simplify) {
    auto now = svm::build<Q>(polys, eye, {.simplify = simplify});
    auto paper = svm::build<Q>(polys, eye, {.simplify = simplify, .keep_construction_tree = true});
    check_map(now, simplify);
    CHECK(now.stats.overlapping_pieces == 0);
    CHECK(now.stats.hidden_pieces <= paper.stats.hidden_pieces);
    CHECK(now.stats.v_nodes_peak <= paper.stats.v_nodes);
    CHECK(now.stats.locator_nodes == now.locator.statistics().interior_nodes);
    if (simplify) {
      CHECK(now.stats.simplified.faces == paper.stats.simplified.faces);
      CHECK(now.stats.simplified.edges == paper.stats.simplified.edges);
      CHECK(now.stats.simplified.vertices == paper.stats.simplified.vertices);
    }
    hidden_new += now.stats.hidden_pieces, hidden_old += paper.stats.hidden_pieces;
    nodes_new += now.stats.v_nodes_peak, nodes_old += paper.stats.v_nodes;
    auto const& m = now.map;
    for (int r = 0; r < 10000; ++r) {
      ivec d = rp(1000);
      if (d == ivec{0, 0, 0}) continue;
      s2::point<Q> dq(std::array<Q, 3>{Q(d[0]), Q(d[1]), Q(d[2])});
      auto a = svm::locate(now, dq), b = svm::locate(paper, dq);
      ++compared;
      if (a == b) continue;
      // Allowed only on an edge of the map between the two answers.
      bool between = false;
      for (svm::index e = 0; e < m.half_edges().size() && !between; ++e)
        between = m.faces()[m.face_of(e)].label == a && m.faces()[m.face_of(m.twin(e))].label == b &&
                  geometry::s2::side(m.circles()[m.half_edges()[e].circle], dq) == oriented_side::on;
      CHECK(between);
      ++on_edges;
    }
  };
  for (int t = 0; t < 36; ++t) {
    auto sc = make_scene(t % 6);
    if (sc.tris.empty()) continue;
    INFO("scene " << t << ", family " << t % 6);
    check_scene(polygons_of(sc.tris), e3::point<Q>(Q(sc.eye[0]), Q(sc.eye[1]), Q(sc.eye[2])), t % 2 == 0);
  }
  for (auto const& sc : {svm::scenes::bricks(16), svm::scenes::hidden_bricks(16), svm::scenes::platforms(8), svm::scenes::random_cubes(16, 3)})
    for (bool simplify : {true, false}) check_scene(sc.polygons, sc.eye, simplify);
  std::cout << "locate: " << compared << " directions, " << on_edges << " on edges with another polygon; hidden pieces "
            << hidden_new << " against " << hidden_old << ", largest coverage trees " << nodes_new << " nodes against V's " << nodes_old << "\n";
  CHECK(compared > 300000);
  CHECK(hidden_new < hidden_old);
  CHECK(nodes_new < nodes_old);
}

TEST_CASE("a window leaves out the polygons wholly outside it, and nothing else", "[svm][window]") {
  // Narrow frusta in random directions: inside the window the map answers as
  // the map of all directions does; polygons wholly outside are discarded.
  std::size_t discarded = 0, compared = 0;
  for (auto const& sc : {svm::scenes::bricks(16), svm::scenes::random_cubes(32, 5), svm::scenes::platforms(8)}) {
    auto full = svm::build<Q>(sc.polygons, sc.eye);
    for (int k = 0; k < 6; ++k) {
      ivec f = rp(100);
      if (f == ivec{0, 0, 0}) continue;
      svm::camera cam;
      cam.forward = {double(f[0]), double(f[1]), double(f[2])};
      cam.up = std::abs(f[2]) * 10 > std::abs(f[0]) + std::abs(f[1]) ? svm::vec3{1, 0, 0} : svm::vec3{0, 0, 1};
      cam.hfov = 20 + 10 * k;
      cam.width = cam.height = 100;
      auto o = svm::projector(cam, svm::projection::perspective).window_options();
      auto windowed = svm::build<Q>(sc.polygons, sc.eye, o);
      check_map(windowed, true);
      discarded += windowed.stats.discarded_outside_window;
      CHECK(full.stats.discarded_outside_window == 0);
      for (int r = 0; r < 500; ++r) {
        ivec d = rp(1000);
        bool inside = d != ivec{0, 0, 0};
        for (auto const& w : o.window)
          inside = inside && w[0] * double(d[0]) + w[1] * double(d[1]) + w[2] * double(d[2]) > 1e-9 * 1000 * (std::abs(w[0]) + std::abs(w[1]) + std::abs(w[2]));
        if (!inside) continue;
        s2::point<Q> dq(std::array<Q, 3>{Q(d[0]), Q(d[1]), Q(d[2])});
        ++compared;
        CHECK(svm::locate(windowed, dq) == svm::locate(full, dq));
      }
    }
  }
  std::cout << "window: " << discarded << " polygons discarded, " << compared << " directions compared\n";
  CHECK(discarded > 100);
  CHECK(compared > 200);
}

TEST_CASE("the paper's scene families: map sizes, and Platforms linear once simplified", "[svm][scenes]") {
  std::vector<std::size_t> sizes{4, 8, 16};
  std::vector<svm::map_size> platforms, raw_platforms, paper_platforms;
  for (std::size_t n : sizes) {
    auto slabs = svm::scenes::platforms(n);
    paper_platforms.push_back(svm::build<Q>(slabs.polygons, slabs.eye, {.keep_construction_tree = true}).stats.unsimplified);
    for (auto const& [name, sc] : {std::pair{"bricks", svm::scenes::bricks(n)}, std::pair{"hidden bricks", svm::scenes::hidden_bricks(n)},
                                   std::pair{"platforms", svm::scenes::platforms(n)}, std::pair{"random", svm::scenes::random_cubes(n, n)}}) {
      auto vm = svm::build<Q>(sc.polygons, sc.eye);
      auto const& st = vm.stats;
      std::cout << name << " n=" << n << ": map " << st.unsimplified.vertices << "/" << st.unsimplified.edges << "/"
                << st.unsimplified.faces << " (V/E/F), simplified " << st.simplified.vertices << "/" << st.simplified.edges << "/"
                << st.simplified.faces << "\n";
      check_map(vm, true);
      if (std::string(name) == "platforms") platforms.push_back(st.simplified), raw_platforms.push_back(st.unsimplified);
      if (std::string(name) == "hidden bricks") CHECK(st.simplified.faces == 2); // only the hiding box, one region, and the rest
    }
  }
  // Each slab shows one ring (n rings and the background): n + 1 faces, a few corners per ring.
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    CHECK(platforms[i].faces == sizes[i] + 1);
    CHECK(platforms[i].vertices <= 8 * sizes[i]);
  }
  // In the paper's one pass the partition lines of nearer slabs cut the
  // farther ones: quadratic before simplification.  Built from the visible
  // pieces in random order, the map before simplification is smaller at n = 16
  // (docs/benchmarks.md measures how much at larger n).
  CHECK(paper_platforms[2].edges > 3 * paper_platforms[1].edges);
  CHECK(raw_platforms[2].edges < paper_platforms[2].edges);
}

TEST_CASE("Boost.Graph on the map: components for Euler, visible regions per polygon", "[svm][graph]") {
  int checked = 0;
  for (int t = 0; t < 30; ++t) {
    auto sc = make_scene(t % 6);
    if (sc.tris.empty()) continue;
    auto polys = polygons_of(sc.tris);
    e3::point<Q> eye(Q(sc.eye[0]), Q(sc.eye[1]), Q(sc.eye[2]));
    auto raw = svm::build<Q>(polys, eye, {.simplify = false});
    auto simple = svm::build<Q>(polys, eye);
    // BGL's components satisfy Euler's formula on both maps.
    for (auto const* vm : {&raw, &simple}) {
      auto const& m = vm->map;
      long lhs = static_cast<long>(m.vertices().size()) - static_cast<long>(m.half_edges().size() / 2) + static_cast<long>(m.faces().size());
      CHECK(lhs == 1 + static_cast<long>(svm::edge_components(m)));
    }
    // The regions BGL finds in the raw map, polygon by polygon, are the faces of the simplified map.
    auto regions = svm::visible_regions(raw.map);
    std::map<std::int64_t, std::size_t> faces;
    for (auto const& f : simple.map.faces())
      if (f.label >= 0) ++faces[f.label];
    CHECK(regions == faces);
    CHECK(svm::visible_regions(simple.map) == faces);
    ++checked;
  }
  CHECK(checked >= 25);
}

TEST_CASE("queries: visible polygons, their faces, adjacency", "[svm][query]") {
  // A square at z = 5 and, in front of it, a smaller one: the far square is seen as a ring.
  auto P = [](long x, long y, long z) { return e3::point<Q>(Q(x), Q(y), Q(z)); };
  std::vector<svm::polygon<Q>> polys{{{P(-4, -4, 5), P(-4, 4, 5), P(4, 4, 5), P(4, -4, 5)}, 0},
                                     {{P(-1, -1, 2), P(-1, 1, 2), P(1, 1, 2), P(1, -1, 2)}, 1},
                                     {{P(-1, -1, -2), P(-1, 1, -2), P(1, 1, -2), P(1, -1, -2)}, 2}};
  auto vm = svm::build<Q>(polys, P(0, 0, 0));
  CHECK(svm::visible_polygons(vm.map) == std::vector<std::int64_t>{0, 1, 2});
  auto ring = svm::faces_of(vm.map, 0);
  REQUIRE(ring.size() == 1);
  auto near = svm::faces_of(vm.map, 1);
  REQUIRE(near.size() == 1);
  auto around = svm::adjacent_faces(vm.map, ring[0]);
  // The ring touches the near square (its hole) and the background.
  CHECK(around.size() == 2);
  CHECK(std::count(around.begin(), around.end(), near[0]) == 1);
  CHECK(svm::adjacent_faces(vm.map, near[0]) == std::vector<svm::index>{ring[0]});
  CHECK(svm::face_cycles(vm.map)[ring[0]].size() == 2);
}

TEST_CASE("a direction read from doubles is the direction of their exact values", "[svm][query]") {
  // Equal directions compare equal whichever way they were made, including
  // subnormals, common odd factors and exponents too far apart for 128 bits.
  double const tiny = std::numeric_limits<double>::denorm_min();
  std::vector<std::array<double, 3>> cases{{3, 6, 9},          {-0.75, 0.5, 0},   {1e-300, 1, -1e300}, {tiny, 0, 0},
                                           {tiny, 3 * tiny, 1}, {0, -5e-324, 2}, {1, 0x1p-60, 0x1p60}, {0.1, 0.2, 0.3},
                                           {-1, -1, -1},       {0x1p-1074, 0x1p-1000, 0x1p-1050}};
  for (auto const& d : cases) {
    auto fast = svm::direction_of_doubles<Q>(d);
    s2::point<Q> slow(std::array<Q, 3>{Q(d[0]), Q(d[1]), Q(d[2])});
    INFO(d[0] << " " << d[1] << " " << d[2]);
    CHECK(fast == slow);
    for (std::size_t i = 0; i < 3; ++i) CHECK(fast.sign_at(i) == slow.sign_at(i));
  }
  // A positive multiple is the same direction, a negative one is not.
  CHECK(svm::direction_of_doubles<Q>({3, 6, 9}) == svm::direction_of_doubles<Q>({1, 2, 3}));
  CHECK(svm::direction_of_doubles<Q>({0.5, 0x1p-70, 0}) == svm::direction_of_doubles<Q>({0x1p69, 1, 0}));
  CHECK_FALSE(svm::direction_of_doubles<Q>({-1, -2, -3}) == svm::direction_of_doubles<Q>({1, 2, 3}));
}

TEST_CASE("back faces are culled only on closed convex solids the eye is outside of", "[svm][cull]") {
  // Each scene against the ray caster (two-sided), with the number of solids
  // the build must prove convex and seen from outside.
  auto box = [](ivec lo, ivec hi) {
    std::vector<triangle> s;
    add_box(s, lo, hi);
    return s;
  };
  auto reversed = [](std::vector<triangle> s) {
    for (auto& t : s) std::swap(t.v[1], t.v[2]);
    return s;
  };
  auto join = [](std::vector<triangle> a, std::vector<triangle> const& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  auto cube = box({0, 0, 0}, {4, 4, 4}); // its top is the last face: triangles 2 and 3
  auto open_top = cube;
  open_top.erase(open_top.begin() + 2, open_top.begin() + 4);
  // The top replaced by four triangles down to a point inside: closed, not convex.
  auto dented = open_top;
  ivec c{2, 2, 2};
  for (auto [a, b] : {std::pair{ivec{0, 0, 4}, ivec{4, 0, 4}}, {ivec{4, 0, 4}, ivec{4, 4, 4}}, {ivec{4, 4, 4}, ivec{0, 4, 4}},
                      {ivec{0, 4, 4}, ivec{0, 0, 4}}})
    dented.push_back({{a, b, c}});
  // The top cut at the middle of a side its neighbour keeps whole: a T-junction.
  auto t_junction = open_top;
  ivec m{2, 0, 4};
  t_junction.push_back({{ivec{0, 0, 4}, m, ivec{0, 4, 4}}});
  t_junction.push_back({{m, ivec{4, 4, 4}, ivec{0, 4, 4}}});
  t_junction.push_back({{m, ivec{4, 0, 4}, ivec{4, 4, 4}}});
  struct cull_case {
    char const* name;
    std::vector<triangle> tris;
    ivec eye;
    std::size_t solids;
  };
  std::vector<cull_case> cases{
      {"outside", cube, {7, 2, 3}, 1},
      {"in the plane of a face", cube, {2, 9, 4}, 1},
      {"on the line of an edge", cube, {9, 0, 0}, 1},
      {"inside", cube, {1, 2, 3}, 0},
      {"open", open_top, {1, 2, 9}, 0},
      {"facing in", reversed(cube), {7, 2, 3}, 0},
      {"dented", dented, {1, 3, 9}, 0},
      {"T-junction", t_junction, {1, 3, 9}, 0},
      {"two boxes glued face to face", join(cube, box({4, 0, 0}, {8, 4, 4})), {3, -5, 6}, 0},
      {"one box behind another", join(cube, box({-1, 9, 1}, {5, 12, 3})), {2, -6, 2}, 2},
  };
  // A solid past the budget is left whole: this cube costs 12 faces × 8 vertices.
  for (std::size_t budget : {95, 96}) {
    std::size_t counted = 0;
    auto hidden = svm::detail::on_convex_solids_seen_from_outside(polygons_of(cube), e3::point<Q>(Q(7), Q(2), Q(3)), budget, &counted);
    CHECK(counted == (budget == 96 ? 1u : 0u));
    CHECK(std::count(hidden.begin(), hidden.end(), 1) == (budget == 96 ? 12 : 0));
  }
  for (auto const& k : cases) {
    INFO(k.name);
    auto polys = polygons_of(k.tris);
    e3::point<Q> eye(Q(k.eye[0]), Q(k.eye[1]), Q(k.eye[2]));
    auto vm = svm::build<Q>(polys, eye);
    CHECK(vm.stats.convex_solids == k.solids);
    CHECK((vm.stats.discarded_backfacing > 0) == (k.solids > 0));
    check_map(vm, true);
    long compared = 0, wrong = 0;
    for (int r = 0; r < 3000; ++r) {
      ivec d = rp(1000);
      if (d == ivec{0, 0, 0}) continue;
      long truth = cast(k.tris, k.eye, d);
      if (truth == ambiguous) continue;
      ++compared;
      wrong += svm::locate(vm, s2::point<Q>(std::array<Q, 3>{Q(d[0]), Q(d[1]), Q(d[2])})) != truth;
    }
    CHECK(compared > 2500);
    CHECK(wrong == 0);
  }
}

TEST_CASE("a closed sphere: culling back faces changes no answer", "[svm][scenes]") {
  auto sc = svm::scenes::sphere(8); // 224 triangles
  CHECK(sc.polygons.size() == 224);
  auto two_sided = svm::build<Q>(sc.polygons, sc.eye, {.cull_convex_solids = false});
  auto culled = svm::build<Q>(sc.polygons, sc.eye, {.cull_backfaces = true});
  CHECK(culled.stats.discarded_backfacing > 80);
  check_map(two_sided, true);
  check_map(culled, true);
  int visible = 0;
  for (int r = 0; r < 2000; ++r) {
    // Directions towards the sphere's centre, spread around it.
    s2::point<Q> d(std::array<Q, 3>{Q(-250000 + test::uniform(-80000, 80000)), Q(-120000 + test::uniform(-80000, 80000)),
                                    Q(-90000 + test::uniform(-80000, 80000))});
    auto a = svm::locate(two_sided, d);
    CHECK(a == svm::locate(culled, d));
    visible += a >= 0;
  }
  CHECK(visible > 500);
}

TEST_CASE("over double, the map of a scene seen from a non-dyadic eye is the exact map", "[svm][double]") {
  // Double rounds the eye (1/3, 1/7, 0) and every circle; its signs stay
  // exact for the rounded objects, so the map stays a valid map (with
  // slivers where exact circles meet in one point) and every sampled
  // direction sees what the exact map sees, but within rounding distance of
  // an edge.  Scenes with integer vertices
  // only: rounded rotated cubes (random_cubes) still go wrong over double.
  std::vector<std::pair<std::string, svm::scenes::scene>> scenes{{"bricks 4", svm::scenes::bricks(4)},
                                                                {"bricks 16", svm::scenes::bricks(16)},
                                                                {"hidden bricks 8", svm::scenes::hidden_bricks(8)},
                                                                {"platforms 8", svm::scenes::platforms(8)}};
  for (auto const& [name, sc] : scenes) {
    INFO(name);
    auto exact = svm::build<Q>(sc.polygons, sc.eye);
    std::vector<svm::polygon<double>> pd;
    for (auto const& p : sc.polygons) {
      std::vector<e3::point<double>> v;
      for (auto const& q : p.vertices) v.emplace_back(q.x().convert_to<double>(), q.y().convert_to<double>(), q.z().convert_to<double>());
      pd.push_back({std::move(v), p.face});
    }
    e3::point<double> eye(sc.eye.x().convert_to<double>(), sc.eye.y().convert_to<double>(), sc.eye.z().convert_to<double>());
    auto rounded = svm::build<double>(pd, eye);
    check_map(rounded, true);
    // A direction may differ only within rounding distance of an edge: then
    // the exact map shows the double answer a millionth of a radian away.
    int differ = 0, far = 0, compared = 0;
    for (int r = 0; r < 3000; ++r) {
      ivec d = rp(1000);
      if (d == ivec{0, 0, 0}) continue;
      ++compared;
      long a = svm::locate(exact, s2::point<Q>(std::array<Q, 3>{Q(d[0]), Q(d[1]), Q(d[2])}));
      long b = svm::locate(rounded, s2::point<double>(std::array<double, 3>{double(d[0]), double(d[1]), double(d[2])}));
      if (a == b) continue;
      ++differ;
      double len = std::sqrt(double(d[0]) * double(d[0]) + double(d[1]) * double(d[1]) + double(d[2]) * double(d[2]));
      bool near = false;
      for (int k = 0; k < 3 && !near; ++k)
        for (int sgn : {-1, 1}) {
          std::array<Q, 3> p{Q(d[0]), Q(d[1]), Q(d[2])};
          p[static_cast<std::size_t>(k)] += Q(sgn * len * 1e-6);
          if (svm::locate(exact, s2::point<Q>(p)) == b) near = true;
        }
      far += !near;
    }
    INFO(differ << " of " << compared << " directions differ, " << far << " of them away from an edge");
    CHECK(far == 0);
    CHECK(differ * 1000 <= compared);
  }
}
