// 2D visibility regions against an exact brute-force ray caster written here
// on 64/128-bit integers: it shares no predicate with the library.
#include "support.hpp"

#include <catch2/catch.hpp>
#include <svm/visibility2d.hpp>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

namespace svm_visibility2d_tests {

namespace {

using geometry::rational;
using point = geometry::e2::point<rational>;
__extension__ using i128 = __int128;

struct ipt {
  long x, y;
  bool operator==(ipt const&) const = default;
};

/// A scene on the integer grid: rings (inside on the left) and free segments.
struct iscene {
  std::vector<std::vector<ipt>> rings;
  std::vector<std::array<ipt, 2>> segments;
  ipt eye;
  char const* family;
};

i128 cross(long ax, long ay, long bx, long by) { return i128(ax) * by - i128(ay) * bx; }

svm::wall_scene<rational> to_scene(iscene const& s) {
  svm::wall_scene<rational> out;
  auto p = [](ipt q) { return point(rational(q.x), rational(q.y)); };
  for (auto const& r : s.rings) {
    out.rings.emplace_back();
    for (auto q : r) out.rings.back().push_back(p(q));
  }
  for (auto const& g : s.segments) out.segments.push_back({p(g[0]), p(g[1])});
  out.ring_polygon.assign(out.rings.size(), 0); // a room and its holes: one polygon, as the ray caster reads them
  return out;
}

/// What the brute force sees in direction d: nothing decided (ambiguous
/// along a boundary), blocked (out of a ring the eye is on), no wall, or the
/// distance t of the first hit as num/den.
struct truth {
  enum kind { ambiguous, blocked, none, hit } k;
  i128 num = 0, den = 1;
};

/// Whether d lies strictly inside the arc counter-clockwise from p to q
/// (the whole circle but p when p and q are the same direction); nullopt on its boundary.
std::optional<bool> strictly_inside(ipt p, ipt q, ipt d) {
  i128 pq = cross(p.x, p.y, q.x, q.y), pd = cross(p.x, p.y, d.x, d.y), dq = cross(d.x, d.y, q.x, q.y);
  i128 dot_pd = i128(p.x) * d.x + i128(p.y) * d.y, dot_qd = i128(q.x) * d.x + i128(q.y) * d.y;
  if ((pd == 0 && dot_pd > 0) || (dq == 0 && dot_qd > 0)) return std::nullopt;
  if (pq > 0) return pd > 0 && dq > 0;
  if (pq < 0) return !(cross(q.x, q.y, d.x, d.y) >= 0 && cross(d.x, d.y, p.x, p.y) >= 0);
  i128 dot_pq = i128(p.x) * q.x + i128(p.y) * q.y;
  if (dot_pq > 0) return true; // the whole circle but p
  return pd > 0;
}

truth cast(iscene const& s, ipt d) {
  ipt e = s.eye;
  // Out of a ring the eye lies on?
  for (auto const& r : s.rings) {
    std::size_t k = r.size();
    for (std::size_t i = 0; i < k; ++i) {
      ipt a = r[i], b = r[(i + 1) % k];
      if (a == b) continue;
      if (a == e) {
        std::size_t j = (i + k - 1) % k;
        while (r[j] == e) j = (j + k - 1) % k;
        ipt w{b.x - e.x, b.y - e.y}, u{r[j].x - e.x, r[j].y - e.y};
        auto in = strictly_inside(w, u, d); // the inside: from the next vertex counter-clockwise to the previous
        if (!in) return {truth::ambiguous};
        if (!*in) return {truth::blocked};
        continue;
      }
      if (b == e) continue;
      if (cross(b.x - a.x, b.y - a.y, e.x - a.x, e.y - a.y) != 0) continue;
      if (i128(a.x - e.x) * (b.x - e.x) + i128(a.y - e.y) * (b.y - e.y) >= 0) continue; // not between the ends
      i128 side = cross(b.x - a.x, b.y - a.y, d.x, d.y);
      if (side == 0) return {truth::ambiguous};
      if (side < 0) return {truth::blocked};
    }
  }
  // The first wall the ray e + t·d (t > 0) meets, walls on lines through the eye left out.
  std::optional<std::pair<i128, i128>> best;
  auto consider = [&](ipt a, ipt b) {
    if (a == b) return;
    long ex = b.x - a.x, ey = b.y - a.y;
    if (cross(ex, ey, e.x - a.x, e.y - a.y) == 0) return; // edge-on
    // e + t d = a + u (b − a): t = cross(a − e, b − a) / cross(d, b − a), u = cross(a − e, d) / cross(d, b − a).
    i128 den = cross(d.x, d.y, ex, ey);
    if (den == 0) return;
    i128 tn = cross(a.x - e.x, a.y - e.y, ex, ey), un = cross(a.x - e.x, a.y - e.y, d.x, d.y);
    if (den < 0) den = -den, tn = -tn, un = -un;
    if (tn <= 0 || un < 0 || un > den) return;
    if (!best || tn * best->second < best->first * den) best = {tn, den};
  };
  for (auto const& r : s.rings)
    for (std::size_t i = 0; i < r.size(); ++i) consider(r[i], r[(i + 1) % r.size()]);
  for (auto const& g : s.segments) consider(g[0], g[1]);
  if (!best) return {truth::none};
  return {truth::hit, best->first, best->second};
}

/// Whether the ray meets wall w (its segment) at distance num/den.
bool meets_at(iscene const& s, std::size_t w, ipt d, i128 num, i128 den) {
  std::array<ipt, 2> ab;
  std::size_t i = w;
  bool found = false;
  for (auto const& r : s.rings) {
    if (i < r.size()) {
      ab = {r[i], r[(i + 1) % r.size()]};
      found = true;
      break;
    }
    i -= r.size();
  }
  if (!found) ab = s.segments.at(i);
  ipt e = s.eye, a = ab[0], b = ab[1];
  long ex = b.x - a.x, ey = b.y - a.y;
  i128 dn = cross(d.x, d.y, ex, ey);
  if (dn == 0) return false;
  i128 tn = cross(a.x - e.x, a.y - e.y, ex, ey), un = cross(a.x - e.x, a.y - e.y, d.x, d.y);
  if (dn < 0) dn = -dn, tn = -tn, un = -un;
  return un >= 0 && un <= dn && tn * den == num * dn;
}

long rnd(long lo, long hi) { return test::uniform(lo, hi); }

std::vector<ipt> box_ring(long x0, long y0, long x1, long y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

/// A star-shaped room about the origin, counter-clockwise, with `k` vertices.
std::vector<ipt> star_room(int k, long r0, long r1) {
  std::vector<ipt> out;
  for (int i = 0; i < k; ++i) {
    double a = 2 * 3.141592653589793 * (i + 0.5 * static_cast<double>(rnd(0, 99)) / 100.0) / k;
    double r = static_cast<double>(rnd(r0, r1));
    out.push_back({std::lround(r * std::cos(a)), std::lround(r * std::sin(a))});
  }
  // Keep a simple polygon: drop vertices that would make the turn from the origin non-increasing.
  std::vector<ipt> simple;
  for (auto p : out)
    if (simple.empty() || cross(simple.back().x, simple.back().y, p.x, p.y) > 0) simple.push_back(p);
  while (simple.size() > 3 && cross(simple.back().x, simple.back().y, simple.front().x, simple.front().y) <= 0) simple.pop_back();
  return simple;
}

std::vector<iscene> scenes() {
  std::vector<iscene> out;
  // Random segments on a small grid, in a room: shared ends, collinear and
  // overlapping walls, the eye on walls' lines and vertices' rays.
  for (int i = 0; i < 50; ++i) {
    iscene s{{box_ring(-12, -12, 12, 12)}, {}, {rnd(-11, 11), rnd(-11, 11)}, "segments"};
    int n = static_cast<int>(rnd(1, 25));
    for (int k = 0; k < n; ++k) s.segments.push_back({ipt{rnd(-10, 10), rnd(-10, 10)}, ipt{rnd(-10, 10), rnd(-10, 10)}});
    out.push_back(s);
  }
  // Rooms with holes (clockwise), the eye anywhere (in a hole too).
  for (int i = 0; i < 50; ++i) {
    iscene s{{star_room(static_cast<int>(rnd(5, 30)), 40, 100)}, {}, {rnd(-30, 30), rnd(-30, 30)}, "room with holes"};
    if (s.rings[0].size() < 3) continue;
    int holes = static_cast<int>(rnd(0, 6));
    for (int h = 0; h < holes; ++h) {
      long x = rnd(-25, 20), y = rnd(-25, 20), w = rnd(1, 6), t = rnd(1, 6);
      auto r = box_ring(x, y, x + w, y + t);
      std::reverse(r.begin(), r.end());
      s.rings.push_back(r);
    }
    out.push_back(s);
  }
  // The eye on the boundary: at a vertex of the room or of a hole, or inside an edge.
  for (int i = 0; i < 50; ++i) {
    iscene s{{star_room(static_cast<int>(rnd(4, 20)), 30, 80)}, {}, {0, 0}, "eye on the boundary"};
    if (s.rings[0].size() < 3) continue;
    auto r = box_ring(-6, -6, 6, 6);
    std::reverse(r.begin(), r.end());
    s.rings.push_back(r);
    s.segments.push_back({ipt{-20, 10}, ipt{20, 10}});
    auto const& ring = s.rings[static_cast<std::size_t>(rnd(0, 1))];
    std::size_t v = static_cast<std::size_t>(rnd(0, static_cast<long>(ring.size()) - 1));
    ipt a = ring[v], b = ring[(v + 1) % ring.size()];
    if (i % 2 == 0 || (a.x + b.x) % 2 != 0 || (a.y + b.y) % 2 != 0)
      s.eye = a;
    else
      s.eye = {(a.x + b.x) / 2, (a.y + b.y) / 2};
    out.push_back(s);
  }
  // Mazes: walls along grid lines, the eye at a grid point or a cell's middle.
  for (int i = 0; i < 50; ++i) {
    long n = rnd(2, 8);
    iscene s{{box_ring(0, 0, 2 * n, 2 * n)}, {}, {2 * rnd(0, n), 2 * rnd(0, n)}, "maze"};
    if (i % 2) s.eye = {2 * rnd(0, n - 1) + 1, 2 * rnd(0, n - 1) + 1};
    for (long x = 0; x < n; ++x)
      for (long y = 0; y < n; ++y) {
        if (rnd(0, 2) == 0) s.segments.push_back({ipt{2 * x, 2 * y}, ipt{2 * x + 2, 2 * y}});
        if (rnd(0, 2) == 0) s.segments.push_back({ipt{2 * x, 2 * y}, ipt{2 * x, 2 * y + 2}});
      }
    out.push_back(s);
  }
  // No room: the view is unbounded between obstacles; collinear walls in a row.
  for (int i = 0; i < 20; ++i) {
    iscene s{{}, {}, {rnd(-5, 5), rnd(-5, 5)}, "unbounded"};
    int n = static_cast<int>(rnd(0, 8));
    for (int k = 0; k < n; ++k) {
      long x = rnd(-10, 10), y = rnd(-10, 10);
      s.segments.push_back({ipt{x, y}, ipt{x + rnd(1, 4), y}});
      s.segments.push_back({ipt{x + 5, y}, ipt{x + 5 + rnd(1, 4), y}});
    }
    out.push_back(s);
  }
  return out;
}

} // namespace

TEST_CASE("2D visibility regions agree with an exact ray caster on 220 scenes, at 1,000 random directions and toward every vertex",
          "[visibility2d]") {
  std::size_t checked = 0, ambiguous = 0, wrong = 0, scene_count = 0, toward_vertices = 0;
  for (auto const& s : scenes()) {
    ++scene_count;
    auto region = svm::visibility(to_scene(s), point(rational(s.eye.x), rational(s.eye.y)));
    // The arcs cover the circle once, each ending where the next starts.
    auto const& arcs = region.arcs;
    REQUIRE(!arcs.empty());
    if (arcs.size() == 1) {
      CHECK(arcs[0].whole);
    } else {
      for (std::size_t i = 0; i < arcs.size(); ++i) {
        auto const& a = arcs[i];
        auto const& b = arcs[(i + 1) % arcs.size()];
        CHECK(geometry::parallel(a.end(), b.start()) == geometry::sign::positive);
        CHECK(!(a.wall == b.wall && a.wall >= 0)); // maximal
      }
    }
    // Toward each wall's ends, where arcs meet: the ray's first hit is the
    // wall of the arc that starts there or of the one that ends there.
    auto toward = [&](ipt v) {
      ipt d{v.x - s.eye.x, v.y - s.eye.y};
      if (d.x == 0 && d.y == 0) return;
      auto t = cast(s, d);
      if (t.k == truth::ambiguous) return;
      geometry::s1::point<rational> dir(std::array<rational, 2>{rational(d.x), rational(d.y)});
      auto const& after = svm::locate(region, dir);
      auto const* before = &after;
      if (!after.whole && geometry::parallel(after.start(), dir) == geometry::sign::positive)
        before = &arcs[(static_cast<std::size_t>(&after - arcs.data()) + arcs.size() - 1) % arcs.size()];
      auto ok = [&](svm::view_arc<rational> const& arc) {
        if (t.k == truth::blocked) return arc.wall == svm::behind_boundary;
        if (t.k == truth::none) return arc.wall == svm::no_wall;
        return arc.wall >= 0 && meets_at(s, static_cast<std::size_t>(arc.wall), d, t.num, t.den);
      };
      ++toward_vertices;
      if (!ok(after) && !ok(*before)) {
        ++wrong;
        if (wrong <= 5) WARN(s.family << ": toward vertex " << v.x << "," << v.y << " from " << s.eye.x << "," << s.eye.y);
      }
    };
    for (auto const& r : s.rings)
      for (auto v : r) toward(v);
    for (auto const& g : s.segments) toward(g[0]), toward(g[1]);
    for (int k = 0; k < 1000; ++k) {
      ipt d{rnd(-1000000, 1000000), rnd(-1000000, 1000000)};
      if (d.x == 0 && d.y == 0) continue;
      auto t = cast(s, d);
      geometry::s1::point<rational> dir(std::array<rational, 2>{rational(d.x), rational(d.y)});
      auto const& arc = svm::locate(region, dir);
      bool at_end = !arc.whole && (geometry::parallel(arc.start(), dir) == geometry::sign::positive ||
                                   geometry::parallel(arc.end(), dir) == geometry::sign::positive);
      if (t.k == truth::ambiguous || at_end) {
        ++ambiguous;
        continue;
      }
      ++checked;
      bool ok = false;
      if (t.k == truth::blocked) ok = arc.wall == svm::behind_boundary;
      else if (t.k == truth::none) ok = arc.wall == svm::no_wall;
      else ok = arc.wall >= 0 && meets_at(s, static_cast<std::size_t>(arc.wall), d, t.num, t.den);
      if (!ok) {
        ++wrong;
        if (wrong <= 5)
          WARN(s.family << ": eye " << s.eye.x << "," << s.eye.y << " direction " << d.x << "," << d.y << " answer " << arc.wall
                        << " truth kind " << static_cast<int>(t.k));
      }
    }
  }
  INFO(checked << " directions checked, " << ambiguous << " on boundaries");
  INFO(toward_vertices << " directions toward vertices checked");
  CHECK(toward_vertices >= 5000);
  CHECK(scene_count >= 200);
  CHECK(checked >= 200000);
  CHECK(wrong == 0);
}

TEST_CASE("Walls by number: the table and the visit in order give the ends that the rings and segments give", "[visibility2d]") {
  svm::wall_scene<rational> s;
  auto p = [](long x, long y) { return point(rational(x), rational(y)); };
  s.rings = {{p(0, 0), p(4, 0), p(4, 4)}, {}, {p(1, 1), p(1, 2)}, {p(9, 9)}, {p(5, 5), p(6, 5), p(6, 6), p(5, 6)}};
  s.segments = {{p(7, 0), p(8, 1)}, {p(-1, -1), p(-2, 3)}};
  std::vector<std::array<point, 2>> expected = {
      {p(0, 0), p(4, 0)}, {p(4, 0), p(4, 4)}, {p(4, 4), p(0, 0)}, // the triangle, closed
      {p(1, 1), p(1, 2)}, {p(1, 2), p(1, 1)},                     // a two-vertex ring, after an empty one
      {p(9, 9), p(9, 9)},                                         // one vertex: a wall of no length
      {p(5, 5), p(6, 5)}, {p(6, 5), p(6, 6)}, {p(6, 6), p(5, 6)}, {p(5, 6), p(5, 5)},
      {p(7, 0), p(8, 1)}, {p(-1, -1), p(-2, 3)}};
  REQUIRE(s.wall_count() == expected.size());
  svm::wall_table<rational> table(s);
  std::size_t visited = 0;
  s.for_each_wall([&](std::size_t i, point const& a, point const& b) {
    REQUIRE(i == visited++);
    CHECK(a == expected[i][0]);
    CHECK(b == expected[i][1]);
  });
  CHECK(visited == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    INFO("wall " << i);
    CHECK(table(i) == expected[i]);
    CHECK(s.wall(i) == expected[i]);
  }
  CHECK_THROWS_AS(table(expected.size()), std::out_of_range);
}

TEST_CASE("A convex room seen from inside, at a vertex or on an edge, is the whole room", "[visibility2d]") {
  using Q = rational;
  svm::wall_scene<Q> room;
  room.rings.push_back({point(Q(0), Q(0)), point(Q(7), Q(0)), point(Q(9), Q(5)), point(Q(3), Q(8)), point(Q(-1), Q(4))});
  // Twice its area, by the shoelace formula.
  Q twice(0);
  auto const& r = room.rings[0];
  for (std::size_t i = 0; i < r.size(); ++i) {
    auto const &a = r[i], &b = r[(i + 1) % r.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  for (auto eye : {point(Q(3), Q(3)), point(Q(0), Q(0)), point(Q(9), Q(5)), point(Q(7, 2), Q(0)), point(Q(1, 3), Q(1, 7))}) {
    auto v = svm::visibility(room, eye);
    REQUIRE(v.bounded());
    auto a = svm::area(v, room);
    REQUIRE(a);
    CHECK(*a == twice / 2);
    auto b = svm::boundary(v, room);
    REQUIRE(b);
    CHECK(b->size() >= 5);
  }
}

TEST_CASE("Walls in a row hide one another; no room leaves the view unbounded", "[visibility2d]") {
  using Q = rational;
  svm::wall_scene<Q> s;
  s.segments.push_back({point(Q(2), Q(-1)), point(Q(2), Q(1))});
  s.segments.push_back({point(Q(4), Q(-3)), point(Q(4), Q(3))});
  s.segments.push_back({point(Q(6), Q(-1)), point(Q(6), Q(1))}); // wholly behind the second
  auto v = svm::visibility(s, point(Q(0), Q(0)));
  CHECK(!v.bounded());
  CHECK(!svm::area(v, s));
  std::vector<std::int64_t> seen;
  for (auto const& a : v.arcs)
    if (a.wall >= 0) seen.push_back(a.wall);
  std::sort(seen.begin(), seen.end());
  // Wall 1 is seen above and below wall 0: two arcs; wall 2 never.
  CHECK(seen == std::vector<std::int64_t>{0, 1, 1});
  CHECK(v.stats.hidden_pieces >= 1);
}

TEST_CASE("An eye on the boundaries of several polygons looks into each; at a hole's corner in the room's, into neither",
          "[visibility2d]") {
  using Q = rational;
  // Two unit squares side by side, two polygons; the eye in the middle of the edge they share.
  svm::wall_scene<Q> rooms;
  rooms.rings.push_back({point(Q(0), Q(0)), point(Q(1), Q(0)), point(Q(1), Q(1)), point(Q(0), Q(1))});
  rooms.rings.push_back({point(Q(1), Q(0)), point(Q(2), Q(0)), point(Q(2), Q(1)), point(Q(1), Q(1))});
  rooms.ring_polygon = {0, 1};
  auto v = svm::visibility(rooms, point(Q(1), Q(1, 2)));
  REQUIRE(v.bounded());
  CHECK(*svm::area(v, rooms) == Q(2));
  // The same rings as one polygon (an outer ring and a hole would be; here two
  // outer rings of one polygon): only directions inside both are open, none.
  rooms.ring_polygon = {0, 0};
  auto w = svm::visibility(rooms, point(Q(1), Q(1, 2)));
  CHECK(*svm::area(w, rooms) == Q(0));
  // A room [0,4]² with a square hole [0,1]² in its corner (clockwise): at
  // the shared corner (0,0) the hole fills the room's wedge, and nothing is
  // open; from (2,0) on the room's wall the eye sees the room but the hole
  // and its shadow, the triangle (0,1) (1,1) (0,2): 16 − 1 − 1/2.
  svm::wall_scene<Q> corner;
  corner.rings.push_back({point(Q(0), Q(0)), point(Q(4), Q(0)), point(Q(4), Q(4)), point(Q(0), Q(4))});
  corner.rings.push_back({point(Q(0), Q(0)), point(Q(0), Q(1)), point(Q(1), Q(1)), point(Q(1), Q(0))});
  corner.ring_polygon = {0, 0};
  auto c = svm::visibility(corner, point(Q(0), Q(0)));
  CHECK(*svm::area(c, corner) == Q(0));
  auto c2 = svm::visibility(corner, point(Q(2), Q(0)));
  CHECK(*svm::area(c2, corner) == Q(29, 2));
}

} // namespace svm_visibility2d_tests
