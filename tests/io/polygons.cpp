// From faces to convex polygons: convex faces kept whole, non-convex and non-planar
// faces cut into pieces whose exact areas add up to the face's, degenerate faces
// counted, face indices kept.  The reference areas are computed here on raw
// rationals (a fan from the first vertex), independently of the Newell normal
// the library uses.
#include "../support.hpp"

#include <catch2/catch.hpp>
#include <geometry/e3.hpp>
#include <geometry/io/polygons.hpp>

#include <algorithm>
#include <sstream>

using namespace geometry;
using test::Q;

namespace io_polygons_tests {

namespace {

using V = std::array<Q, 3>;
using P = e3::point<Q>;

V diff(P const& a, P const& b) { return {a.x() - b.x(), a.y() - b.y(), a.z() - b.z()}; }
bool zero(V const& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

/// Twice the vector area of a closed polygon, as a fan from its first vertex.
V twice_area(std::vector<P> const& v) {
  V s{Q(0), Q(0), Q(0)};
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    V c = test::ref_cross(diff(v[i], v[0]), diff(v[i + 1], v[0]));
    for (int k = 0; k < 3; ++k) s[k] += c[k];
  }
  return s;
}

/// A scene whose faces are given by their points (each face its own vertices).
io::scene make(std::vector<std::vector<P>> const& faces) {
  io::scene s;
  for (auto const& f : faces) {
    io::scene::face g;
    for (auto const& p : f) {
      g.vertices.push_back(static_cast<std::uint32_t>(s.vertices.size()));
      s.vertices.push_back(p);
    }
    s.faces.push_back(std::move(g));
  }
  return s;
}

std::vector<P> face_points(io::scene const& s, std::size_t f) {
  std::vector<P> v;
  for (auto i : s.faces[f].vertices) v.push_back(s.vertices[i]);
  return v;
}

std::vector<io::polygon> pieces_of(io::prepared const& r, std::size_t f) {
  std::vector<io::polygon> out;
  for (auto const& p : r.polygons)
    if (p.face == f) out.push_back(p);
  return out;
}

/// Every piece of face `f` is strictly convex and planar, made of the face's own
/// vertices, and e3::convex_polygon accepts it with all its vertices; for a
/// planar face the pieces face its side and their exact areas, projected on
/// each coordinate plane, add up to the face's.  Returns the number of pieces.
std::size_t check_pieces(io::scene const& s, io::prepared const& r, std::size_t f, bool planar = true) {
  INFO("face " << f);
  auto input = face_points(s, f);
  auto pieces = pieces_of(r, f);
  V face2 = twice_area(input), sum2{Q(0), Q(0), Q(0)};
  std::array<Q, 3> projected{Q(0), Q(0), Q(0)};
  for (auto const& piece : pieces) {
    auto const& v = piece.vertices;
    REQUIRE(v.size() >= 3);
    for (auto const& p : v) CHECK(std::find(input.begin(), input.end(), p) != input.end()); // nothing constructed
    V n = test::ref_cross(diff(v[1], v[0]), diff(v[2], v[0]));
    REQUIRE_FALSE(zero(n));
    for (auto const& p : v) CHECK(test::ref_dot(n, diff(p, v[0])) == 0); // planar
    for (std::size_t i = 0; i < v.size(); ++i) {
      // strictly convex: every corner turns the same way as the whole polygon
      V c = test::ref_cross(diff(v[(i + 1) % v.size()], v[i]), diff(v[(i + 2) % v.size()], v[(i + 1) % v.size()]));
      CHECK(test::ref_dot(c, n) > 0);
    }
    auto poly = e3::convex_polygon(v);
    auto back = e3::vertices(poly);
    REQUIRE(back);
    CHECK(back->size() == v.size());
    for (std::size_t k = 0; k < 3; ++k) projected[k] += *e3::projected_area(poly, k);
    V a = twice_area(v);
    for (int k = 0; k < 3; ++k) sum2[k] += a[k];
    if (planar) {
      CHECK(zero(test::ref_cross(a, face2))); // parallel …
      CHECK(test::ref_dot(a, face2) > 0);     // … and facing the face's front
    }
  }
  // The pieces tile the face: the same exact (vector) area, seen along each axis.
  for (int k = 0; k < 3; ++k) {
    CHECK(sum2[k] == face2[k]);
    CHECK(projected[k] == face2[k] / 2);
  }
  return pieces.size();
}

/// The points (a, b) of a plane in E3: origin + a·u + b·w.
std::vector<P> in_plane(std::vector<std::array<Q, 2>> const& ab, V const& o = {Q(0), Q(0), Q(0)},
                        V const& u = {Q(1), Q(0), Q(0)}, V const& w = {Q(0), Q(1), Q(0)}) {
  std::vector<P> out;
  for (auto const& [a, b] : ab)
    out.emplace_back(Q(o[0] + a * u[0] + b * w[0]), Q(o[1] + a * u[1] + b * w[1]), Q(o[2] + a * u[2] + b * w[2]));
  return out;
}

std::vector<std::array<Q, 2>> const L_shape{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
std::vector<std::array<Q, 2>> const four_star{{10, 0}, {2, 2}, {0, 10}, {-2, 2}, {-10, 0}, {-2, -2}, {0, -10}, {2, -2}};
std::vector<std::array<Q, 2>> const five_star{{0, 100}, {22, 31},   {95, 31},   {36, -12}, {59, -81},
                                              {0, -38}, {-59, -81}, {-36, -12}, {-95, 31}, {-22, 31}};
std::vector<std::array<Q, 2>> const comb{{0, 0}, {9, 0}, {9, 5}, {8, 5}, {8, 1}, {7, 1}, {7, 5},
                                         {6, 5}, {6, 1}, {5, 1}, {5, 5}, {4, 5}, {4, 1}, {3, 1},
                                         {3, 5}, {2, 5}, {2, 1}, {1, 1}, {1, 5}, {0, 5}};

template <class T> std::vector<T> reversed(std::vector<T> v) {
  std::reverse(v.begin(), v.end());
  return v;
}

} // namespace

TEST_CASE("convex planar faces are kept whole, in their vertex order", "[io][polygons]") {
  V o{Q(1), Q(-2), Q(3, 7)}, u{Q(1, 10), Q(2), Q(-1)}, w{Q(3), Q(1, 3), Q(5)};
  std::vector<std::array<Q, 2>> square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  auto slanted = in_plane(square, o, u, w);
  // The same square with a repeated vertex, a midpoint and the first vertex repeated at the end.
  auto messy = in_plane({{0, 0}, {2, 0}, {4, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}}, o, u, w);
  auto s = make({slanted, messy, in_plane({{0, 0}, {1, 0}, {0, 1}}), reversed(slanted)});
  // A repeated index, not only repeated coordinates.
  s.faces[1].vertices[3] = s.faces[1].vertices[2];
  auto r = io::convex_polygons(s);
  CHECK(r.degenerate_faces == 0);
  CHECK(r.triangulated_faces == 0);
  REQUIRE(r.polygons.size() == 4);
  for (std::uint32_t f = 0; f < 4; ++f) {
    CHECK(r.polygons[f].face == f);
    CHECK(check_pieces(s, r, f) == 1);
  }
  CHECK(r.polygons[0].vertices == slanted);
  CHECK(r.polygons[1].vertices == slanted); // duplicates and the midpoint gone, order kept
  CHECK(r.polygons[3].vertices == reversed(slanted));
  // Its plane, through the first three vertices, faces the face's front.
  auto h = e3::plane_through(r.polygons[0].vertices[0], r.polygons[0].vertices[1], r.polygons[0].vertices[2]);
  V n2 = twice_area(slanted);
  CHECK(test::ref_dot({h.n[0], h.n[1], h.n[2]}, n2) > 0);
}

TEST_CASE("non-convex planar faces are cut into pieces with the face's exact area", "[io][polygons]") {
  V o{Q(1, 2), Q(-2), Q(3)}, u{Q(1, 10), Q(2), Q(-1)}, w{Q(3), Q(1, 3), Q(5)};
  std::vector<std::vector<P>> faces{
      in_plane(L_shape),                                             // 0: in z = 0
      reversed(in_plane(L_shape, o, u, w)),                          // 1: slanted, clockwise
      in_plane(four_star, o, w, u),                                  // 2
      in_plane(five_star, o, u, w),                                  // 3
      reversed(in_plane(five_star)),                                 // 4
      in_plane(comb, o, {Q(0), Q(1), Q(1)}, {Q(1), Q(0), Q(1, 10)}), // 5: many reflex vertices
      in_plane({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 1}}, o, u, w), // 6: L, with clutter
  };
  auto s = make(faces);
  auto r = io::convex_polygons(s);
  CHECK(r.degenerate_faces == 0);
  CHECK(r.triangulated_faces == faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) CHECK(check_pieces(s, r, f) >= 2);
  CHECK(pieces_of(r, 0).size() == 4); // n − 2 triangles
  // Not 8: once the top point is clipped, (-95, 31), (-22, 31), (22, 31) are collinear and
  // the straight vertex goes without a (flat) triangle.
  CHECK(pieces_of(r, 3).size() == 7);
  CHECK(pieces_of(r, 5).size() == 18);
  // The L has area 3, the four-pointed star 80.
  Q l(0);
  for (auto const& p : pieces_of(r, 0)) l += *e3::projected_area(e3::convex_polygon(p.vertices), 2);
  CHECK(l == 3);
  // Pieces come in face order.
  CHECK(std::is_sorted(r.polygons.begin(), r.polygons.end(),
                       [](auto const& a, auto const& b) { return a.face < b.face; }));
}

TEST_CASE("a square with a hole joined by a bridge (repeated vertices) is cut around the hole", "[io][polygons]") {
  // Outer square counter-clockwise, then the bridge to the hole, the hole clockwise, and back.
  auto s = make({in_plane({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}, {3, 3}, {3, 7}, {7, 7}, {7, 3}, {3, 3}})});
  auto r = io::convex_polygons(s);
  CHECK(r.triangulated_faces == 1);
  CHECK(check_pieces(s, r, 0) == 8);
  Q area(0);
  for (auto const& p : r.polygons) {
    auto poly = e3::convex_polygon(p.vertices);
    area += *e3::projected_area(poly, 2);
    // No piece reaches into the hole.
    for (auto const& [x, y] : std::vector<std::array<int, 2>>{{4, 4}, {6, 6}, {4, 6}, {6, 4}, {5, 5}}) {
      bool in = true;
      for (std::size_t i = 0; i < 3; ++i) {
        auto const &a = p.vertices[i], &b = p.vertices[(i + 1) % 3];
        in = in && (b.x() - a.x()) * (Q(y) - a.y()) - (b.y() - a.y()) * (Q(x) - a.x()) >= 0;
      }
      CHECK_FALSE(in);
    }
  }
  CHECK(area == 100 - 16);
}

TEST_CASE("a pentagram winds twice: locally convex but not convex", "[io][polygons]") {
  // Every corner turns left, so a check of turns alone would keep it whole.
  auto s = make({in_plane({{0, 100}, {59, -81}, {-95, 31}, {95, 31}, {-59, -81}})});
  auto r = io::convex_polygons(s);
  CHECK(r.triangulated_faces == 1);
  REQUIRE_FALSE(r.polygons.empty());
  for (auto const& p : r.polygons) {
    CHECK(p.face == 0);
    CHECK(p.vertices.size() == 3);
    CHECK_NOTHROW(e3::convex_polygon(p.vertices));
  }
}

TEST_CASE("non-planar faces are triangulated", "[io][polygons]") {
  std::vector<std::vector<P>> faces{
      // 0: a twisted quadrilateral: the fan from the first vertex
      {P(0, 0, 0), P(1, 0, 0), P(1, 1, 1), P(0, 1, 0)},
      // 1: a pentagon whose fan has a flat triangle (v0, v2, v3 collinear): ear clipping instead
      {P(0, 0, 0), P(4, 0, 0), P(4, 4, 2), P(2, 2, 1), P(0, 4, 0)},
      // 2: a non-planar L: lift one corner
      {P(0, 0, 0), P(2, 0, 0), P(2, 1, 0), P(1, 1, 0), P(1, 2, Q(1, 3)), P(0, 2, 0)},
  };
  auto s = make(faces);
  auto r = io::convex_polygons(s);
  CHECK(r.degenerate_faces == 0);
  CHECK(r.triangulated_faces == 3);
  CHECK(check_pieces(s, r, 0, false) == 2);
  auto fan = pieces_of(r, 0);
  CHECK(fan[0].vertices == std::vector<P>{faces[0][0], faces[0][1], faces[0][2]});
  CHECK(fan[1].vertices == std::vector<P>{faces[0][0], faces[0][2], faces[0][3]});
  CHECK(check_pieces(s, r, 1, false) == 3);
  for (auto const& p : pieces_of(r, 1)) {
    bool flat_fan = std::find(p.vertices.begin(), p.vertices.end(), faces[1][0]) != p.vertices.end() &&
                    std::find(p.vertices.begin(), p.vertices.end(), faces[1][2]) != p.vertices.end() &&
                    std::find(p.vertices.begin(), p.vertices.end(), faces[1][3]) != p.vertices.end();
    CHECK_FALSE(flat_fan);
  }
  CHECK(check_pieces(s, r, 2, false) == 4);
}

TEST_CASE("degenerate faces are skipped and counted; later faces keep their index", "[io][polygons]") {
  std::vector<std::vector<P>> faces{
      {P(0, 0, 0), P(1, 0, 0), P(0, 1, 0)},                         // 0: fine
      {P(0, 0, 0), P(1, 0, 0), P(1, 0, 0), P(0, 0, 0)},             // 1: repeated vertices
      {P(0, 0, 0), P(1, 1, 1), P(2, 2, 2), P(3, 3, 3)},             // 2: collinear
      {P(0, 0, 0), P(1, 2, 3)},                                     // 3: two vertices
      {P(5, 5, 5), P(5, 5, 5), P(5, 5, 5)},                         // 4: one point
      {P(0, 0, 0), P(1, 0, 0), P(2, 0, 0), P(1, 0, 0)},             // 5: a spike, there and back
      {P(0, 0, 0), P(2, 2, 0), P(2, 0, 0), P(0, 2, 0)},             // 6: a bow tie whose lobes cancel
      {},                                                           // 7: no vertices at all
      {P(0, 0, 1), P(1, 0, 1), P(1, 0, 1), P(1, 1, 1), P(0, 1, 1)}, // 8: fine, after cleaning
  };
  auto s = make(faces);
  auto r = io::convex_polygons(s);
  CHECK(r.degenerate_faces == 7);
  CHECK(r.triangulated_faces == 0);
  REQUIRE(r.polygons.size() == 2);
  CHECK(r.polygons[0].face == 0);
  CHECK(r.polygons[1].face == 8);
  CHECK(r.polygons[1].vertices.size() == 4);
  check_pieces(s, r, 8);
}

TEST_CASE("random star-shaped faces in random planes tile exactly", "[io][polygons]") {
  auto before = [](std::array<Q, 2> const& a, std::array<Q, 2> const& b) {
    auto half = [](std::array<Q, 2> const& p) { return p[1] > 0 || (p[1] == 0 && p[0] > 0) ? 0 : 1; };
    if (half(a) != half(b)) return half(a) < half(b);
    return a[0] * b[1] - a[1] * b[0] > 0;
  };
  std::vector<std::vector<P>> faces;
  while (faces.size() < 150) {
    std::vector<std::array<Q, 2>> ab;
    long n = test::uniform(4, 24);
    for (long i = 0; i < n; ++i) {
      std::array<Q, 2> p{test::random_integer(30), test::random_integer(30)};
      if (p[0] == 0 && p[1] == 0) continue;
      // one vertex per direction from the origin, so the polygon is simple
      bool same = std::any_of(ab.begin(), ab.end(), [&](auto const& q) {
        return p[0] * q[1] - p[1] * q[0] == 0 && p[0] * q[0] + p[1] * q[1] > 0;
      });
      if (!same) ab.push_back(p);
    }
    std::sort(ab.begin(), ab.end(), before);
    bool star = ab.size() >= 3;
    for (std::size_t i = 0; i < ab.size() && star; ++i) {
      auto const &p = ab[i], &q = ab[(i + 1) % ab.size()];
      star = p[0] * q[1] - p[1] * q[0] > 0; // consecutive directions less than half a turn apart
    }
    if (!star) continue;
    V o{test::random_decimal(2, 10), test::random_decimal(2, 10), test::random_decimal(2, 10)};
    V u{test::random_integer(5), test::random_integer(5), test::random_integer(5)};
    V w{test::random_decimal(1, 5), test::random_decimal(1, 5), test::random_decimal(1, 5)};
    if (zero(test::ref_cross(u, w))) continue;
    auto pts = in_plane(ab, o, u, w);
    faces.push_back(test::uniform(0, 1) ? pts : reversed(pts));
  }
  auto s = make(faces);
  auto r = io::convex_polygons(s);
  CHECK(r.degenerate_faces == 0);
  for (std::size_t f = 0; f < faces.size(); ++f) CHECK(check_pieces(s, r, f) >= 1);
  CHECK(r.triangulated_faces > 0);
  CHECK(r.triangulated_faces < faces.size());
}

TEST_CASE("a face read from OFF keeps its file index through triangulation", "[io][polygons]") {
  std::istringstream in("OFF\n10 3 0\n"
                        "0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n" // an L
                        "0 0 1\n0.1 0 1\n0 0.1 1\n"                  // a small triangle
                        "5 5 5\n"
                        "3 9 9 9\n"           // face 0: degenerate
                        "6 0 1 2 3 4 5\n"     // face 1: the L
                        "3 6 7 8 0 255 0\n"); // face 2
  auto s = io::read_off(in, "l.off");
  auto r = io::convex_polygons(s);
  CHECK(r.degenerate_faces == 1);
  CHECK(r.triangulated_faces == 1);
  REQUIRE(r.polygons.size() == 5);
  for (int i = 0; i < 4; ++i) CHECK(r.polygons[i].face == 1);
  CHECK(r.polygons[4].face == 2);
  CHECK(r.polygons[4].vertices[1] == P(Q(1, 10), 0, 1));
  check_pieces(s, r, 1);
  check_pieces(s, r, 2);
}

TEST_CASE("a hand-built face with a missing vertex is an error, not undefined behaviour", "[io][polygons]") {
  io::scene s;
  s.vertices = {P(0, 0, 0), P(1, 0, 0)};
  s.faces.push_back({{0, 1, 2}, std::nullopt, 0});
  CHECK_THROWS_AS(io::convex_polygons(s), std::out_of_range);
}

} // namespace io_polygons_tests
