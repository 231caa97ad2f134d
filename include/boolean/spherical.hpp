/// @file
/// Boolean operations on spherical polygons, exact: loops of directions
/// joined by minor great-circle arcs become point-set trees over
/// `geometry::s2`, trees are merged, and the result is read back as loops.
///
/// A loop's region is on its left (seen from outside the sphere), the
/// convention of RFC 7946 for GeoJSON exterior rings (counter-clockwise) and
/// holes (clockwise), and of Google's S2.  So a polygon may be larger than a
/// hemisphere, contain a pole or cross the antimeridian: only the order of its
/// vertices decides which side is inside.
///
/// Directions are exact rational vectors, never normalised; longitude and
/// latitude in degrees are turned into the exact rationals of their nearest
/// double unit vectors, with multiples of 90° exact (the equator is z = 0,
/// the poles are (0, 0, ±1)).
#pragma once

#include "polygons.hpp"

#include <bsp/boolean.hpp>
#include <bsp/point_set.hpp>
#include <geometry/hash.hpp>
#include <geometry/s2.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <unordered_map>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace boolean {

/// The sphere, exact, as the trees see it.
using sphere_kernel = geometry::s2::exact_kernel;
/// A region of the sphere: a point-set tree, `true` inside.
using region_s2 = bsp::point_set<sphere_kernel, bool>;
/// A direction (a point of the sphere), exact and unnormalised.
using direction = geometry::s2::point<rational>;
/// A closed loop of directions, consecutive ones joined by the minor arc;
/// the region it bounds is on its left.
using loop = std::vector<direction>;

/// Mean Earth radius in kilometres (IUGG), for areas in km².
inline constexpr double earth_radius_km = 6371.0088;

namespace detail {

/// sin and cos of an angle in degrees: exact at multiples of 90°, and from
/// the reduced angle in [0°, 45°] otherwise so that symmetric angles agree.
inline std::pair<double, double> sincos_degrees(rational const& deg) {
  rational turns = deg / 360;
  geometry::integer whole = boost::multiprecision::numerator(turns) / boost::multiprecision::denominator(turns); // towards zero
  rational r = deg - 360 * rational(whole);
  if (r < 0) r += 360;
  int q = 0;
  while (r >= 90) r -= 90, ++q;
  double t = r.convert_to<double>();
  double s, c;
  if (t == 0) {
    s = 0, c = 1;
  } else if (t <= 45) {
    s = std::sin(t * std::numbers::pi / 180), c = std::cos(t * std::numbers::pi / 180);
  } else {
    double u = (90 - r).convert_to<double>() * std::numbers::pi / 180;
    s = std::cos(u), c = std::sin(u);
  }
  switch (q) {
  case 0: return {s, c};
  case 1: return {c, -s};
  case 2: return {-s, -c};
  default: return {-c, s};
  }
}

/// a + λ b, exact.
inline direction combine(direction const& a, direction const& b, rational const& lambda = rational(1)) {
  return direction(std::array<rational, 3>{rational(a[0] + lambda * b[0]), rational(a[1] + lambda * b[1]),
                                            rational(a[2] + lambda * b[2])});
}
inline rational dot(direction const& a, direction const& b) { return geometry::dot(a.exact(), b.exact()); }

inline bool same_direction(direction const& a, direction const& b) {
  return geometry::parallel(a, b) == geometry::sign::positive;
}

/// An input vertex where an arc ends: the arc's circle (`support`), its
/// bounding circle there (`bound`) and the vertex.  An arc cut out of that
/// arc keeps both circles where it keeps that end.
struct arc_end {
  sphere_kernel::hyperplane support, bound;
  direction vertex;
};

/// The arcs of a loop with its region on their negative side (the tree
/// builder's convention), and in `ends` (when given) each arc's circles at
/// its ends with the vertices there.  Each arc is bounded at a vertex by
/// the circle of the loop's arc on the other side of that vertex (turned
/// so that the arc is on its positive side), so that an arc cut out of a
/// neighbour's piece and ending at that vertex is known to lie on the
/// circle without arithmetic (`geometry::shares_numbers`), or, where the
/// two arcs run along one circle, by the circle through the vertex
/// perpendicular to the arc, as `geometry::s2::arc` bounds it.  Repeated
/// directions are dropped; an edge between antipodal directions has no
/// minor arc and is refused.
inline void add_arcs(loop l, std::vector<sphere_kernel::sub_hyperplane>& out, std::vector<arc_end>* ends = nullptr) {
  using circle = sphere_kernel::hyperplane;
  loop v;
  for (auto& d : l)
    if (v.empty() || !same_direction(v.back(), d)) v.push_back(std::move(d));
  while (v.size() >= 2 && same_direction(v.back(), v.front())) v.pop_back();
  if (v.size() < 3) return;
  std::size_t n = v.size();
  // Arc i runs from v[i+1] to v[i] (the region on its negative side) on circle i.
  std::vector<circle> c;
  c.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    auto const &a = v[i], &b = v[(i + 1) % n];
    if (geometry::parallel(a, b) != geometry::sign::zero)
      throw invalid_polygon("an edge joins two antipodal points: no minor arc is defined between them");
    c.push_back(geometry::s2::circle_through(b, a));
  }
  // The neighbour's circle through x, turned to have y (the arc's other end)
  // on its positive side; the perpendicular circle where y is on it.
  auto bound_at = [](circle const& on, circle const& neighbour, direction const& x, direction const& y, int sign) {
    switch (geometry::dot_sign(neighbour.n, y)) {
    case geometry::sign::positive: return neighbour;
    case geometry::sign::negative: return neighbour.opposite();
    default: return geometry::s2::perpendicular_through(on, x, sign);
    }
  };
  for (std::size_t i = 0; i < n; ++i) {
    auto const &from = v[(i + 1) % n], &to = v[i];
    auto start = bound_at(c[i], c[(i + 1) % n], from, to, +1), end = bound_at(c[i], c[(i + n - 1) % n], to, from, -1);
    out.push_back(geometry::s2::arc_bounded_by(c[i], from, to, std::move(start), std::move(end)));
    if (ends) {
      auto const& a = out.back();
      ends->push_back({a.support, a.bounds.front().original, from});
      ends->push_back({a.support, a.bounds.back().original, to});
    }
  }
}

/// A point inside the convex spherical polygon `c` (none when it has no interior).
inline std::optional<direction> interior_point(geometry::s2::polytope<rational> const& c) {
  auto const& b = c.bounds;
  direction p;
  if (b.empty()) {
    p = direction(std::array<rational, 3>{rational(1), rational(0), rational(0)});
  } else if (b.size() == 1) {
    p = b[0].n;
  } else if (b.size() == 2) { // a lune: n1 + λ n2 with both dot products positive
    rational d = dot(b[0].n, b[1].n), a1 = dot(b[0].n, b[0].n), a2 = dot(b[1].n, b[1].n);
    rational lambda = d >= 0 ? rational(1) : rational((a1 / -d + -d / a2) / 2);
    p = combine(b[0].n, b[1].n, lambda);
  } else {
    p = direction(std::array<rational, 3>{rational(0), rational(0), rational(0)});
    for (auto const& v : geometry::s2::vertices(c)) p = combine(p, v);
  }
  for (auto const& h : b)
    if (geometry::s2::side(h, p) != geometry::oriented_side::positive) return std::nullopt;
  return p;
}

} // namespace detail

/// The direction of longitude `lon` and latitude `lat` in degrees (x towards
/// (0°, 0°), z towards the north pole), exact for multiples of 90°.
inline direction from_lonlat(rational const& lon, rational const& lat) {
  auto [slon, clon] = detail::sincos_degrees(lon);
  auto [slat, clat] = detail::sincos_degrees(lat);
  return direction(std::array<rational, 3>{rational(clat * clon), rational(clat * slon), rational(slat)});
}

/// Longitude and latitude in degrees of a direction, in (−180°, 180°] and
/// [−90°, 90°] (longitude 0 at the poles); exact on the axes.
inline std::pair<double, double> to_lonlat(direction const& d) {
  auto u = geometry::s2::to_unit(d);
  double lon = 0, lat = 0;
  if (d[0] == 0 && d[1] == 0) return {0.0, d[2] > 0 ? 90.0 : -90.0};
  if (d[1] == 0)
    lon = d[0] > 0 ? 0 : 180;
  else if (d[0] == 0)
    lon = d[1] > 0 ? 90 : -90;
  else
    lon = std::atan2(u[1], u[0]) * 180 / std::numbers::pi;
  lat = d[2] == 0 ? 0 : std::atan2(u[2], std::hypot(u[0], u[1])) * 180 / std::numbers::pi;
  return {lon, lat};
}

/// The region bounded by `loops`, each with its region on its left: the
/// loops of one polygon (an outer loop and its holes, or any set of loops
/// that do not cross).  Built in one pass (Thibault and Naylor).
inline region_s2 spherical_region(std::vector<loop> const& loops) {
  std::vector<sphere_kernel::sub_hyperplane> arcs;
  for (auto const& l : loops) detail::add_arcs(l, arcs);
  return bsp::build_point_set<sphere_kernel>(std::move(arcs), true, false, bsp::random_order(20261128));
}

namespace detail {

/// The loops of a polygon given in longitude/latitude degrees.
inline std::vector<loop> loops_of_lonlat(geometry::io::polygon_with_holes const& p) {
  auto convert = [](ring const& r) {
    loop l;
    for (auto const& v : r) l.push_back(from_lonlat(v.x(), v.y()));
    return l;
  };
  std::vector<loop> loops{convert(p.outer)};
  for (auto const& h : p.holes) loops.push_back(convert(h));
  return loops;
}

} // namespace detail

/// The union of GeoJSON polygons given in longitude/latitude degrees: each
/// polygon's outer ring counter-clockwise and its holes clockwise (RFC 7946),
/// its edges great-circle arcs.  Polygons are built one by one and united,
/// so overlapping polygons are read as their union.
inline region_s2 spherical_region(multipolygon const& lonlat) {
  region_s2 out(false);
  for (auto const& p : lonlat) out = bsp::set_union(out, spherical_region(detail::loops_of_lonlat(p)));
  return out;
}

/// The area of a region in steradians (double: a sum of exact cells' areas).
inline double area(region_s2 const& r) { return bsp::measure(r, true); }

/// A spherical polygon: its outer loop and its holes (each with the
/// polygon's region on its left).
struct spherical_polygon {
  loop outer;
  std::vector<loop> holes;
};

/// An operand of a spherical Boolean operation: its tree and the arcs it
/// was built from, which `combine` classifies instead of building the
/// merged tree; and, where the arcs come from loops, their bounding circles
/// with the loops' vertices they pass through, so that an output arc ending
/// at an input vertex takes that vertex instead of constructing it.
struct spherical_operand : basic_operand<sphere_kernel> {
  std::vector<detail::arc_end> ends;
};

/// The operand bounded by `loops` (see `spherical_region`), with its arcs.
inline spherical_operand spherical_operand_of(std::vector<loop> const& loops) {
  std::vector<sphere_kernel::sub_hyperplane> arcs;
  std::vector<detail::arc_end> ends;
  for (auto const& l : loops) detail::add_arcs(l, arcs, &ends);
  auto t = bsp::build_point_set<sphere_kernel>(arcs, true, false, bsp::random_order(20261128));
  return {{std::move(t), std::move(arcs)}, std::move(ends)};
}

/// The operand of GeoJSON polygons in longitude/latitude degrees (see
/// `spherical_region`): one polygon's boundary is its loops' arcs; several
/// polygons are united and their boundary is read off the union.
inline spherical_operand spherical_operand_of(multipolygon const& lonlat) {
  if (lonlat.size() == 1) return spherical_operand_of(detail::loops_of_lonlat(lonlat.front()));
  auto t = spherical_region(lonlat);
  auto b = bsp::oriented_boundary(t);
  return {{std::move(t), std::move(b)}, {}};
}

namespace detail {

/// Input vertices by the identities (`hvec::identity`) of an arc's circle
/// and its bounding circle there.
struct identity_pair_hash {
  std::size_t operator()(std::pair<void const*, void const*> const& k) const noexcept {
    auto a = reinterpret_cast<std::uintptr_t>(k.first), b = reinterpret_cast<std::uintptr_t>(k.second);
    return std::hash<std::uintptr_t>{}(a * 0x9e3779b97f4a7c15ull ^ (b + (a << 6) + (a >> 2)));
  }
};
using known_vertices = std::unordered_map<std::pair<void const*, void const*>, direction const*, identity_pair_hash>;

/// An arc of an output loop, with the normal of its circle (the region on
/// its positive side).
struct arc_edge {
  direction from, to, normal;
};

/// The loops bounded by `pieces`, each with the region on its negative side
/// (as `bsp::oriented_boundary` and `bsp::merged_boundary` give them), as
/// vertex lists with the region on their left.  Vertices are numbered by
/// their primitive integer coordinates (no rational is made); whole and half
/// circles get vertices every quarter turn, and consecutive arcs on one
/// circle are joined unless that would leave an arc of a half circle or
/// more, so every edge is the minor arc between its ends.  At a vertex where
/// the boundary touches itself a loop turns as far left as it can and is
/// cut there.
inline std::vector<loop> loops_of(std::vector<sphere_kernel::sub_hyperplane> const& pieces,
                                  known_vertices const& known = {}) {
  std::vector<arc_edge> edges;
  // An arc's start or end: a known vertex when its circle and its bounding
  // circle there are an input arc's (their numbers, shared by every copy and
  // by the opposite circles, identify them).
  auto end_of = [&](sphere_kernel::sub_hyperplane const& piece, bool end) {
    if (!known.empty()) {
      auto const& b = end ? piece.bounds.back() : piece.bounds.front();
      if (auto it = known.find({piece.support.n.identity(), b.original.n.identity()}); it != known.end())
        return *it->second;
    }
    return geometry::s2::endpoint(piece, end);
  };
  for (auto const& p : pieces) {
    auto piece = geometry::s2::opposite(p);
    auto const& n = piece.support.n;
    std::vector<direction> ends;
    if (piece.bounds.size() == 2) ends = {end_of(piece, false), end_of(piece, true)};
    else ends = geometry::s2::endpoints(piece);
    std::vector<direction> pts;
    if (ends.empty()) {
      std::size_t k = 0;
      for (std::size_t i = 1; i < 3; ++i)
        if (abs(n[i]) < abs(n[k])) k = i;
      std::array<rational, 3> e{rational(0), rational(0), rational(0)};
      e[k] = 1;
      direction a = geometry::cross(n, direction(e));
      direction q = geometry::cross(n, a);
      pts = {a, q, -a, -q, a};
    } else if (geometry::parallel(ends[0], ends[1]) == geometry::sign::negative) {
      pts = {ends[0], geometry::cross(n, ends[0]), ends[1]};
    } else {
      pts = {ends[0], ends[1]};
    }
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) edges.push_back({pts[i], pts[i + 1], n});
  }
  if (edges.empty()) return {};
  geometry::welder<3> vertex_id;
  std::vector<std::uint32_t> from, to;
  from.reserve(edges.size()), to.reserve(edges.size());
  for (auto const& e : edges) from.push_back(vertex_id(e.from)), to.push_back(vertex_id(e.to));
  // Tangents: leaving `v` along a circle of normal n the direction is n × v.
  auto loops = trace_loops(vertex_id.vertex.size(), from, to, [&](std::size_t in, std::size_t a, std::size_t b) {
    auto const& v = edges[in].to;
    direction back = -geometry::cross(edges[in].normal, v);
    direction ta = geometry::cross(edges[a].normal, v), tb = geometry::cross(edges[b].normal, v);
    auto cr = [&](direction const& x, direction const& y) { return geometry::det_sign(v, x, y); };
    auto half = [&](direction const& d) {
      auto c = cr(back, d);
      if (c == geometry::sign::negative) return 0;
      if (c == geometry::sign::positive) return 2;
      return geometry::dot_sign(back, d) == geometry::sign::negative ? 1 : 3;
    };
    int ha = half(ta), hb = half(tb);
    if (ha != hb) return ha < hb;
    return cr(ta, tb) == geometry::sign::negative;
  });
  // Edge e of a loop may absorb the next, f, when both lie on one circle and
  // the arc from e's start to f's end is still a minor arc.
  auto joins = [&](std::size_t e, std::size_t f, direction const& end) {
    return geometry::parallel(edges[e].normal, edges[f].normal) == geometry::sign::positive &&
           geometry::dot_sign(geometry::cross(edges[e].from, end), edges[f].normal) == geometry::sign::positive;
  };
  std::vector<loop> all;
  std::vector<std::size_t> kept; // the loop's edges that remain, each absorbing the ones after it
  for (auto const& l : loops) {
    kept.clear();
    for (std::size_t i = 0, k = l.size(); i < k; ++i)
      if (kept.empty() || !joins(kept.back(), l[i], edges[l[i]].to)) kept.push_back(l[i]);
    // Across the seam: the last kept edge may absorb the first ones.
    while (kept.size() > 3 && joins(kept.back(), kept.front(), edges[kept[1]].from)) kept.erase(kept.begin());
    if (kept.size() < 3) continue;
    loop v;
    v.reserve(kept.size());
    for (auto e : kept) v.push_back(edges[e].from);
    all.push_back(std::move(v));
  }
  return all;
}

/// Groups loops into polygons, given a direction `outside` outside their
/// region and off every loop: loops that keep it on their right are outer
/// loops, the others holes, each in the smallest outer loop whose region
/// holds it.  Works for any loops, a point-set tree built per loop.
inline std::vector<spherical_polygon> nest_by_trees(std::vector<loop> all, direction const& outside) {
  struct loop_info {
    region_s2 left;
    double area;
    bool outer;
  };
  std::vector<loop_info> info;
  for (auto const& l : all) {
    auto t = spherical_region(std::vector<loop>{l});
    bool holds_outside = bsp::classify(t, outside).value_or(false);
    double a = bsp::measure(t, true);
    info.push_back({std::move(t), a, !holds_outside});
  }
  std::vector<spherical_polygon> out;
  std::vector<std::size_t> shell_of(all.size(), all.size()), shells;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (info[i].outer) shell_of[i] = out.size(), shells.push_back(i), out.push_back({all[i], {}});
  std::sort(shells.begin(), shells.end(), [&](std::size_t a, std::size_t b) { return info[a].area < info[b].area; });
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (info[i].outer) continue;
    // The smallest outer loop whose region holds a vertex (or an arc's midpoint) of this hole.
    std::size_t best = all.size();
    for (auto s : shells) {
      std::optional<bool> in;
      for (std::size_t k = 0; k < all[i].size() && !in; ++k) in = bsp::classify(info[s].left, all[i][k]);
      for (std::size_t k = 0; k < all[i].size() && !in; ++k)
        in = bsp::classify(info[s].left, detail::combine(all[i][k], all[i][(k + 1) % all[i].size()]));
      if (in.value_or(false)) {
        best = s;
        break;
      }
    }
    if (best == all.size()) throw std::invalid_argument("boolean::spherical_polygons: a hole lies in no outer loop");
    out[shell_of[best]].holes.push_back(all[i]);
  }
  return out;
}

/// A unit vector of doubles in the direction of `d`: from the filter's
/// doubles (`unit_doubles`), or from its rationals when they have none.
inline std::array<double, 3> unit_of(direction const& d) {
  auto u = geometry::detail::unit_doubles(d);
  if (!u) return geometry::s2::to_unit(d);
  double l = std::sqrt((*u)[0] * (*u)[0] + (*u)[1] * (*u)[1] + (*u)[2] * (*u)[2]);
  return {(*u)[0] / l, (*u)[1] / l, (*u)[2] / l};
}

/// A direction near the middle of the loops' vertices, on integers below
/// 2^25 (the sum of their unit vectors, rounded); none when that sum is
/// about zero.
inline std::optional<direction> centre_of(std::vector<loop> const& all) {
  std::array<double, 3> s{};
  for (auto const& l : all)
    for (auto const& v : l) {
      auto u = unit_of(v);
      for (std::size_t k = 0; k < 3; ++k) s[k] += u[k];
    }
  double len = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  if (!(len > 0)) return std::nullopt;
  std::array<geometry::integer, 3> c;
  bool zero = true;
  for (std::size_t k = 0; k < 3; ++k) {
    c[k] = std::llround(std::ldexp(s[k] / len, 24));
    zero = zero && c[k] == 0;
  }
  if (zero) return std::nullopt;
  geometry::detail::make_primitive(c);
  return direction::from_integers(geometry::detail::integer_vector<3>(std::move(c)));
}

/// Groups loops into polygons as `nest_by_trees` does, when every vertex
/// lies in the open hemisphere around `c` and −c is outside the region:
/// there the central projection onto the plane touching the sphere at `c`
/// sends minor arcs to segments, keeps every turn, and sends the region to
/// a bounded one, so the plane's `nest_indices` groups the projected rings
/// (counter-clockwise: outer loops).  The projected points are homogeneous
/// integers (v·e1, v·e2, v·c) of each vertex v, with e1, e2, c a right-handed
/// orthogonal frame on integers: no rational is made unless two outer rings
/// compete for a hole.  None when some vertex is not in the hemisphere.
inline std::optional<std::vector<spherical_polygon>> nest_in_hemisphere(std::vector<loop>& all, direction const& c) {
  using geometry::integer;
  auto const& C = c.integers();
  std::size_t k = 0;
  for (std::size_t i = 1; i < 3; ++i)
    if (abs(C[i]) < abs(C[k])) k = i;
  std::array<integer, 3> axis{integer(0), integer(0), integer(0)};
  axis[k] = 1;
  auto e1 = geometry::cross(C, axis), e2 = geometry::cross(C, e1); // e1 × e2 = |e1|²·c
  std::vector<ring> rings;
  rings.reserve(all.size());
  for (auto const& l : all) {
    ring r;
    r.reserve(l.size());
    for (auto const& v : l) {
      auto const& z = v.integers();
      std::array<integer, 3> h{geometry::dot(z, e1), geometry::dot(z, e2), geometry::dot(z, C)};
      if (h[2].sign() <= 0) return std::nullopt;
      geometry::detail::make_primitive(h);
      r.push_back(point2::from_homogeneous(geometry::hvec<rational, 3>::from_integers(geometry::detail::integer_vector<3>(std::move(h)))));
    }
    rings.push_back(std::move(r));
  }
  std::vector<spherical_polygon> out;
  for (auto& g : nest_indices(rings)) {
    spherical_polygon p{std::move(all[g.outer]), {}};
    for (auto h : g.holes) p.holes.push_back(std::move(all[h]));
    out.push_back(std::move(p));
  }
  return out;
}

} // namespace detail

/// The polygons of a region that is neither empty nor the whole sphere is
/// a set of loops; grouped into polygons here by taking a point outside the
/// region as "infinity": loops that keep it on their right are outer loops,
/// the others are holes, each in the smallest outer loop whose region holds
/// it.  Each output arc is shorter than a half circle (half and whole circles
/// get extra vertices), so every edge is the minor arc between its ends.
/// When the loops lie in an open hemisphere whose centre's antipode is
/// outside the region, they are nested in the plane by central projection
/// (`detail::nest_in_hemisphere`); otherwise by a tree per loop.
/// Returns no polygon for the empty region; throws `std::invalid_argument`
/// for the whole sphere, which no loop bounds.
inline std::vector<spherical_polygon> spherical_polygons(region_s2 const& r) {
  auto all = detail::loops_of(bsp::oriented_boundary(r));
  if (all.empty()) {
    if (bsp::classify(r, direction(std::array<rational, 3>{rational(0), rational(0), rational(1)})).value_or(false))
      throw std::invalid_argument("boolean::spherical_polygons: the region is the whole sphere");
    return {};
  }
  if (all.size() == 1) return {{std::move(all.front()), {}}}; // the region is the left of its one loop
  if (auto c = detail::centre_of(all); c && bsp::classify(r, -*c) == false)
    if (auto out = detail::nest_in_hemisphere(all, *c)) return std::move(*out);
  // A point outside the region, off every loop.
  std::optional<direction> outside;
  for (auto const& c : bsp::cells(r))
    if (!r.leaf_data(c.leaf))
      if ((outside = detail::interior_point(c.region))) break;
  if (!outside) throw std::invalid_argument("boolean::spherical_polygons: the region is the whole sphere");
  return detail::nest_by_trees(std::move(all), *outside);
}

/// The valid spherical polygons of `op(a, b)`, from the operands' arcs
/// classified against both trees (`bsp::merged_boundary`): the merged tree
/// is not built (unless the result's loops lie in no open hemisphere whose
/// centre's antipode is outside the result, or the result has no loop: then
/// it is built and read as `spherical_polygons(apply(op, a.tree, b.tree))`
/// reads it).  The same polygons as that.  Throws `std::invalid_argument`
/// when the result is the whole sphere.
inline std::vector<spherical_polygon> combine(set_op op, spherical_operand const& a, spherical_operand const& b) {
  // The input vertices by the arcs' circles and bounding circles through them.
  detail::known_vertices known;
  known.reserve(a.ends.size() + b.ends.size());
  for (auto const* o : {&a, &b})
    for (auto const& e : o->ends) known.emplace(std::pair{e.support.n.identity(), e.bound.n.identity()}, &e.vertex);
  auto all = detail::loops_of(bsp::merged_boundary(a.tree, a.boundary, b.tree, b.boundary,
                                                   [op](bool x, bool y) { return detail::label_op(op, x, y); }, true),
                              known);
  if (all.size() == 1) return {{std::move(all.front()), {}}}; // the result is the left of its one loop
  if (!all.empty())
    if (auto c = detail::centre_of(all)) {
      // −c outside the result: both operands' labels there decide it (none on a boundary).
      auto x = bsp::classify(a.tree, -*c), y = bsp::classify(b.tree, -*c);
      if (x && y && !detail::label_op(op, *x, *y))
        if (auto out = detail::nest_in_hemisphere(all, *c)) return std::move(*out);
    }
  return spherical_polygons(apply(op, a.tree, b.tree));
}

/// The area of spherical polygons in steradians (double): by Gauss–Bonnet,
/// 2π minus the turns of each loop, less 4π for each hole; each turn is
/// the angle between the exact normals of the circles meeting there, its
/// sign exact.
inline double area(std::vector<spherical_polygon> const& polygons) {
  double sum = 0;
  auto loop_area = [](loop const& l) {
    std::size_t k = l.size();
    std::vector<direction> normal(k);
    for (std::size_t i = 0; i < k; ++i) normal[i] = geometry::cross(l[i], l[(i + 1) % k]);
    double turn = 0;
    for (std::size_t i = 0; i < k; ++i) {
      auto const &n0 = normal[(i + k - 1) % k], &n1 = normal[i];
      double a = geometry::s2::angle_between(detail::unit_of(n0), detail::unit_of(n1));
      turn += geometry::det_sign(n0, n1, l[i]) == geometry::sign::negative ? -a : a;
    }
    return 2 * std::numbers::pi - turn;
  };
  for (auto const& p : polygons) {
    sum += loop_area(p.outer);
    for (auto const& h : p.holes) sum += loop_area(h) - 4 * std::numbers::pi;
  }
  return sum;
}

/// Spherical polygons as longitude/latitude rings in degrees (the nearest
/// doubles, read exactly), ready for WKT or GeoJSON.
inline multipolygon lonlat_polygons(std::vector<spherical_polygon> const& polygons) {
  auto lonlat = [](loop const& l) {
    ring out;
    for (auto const& d : l) {
      auto [lon, lat] = to_lonlat(d);
      out.emplace_back(geometry::rational(lon), geometry::rational(lat));
    }
    return out;
  };
  multipolygon m;
  for (auto const& p : polygons) {
    geometry::io::polygon_with_holes q{lonlat(p.outer), {}};
    for (auto const& h : p.holes) q.holes.push_back(lonlat(h));
    m.push_back(std::move(q));
  }
  return m;
}

/// The polygons of a region as longitude/latitude rings in degrees (see
/// above).  A region that is the whole sphere has no ring:
/// `std::invalid_argument`.
inline multipolygon lonlat_polygons(region_s2 const& r) { return lonlat_polygons(spherical_polygons(r)); }

} // namespace boolean
