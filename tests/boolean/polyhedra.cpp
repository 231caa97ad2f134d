// Exact CSG on closed polyhedra: volumes of boxes combined in every
// degenerate way (overlapping, sharing a face, an edge, a vertex), rotated
// cubes with rational rotations, icospheres with rational vertices
// (inclusion–exclusion, exactly), input errors, and every output mesh checked
// independently: closed, welded, planar faces, no mergeable neighbours, and its
// own enclosed volume equal to the tree's.
#include "../support.hpp"

#include <catch2/catch.hpp>

#include <boolean/polyhedra.hpp>
#include <geometry/io/scene.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <vector>

using boolean::csg_op;
using boolean::mesh;
using boolean::solid;
using geometry::io::scene;
using test::Q;
using P = boolean::point3;

namespace {

/// A scene of triangles or quadrilaterals given by vertices and index cycles.
scene make_scene(std::vector<P> v, std::vector<std::vector<std::uint32_t>> faces) {
  scene s;
  s.vertices = std::move(v);
  for (auto& f : faces) s.faces.push_back({std::move(f), std::nullopt, 0});
  return s;
}

/// The box [lo, hi] as six quadrilaterals, counter-clockwise seen from outside.
scene box(std::array<Q, 3> lo, std::array<Q, 3> hi) {
  std::vector<P> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]);
  return make_scene(v, {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}});
}

solid box_solid(Q x0, Q y0, Q z0, Q x1, Q y1, Q z1) { return boolean::from_scene(box({x0, y0, z0}, {x1, y1, z1})); }

/// Every vertex mapped by the rational matrix `r`.
scene transformed(scene s, std::array<std::array<Q, 3>, 3> const& r) {
  for (auto& p : s.vertices) {
    std::array<Q, 3> c{p.x(), p.y(), p.z()}, o;
    for (int i = 0; i < 3; ++i) o[i] = r[i][0] * c[0] + r[i][1] * c[1] + r[i][2] * c[2];
    p = P(o[0], o[1], o[2]);
  }
  return s;
}

/// The rotation of the unit quaternion (a, b, c, d) / |q|: rational for integer a, b, c, d.
std::array<std::array<Q, 3>, 3> rotation(long a, long b, long c, long d) {
  Q n(a * a + b * b + c * c + d * d);
  return {{{Q(a * a + b * b - c * c - d * d) / n, Q(2 * (b * c - a * d)) / n, Q(2 * (b * d + a * c)) / n},
           {Q(2 * (b * c + a * d)) / n, Q(a * a - b * b + c * c - d * d) / n, Q(2 * (c * d - a * b)) / n},
           {Q(2 * (b * d - a * c)) / n, Q(2 * (c * d + a * b)) / n, Q(a * a - b * b - c * c + d * d) / n}}};
}

/// An icosphere with rational vertices: an icosahedron (golden ratio 809/500)
/// subdivided `levels` times, every vertex pushed to about `radius` from the
/// centre by a rational factor (multiples of 1/4096).
scene icosphere(int levels, double radius, std::array<Q, 3> centre) {
  Q t(809, 500);
  std::vector<std::array<Q, 3>> v{{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                  {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::uint32_t, 3>> f{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                              {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                              {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                              {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      auto key = std::minmax(a, b);
      auto [it, added] = mid.try_emplace(key, static_cast<std::uint32_t>(v.size()));
      if (added) v.push_back({(v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2});
      return it->second;
    };
    std::vector<std::array<std::uint32_t, 3>> g;
    for (auto [a, b, c] : f) {
      auto ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      g.push_back({a, ab, ca});
      g.push_back({b, bc, ab});
      g.push_back({c, ca, bc});
      g.push_back({ab, bc, ca});
    }
    f = std::move(g);
  }
  std::vector<P> pts;
  for (auto const& p : v) {
    double len = std::sqrt(p[0].convert_to<double>() * p[0].convert_to<double>() +
                           p[1].convert_to<double>() * p[1].convert_to<double>() +
                           p[2].convert_to<double>() * p[2].convert_to<double>());
    Q s(std::lround(radius / len * 4096), 4096);
    pts.emplace_back(centre[0] + p[0] * s, centre[1] + p[1] * s, centre[2] + p[2] * s);
  }
  std::vector<std::vector<std::uint32_t>> faces;
  for (auto [a, b, c] : f) faces.push_back({a, b, c});
  return make_scene(pts, faces);
}

/// The oriented plane of a face, normalised (first non-zero normal component ±1).
std::array<Q, 4> plane_of(mesh const& m, std::vector<std::uint32_t> const& f) {
  std::array<Q, 3> n{0, 0, 0};
  for (std::size_t i = 0; i < f.size(); ++i) {
    auto const &p = m.vertices[f[i]], &q = m.vertices[f[(i + 1) % f.size()]];
    n[0] += p.y() * q.z() - p.z() * q.y();
    n[1] += p.z() * q.x() - p.x() * q.z();
    n[2] += p.x() * q.y() - p.y() * q.x();
  }
  auto const& o = m.vertices[f[0]];
  std::array<Q, 4> h{n[0], n[1], n[2], -(n[0] * o.x() + n[1] * o.y() + n[2] * o.z())};
  std::size_t k = h[0] != 0 ? 0 : h[1] != 0 ? 1 : 2;
  Q s = abs(h[k]);
  for (auto& c : h) c /= s;
  return h;
}

/// Six times the signed volume enclosed by the faces (fans), computed here from the coordinates.
Q enclosed_volume(mesh const& m) {
  Q six(0);
  for (auto const& f : m.faces)
    for (std::size_t i = 1; i + 1 < f.size(); ++i) {
      auto const &a = m.vertices[f[0]], &b = m.vertices[f[i]], &c = m.vertices[f[i + 1]];
      six += test::ref_det3({a.x(), a.y(), a.z()}, {b.x(), b.y(), b.z()}, {c.x(), c.y(), c.z()});
    }
  return six / 6;
}

struct mesh_facts {
  std::size_t directed_edges = 0, unmatched = 0, non_manifold = 0, mergeable = 0;
};

/// Independent checks of an output mesh; returns its edge facts.
mesh_facts check_mesh(mesh const& m, Q const& volume) {
  mesh_facts r;
  // Welded: pairwise distinct vertices, every one used.
  std::set<std::array<Q, 3>> seen;
  for (auto const& p : m.vertices) CHECK(seen.insert({p.x(), p.y(), p.z()}).second);
  std::vector<bool> used(m.vertices.size(), false);
  // Faces: at least 3 distinct vertices, planar, not flat.
  for (auto const& f : m.faces) {
    REQUIRE(f.size() >= 3);
    CHECK(std::set<std::uint32_t>(f.begin(), f.end()).size() == f.size());
    auto h = plane_of(m, f);
    CHECK((h[0] != 0 || h[1] != 0 || h[2] != 0));
    for (auto i : f) {
      used[i] = true;
      auto const& p = m.vertices[i];
      CHECK(h[0] * p.x() + h[1] * p.y() + h[2] * p.z() + h[3] == 0);
    }
  }
  CHECK(std::count(used.begin(), used.end(), false) == 0);
  // Edges: each directed edge against its reverse; neighbours across an edge in different planes.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> runs;
  for (std::size_t k = 0; k < m.faces.size(); ++k) {
    auto const& f = m.faces[k];
    for (std::size_t i = 0; i < f.size(); ++i) runs[{f[i], f[(i + 1) % f.size()]}].push_back(k);
  }
  for (auto const& [e, faces] : runs) {
    ++r.directed_edges;
    auto it = runs.find({e.second, e.first});
    std::size_t back = it == runs.end() ? 0 : it->second.size();
    if (back != faces.size())
      ++r.unmatched;
    else if (faces.size() > 1)
      ++r.non_manifold;
    else if (plane_of(m, m.faces[faces[0]]) == plane_of(m, m.faces[it->second[0]]))
      ++r.mergeable;
  }
  CHECK(r.unmatched == 0);
  CHECK(enclosed_volume(m) == volume);
  CHECK(boolean::volume(m) == volume);
  auto rep = boolean::inspect_edges(m);
  CHECK(rep.edges * 2 == r.directed_edges);
  CHECK(rep.unmatched == r.unmatched);
  CHECK(rep.non_manifold * 2 == r.non_manifold);
  CHECK(boolean::closed(m) == (r.unmatched == 0 && r.non_manifold == 0));
  // The triangles cover the same surface: same volume, still closed.
  auto tris = boolean::triangles(m);
  mesh tm{m.vertices, {}};
  for (auto const& t : tris) tm.faces.push_back({t[0], t[1], t[2]});
  CHECK(enclosed_volume(tm) == volume);
  CHECK(boolean::inspect_edges(tm).unmatched == 0);
  std::size_t corners = 0;
  for (auto const& f : m.faces) corners += f.size() - 2;
  CHECK(tris.size() == corners); // every vertex kept, no flat triangle dropped or added
  return r;
}

/// Euler characteristic V − E + F of a mesh (2 for a sphere-like closed manifold).
long euler(mesh const& m) {
  auto r = boolean::inspect_edges(m);
  return static_cast<long>(m.vertices.size()) - static_cast<long>(r.edges) + static_cast<long>(m.faces.size());
}

/// The number of connected pieces of a mesh (vertices joined by edges).
long components(mesh const& m) {
  std::vector<std::uint32_t> up(m.vertices.size());
  for (std::uint32_t i = 0; i < up.size(); ++i) up[i] = i;
  auto root = [&](std::uint32_t i) {
    while (up[i] != i) i = up[i] = up[up[i]];
    return i;
  };
  for (auto const& f : m.faces)
    for (std::size_t i = 0; i < f.size(); ++i) up[root(f[i])] = root(f[(i + 1) % f.size()]);
  long n = 0;
  for (std::uint32_t i = 0; i < up.size(); ++i) n += root(i) == i;
  return n;
}

/// A mesh as a set of faces, each the cycle of its vertices' coordinates
/// started at its least vertex: equal for meshes that differ only in the
/// numbering of vertices and the first vertex of each face.
std::multiset<std::vector<std::array<Q, 3>>> face_cycles(mesh const& m) {
  std::multiset<std::vector<std::array<Q, 3>>> out;
  for (auto const& f : m.faces) {
    std::vector<std::array<Q, 3>> c;
    for (auto v : f) c.push_back({m.vertices[v].x(), m.vertices[v].y(), m.vertices[v].z()});
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    out.insert(std::move(c));
  }
  return out;
}

/// Planes made into one face on integer vertices, and planes in all, over
/// every mesh `op` checked.
std::size_t integer_planes = 0, all_planes = 0;

/// `apply`, with the fast paths checked against it: `combine` (no merged
/// tree) gives the same mesh as the merged tree's boundary, and the merged
/// boundary's mesh is the same with and without the integer path for
/// single faces (`build_mesh`).
solid op(csg_op o, solid const& a, solid const& b) {
  auto r = boolean::apply(o, a, b);
  auto fast = boolean::combine(o, a, b), slow = boolean::to_mesh(r.tree);
  CHECK(fast.faces.size() == slow.faces.size());
  CHECK(fast.vertices.size() == slow.vertices.size());
  CHECK(boolean::volume(fast) == r.volume);
  CHECK(boolean::closed(fast) == boolean::closed(slow));
  auto pieces = bsp::oriented_boundary(r.tree);
  std::set<std::array<Q, 4>> planes;
  for (auto const& p : pieces) planes.insert(boolean::detail::polyhedra::canonical(p));
  all_planes += planes.size();
  auto integer = boolean::detail::polyhedra::build_mesh(pieces, true, &integer_planes);
  auto rational = boolean::detail::polyhedra::build_mesh(pieces, false);
  CHECK(integer.vertices.size() == rational.vertices.size());
  CHECK(face_cycles(integer) == face_cycles(rational));
  return r;
}

} // namespace

TEST_CASE("Polyhedra: the unit cube, exactly, and its mesh", "[boolean][polyhedra]") {
  auto c = box_solid(0, 0, 0, 1, 1, 1);
  CHECK(c.volume == 1);
  CHECK(!c.flipped);
  CHECK(bsp::measure(c.tree, true) == Q(1));
  CHECK(bsp::classify(c.tree, P(Q(1, 2), Q(1, 2), Q(1, 2))) == true);
  CHECK(bsp::classify(c.tree, P(2, 0, 0)) == false);
  auto m = boolean::to_mesh(c);
  CHECK(m.faces.size() == 6);
  CHECK(m.vertices.size() == 8);
  CHECK(boolean::closed(m));
  auto f = check_mesh(m, 1);
  CHECK(f.mergeable == 0);
  // Read back: the same solid.
  CHECK(boolean::from_scene(boolean::to_scene(m)).volume == 1);
}

TEST_CASE("Polyhedra: input errors and inside-out meshes", "[boolean][polyhedra]") {
  auto s = box({0, 0, 0}, {1, 1, 1});
  SECTION("inside out: flipped and solved") {
    for (auto& f : s.faces) std::reverse(f.vertices.begin(), f.vertices.end());
    auto c = boolean::from_scene(s);
    CHECK(c.flipped);
    CHECK(c.volume == 1);
    auto m = boolean::to_mesh(c);
    CHECK(boolean::volume(m) == 1);
    CHECK(boolean::closed(m));
  }
  SECTION("open: a face missing") {
    s.faces.pop_back();
    CHECK_THROWS_WITH(boolean::from_scene(s),
                      Catch::Contains("open mesh: edge between vertices") && Catch::Contains("has 1 face"));
    CHECK_THROWS_AS(boolean::from_scene(s), std::invalid_argument);
  }
  SECTION("one face reversed") {
    std::reverse(s.faces[2].vertices.begin(), s.faces[2].vertices.end());
    CHECK_THROWS_WITH(boolean::from_scene(s),
                      Catch::StartsWith("inconsistently oriented faces at edge between vertices"));
    CHECK_THROWS_AS(boolean::from_scene(s), std::invalid_argument);
  }
  SECTION("two overlapping cubes in one mesh: self-intersecting") {
    auto t = box({Q(1, 2), Q(1, 2), Q(1, 2)}, {Q(3, 2), Q(3, 2), Q(3, 2)});
    auto base = static_cast<std::uint32_t>(s.vertices.size());
    for (auto const& p : t.vertices) s.vertices.push_back(p);
    for (auto f : t.faces) {
      for (auto& i : f.vertices) i += base;
      s.faces.push_back(f);
    }
    CHECK_THROWS_WITH(boolean::from_scene(s), Catch::StartsWith("self-intersecting mesh (the faces' enclosed volume 2 "
                                                                "differs from the volume of the solid they bound"));
  }
  SECTION("no volume") { CHECK_THROWS_WITH(boolean::from_scene(scene{}), Catch::Contains("encloses no volume")); }
  SECTION("a triangle soup with repeated vertices (as STL gives it) is welded") {
    scene soup;
    for (auto const& f : s.faces) {
      std::uint32_t b = static_cast<std::uint32_t>(soup.vertices.size());
      for (int k : {0, 1, 2, 0, 2, 3}) soup.vertices.push_back(s.vertices[f.vertices[static_cast<std::size_t>(k)]]);
      soup.faces.push_back({{b, b + 1, b + 2}, std::nullopt, 0});
      soup.faces.push_back({{b + 3, b + 4, b + 5}, std::nullopt, 0});
    }
    auto c = boolean::from_scene(soup);
    CHECK(c.volume == 1);
    auto m = boolean::to_mesh(c);
    CHECK(m.faces.size() == 6);
    CHECK(m.vertices.size() == 8);
    soup.faces.pop_back();
    CHECK_THROWS_WITH(boolean::from_scene(soup), Catch::Contains("open mesh"));
  }
}

TEST_CASE("Polyhedra: boxes overlapping, sharing a face, an edge, a vertex", "[boolean][polyhedra]") {
  auto a = box_solid(0, 0, 0, 2, 2, 2);
  SECTION("overlapping") {
    auto b = box_solid(1, 1, 1, 3, 3, 3);
    auto u = op(csg_op::union_, a, b), i = op(csg_op::intersection, a, b), d = op(csg_op::difference, a, b);
    CHECK(u.volume == 15);
    CHECK(i.volume == 1);
    CHECK(d.volume == 7);
    auto mu = boolean::to_mesh(u), mi = boolean::to_mesh(i), md = boolean::to_mesh(d);
    CHECK(mu.faces.size() == 12); // three squares and three L-shapes of each box
    CHECK(mu.vertices.size() == 20);
    CHECK(mi.faces.size() == 6);
    CHECK(mi.vertices.size() == 8);
    CHECK(md.faces.size() == 9); // three squares, three L-shapes, the three walls of the notch
    CHECK(md.vertices.size() == 14);
    for (auto const* x : {&mu, &mi, &md}) {
      CHECK(boolean::closed(*x));
      CHECK(euler(*x) == 2);
    }
    CHECK(check_mesh(mu, 15).mergeable == 0);
    CHECK(check_mesh(mi, 1).mergeable == 0);
    CHECK(check_mesh(md, 7).mergeable == 0);
  }
  SECTION("sharing a face: a 2 × 1 × 1 box") {
    auto p = box_solid(0, 0, 0, 1, 1, 1), q = box_solid(1, 0, 0, 2, 1, 1);
    auto u = op(csg_op::union_, p, q);
    CHECK(u.volume == 2);
    auto m = boolean::to_mesh(u);
    CHECK(m.faces.size() == 6);
    CHECK(m.vertices.size() == 8);
    CHECK(check_mesh(m, 2).mergeable == 0);
    CHECK(boolean::closed(m));
    auto i = op(csg_op::intersection, p, q);
    CHECK(i.volume == 0);
    CHECK(boolean::to_mesh(i).faces.empty());
    auto d = op(csg_op::difference, p, q);
    CHECK(d.volume == 1);
    auto md = boolean::to_mesh(d);
    CHECK(md.faces.size() == 6);
    CHECK(md.vertices.size() == 8);
    check_mesh(md, 1);
  }
  SECTION("sharing an edge: non-manifold, reported") {
    auto q = box_solid(2, 2, 0, 4, 4, 2);
    auto u = op(csg_op::union_, a, q);
    CHECK(u.volume == 16);
    auto m = boolean::to_mesh(u);
    auto r = boolean::inspect_edges(m);
    CHECK(r.non_manifold == 1);
    CHECK(r.unmatched == 0);
    CHECK(!boolean::closed(m));
    CHECK(m.faces.size() == 12);
    CHECK(m.vertices.size() == 14);
    auto f = check_mesh(m, 16);
    CHECK(f.non_manifold == 2);
    CHECK(f.mergeable == 0);
    CHECK(op(csg_op::intersection, a, q).volume == 0);
    CHECK(op(csg_op::difference, a, q).volume == 8);
    // Read back, the four faces at the edge balance: the same solid.
    CHECK(boolean::from_scene(boolean::to_scene(m)).volume == 16);
  }
  SECTION("sharing a vertex") {
    auto q = box_solid(2, 2, 2, 3, 3, 3);
    auto u = op(csg_op::union_, a, q);
    CHECK(u.volume == 9);
    auto m = boolean::to_mesh(u);
    CHECK(boolean::closed(m));
    CHECK(m.faces.size() == 12);
    CHECK(m.vertices.size() == 15);
    CHECK(check_mesh(m, 9).mergeable == 0);
    CHECK(op(csg_op::intersection, a, q).volume == 0);
    CHECK(op(csg_op::difference, q, a).volume == 1);
    CHECK(boolean::to_mesh(op(csg_op::intersection, a, q)).faces.empty());
  }
  SECTION("a wedge under half of a long box: a T-junction removed") {
    auto p = box_solid(0, 0, 0, 2, 1, 1);
    // The prism over the triangle (y, z) = (0, 0), (1, 0), (1, -1), for x in [1, 2].
    auto w = boolean::from_scene(make_scene({P(1, 0, 0), P(1, 1, 0), P(1, 1, -1), P(2, 0, 0), P(2, 1, 0), P(2, 1, -1)},
                                            {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {0, 3, 5, 2}}));
    CHECK(w.volume == Q(1, 2));
    auto u = op(csg_op::union_, p, w);
    CHECK(u.volume == Q(5, 2));
    auto m = boolean::to_mesh(u);
    CHECK(m.faces.size() == 8);
    CHECK(m.vertices.size() == 11);
    CHECK(boolean::closed(m));
    CHECK(euler(m) == 2);
    CHECK(check_mesh(m, Q(5, 2)).mergeable == 0);
    // The face y = 0 is the whole 2 × 1 rectangle, with the wedge's edge end (1, 0, 0) inserted.
    CHECK(std::count_if(m.faces.begin(), m.faces.end(), [](auto const& f) { return f.size() == 5; }) == 1);
  }
  SECTION("drilled: faces with holes are cut into simple faces") {
    auto drill = box_solid(Q(1, 2), Q(1, 2), -1, Q(3, 2), Q(3, 2), 3);
    auto d = op(csg_op::difference, a, drill);
    CHECK(d.volume == 6);
    auto m = boolean::to_mesh(d);
    CHECK(boolean::closed(m));
    CHECK(euler(m) == 0);        // a torus
    CHECK(m.faces.size() == 12); // four outer walls, four inner, top and bottom in two pieces each
    auto f = check_mesh(m, 6);
    CHECK(f.mergeable == 8); // both directions of the two cuts of the top and of the bottom
    CHECK(boolean::from_scene(boolean::to_scene(m)).volume == 6);
  }
}

TEST_CASE("Polyhedra: cubes with rational rotations", "[boolean][polyhedra]") {
  auto cube = box({-1, -1, -1}, {1, 1, 1});
  auto a = boolean::from_scene(cube);
  for (auto r : {rotation(2, 0, 0, 1) /* 3-4-5 about z */, rotation(3, 1, 1, 1), rotation(4, 1, 2, 0)}) {
    auto b = boolean::from_scene(transformed(cube, r));
    CHECK(b.volume == 8);
    auto u = op(csg_op::union_, a, b), i = op(csg_op::intersection, a, b), d = op(csg_op::difference, a, b);
    CHECK(u.volume == a.volume + b.volume - i.volume);
    CHECK(d.volume == a.volume - i.volume);
    CHECK(i.volume < 8);
    CHECK(i.volume > 4);
    for (auto const* s : {&u, &i, &d}) {
      auto m = boolean::to_mesh(*s);
      CHECK(boolean::closed(m));
      CHECK(euler(m) == 2 * components(m)); // spheres (the difference about z: four corner prisms)
      CHECK(check_mesh(m, s->volume).mergeable == 0);
      CHECK(boolean::from_scene(boolean::to_scene(m)).volume == s->volume);
    }
  }
  // About z by the 3-4-5 angle: the intersection is an octagonal prism.
  auto b = boolean::from_scene(transformed(cube, rotation(2, 0, 0, 1)));
  auto m = boolean::to_mesh(op(csg_op::intersection, a, b));
  CHECK(m.faces.size() == 10);
  CHECK(m.vertices.size() == 16);
  auto corners = boolean::to_mesh(op(csg_op::difference, a, b));
  CHECK(components(corners) == 4);
  CHECK(corners.faces.size() == 20);
}

TEST_CASE("Polyhedra: icospheres, inclusion–exclusion exactly", "[boolean][polyhedra]") {
  auto sa = icosphere(1, 2.0, {0, 0, 0});
  auto sb = icosphere(1, 1.75, {Q(1), Q(1, 2), Q(1, 3)});
  CHECK(sa.faces.size() == 80);
  auto a = boolean::from_scene(sa), b = boolean::from_scene(sb);
  CHECK(!a.flipped);
  double ball = 4.0 / 3 * 3.14159265358979 * 8;
  CHECK(a.volume.convert_to<double>() > 0.8 * ball);
  CHECK(a.volume.convert_to<double>() < ball);
  auto u = op(csg_op::union_, a, b), i = op(csg_op::intersection, a, b), d = op(csg_op::difference, a, b),
       e = op(csg_op::difference, b, a);
  CHECK(u.volume == a.volume + b.volume - i.volume);
  CHECK(d.volume == a.volume - i.volume);
  CHECK(e.volume == b.volume - i.volume);
  CHECK(i.volume > 0);
  for (auto const* s : {&u, &i, &d, &e}) {
    auto m = boolean::to_mesh(*s);
    CHECK(boolean::closed(m));
    CHECK(euler(m) == 2);
    CHECK(check_mesh(m, s->volume).mergeable == 0);
  }
  // The input mesh again: 80 faces, 42 vertices.
  auto ma = boolean::to_mesh(a);
  CHECK(ma.faces.size() == 80);
  CHECK(ma.vertices.size() == 42);
  // A finer sphere through a box: the box's faces with holes are cut.
  auto fine = boolean::from_scene(icosphere(2, 1.5, {0, 0, 0}));
  CHECK(fine.tree.statistics().depth < 120); // free cuts: 320 convex faces would make a chain 320 deep
  auto slab = box_solid(-3, -3, Q(-1, 2), 3, 3, Q(1, 2));
  auto cut = op(csg_op::difference, slab, fine);
  CHECK(cut.volume == slab.volume - op(csg_op::intersection, slab, fine).volume);
  auto mc = boolean::to_mesh(cut);
  CHECK(boolean::closed(mc));
  CHECK(euler(mc) == 0);
  check_mesh(mc, cut.volume);
  // Both ways of making a plane's faces ran: most planes are one face, the
  // slab's faces with a hole are not.
  CHECK(integer_planes > all_planes / 2);
  CHECK(integer_planes < all_planes);
}

TEST_CASE("Polyhedra: random boxes, some rotated, combined in sequence", "[boolean][polyhedra]") {
  // Integer boxes meet in every degenerate way (shared planes, collinear
  // edges, holes whose edges line up with the outer ring); rotated ones bring
  // slanted planes and large rationals.
  int meshes = 0;
  for (int t = 0; t < 36; ++t) {
    bool rotate = t % 6 == 5;
    auto acc = box_solid(0, 0, 0, 6, 6, 6);
    Q expected = acc.volume;
    for (long k = 0, n = test::uniform(1, 5); k < n; ++k) {
      std::array<Q, 3> lo, hi;
      for (std::size_t c = 0; c < 3; ++c) {
        long x = test::uniform(-2, 6);
        lo[c] = Q(x), hi[c] = Q(x + test::uniform(1, 5));
      }
      auto sc = box(lo, hi);
      if (rotate) {
        auto r = rotation(test::uniform(1, 3), test::uniform(-2, 2), test::uniform(-2, 2), test::uniform(-2, 2));
        for (auto& p : sc.vertices) p = P(p.x() - 3, p.y() - 3, p.z() - 3);
        sc = transformed(sc, r);
        for (auto& p : sc.vertices) p = P(p.x() + 3, p.y() + 3, p.z() + 3);
      }
      auto b = boolean::from_scene(sc);
      auto o = test::uniform(0, 2) == 0 ? csg_op::union_ : csg_op::difference;
      auto i = op(csg_op::intersection, acc, b);
      expected = o == csg_op::union_ ? expected + b.volume - i.volume : expected - i.volume;
      acc = op(o, acc, b);
      CHECK(acc.volume == expected);
    }
    auto m = boolean::to_mesh(acc);
    auto f = check_mesh(m, acc.volume);
    CHECK(f.unmatched == 0);
    if (f.non_manifold == 0 && !m.faces.empty()) {
      CHECK(boolean::from_scene(boolean::to_scene(m)).volume == acc.volume);
      ++meshes;
    }
  }
  CHECK(meshes > 20);
}

TEST_CASE("Polyhedra: OFF, OBJ and STL text", "[boolean][polyhedra]") {
  auto a = box_solid(0, 0, 0, 2, 2, 2), b = box_solid(1, 1, 1, 3, 3, 3);
  auto m = boolean::to_mesh(op(csg_op::union_, a, b));
  std::istringstream off(boolean::to_off(m)), obj(boolean::to_obj(m)), stl(boolean::to_stl(m));
  auto so = geometry::io::read_off(off, "u.off");
  auto sj = geometry::io::read_obj(obj, "u.obj");
  auto st = geometry::io::read_stl(stl, "u.stl");
  CHECK(so.faces.size() == m.faces.size());
  CHECK(sj.faces.size() == m.faces.size());
  CHECK(st.faces.size() == boolean::triangles(m).size());
  CHECK(so.vertices == m.vertices); // integer coordinates: exact through text
  for (auto const* s : {&so, &sj, &st}) CHECK(boolean::from_scene(*s).volume == 15);
  // Shortest round-trip decimals.
  mesh tenth{{P(Q(1, 10), 0, Q(-3, 2)), P(1, 0, Q(-3, 2)), P(0, 1, Q(-3, 2))}, {{0, 1, 2}}};
  CHECK(boolean::to_obj(tenth) == "v 0.1 0 -1.5\nv 1 0 -1.5\nv 0 1 -1.5\nf 1 2 3\n");
  CHECK(boolean::to_off(tenth) == "OFF\n3 1 0\n0.1 0 -1.5\n1 0 -1.5\n0 1 -1.5\n3 0 1 2\n");
  CHECK(boolean::to_stl(tenth).find("facet normal 0 0 1\n") != std::string::npos);
}
