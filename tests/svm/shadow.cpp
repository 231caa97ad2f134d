// Shadows from point lights against an independent exact reference: for a
// point strictly inside each piece, a segment to each light tested against
// every polygon with plain GMP rationals on the raw coordinates (nothing of
// the library's predicates); exact areas (each polygon's pieces sum to its
// area), a light inside a closed box, and a shadow's area on a floor against
// the closed-form central projection of its caster.
#include "../support.hpp"

#include <catch2/catch.hpp>
#include <svm/scenes.hpp>
#include <svm/shadow.hpp>

#include <numeric>

using namespace geometry;
using test::Q;

namespace {

using P = e3::point<Q>;
using V = std::array<Q, 3>;

V vec(P const& p) { return {p.x(), p.y(), p.z()}; }
V sub(V const& a, V const& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V cross(V const& a, V const& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
Q dot(V const& a, V const& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// The reference's view of a polygon: raw vertices and the normal of its
/// first three (counter-clockwise seen from the front).
struct ref_polygon {
  std::vector<V> v;
  V n;
};

std::vector<ref_polygon> reference(std::vector<svm::polygon<Q>> const& ps) {
  std::vector<ref_polygon> out;
  for (auto const& p : ps) {
    ref_polygon r;
    for (auto const& q : p.vertices) r.v.push_back(vec(q));
    r.n = cross(sub(r.v[1], r.v[0]), sub(r.v[2], r.v[0]));
    out.push_back(std::move(r));
  }
  return out;
}

/// Whether `y`, on the plane of `q`, lies in the closed polygon `q`.
bool inside_closed(ref_polygon const& q, V const& y) {
  for (std::size_t k = 0; k < q.v.size(); ++k)
    if (dot(q.n, cross(sub(q.v[(k + 1) % q.v.size()], q.v[k]), sub(y, q.v[k]))) < 0) return false;
  return true;
}

/// Whether the light `l` lights the point `x` strictly inside polygon `i`:
/// `l` strictly in front of polygon i, and the open segment from x to l
/// meeting no other closed polygon whose plane does not hold l.  Coplanar
/// polygons follow the depth order's tie: a lower input index is in front.
bool lit(std::vector<ref_polygon> const& scene, std::size_t i, V const& x, V const& l) {
  if (dot(scene[i].n, sub(l, scene[i].v[0])) <= 0) return false;
  for (std::size_t j = 0; j < scene.size(); ++j) {
    if (j == i) continue;
    auto const& q = scene[j];
    Q dx = dot(q.n, sub(x, q.v[0])), dl = dot(q.n, sub(l, q.v[0]));
    if (dl == 0) continue;
    if (dx == 0) {
      bool coplanar = cross(q.n, scene[i].n) == V{0, 0, 0};
      if (coplanar && j < i && inside_closed(q, x)) return false;
      continue;
    }
    if ((dx > 0) == (dl > 0)) continue;
    Q t = dx / (dx - dl);
    V y{x[0] + t * (l[0] - x[0]), x[1] + t * (l[1] - x[1]), x[2] + t * (l[2] - x[2])};
    if (inside_closed(q, y)) return false;
  }
  return true;
}

/// Whether the sun in direction `d` (towards it) lights the point `x`
/// strictly inside polygon `i`: the same test with the ray from x along d.
bool sunlit(std::vector<ref_polygon> const& scene, std::size_t i, V const& x, V const& d) {
  if (dot(scene[i].n, d) <= 0) return false;
  for (std::size_t j = 0; j < scene.size(); ++j) {
    if (j == i) continue;
    auto const& q = scene[j];
    Q dx = dot(q.n, sub(x, q.v[0])), dd = dot(q.n, d);
    if (dd == 0) continue;
    if (dx == 0) {
      bool coplanar = cross(q.n, scene[i].n) == V{0, 0, 0};
      if (coplanar && j < i && inside_closed(q, x)) return false;
      continue;
    }
    Q t = -dx / dd;
    if (t <= 0) continue;
    V y{x[0] + t * d[0], x[1] + t * d[1], x[2] + t * d[2]};
    if (inside_closed(q, y)) return false;
  }
  return true;
}

/// The centroid of a piece's exact vertices: a point strictly inside it.
V centroid(e3::sub_hyperplane<Q> const& s) {
  auto vs = e3::vertices(s);
  REQUIRE(vs);
  V c{0, 0, 0};
  for (auto const& p : *vs)
    for (std::size_t k = 0; k < 3; ++k) c[k] += vec(p)[k];
  for (auto& x : c) x /= Q(static_cast<long>(vs->size()));
  return c;
}

std::size_t dominant(V const& n) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < 3; ++i)
    if (abs(n[i]) > abs(n[k])) k = i;
  return k;
}

struct checked {
  std::size_t pieces = 0, lit = 0, shadowed = 0, wrong = 0;
};

/// Every piece (or `sample` of them, chosen at random) against the
/// reference for each light, and each polygon's pieces against its area.
checked check(std::vector<svm::polygon<Q>> const& polygons, std::vector<svm::light_source<Q>> const& lights, std::size_t sample = 0);

checked check(std::vector<svm::polygon<Q>> const& polygons, std::vector<P> const& points, std::size_t sample = 0) {
  std::vector<svm::light_source<Q>> lights;
  for (auto const& p : points) lights.push_back(svm::light_source<Q>::at(p));
  return check(polygons, lights, sample);
}

checked check(std::vector<svm::polygon<Q>> const& polygons, std::vector<svm::light_source<Q>> const& lights, std::size_t sample) {
  auto sh = svm::compute_shadows<Q>(polygons, lights);
  auto scene = reference(polygons);
  // Areas: the pieces of a polygon, projected on the coordinate plane its
  // normal is most perpendicular to, sum to its projection.
  std::vector<Q> area(polygons.size(), Q(0));
  for (auto const& p : sh.pieces) {
    auto a = e3::projected_area(p.shape, dominant(scene[p.polygon].n));
    REQUIRE(a);
    area[p.polygon] += *a;
  }
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    auto whole = e3::projected_area(e3::convex_polygon<Q>(polygons[i].vertices), dominant(scene[i].n));
    REQUIRE(whole);
    INFO("polygon " << i);
    CHECK(area[i] == *whole);
  }
  std::vector<std::size_t> order(sh.pieces.size());
  std::iota(order.begin(), order.end(), 0);
  if (sample > 0 && sample < order.size()) {
    std::shuffle(order.begin(), order.end(), test::rng());
    order.resize(sample);
  }
  checked c;
  for (std::size_t at : order) {
    auto const& p = sh.pieces[at];
    V x = centroid(p.shape);
    ++c.pieces;
    for (std::size_t k = 0; k < lights.size(); ++k) {
      bool expected = lights[k].point ? lit(scene, p.polygon, x, vec(*lights[k].point)) : sunlit(scene, p.polygon, x, lights[k].direction);
      bool got = (p.lights >> k) & 1u;
      ++(got ? c.lit : c.shadowed);
      if (expected != got) {
        ++c.wrong;
        UNSCOPED_INFO("polygon " << p.polygon << " light " << k << ": library " << got << ", reference " << expected);
      }
    }
  }
  return c;
}

std::vector<svm::polygon<Q>> square(long x0, long y0, long x1, long y1, long z, std::uint32_t face, bool up = true) {
  std::vector<P> v{P(Q(x0), Q(y0), Q(z)), P(Q(x1), Q(y0), Q(z)), P(Q(x1), Q(y1), Q(z)), P(Q(x0), Q(y1), Q(z))};
  if (!up) std::reverse(v.begin(), v.end());
  return {{std::move(v), face}};
}

void append(std::vector<svm::polygon<Q>>& to, std::vector<svm::polygon<Q>> const& more) {
  for (auto p : more) {
    p.face = static_cast<std::uint32_t>(to.size());
    to.push_back(std::move(p));
  }
}

} // namespace

TEST_CASE("shadows: Bricks lit off-axis, every piece against the reference", "[shadow]") {
  auto s = svm::scenes::bricks(6);
  auto c = check(s.polygons, {P(Q(7, 3), Q(-5, 2), Q(-3))});
  CHECK(c.wrong == 0);
  CHECK(c.lit > 10);
  CHECK(c.shadowed > 10);
}

TEST_CASE("shadows: the room with a lamp and a window light", "[shadow]") {
  auto s = svm::scenes::room();
  auto c = check(s.polygons, {P(Q(301), Q(249), Q(255)), P(Q(40) + Q(1, 3), Q(480), Q(150))}, 400);
  CHECK(c.wrong == 0);
  CHECK(c.lit > 50);
  CHECK(c.shadowed > 50);
}

TEST_CASE("shadows: a closed mesh over a floor", "[shadow]") {
  auto s = svm::scenes::sphere(5);
  auto polygons = s.polygons;
  append(polygons, square(-400000, -400000, 400000, 400000, -150000, 0));
  auto c = check(polygons, {P(Q(120000), Q(-70001), Q(350000))});
  CHECK(c.wrong == 0);
  CHECK(c.lit > 10);
  CHECK(c.shadowed > 10);
}

TEST_CASE("shadows: coplanar, touching and edge-on polygons, several lights", "[shadow]") {
  std::vector<svm::polygon<Q>> polygons;
  svm::scenes::scene boxes;
  svm::scenes::add_box(boxes, P(Q(0), Q(0), Q(0)), P(Q(4), Q(4), Q(4)));
  svm::scenes::add_box(boxes, P(Q(4), Q(0), Q(0)), P(Q(8), Q(4), Q(2)));  // touching the first along a face
  svm::scenes::add_box(boxes, P(Q(2), Q(6), Q(0)), P(Q(6), Q(10), Q(3))); // its base in the floor's plane
  append(polygons, boxes.polygons);
  append(polygons, square(-20, -20, 30, 30, 0, 0));        // the floor
  append(polygons, square(-10, -10, 0, 20, 0, 0));         // coplanar with the floor, overlapping it
  append(polygons, square(10, 12, 14, 16, 5, 0, false));   // facing down
  // Edge-on to the first light (its plane x = 9 holds it).
  append(polygons, {{{P(Q(9), Q(0), Q(3)), P(Q(9), Q(5), Q(3)), P(Q(9), Q(5), Q(8)), P(Q(9), Q(0), Q(8))}, 0}});
  auto c = check(polygons, {P(Q(9), Q(3), Q(12)), P(Q(-7), Q(15, 2), Q(9)), P(Q(20), Q(25), Q(30))});
  CHECK(c.wrong == 0);
  CHECK(c.lit > 10);
  CHECK(c.shadowed > 10);
}

TEST_CASE("shadows: a light inside a closed box lights nothing outside", "[shadow]") {
  svm::scenes::scene s;
  svm::scenes::add_box(s, P(Q(0), Q(0), Q(0)), P(Q(10), Q(10), Q(10)));
  std::size_t const box = s.polygons.size();
  auto polygons = s.polygons;
  append(polygons, square(-50, -50, 60, 60, -1, 0));                                          // a floor
  append(polygons, {{{P(Q(20), Q(0), Q(0)), P(Q(20), Q(10), Q(0)), P(Q(20), Q(5), Q(9))}, 0}}); // a triangle beside
  append(polygons, square(2, 2, 5, 5, 3, 0));                                                  // a tile inside, lit
  auto sh = svm::compute_shadows<Q>(polygons, {P(Q(5), Q(5), Q(7))});
  bool tile_lit = false;
  for (auto const& p : sh.pieces) {
    if (p.polygon == polygons.size() - 1) tile_lit = tile_lit || p.lights != 0;
    else CHECK(p.lights == 0); // the box's faces turn their backs to the light; the rest is outside
  }
  CHECK(tile_lit);
  CHECK(box == 6);
}

TEST_CASE("shadows: a triangle's shadow on a floor is its central projection", "[shadow]") {
  // The floor z = 0, a triangle at height 3 under a light at height 9: the
  // shadow is the triangle projected from the light, scaled by 9 / (9 − 3)
  // about the light's foot.
  std::vector<svm::polygon<Q>> polygons = square(-100, -100, 100, 100, 0, 0);
  std::vector<P> tri{P(Q(1), Q(2), Q(3)), P(Q(7, 2), Q(1), Q(3)), P(Q(2), Q(5), Q(3))};
  append(polygons, {{tri, 0}});
  P light(Q(1, 3), Q(-2), Q(9));
  auto sh = svm::compute_shadows<Q>(polygons, {light});
  Q shadow(0);
  std::size_t floor_pieces = 0;
  for (auto const& p : sh.pieces)
    if (p.polygon == 0) {
      ++floor_pieces;
      if (p.lights == 0) shadow += *e3::projected_area(p.shape, 2);
    }
  // The closed form, by the shoelace formula on the projected vertices.
  std::vector<std::array<Q, 2>> proj;
  for (auto const& v : tri) {
    Q t = light.z() / (light.z() - v.z());
    proj.push_back({light.x() + t * (v.x() - light.x()), light.y() + t * (v.y() - light.y())});
  }
  Q expected(0);
  for (std::size_t i = 0; i < 3; ++i) expected += proj[i][0] * proj[(i + 1) % 3][1] - proj[(i + 1) % 3][0] * proj[i][1];
  expected /= 2;
  CHECK(floor_pieces >= 2);
  CHECK(abs(shadow) == abs(expected));
  CHECK(expected != 0);
}

TEST_CASE("shadows: regions join pieces of one face that the same lights reach", "[shadow]") {
  auto s = svm::scenes::bricks(4);
  auto sh = svm::compute_shadows<Q>(s.polygons, {P(Q(1), Q(2), Q(-4)), P(Q(-3), Q(1), Q(-2))});
  auto labelled = svm::label_regions(sh, s.polygons);
  // The lit pieces as they are, and each polygon with a shadowed piece whole
  // after them, labelled as reached by no light.
  std::size_t k = 0, dark = 0;
  for (std::size_t i = 0; i < s.polygons.size(); ++i) {
    bool shadowed = false;
    for (auto const& p : sh.pieces) {
      if (p.polygon != i) continue;
      shadowed = shadowed || p.lights == 0;
      if (p.lights == 0) continue;
      REQUIRE(k < labelled.pieces.size());
      auto const& r = labelled.regions.at(static_cast<std::size_t>(labelled.pieces[k].label));
      CHECK(r.face == s.polygons[i].face);
      CHECK(r.lights == p.lights);
      CHECK(*e3::projected_area(labelled.pieces[k].shape, 2) == *e3::projected_area(p.shape, 2));
      ++k;
    }
    if (shadowed) {
      REQUIRE(k < labelled.pieces.size());
      auto const& r = labelled.regions.at(static_cast<std::size_t>(labelled.pieces[k].label));
      CHECK(r.face == s.polygons[i].face);
      CHECK(r.lights == 0);
      CHECK(*e3::projected_area(labelled.pieces[k].shape, 2) == *e3::projected_area(e3::convex_polygon<Q>(s.polygons[i].vertices), 2));
      ++k, ++dark;
    }
  }
  CHECK(k == labelled.pieces.size());
  CHECK(dark > 0);
  CHECK(dark < s.polygons.size());
  for (std::size_t a = 0; a < labelled.regions.size(); ++a)
    for (std::size_t b = a + 1; b < labelled.regions.size(); ++b) CHECK_FALSE(labelled.regions[a] == labelled.regions[b]);
  CHECK_THROWS_AS(svm::compute_shadows<Q>(s.polygons, std::vector<P>(65, P(Q(0), Q(0), Q(-5)))), std::invalid_argument);
}

TEST_CASE("shadows: with one light, the lit pieces alone, and which polygons have a shadow", "[shadow]") {
  for (auto const& s : {svm::scenes::bricks(6), svm::scenes::platforms(5), svm::scenes::random_cubes(10, 4)}) {
    std::vector<P> light{P(s.eye.x() + Q(3), s.eye.y() - Q(2), s.eye.z() + Q(1, 3))};
    auto all = svm::compute_shadows<Q>(s.polygons, light);
    auto lit = svm::compute_shadows<Q>(s.polygons, light, {.shadowed_pieces = false});
    std::vector<Q> lit_area(s.polygons.size(), Q(0)), lit_area2(s.polygons.size(), Q(0));
    std::vector<char> dark(s.polygons.size(), 0);
    for (auto const& p : all.pieces) {
      if (p.lights == 0) dark[p.polygon] = 1;
      else lit_area[p.polygon] += *e3::projected_area(p.shape, p.shape.axis);
    }
    for (auto const& p : lit.pieces) {
      CHECK(p.lights == 1);
      lit_area2[p.polygon] += *e3::projected_area(p.shape, p.shape.axis);
    }
    CHECK(lit_area == lit_area2);
    CHECK(lit.dark == dark);
    CHECK(all.dark == dark);
    CHECK(lit.pieces.size() < all.pieces.size());
  }
}

TEST_CASE("shadows: suns (lights at infinity) against the reference", "[shadow]") {
  using L = svm::light_source<Q>;
  {
    auto c = check(svm::scenes::bricks(6).polygons, {L::sun({Q(1, 3), Q(-1, 4), Q(-1)})});
    CHECK(c.wrong == 0);
    CHECK(c.lit > 10);
    CHECK(c.shadowed > 10);
  }
  {
    auto s = svm::scenes::sphere(5);
    auto polygons = s.polygons;
    append(polygons, square(-400000, -400000, 400000, 400000, -150000, 0));
    auto c = check(polygons, {L::sun({Q(2), Q(-1), Q(5)})});
    CHECK(c.wrong == 0);
    CHECK(c.lit > 10);
    CHECK(c.shadowed > 10);
  }
  {
    // Touching boxes on a floor, with two suns (one grazing the floor's
    // plane, lighting it not at all) and a point light.
    std::vector<svm::polygon<Q>> polygons;
    svm::scenes::scene boxes;
    svm::scenes::add_box(boxes, P(Q(0), Q(0), Q(0)), P(Q(4), Q(4), Q(4)));
    svm::scenes::add_box(boxes, P(Q(4), Q(0), Q(0)), P(Q(8), Q(4), Q(2)));
    append(polygons, boxes.polygons);
    append(polygons, square(-20, -20, 30, 30, 0, 0));
    append(polygons, square(-10, -10, 0, 20, 0, 0));
    auto c = check(polygons, {L::sun({Q(1), Q(2), Q(3)}), L::sun({Q(-1), Q(0), Q(0)}), L::at(P(Q(9), Q(3), Q(12)))});
    CHECK(c.wrong == 0);
    CHECK(c.lit > 10);
    CHECK(c.shadowed > 10);
  }
  CHECK_THROWS_AS(svm::compute_shadows<Q>(svm::scenes::bricks(2).polygons, {L::sun({Q(0), Q(0), Q(0)})}), std::invalid_argument);
}

TEST_CASE("shadows: a sun casts a floating triangle's translate on a floor", "[shadow]") {
  // Parallel rays: the shadow of a triangle parallel to the floor is its
  // translate, of the same area.
  std::vector<svm::polygon<Q>> polygons = square(-100, -100, 100, 100, 0, 0);
  std::vector<P> tri{P(Q(1), Q(2), Q(3)), P(Q(7, 2), Q(1), Q(3)), P(Q(2), Q(5), Q(3))};
  append(polygons, {{tri, 0}});
  auto sh = svm::compute_shadows<Q>(polygons, {svm::light_source<Q>::sun({Q(1), Q(-2), Q(5)})});
  Q shadow(0);
  for (auto const& p : sh.pieces)
    if (p.polygon == 0 && p.lights == 0) shadow += *e3::projected_area(p.shape, 2);
  Q area = *e3::projected_area(e3::convex_polygon<Q>(tri), 2);
  CHECK(abs(shadow) == abs(area));
  CHECK(area != 0);
}
