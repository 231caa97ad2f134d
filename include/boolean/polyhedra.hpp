/// @file
/// Exact Boolean operations (CSG) on closed polyhedra: a closed, consistently
/// oriented polygon mesh becomes a point-set tree (Thibault and Naylor), two
/// trees are merged (Naylor, Amanatides and Thibault), and the boundary of the
/// result is turned back into a polygon mesh with as few faces as the planes
/// allow, welded and free of T-junctions.
///
/// Everything is exact: planes and vertices are integer homogeneous vectors
/// (the mesh's vertices are written as rationals, once each), volumes are
/// rational, every decision is an exact sign.  Doubles appear only in the
/// text writers, in filters that certify signs, and, as a conservative
/// filter that never decides anything, in the search for vertices lying on
/// edges.
///
/// Conventions: mesh faces turn counter-clockwise seen from outside (their
/// normals point outwards); a tree's region lies on the negative side of its
/// boundary pieces (`bsp::build_point_set`).
#pragma once

#include "rings.hpp"

#include <bsp/boolean.hpp>
#include <bsp/point_set.hpp>
#include <bsp/splitter.hpp>
#include <geometry/e2.hpp>
#include <geometry/e3.hpp>
#include <geometry/hash.hpp>
#include <geometry/io/polygons.hpp>
#include <geometry/io/scene.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace boolean {

/// Exact space E3, the geometry of solids.
using space_kernel = geometry::e3::exact_kernel;

/// A point of space with rational coordinates.
using point3 = geometry::e3::point<rational>;

/// A solid as a point-set tree: `true` inside.
using solid_tree = bsp::point_set<space_kernel, bool>;

/// A bounded solid: its tree and its exact volume.
struct solid {
  solid_tree tree;                    ///< the point-set tree, `true` inside
  /// Pieces covering the boundary, the solid on their negative side: for a
  /// solid read from a mesh, the convex polygons the tree was built from.
  std::vector<geometry::e3::sub_hyperplane<rational>> boundary;
  rational volume;                    ///< exact volume of the inside cells
  bool flipped = false;               ///< the input mesh was inside out (inward normals) and was turned outside in
  std::size_t degenerate_faces = 0;   ///< input faces of zero area, ignored
  std::size_t triangulated_faces = 0; ///< non-convex or non-planar input faces cut into triangles
};

/// A polygon mesh with exact vertices: faces are cycles of vertex indices,
/// counter-clockwise seen from outside.
struct mesh {
  std::vector<point3> vertices;                  ///< exact vertices, pairwise distinct in meshes made here
  std::vector<std::vector<std::uint32_t>> faces; ///< 0-based indices into `vertices`
};

/// The Boolean operations on solids.
enum class csg_op {
  union_,       ///< points in either solid
  intersection, ///< points in both solids
  difference    ///< points in the first solid and not in the second
};

/// How the edges of a mesh are used by its faces.  An edge is an unordered
/// pair of distinct vertex indices that follow each other in some face.
struct edge_report {
  std::size_t edges = 0;        ///< edges of the mesh
  std::size_t unmatched = 0;    ///< edges run more often one way than the other (holes, flipped faces)
  std::size_t non_manifold = 0; ///< edges run equally often both ways, but by more than two faces
};

namespace detail::polyhedra {

using vec3 = std::array<rational, 3>;
using plane_key = std::array<rational, 4>;
using piece3 = space_kernel::sub_hyperplane;

inline vec3 minus(point3 const& a, point3 const& b) { return {a.x() - b.x(), a.y() - b.y(), a.z() - b.z()}; }
inline vec3 cross(vec3 const& a, vec3 const& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline rational dot(vec3 const& a, vec3 const& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// `a · (b × c)`: six times the signed volume of the tetrahedron (origin, a, b, c).
inline rational triple(point3 const& a, point3 const& b, point3 const& c) {
  return a.x() * (b.y() * c.z() - b.z() * c.y()) - a.y() * (b.x() * c.z() - b.z() * c.x()) +
         a.z() * (b.x() * c.y() - b.y() * c.x());
}

/// Six times the signed volume enclosed by a closed polygon (a fan from its first vertex).
template <class Points> rational six_volume(Points const& v) {
  rational s(0);
  for (std::size_t i = 1; i + 1 < v.size(); ++i) s += triple(v[0], v[i], v[i + 1]);
  return s;
}

/// Shortest text that reads back as the same double; never "-0".
inline std::string shortest(double d) {
  if (d == 0) d = 0;
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, d);
  return std::string(buf, r.ptr);
}

/// Appends the coordinates of `p`, rounded, separated by spaces.
inline std::string& append_point(std::string& s, point3 const& p) {
  s.append(shortest(geometry::to_double(p.x()))).append(" ").append(shortest(geometry::to_double(p.y()))).append(" ");
  return s.append(shortest(geometry::to_double(p.z())));
}

/// A number for a message: exact when an integer, else its nearest double.
inline std::string text(rational const& x) {
  if (denominator(x) == 1) return numerator(x).str();
  return shortest(geometry::to_double(x));
}

/// The coordinates of a point as an array, for ordering.
inline vec3 coords(point3 const& p) { return {p.x(), p.y(), p.z()}; }

/// The operation on labels: inside the result from inside the operands.
inline auto label_op(csg_op op) {
  return [op](bool x, bool y) { return op == csg_op::union_ ? x || y : op == csg_op::intersection ? x && y : x && !y; };
}

/// Checks that every edge of the scene's faces (vertices with equal
/// coordinates taken as one) is run equally often in both directions.
inline void check_closed(geometry::io::scene const& s) {
  std::size_t nv = s.vertices.size();
  // Each vertex's representative: the first vertex with the same coordinates.
  std::vector<std::uint32_t> order(nv), rep(nv);
  for (std::uint32_t i = 0; i < nv; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    auto const &p = s.vertices[a], &q = s.vertices[b]; // lexicographic, without copying the numbers
    for (std::size_t k = 0; k < 3; ++k)
      if (p[k] != q[k]) return p[k] < q[k];
    return false;
  });
  for (std::size_t i = 0; i < nv; ++i)
    rep[order[i]] = (i > 0 && s.vertices[order[i]] == s.vertices[order[i - 1]]) ? rep[order[i - 1]] : order[i];

  struct use {
    std::uint32_t lo, hi;
    bool forward; // runs from lo to hi
    std::uint32_t face;
  };
  std::vector<use> uses;
  std::vector<std::uint32_t> cycle;
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    cycle.clear();
    for (auto i : s.faces[f].vertices) {
      if (i >= nv)
        throw std::out_of_range(geometry::io::detail::cat("boolean::from_scene: face ", std::to_string(f),
                                                          " refers to vertex ", std::to_string(i), " of ",
                                                          std::to_string(nv)));
      if (cycle.empty() || cycle.back() != rep[i]) cycle.push_back(rep[i]);
    }
    while (cycle.size() >= 2 && cycle.back() == cycle.front()) cycle.pop_back();
    if (cycle.size() < 3) continue; // no area: nothing to close
    for (std::size_t k = 0; k < cycle.size(); ++k) {
      std::uint32_t a = cycle[k], b = cycle[(k + 1) % cycle.size()];
      uses.push_back({std::min(a, b), std::max(a, b), a < b, static_cast<std::uint32_t>(f)});
    }
  }
  std::sort(uses.begin(), uses.end(), [](use const& a, use const& b) {
    return a.lo != b.lo ? a.lo < b.lo : a.hi != b.hi ? a.hi < b.hi : a.face < b.face;
  });
  // The faulty edge met first in face order.
  std::size_t bad = uses.size(), bad_face = 0, bad_end = 0;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i, fwd = 0;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) fwd += uses[j++].forward;
    std::size_t total = j - i;
    if (2 * fwd != total && (bad == uses.size() || uses[i].face < bad_face))
      bad = i, bad_face = uses[i].face, bad_end = j;
    i = j;
  }
  if (bad == uses.size()) return;
  using geometry::io::detail::cat;
  auto const& e = uses[bad];
  std::size_t total = bad_end - bad, fwd = 0;
  std::string faces;
  for (std::size_t i = bad; i < bad_end; ++i) {
    fwd += uses[i].forward;
    if (i - bad < 4) faces.append(i > bad ? ", " : "").append(std::to_string(uses[i].face));
  }
  if (total > 4) faces.append(", ...");
  std::string lo = std::to_string(e.lo), hi = std::to_string(e.hi);
  std::string edge = cat("edge between vertices ", lo, " and ", hi);
  if (total % 2 == 1)
    throw std::invalid_argument(cat("open mesh: ", edge, " has ", std::to_string(total),
                                    total == 1 ? " face" : " faces", total == 1 ? " (face " : " (faces ", faces, ")"));
  throw std::invalid_argument(cat("inconsistently oriented faces at ", edge, ": ", std::to_string(fwd), " run from ",
                                  lo, " to ", hi, " and ", std::to_string(total - fwd), " the other way (faces ", faces,
                                  ")"));
}

// ---------------------------------------------------------------- planes

/// The oriented plane of a boundary piece, scaled so that its first non-zero
/// normal component is ±1: equal keys, equal oriented planes.
inline plane_key canonical(piece3 const& s) {
  auto n = s.support.n.exact();
  std::size_t k = n[0] != 0 ? 0 : n[1] != 0 ? 1 : 2;
  rational a = abs(n[k]);
  for (auto& c : n) c /= a;
  return n;
}

/// A plane seen in 2D: coordinate `k` (the normal's largest) dropped, the
/// other two swapped when the normal's k-th component is negative, so that
/// counter-clockwise seen from the plane's positive side is counter-clockwise
/// in 2D.
struct frame {
  plane_key n;
  std::size_t k, i, j;
  bool swap;

  explicit frame(plane_key const& p) : n(p) {
    k = 0;
    for (std::size_t c = 1; c < 3; ++c)
      if (abs(n[c]) > abs(n[k])) k = c;
    i = (k + 1) % 3, j = (k + 2) % 3;
    swap = n[k] < 0;
  }
  point2 to2d(point3 const& p) const { return swap ? point2(p[j], p[i]) : point2(p[i], p[j]); }
  /// The point of the plane above `q`: exact, solving the plane equation for coordinate k.
  point3 lift(point2 const& q) const {
    std::array<rational, 3> c;
    c[i] = swap ? q.y() : q.x();
    c[j] = swap ? q.x() : q.y();
    c[k] = -(n[i] * c[i] + n[j] * c[j] + n[3]) / n[k];
    return point3(c[0], c[1], c[2]);
  }
};

// ---------------------------------------------------------------- 2D edges

/// A change of the signed count of edges covering a line, at parameter `t`.
struct event {
  rational t;
  point2 at;
  int delta;
};

/// Sweeps `events` along their line and calls `emit(from, to, count)` for
/// every maximal stretch where the running count is a non-zero `count`
/// (`from` before `to` along the line).
template <class Emit> void sweep(std::vector<event>& events, Emit&& emit) {
  std::sort(events.begin(), events.end(), [](event const& a, event const& b) { return a.t < b.t; });
  int net = 0;
  point2 start;
  for (std::size_t a = 0; a < events.size();) {
    std::size_t b = a;
    int next = net;
    while (b < events.size() && events[b].t == events[a].t) next += events[b++].delta;
    if (next != net) {
      if (net != 0) emit(start, events[a].at, net);
      if (next != 0) start = events[a].at;
      net = next;
    }
    a = b;
  }
}

/// The boundary of the union of polygons with disjoint interiors, given by
/// all their directed edges: edges that run the opposite way along the same
/// line cancel where they overlap (fragments meet at T-junctions, so overlap
/// is measured along the line, not by endpoints); what is left, joined into
/// maximal collinear runs, bounds the union.
inline std::vector<directed_segment> cancel(std::vector<directed_segment> const& edges) {
  // Key of a line: its direction with the first non-zero component 1, and
  // the cross product of that direction with any of its points.
  std::map<std::array<rational, 3>, std::vector<event>> lines;
  for (auto const& e : edges) {
    rational dx = e.to.x() - e.from.x(), dy = e.to.y() - e.from.y();
    if (dx == 0 && dy == 0) continue;
    bool forward = dx != 0 ? dx > 0 : dy > 0;
    rational s = abs(dx != 0 ? dx : dy);
    rational ux = dx / s, uy = dy / s;
    if (!forward) ux = -ux, uy = -uy;
    rational c = ux * e.from.y() - uy * e.from.x();
    auto& ev = lines[{ux, uy, c}];
    rational t0 = ux * e.from.x() + uy * e.from.y(), t1 = ux * e.to.x() + uy * e.to.y();
    // +1 from `from` to `to`: the count is positive on forward edges, negative on backward ones.
    ev.push_back({std::move(t0), e.from, 1});
    ev.push_back({std::move(t1), e.to, -1});
  }
  std::vector<directed_segment> out;
  for (auto& [key, ev] : lines)
    sweep(ev, [&](point2 const& a, point2 const& b, int count) {
      for (int m = 0; m < std::abs(count); ++m)
        out.push_back(count > 0 ? directed_segment{a, b} : directed_segment{b, a});
    });
  return out;
}

/// Splits every edge at the endpoints of edges that lie strictly inside it,
/// so that where the boundary touches itself (a vertex of one part of a
/// region on an edge of another) `assemble` sees the vertex and keeps the
/// rings apart.  Candidates come from the endpoints sorted along x and along
/// y: the coordinate whose range over the edge holds fewer of them is searched.
inline void split_at_endpoints(std::vector<directed_segment>& edges) {
  auto by_x = [](point2 const& a, point2 const& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); };
  auto by_y = [](point2 const& a, point2 const& b) { return a.y() < b.y() || (a.y() == b.y() && a.x() < b.x()); };
  std::vector<point2> xs;
  for (auto const& e : edges) xs.push_back(e.from), xs.push_back(e.to);
  std::sort(xs.begin(), xs.end(), by_x);
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::vector<point2> ys = xs;
  std::sort(ys.begin(), ys.end(), by_y);
  std::vector<directed_segment> out;
  std::vector<std::pair<rational, point2>> found;
  for (auto const& e : edges) {
    point2 lo_x = by_x(e.from, e.to) ? e.from : e.to, hi_x = by_x(e.from, e.to) ? e.to : e.from;
    point2 lo_y = by_y(e.from, e.to) ? e.from : e.to, hi_y = by_y(e.from, e.to) ? e.to : e.from;
    auto x0 = std::upper_bound(xs.begin(), xs.end(), lo_x, by_x),
         x1 = std::lower_bound(xs.begin(), xs.end(), hi_x, by_x);
    auto y0 = std::upper_bound(ys.begin(), ys.end(), lo_y, by_y),
         y1 = std::lower_bound(ys.begin(), ys.end(), hi_y, by_y);
    bool use_x = x1 - x0 <= y1 - y0;
    auto first = use_x ? x0 : y0, last = use_x ? x1 : y1;
    rational dx = e.to.x() - e.from.x(), dy = e.to.y() - e.from.y();
    found.clear();
    for (auto it = first; it < last; ++it) {
      // Strictly between the ends in the order searched; on the segment when on its line.
      rational px = it->x() - e.from.x(), py = it->y() - e.from.y();
      if (dx * py - dy * px != 0) continue;
      rational t = dx * px + dy * py;
      if (t > 0 && t < dx * dx + dy * dy) found.emplace_back(std::move(t), *it);
    }
    if (found.empty()) {
      out.push_back(e);
      continue;
    }
    std::sort(found.begin(), found.end(), [](auto const& a, auto const& b) { return a.first < b.first; });
    point2 at = e.from;
    for (auto const& f : found) out.push_back({at, f.second}), at = f.second;
    out.push_back({at, e.to});
  }
  edges = std::move(out);
}

/// The two parts of the polygon `q` on either side of the line through `p`
/// and `r` (left of p → r first), as directed boundary edges.  The parts of
/// the line inside `q` are found by a sweep along it: the count of boundary
/// crossings of a line infinitesimally to its left (right) tells where `q`
/// lies just to that side.
inline std::pair<std::vector<directed_segment>, std::vector<directed_segment>> split(polygon const& q, point2 const& p,
                                                                                     point2 const& r) {
  rational dx = r.x() - p.x(), dy = r.y() - p.y();
  auto side = [&](point2 const& a) { return dx * (a.y() - p.y()) - dy * (a.x() - p.x()); };
  auto along = [&](point2 const& a) { return dx * a.x() + dy * a.y(); };
  std::vector<directed_segment> left, right;
  std::vector<event> left_events, right_events;
  auto edges = [&](ring const& g) {
    for (std::size_t m = 0, n = g.size(); m < n; ++m) {
      point2 const &a = g[m], &b = g[(m + 1) % n];
      rational sa = side(a), sb = side(b);
      int ga = sa.sign(), gb = sb.sign();
      if (ga == 0 && gb == 0) continue; // on the line: the sweep decides
      // Where the edge meets the line, when it does (its signs differ or one is 0).
      point2 x = ga == 0 ? a : gb == 0 ? b : a;
      if (ga * gb < 0) {
        rational f = sa / (sa - sb);
        x = point2(a.x() + (b.x() - a.x()) * f, a.y() + (b.y() - a.y()) * f);
      }
      if (ga >= 0 && gb >= 0)
        left.push_back({a, b});
      else if (ga <= 0 && gb <= 0)
        right.push_back({a, b});
      else if (ga > 0)
        left.push_back({a, x}), right.push_back({x, b});
      else
        right.push_back({a, x}), left.push_back({x, b});
      // Walking along p → r, an edge towards the left is left behind the
      // region (the region is on its left): the count drops.
      int delta = sb > sa ? -1 : 1;
      if ((ga <= 0 && gb > 0) || (gb <= 0 && ga > 0)) left_events.push_back({along(x), x, delta});
      if ((ga < 0 && gb >= 0) || (gb < 0 && ga >= 0)) right_events.push_back({along(x), x, delta});
    }
  };
  edges(q.outer);
  for (auto const& h : q.holes) edges(h);
  sweep(left_events, [&](point2 const& a, point2 const& b, int count) {
    if (count > 0) left.push_back({a, b});
  });
  sweep(right_events, [&](point2 const& a, point2 const& b, int count) {
    if (count > 0) right.push_back({b, a});
  });
  return {std::move(left), std::move(right)};
}

/// The polygon `q` cut into polygons without holes, appended to `out` as
/// their outer rings.  While a part has a hole, it is cut by the line through
/// an edge of that hole (an axis-parallel edge when there is one, so that the
/// new vertices keep simple coordinates): the hole lies along that line, so
/// on each side it opens into the line's segment inside the part and becomes
/// a notch of the outer ring.  Each cut removes at least one hole and makes
/// none, so this ends, and every face it gives is a simple polygon.
inline void without_holes(polygon q, std::vector<ring>& out) {
  std::vector<polygon> stack;
  stack.push_back(std::move(q));
  while (!stack.empty()) {
    polygon g = std::move(stack.back());
    stack.pop_back();
    if (g.holes.empty()) {
      out.push_back(std::move(g.outer));
      continue;
    }
    ring const& h = g.holes.front();
    std::size_t e = 0;
    for (std::size_t m = 0; m < h.size(); ++m) {
      auto const &a = h[m], &b = h[(m + 1) % h.size()];
      if (a.x() == b.x() || a.y() == b.y()) {
        e = m;
        break;
      }
    }
    auto [left, right] = split(g, h[e], h[(e + 1) % h.size()]);
    split_at_endpoints(left);
    split_at_endpoints(right);
    for (auto& part : assemble(left)) stack.push_back(std::move(part));
    for (auto& part : assemble(right)) stack.push_back(std::move(part));
  }
}

// ---------------------------------------------------------------- 3D mesh

/// Whether `w` lies strictly inside the segment from `u` to `v`.
inline bool strictly_inside(point3 const& u, point3 const& v, point3 const& w) {
  vec3 d = minus(v, u), e = minus(w, u);
  auto c = cross(d, e);
  if (c[0] != 0 || c[1] != 0 || c[2] != 0) return false;
  rational t = dot(d, e);
  return t > 0 && t < dot(d, d);
}

/// Inserts into every face edge, in order, the vertices lying strictly
/// inside it.  Candidates come from the vertices sorted along each axis: of
/// the three slabs spanned by the edge, the one holding the fewest vertices
/// is searched (rounding to double is monotone, so the slab in doubles holds
/// every vertex of the exact slab); each candidate is then tested exactly.
inline void split_edges(mesh& m) {
  std::size_t nv = m.vertices.size();
  std::array<std::vector<double>, 3> at;            // approximate coordinates per vertex
  std::array<std::vector<std::uint32_t>, 3> sorted; // vertices sorted along each axis
  std::array<std::vector<double>, 3> sorted_at;     // their coordinates, in that order
  for (std::size_t a = 0; a < 3; ++a) {
    at[a].resize(nv);
    for (std::size_t v = 0; v < nv; ++v) at[a][v] = geometry::to_double(m.vertices[v][a]);
    sorted[a].resize(nv);
    for (std::uint32_t v = 0; v < nv; ++v) sorted[a][v] = v;
    std::sort(sorted[a].begin(), sorted[a].end(),
              [&](std::uint32_t x, std::uint32_t y) { return at[a][x] < at[a][y]; });
    sorted_at[a].resize(nv);
    for (std::size_t v = 0; v < nv; ++v) sorted_at[a][v] = at[a][sorted[a][v]];
  }
  std::vector<std::pair<rational, std::uint32_t>> found;
  for (auto& f : m.faces) {
    std::vector<std::uint32_t> g;
    g.reserve(f.size());
    for (std::size_t q = 0; q < f.size(); ++q) {
      std::uint32_t u = f[q], v = f[(q + 1) % f.size()];
      g.push_back(u);
      std::array<double, 3> lo, hi;
      std::size_t best = 0, first = 0, last = 0;
      for (std::size_t a = 0; a < 3; ++a) {
        lo[a] = std::min(at[a][u], at[a][v]), hi[a] = std::max(at[a][u], at[a][v]);
        auto b = std::lower_bound(sorted_at[a].begin(), sorted_at[a].end(), lo[a]) - sorted_at[a].begin();
        auto e = std::upper_bound(sorted_at[a].begin(), sorted_at[a].end(), hi[a]) - sorted_at[a].begin();
        if (a == 0 || static_cast<std::size_t>(e - b) < last - first)
          best = a, first = static_cast<std::size_t>(b), last = static_cast<std::size_t>(e);
      }
      found.clear();
      vec3 d = minus(m.vertices[v], m.vertices[u]);
      for (std::size_t c = first; c < last; ++c) {
        std::uint32_t w = sorted[best][c];
        if (w == u || w == v) continue;
        bool box = true;
        for (std::size_t a = 0; a < 3 && box; ++a) box = lo[a] <= at[a][w] && at[a][w] <= hi[a];
        if (box && strictly_inside(m.vertices[u], m.vertices[v], m.vertices[w]))
          found.emplace_back(dot(d, minus(m.vertices[w], m.vertices[u])), w);
      }
      std::sort(found.begin(), found.end());
      for (auto const& [t, w] : found) g.push_back(w);
    }
    f = std::move(g);
  }
}

/// Cuts a simple polygon (counter-clockwise, distinct vertices, straight
/// vertices allowed) into triangles by ear clipping, using every vertex and
/// making no flat triangle: an ear is a strictly convex corner whose closed
/// triangle holds no other vertex that is not strictly convex (only such a
/// vertex can be in it, and one on the diagonal would leave a T-junction).
inline std::vector<std::array<std::uint32_t, 3>> ear_clip(std::vector<point2> const& p,
                                                          std::vector<std::uint32_t> const& ids) {
  using geometry::sign;
  std::size_t n = p.size();
  std::vector<std::array<std::uint32_t, 3>> out;
  if (n < 3) return out;
  std::vector<std::size_t> prev(n), next(n);
  for (std::size_t i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
  std::vector<sign> corner(n);
  auto update = [&](std::size_t i) { corner[i] = geometry::e2::orientation(p[prev[i]], p[i], p[next[i]]); };
  for (std::size_t i = 0; i < n; ++i) update(i);
  auto in_closed = [&](point2 const& a, point2 const& b, point2 const& c, point2 const& x) {
    return geometry::e2::orientation(a, b, x) != sign::negative &&
           geometry::e2::orientation(b, c, x) != sign::negative && geometry::e2::orientation(c, a, x) != sign::negative;
  };
  auto is_ear = [&](std::size_t i) {
    if (corner[i] != sign::positive) return false;
    std::size_t a = prev[i], c = next[i];
    for (std::size_t j = next[c]; j != a; j = next[j])
      if (corner[j] != sign::positive && in_closed(p[a], p[i], p[c], p[j])) return false;
    return true;
  };
  auto clip = [&](std::size_t i) {
    std::size_t a = prev[i], c = next[i];
    if (corner[i] != sign::zero) out.push_back({ids[a], ids[i], ids[c]});
    next[a] = c, prev[c] = a;
    update(a), update(c);
  };
  std::size_t remaining = n, i = 0, misses = 0;
  while (remaining > 3) {
    if (is_ear(i)) {
      std::size_t a = prev[i];
      clip(i);
      --remaining, misses = 0, i = a;
      continue;
    }
    i = next[i];
    if (++misses <= remaining) continue;
    // No ear in a whole turn: the polygon is not simple.  Clip a convex corner anyway, so that this ends.
    std::size_t j = i;
    for (std::size_t s = 0; s < remaining && corner[j] != sign::positive; ++s) j = next[j];
    std::size_t a = prev[j];
    clip(j);
    --remaining, misses = 0, i = a;
  }
  if (corner[i] != sign::zero) out.push_back({ids[prev[i]], ids[i], ids[next[i]]});
  return out;
}

// ---------------------------------------------------------------- faces on integer vertices

using hvec4 = geometry::hvec<rational, 4>;
using hvec3 = geometry::hvec<rational, 3>;

using geometry::hvec_hash;
using welder = geometry::welder<4>;

/// A line of a face's plane, as the pieces' bounds give it: a bounding plane
/// through it and a direction along it.
struct line3 {
  hvec4 plane; ///< a plane meeting the face's plane in this line
  hvec3 along; ///< a direction of the line (the cross product of the two planes' normals)
};

/// Whether `a` comes before `b` along `d`: the sign of d·a/w_a − d·b/w_b (w > 0).
inline bool before(hvec3 const& d, hvec4 const& a, hvec4 const& b) {
  return geometry::filtered_sign(
             [](auto const& D, auto const& A, auto const& B) {
               return (D[0] * A[0] + D[1] * A[1] + D[2] * A[2]) * B[3] - (D[0] * B[0] + D[1] * B[1] + D[2] * B[2]) * A[3];
             },
             d, a, b) == geometry::sign::negative;
}

/// The faces of one oriented plane, from its pieces' integer vertices,
/// without constructing a coordinate: edges are grouped by line (equal
/// restricted bounds), cancelled along each line by comparing the vertices'
/// positions exactly, and traced into a loop.  Appends the loop's vertices
/// to `face` and returns true when the plane's region is one polygon without
/// holes whose boundary neither touches itself nor runs twice along an edge
/// (the common case); returns false, having appended nothing, in every
/// other case, which the rational path (`cancel`, `assemble`,
/// `without_holes`) then handles.  Throws `std::invalid_argument` for an
/// unbounded piece.
inline bool single_face(std::vector<piece3> const& pieces, std::vector<hvec4>& face) {
  using geometry::sign;
  if (pieces.empty()) return false;
  std::size_t axis = pieces.front().axis;
  for (auto const& p : pieces)
    if (p.axis != axis) return false;
  auto const& support = pieces.front().support.n;

  // Lines by their restricted line with its first non-zero coefficient positive: equal keys, equal lines.
  std::vector<line3> lines;
  std::unordered_map<hvec3, std::uint32_t, hvec_hash> line_of;
  welder vertex_id;
  auto const& vertex = vertex_id.vertex;
  struct event {
    std::uint32_t vertex;
    int delta;
  };
  std::vector<std::vector<event>> events;
  for (auto const& p : pieces) {
    auto hv = geometry::e3::homogeneous_vertices(p);
    if (hv.empty()) throw std::invalid_argument("boolean::to_mesh: the solid is unbounded");
    for (auto const& x : hv)
      if (x.sign_at(3) != sign::positive) throw std::invalid_argument("boolean::to_mesh: the solid is unbounded");
    std::size_t k = hv.size();
    for (std::size_t i = 0; i < k; ++i) {
      // Vertex i − 1 ends bound i − 1 and starts bound i; the edge to vertex i runs along bound i.
      hvec4 const &a = hv[(i + k - 1) % k], &b = hv[i];
      if (a == b) continue;
      auto const& bound = p.bounds[i];
      hvec3 key = bound.line();
      std::size_t first = 0;
      while (first < 3 && key.sign_at(first) == sign::zero) ++first;
      if (first == 3) return false;
      if (key.sign_at(first) == sign::negative) key = -key;
      auto [it, added] = line_of.try_emplace(key, static_cast<std::uint32_t>(lines.size()));
      if (added) {
        auto along = geometry::construct<3>(
            [](auto const& P, auto const& B) {
              using T = std::remove_cvref_t<decltype(P[0])>;
              return std::array<T, 3>{T(P[1] * B[2] - P[2] * B[1]), T(P[2] * B[0] - P[0] * B[2]),
                                      T(P[0] * B[1] - P[1] * B[0])};
            },
            support, bound.original.n);
        lines.push_back({bound.original.n, std::move(along)});
        events.emplace_back();
      }
      // +1 from `a` to `b`: positive where edges run along `along`, negative where they run against it.
      auto& ev = events[it->second];
      ev.push_back({vertex_id(a), 1});
      ev.push_back({vertex_id(b), -1});
    }
  }

  struct edge {
    std::uint32_t from, to, line;
  };
  std::vector<edge> edges;
  for (std::uint32_t l = 0; l < lines.size(); ++l) {
    auto& ev = events[l];
    auto const& d = lines[l].along;
    std::sort(ev.begin(), ev.end(), [&](event const& a, event const& b) { return before(d, vertex[a.vertex], vertex[b.vertex]); });
    int net = 0;
    std::uint32_t start = 0;
    for (std::size_t a = 0; a < ev.size();) {
      std::size_t b = a;
      int next = net;
      while (b < ev.size() && !before(d, vertex[ev[a].vertex], vertex[ev[b].vertex])) next += ev[b++].delta;
      if (next != net) {
        if (std::abs(net) > 1 || std::abs(next) > 1) return false; // an edge run twice: not a manifold face
        if (net > 0) edges.push_back({start, ev[a].vertex, l});
        if (net < 0) edges.push_back({ev[a].vertex, start, l});
        if (next != 0) start = ev[a].vertex;
        net = next;
      }
      a = b;
    }
  }
  if (edges.size() < 3) return false;

  // One loop: every vertex left once and reached once, all edges in one walk.
  constexpr std::uint32_t none = ~std::uint32_t{0};
  std::vector<std::uint32_t> leaving(vertex.size(), none), arriving(vertex.size(), 0);
  for (std::uint32_t e = 0; e < edges.size(); ++e) {
    if (leaving[edges[e].from] != none) return false;
    leaving[edges[e].from] = e;
    ++arriving[edges[e].to];
  }
  std::vector<std::uint32_t> loop;
  loop.reserve(edges.size());
  for (std::uint32_t e = 0;;) {
    loop.push_back(e);
    if (arriving[edges[e].to] != 1 || leaving[edges[e].to] == none) return false;
    e = leaving[edges[e].to];
    if (e == 0) break; // each vertex reached once: the walk is a cycle through edge 0
  }
  if (loop.size() != edges.size()) return false; // several loops: holes or several polygons

  // A vertex inside another edge would make the boundary touch itself.
  constexpr std::size_t quadratic_limit = 512;
  if (edges.size() > quadratic_limit) return false;
  for (auto const& e : edges) {
    auto const& l = lines[e.line];
    hvec4 const &a = vertex[e.from], &b = vertex[e.to];
    bool forward = before(l.along, a, b);
    for (auto const& f : edges) {
      hvec4 const& p = vertex[f.from];
      if (f.from == e.from || f.from == e.to) continue;
      if (geometry::dot_sign(l.plane, p) != sign::zero) continue;
      if (forward ? before(l.along, a, p) && before(l.along, p, b) : before(l.along, b, p) && before(l.along, p, a))
        return false;
    }
  }

  // The sweep joined each line's runs, so consecutive edges lie on different lines: no vertex is straight.
  for (auto e : loop) face.push_back(vertex[edges[e].from]);
  return true;
}

} // namespace detail::polyhedra

/// The point-set tree (`true` inside) of a solid bounded by `pieces`, each
/// with the solid on its negative side: built as `from_scene` builds it, in
/// one pass (Thibault and Naylor), its cuts chosen by `bsp::balanced` among
/// the pieces' planes and axis-parallel planes through the median vertex.
inline solid_tree solid_tree_of(std::vector<geometry::e3::sub_hyperplane<rational>> pieces) {
  return bsp::build_point_set<space_kernel>(std::move(pieces), true, false, bsp::balanced(geometry::e3::axis_median_cut<rational>{}));
}

/// The solid bounded by a closed polygon mesh, checked on the way.
///
/// 1. Vertices with exactly equal coordinates are taken as one; every edge
///    must then be run by the faces equally often in both directions, else
///    `std::invalid_argument`: "open mesh: edge between vertices 3 and 7 has
///    1 face (face 12)" or "inconsistently oriented faces at edge between
///    vertices …" (vertices and faces numbered from 0 in file order, a merged
///    vertex by its first occurrence).
/// 2. Faces become convex polygons (`geometry::io::convex_polygons`); their
///    signed enclosed volume, exact by the divergence theorem, must not be 0
///    (`std::invalid_argument`: "the mesh encloses no volume").  When it is
///    negative the faces point inwards: every face is reversed and `flipped`
///    is set.
/// 3. The tree is built with the solid behind every face, balancing large
///    meshes with free axis-aligned cuts (`bsp::balanced`,
///    `geometry::e3::axis_median_cut`).
/// 4. The exact volume of the tree's inside cells must equal the signed
///    enclosed volume; they differ when faces pass through one another:
///    `std::invalid_argument` "self-intersecting mesh (the faces' enclosed
///    volume X differs from the volume of the solid they bound Y), or a
///    cavity shares part of a face with the outer shell" (the second case
///    is not told apart from two solids meeting face to face yet).
///
/// `std::out_of_range` for a face that refers to a missing vertex (only a
/// scene built by hand can have one).
inline solid from_scene(geometry::io::scene const& s) {
  namespace d = detail::polyhedra;
  d::check_closed(s);
  auto prepared = geometry::io::convex_polygons(s);
  rational six(0);
  for (auto const& p : prepared.polygons) six += d::six_volume(p.vertices);
  if (six == 0) throw std::invalid_argument("the mesh encloses no volume");
  solid out;
  out.flipped = six < 0;
  out.degenerate_faces = prepared.degenerate_faces;
  out.triangulated_faces = prepared.triangulated_faces;
  std::vector<d::piece3> pieces;
  pieces.reserve(prepared.polygons.size());
  for (auto& p : prepared.polygons) {
    if (out.flipped) std::reverse(p.vertices.begin(), p.vertices.end());
    pieces.push_back(geometry::e3::convex_polygon(p.vertices));
  }
  rational enclosed = abs(six) / 6;
  out.boundary = pieces;
  out.tree = solid_tree_of(std::move(pieces));
  auto v = bsp::measure(out.tree, true);
  if (!v || *v != enclosed)
    throw std::invalid_argument(geometry::io::detail::cat("self-intersecting mesh (the faces' enclosed volume ",
                                                          d::text(enclosed),
                                                          " differs from the volume of the solid they bound",
                                                          v ? " " : ", which is unbounded", v ? d::text(*v) : "",
                                                          "), or a cavity shares part of a face with the outer shell"));
  out.volume = std::move(*v);
  return out;
}

/// The Boolean combination `a op b` of two solids, by merging their trees;
/// its volume is exact.
inline solid apply(csg_op op, solid const& a, solid const& b) {
  solid out;
  switch (op) {
  case csg_op::union_:
    out.tree = bsp::set_union(a.tree, b.tree);
    break;
  case csg_op::intersection:
    out.tree = bsp::set_intersection(a.tree, b.tree);
    break;
  case csg_op::difference:
    out.tree = bsp::set_difference(a.tree, b.tree);
    break;
  }
  auto v = bsp::measure(out.tree, true);
  if (!v) throw std::invalid_argument("boolean::apply: the result is unbounded");
  out.volume = std::move(*v);
  out.boundary = bsp::merged_boundary(a.tree, a.boundary, b.tree, b.boundary, detail::polyhedra::label_op(op), true);
  return out;
}


namespace detail::polyhedra {
/// `to_mesh`, with the integer path for single faces (`single_face`) on or
/// off (off: every plane on rational points, for comparison); counts the
/// planes the integer path made into `integer_planes` when given.
inline mesh build_mesh(std::vector<piece3> boundary, bool integer_faces, std::size_t* integer_planes = nullptr) {
  namespace d = detail::polyhedra;
  // Pieces grouped by oriented plane (equal primitive integer coefficients), in order of first appearance.
  std::vector<std::vector<d::piece3>> planes;
  {
    std::unordered_map<d::hvec4, std::size_t, d::hvec_hash> group;
    for (auto& p : boundary) {
      auto [it, added] = group.try_emplace(p.support.n, planes.size());
      if (added) planes.emplace_back();
      planes[it->second].push_back(std::move(p));
    }
  }
  // Every vertex once, by its primitive integer coordinates.
  mesh m;
  d::welder weld;
  auto add_face = [&](std::vector<d::hvec4> const& f) {
    std::vector<std::uint32_t> g;
    g.reserve(f.size());
    for (auto const& v : f) g.push_back(weld(v));
    m.faces.push_back(std::move(g));
  };
  std::vector<d::hvec4> face;
  std::vector<directed_segment> edges;
  std::vector<ring> rings;
  for (auto const& pieces : planes) {
    face.clear();
    if (integer_faces && d::single_face(pieces, face)) {
      add_face(face);
      if (integer_planes) ++*integer_planes;
      continue;
    }
    // The general case, on rational points in the plane's 2D frame.
    d::frame fr(d::canonical(pieces.front()));
    edges.clear();
    for (auto const& p : pieces) {
      auto v = geometry::e3::vertices(p);
      if (!v) throw std::invalid_argument("boolean::to_mesh: the solid is unbounded");
      std::vector<point2> q;
      for (auto const& x : *v) {
        auto y = fr.to2d(x);
        if (q.empty() || !(q.back() == y)) q.push_back(std::move(y));
      }
      while (q.size() >= 2 && q.back() == q.front()) q.pop_back();
      if (q.size() < 3) continue;
      for (std::size_t i = 0; i < q.size(); ++i) edges.push_back({q[i], q[(i + 1) % q.size()]});
    }
    rings.clear();
    auto boundary_edges = d::cancel(edges);
    d::split_at_endpoints(boundary_edges);
    for (auto& poly : assemble(boundary_edges)) d::without_holes(std::move(poly), rings);
    for (auto const& r : rings) {
      face.clear();
      face.reserve(r.size());
      for (auto const& q : r) {
        auto x = fr.lift(q);
        face.emplace_back(std::array<rational, 4>{x.x(), x.y(), x.z(), rational(1)});
      }
      add_face(face);
    }
  }
  m.vertices.reserve(weld.vertex.size());
  for (auto const& v : weld.vertex) {
    auto const& z = v.integers(); // w > 0: one canonical fraction a coordinate
    m.vertices.emplace_back(rational(z[0], z[3]), rational(z[1], z[3]), rational(z[2], z[3]));
  }
  d::split_edges(m);
  return m;
}
} // namespace detail::polyhedra

/// A solid's boundary pieces (the solid on their negative side, as
/// `bsp::oriented_boundary` gives them) as a polygon mesh, exact.
///
/// The pieces are grouped by oriented plane; in each plane their directed
/// edges cancel where opposite edges overlap along a line, and what is left
/// is assembled into polygons: the plane's faces merged as far as possible.
/// Where a plane's region is one polygon without holes whose boundary does
/// not touch itself (the common case), this is done on the pieces' integer
/// homogeneous vertices and bounding lines alone (`single_face`): no
/// coordinate is constructed until the mesh's vertices are written, once
/// each.  Otherwise the plane's edges are projected to 2D rational points
/// and assembled by `boolean::assemble`, and a polygon with holes is cut
/// along the lines of its holes' edges into simple polygons.  Vertices are
/// welded (equal points, one index), and every vertex lying inside a face
/// edge is inserted into it, so no T-junction is left: for a bounded solid
/// whose boundary is a manifold the mesh is `closed`.  Where the solid is
/// not a manifold (two boxes sharing only an edge) the edge is used by four
/// faces: `inspect_edges` counts it as non-manifold.  Faces may be
/// non-convex; adjacent faces never lie in the same oriented plane unless a
/// hole forced the cut.  Throws `std::invalid_argument` for an unbounded
/// solid.
inline mesh to_mesh(std::vector<geometry::e3::sub_hyperplane<rational>> boundary) {
  return detail::polyhedra::build_mesh(std::move(boundary), true);
}

/// The mesh of a solid's tree (see `to_mesh` of boundary pieces).
inline mesh to_mesh(solid_tree const& t) { return to_mesh(bsp::oriented_boundary(t)); }

/// The boundary of a solid as a polygon mesh (see `to_mesh(solid_tree const&)`).
inline mesh to_mesh(solid const& s) { return to_mesh(s.tree); }

/// The mesh of `op(a, b)` without building the merged tree: the operands'
/// boundary pieces are classified against both trees
/// (`bsp::merged_boundary`) and merged into faces as `to_mesh` does.  The
/// same mesh as `to_mesh(apply(op, a, b))`, faster; its exact volume is
/// `volume(mesh)`.
inline mesh combine(csg_op op, solid const& a, solid const& b) {
  return to_mesh(bsp::merged_boundary(a.tree, a.boundary, b.tree, b.boundary, detail::polyhedra::label_op(op), true));
}

/// How the faces of `m` use its edges (see `edge_report`).
inline edge_report inspect_edges(mesh const& m) {
  std::vector<std::pair<std::uint64_t, bool>> uses; // (lo, hi) packed, runs from lo to hi
  for (auto const& f : m.faces)
    for (std::size_t i = 0; i < f.size(); ++i) {
      std::uint32_t a = f[i], b = f[(i + 1) % f.size()];
      if (a == b) continue;
      std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
      uses.emplace_back(lo << 32 | hi, a < b);
    }
  std::sort(uses.begin(), uses.end());
  edge_report r;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i, fwd = 0;
    while (j < uses.size() && uses[j].first == uses[i].first) fwd += uses[j++].second;
    ++r.edges;
    if (2 * fwd != j - i)
      ++r.unmatched;
    else if (j - i > 2)
      ++r.non_manifold;
    i = j;
  }
  return r;
}

/// Whether every directed edge of `m` is run exactly once the other way: the
/// mesh is closed, consistently oriented and manifold at its edges.
inline bool closed(mesh const& m) {
  auto r = inspect_edges(m);
  return r.unmatched == 0 && r.non_manifold == 0;
}

/// The signed volume enclosed by the faces of `m` (divergence theorem),
/// exact; the volume of the solid when `m` is its boundary with outward faces.
inline rational volume(mesh const& m) {
  rational six(0);
  std::vector<point3> v;
  for (auto const& f : m.faces) {
    v.clear();
    for (auto i : f) v.push_back(m.vertices[i]);
    six += detail::polyhedra::six_volume(v);
  }
  return six / 6;
}

/// The faces of `m` cut into triangles (counter-clockwise seen from outside,
/// like the faces) by ear clipping in the plane of each face: every vertex of
/// a face is kept, so a closed mesh gives a closed triangle mesh, and no
/// triangle is flat.  Faces must be planar simple polygons, as `to_mesh`
/// makes them.
inline std::vector<std::array<std::uint32_t, 3>> triangles(mesh const& m) {
  std::vector<std::array<std::uint32_t, 3>> out;
  std::vector<point2> q;
  for (auto const& f : m.faces) {
    if (f.size() == 3) {
      out.push_back({f[0], f[1], f[2]});
      continue;
    }
    // Newell's normal, exact: the face's plane orientation, whatever its shape.
    std::array<rational, 4> n{rational(0), rational(0), rational(0), rational(0)};
    for (std::size_t i = 0; i < f.size(); ++i) {
      auto const &p = m.vertices[f[i]], &r = m.vertices[f[(i + 1) % f.size()]];
      n[0] += p.y() * r.z() - p.z() * r.y();
      n[1] += p.z() * r.x() - p.x() * r.z();
      n[2] += p.x() * r.y() - p.y() * r.x();
    }
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) continue;
    detail::polyhedra::frame fr(n);
    q.clear();
    for (auto i : f) q.push_back(fr.to2d(m.vertices[i]));
    auto t = detail::polyhedra::ear_clip(q, f);
    out.insert(out.end(), t.begin(), t.end());
  }
  return out;
}

/// The mesh as a scene (no colours, no line numbers), for instance to read
/// a result back with `from_scene`.
inline geometry::io::scene to_scene(mesh const& m) {
  geometry::io::scene s;
  s.vertices = m.vertices;
  for (auto const& f : m.faces) s.faces.push_back({f, std::nullopt, 0});
  return s;
}

/// The mesh in OFF: coordinates as the shortest decimals that read back as
/// the same doubles.
inline std::string to_off(mesh const& m) {
  namespace d = detail::polyhedra;
  std::string s = "OFF\n";
  s.append(std::to_string(m.vertices.size())).append(" ").append(std::to_string(m.faces.size())).append(" 0\n");
  for (auto const& p : m.vertices) d::append_point(s, p).append("\n");
  for (auto const& f : m.faces) {
    s.append(std::to_string(f.size()));
    for (auto i : f) s.append(" ").append(std::to_string(i));
    s.append("\n");
  }
  return s;
}

/// The mesh in Wavefront OBJ (`v` and `f` lines, 1-based indices).
inline std::string to_obj(mesh const& m) {
  namespace d = detail::polyhedra;
  std::string s;
  for (auto const& p : m.vertices) d::append_point(s.append("v "), p).append("\n");
  for (auto const& f : m.faces) {
    s.append("f");
    for (auto i : f) s.append(" ").append(std::to_string(i + 1));
    s.append("\n");
  }
  return s;
}

/// The mesh in ASCII STL: the faces cut into `triangles`, each with its unit
/// normal (from the exact cross product, rounded).
inline std::string to_stl(mesh const& m) {
  namespace d = detail::polyhedra;
  std::string s = "solid genbsp\n";
  for (auto const& t : triangles(m)) {
    auto const &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    auto n = d::cross(d::minus(b, a), d::minus(c, a));
    double x = geometry::to_double(n[0]), y = geometry::to_double(n[1]), z = geometry::to_double(n[2]);
    double len = std::sqrt(x * x + y * y + z * z);
    if (len > 0 && std::isfinite(len)) x /= len, y /= len, z /= len;
    s.append("facet normal ").append(d::shortest(x)).append(" ").append(d::shortest(y)).append(" ");
    s.append(d::shortest(z)).append("\n  outer loop\n");
    for (auto const* p : {&a, &b, &c}) d::append_point(s.append("    vertex "), *p).append("\n");
    s.append("  endloop\nendfacet\n");
  }
  s.append("endsolid genbsp\n");
  return s;
}

} // namespace boolean
