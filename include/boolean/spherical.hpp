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
#include <geometry/s2.hpp>

#include <cmath>
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

/// The arcs of a loop with its region on their negative side (the tree
/// builder's convention).  Repeated directions are dropped; an edge between
/// antipodal directions has no minor arc and is refused.
inline void add_arcs(loop l, std::vector<sphere_kernel::sub_hyperplane>& out) {
  loop v;
  for (auto& d : l)
    if (v.empty() || !same_direction(v.back(), d)) v.push_back(std::move(d));
  while (v.size() >= 2 && same_direction(v.back(), v.front())) v.pop_back();
  if (v.size() < 3) return;
  for (std::size_t i = 0, n = v.size(); i < n; ++i) {
    auto const &a = v[i], &b = v[(i + 1) % n];
    if (geometry::parallel(a, b) != geometry::sign::zero)
      throw invalid_polygon("an edge joins two antipodal points: no minor arc is defined between them");
    out.push_back(geometry::s2::arc(b, a));
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

/// Key for a direction: its vector scaled so that its largest coordinate has
/// absolute value 1, which is the same for all positive multiples.
inline std::array<rational, 3> key_of(direction const& d) {
  rational m(0);
  for (std::size_t i = 0; i < 3; ++i)
    if (abs(d[i]) > m) m = abs(d[i]);
  return {rational(d[0] / m), rational(d[1] / m), rational(d[2] / m)};
}

struct key_less {
  bool operator()(std::array<rational, 3> const& a, std::array<rational, 3> const& b) const {
    for (std::size_t i = 0; i < 3; ++i) {
      if (a[i] < b[i]) return true;
      if (b[i] < a[i]) return false;
    }
    return false;
  }
};

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

/// The union of GeoJSON polygons given in longitude/latitude degrees: each
/// polygon's outer ring counter-clockwise and its holes clockwise (RFC 7946),
/// its edges great-circle arcs.  Polygons are built one by one and united,
/// so overlapping polygons are read as their union.
inline region_s2 spherical_region(multipolygon const& lonlat) {
  region_s2 out(false);
  for (auto const& p : lonlat) {
    std::vector<loop> loops;
    auto convert = [](ring const& r) {
      loop l;
      for (auto const& v : r) l.push_back(from_lonlat(v.x(), v.y()));
      return l;
    };
    loops.push_back(convert(p.outer));
    for (auto const& h : p.holes) loops.push_back(convert(h));
    out = bsp::set_union(out, spherical_region(loops));
  }
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

/// The polygons of a region that is neither empty nor the whole sphere is
/// a set of loops; grouped into polygons here by taking a point outside the
/// region as "infinity": loops that keep it on their right are outer loops,
/// the others are holes, each in the smallest outer loop whose region holds
/// it.  Each output arc is shorter than a half circle (half and whole circles
/// get extra vertices), so every edge is the minor arc between its ends.
/// Returns no polygon for the empty region; throws `std::invalid_argument`
/// for the whole sphere, which no loop bounds.
inline std::vector<spherical_polygon> spherical_polygons(region_s2 const& r) {
  using key = std::array<rational, 3>;
  struct arc_edge {
    direction from, to, normal; // the circle's normal: the region on its positive side
  };
  std::vector<arc_edge> edges;
  for (auto& b : bsp::boundary(r)) {
    auto piece = b.positive ? b.piece : geometry::s2::opposite(b.piece);
    auto const& n = piece.support.n;
    auto ends = geometry::s2::endpoints(piece);
    // Whole circles and half circles get vertices every quarter turn.
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
  if (edges.empty()) {
    if (bsp::classify(r, direction(std::array<rational, 3>{rational(0), rational(0), rational(1)})).value_or(false))
      throw std::invalid_argument("boolean::spherical_polygons: the region is the whole sphere");
    return {};
  }
  std::vector<key> from, to;
  for (auto const& e : edges) from.push_back(detail::key_of(e.from)), to.push_back(detail::key_of(e.to));
  // Tangents: leaving `v` along a circle of normal n the direction is n × v.
  auto loops = detail::trace_loops<key, detail::key_less>(from, to, [&](std::size_t in, std::size_t a, std::size_t b) {
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
  // Loops as vertex lists; consecutive arcs on one circle are joined, unless
  // that would leave an arc of a half circle or more.
  std::vector<loop> all;
  std::vector<std::vector<std::size_t>> loop_edges;
  for (auto const& l : loops) {
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < l.size(); ++i) kept.push_back(l[i]);
    loop v;
    std::vector<direction> normals;
    for (auto e : kept) v.push_back(edges[e].from), normals.push_back(edges[e].normal);
    bool changed = true;
    while (changed && v.size() > 3) {
      changed = false;
      for (std::size_t i = 0; i < v.size() && v.size() > 3; ++i) {
        std::size_t n = v.size(), prev = (i + n - 1) % n, next = (i + 1) % n;
        if (geometry::parallel(normals[prev], normals[i]) == geometry::sign::positive &&
            geometry::dot_sign(geometry::cross(v[prev], v[next]), normals[i]) == geometry::sign::positive) {
          v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
          normals.erase(normals.begin() + static_cast<std::ptrdiff_t>(i));
          changed = true;
        }
      }
    }
    if (v.size() >= 3) all.push_back(std::move(v));
  }
  // A point outside the region, off every loop.
  std::optional<direction> outside;
  for (auto const& c : bsp::cells(r))
    if (!r.leaf_data(c.leaf))
      if ((outside = detail::interior_point(c.region))) break;
  if (!outside) throw std::invalid_argument("boolean::spherical_polygons: the region is the whole sphere");
  struct loop_info {
    region_s2 left;
    double area;
    bool outer;
  };
  std::vector<loop_info> info;
  for (auto const& l : all) {
    auto t = spherical_region(std::vector<loop>{l});
    bool holds_outside = bsp::classify(t, *outside).value_or(false);
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

/// The polygons of a region as longitude/latitude rings in degrees (the
/// nearest doubles, read exactly), ready for WKT or GeoJSON.  A region that
/// is the whole sphere has no ring: `std::invalid_argument`.
inline multipolygon lonlat_polygons(region_s2 const& r) {
  auto lonlat = [](loop const& l) {
    ring out;
    for (auto const& d : l) {
      auto [lon, lat] = to_lonlat(d);
      out.emplace_back(geometry::rational(lon), geometry::rational(lat));
    }
    return out;
  };
  multipolygon m;
  for (auto const& p : spherical_polygons(r)) {
    geometry::io::polygon_with_holes q{lonlat(p.outer), {}};
    for (auto const& h : p.holes) q.holes.push_back(lonlat(h));
    m.push_back(std::move(q));
  }
  return m;
}

} // namespace boolean
