/// @file
/// Polygons with holes in the plane, exact, and their assembly from the
/// directed boundary edges of a region: the output side of every Boolean
/// operation in the plane, and of coplanar faces merged in space.
///
/// Output rings follow the simple-features rules: closed (the first vertex is
/// not repeated here; writers repeat it), outer rings counter-clockwise, holes
/// clockwise and nested in their outer ring, no repeated vertices, no spikes,
/// no vertex on a straight line between its neighbours.  Rings may touch one
/// another at isolated vertices (two squares sharing a corner, a hole touching
/// its outer ring), as OGC allows, but never cross.
#pragma once

#include <geometry/e2.hpp>
#include <geometry/io/planar.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace boolean {

using geometry::rational;
/// A point of the plane, exact.
using point2 = geometry::io::point2;
/// A closed ring: vertices in order, the last joined to the first (not repeated).
using ring = geometry::io::ring;
/// A polygon with holes: an outer ring (counter-clockwise) and holes (clockwise).
using polygon = geometry::io::polygon_with_holes;
/// A set of polygons with pairwise disjoint interiors.
using multipolygon = geometry::io::multipolygon;

/// A directed boundary edge with the region on its left.
struct directed_segment {
  point2 from, to;
};

/// Twice the signed area of `r` (positive when counter-clockwise), exact.
inline rational twice_signed_area(ring const& r) {
  rational s(0);
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    auto const &a = r[i], &b = r[(i + 1) % n];
    s += a.x() * b.y() - a.y() * b.x();
  }
  return s;
}

/// The signed area of `r` (positive when counter-clockwise), exact.
inline rational signed_area(ring const& r) { return twice_signed_area(r) / 2; }

/// The area of a multipolygon, exact (its rings are assumed valid).
inline rational area(multipolygon const& m) {
  rational s(0);
  for (auto const& p : m) {
    s += signed_area(p.outer);
    for (auto const& h : p.holes) s += signed_area(h);
  }
  return s;
}

/// Where a point lies with respect to a closed ring.
enum class location { outside, boundary, inside };

/// Whether `p` lies inside, on or outside the ring `r` (non-zero winding; for
/// a simple ring, inside its enclosed area whatever its orientation).  Exact.
inline location locate(ring const& r, point2 const& p) {
  int w = 0;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    auto const &a = r[i], &b = r[(i + 1) % n];
    auto turn = geometry::e2::orientation(a, b, p);
    if (turn == geometry::sign::zero && std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
        std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y()))
      return location::boundary;
    if (a.y() <= p.y()) {
      if (b.y() > p.y() && turn == geometry::sign::positive) ++w;
    } else if (b.y() <= p.y() && turn == geometry::sign::negative) {
      --w;
    }
  }
  return w != 0 ? location::inside : location::outside;
}

namespace detail {

struct point_less {
  bool operator()(point2 const& a, point2 const& b) const {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  }
};

struct vec2 {
  rational x, y;
};
inline vec2 edge_vector(directed_segment const& e) { return {e.to.x() - e.from.x(), e.to.y() - e.from.y()}; }
inline geometry::sign cross(vec2 const& a, vec2 const& b) { return geometry::sign_of(rational(a.x * b.y - a.y * b.x)); }
inline geometry::sign dot(vec2 const& a, vec2 const& b) { return geometry::sign_of(rational(a.x * b.x + a.y * b.y)); }

/// Clockwise angle from `r` to `d` in (0, 2π], as an order: 0 for (0, π),
/// 1 for π, 2 for (π, 2π), 3 for 2π (the direction of `r` itself).
inline int half(vec2 const& r, vec2 const& d) {
  auto c = cross(r, d);
  if (c == geometry::sign::negative) return 0;
  if (c == geometry::sign::positive) return 2;
  return dot(r, d) == geometry::sign::negative ? 1 : 3;
}

/// Whether `a` comes before `b` turning clockwise from `r`.
inline bool clockwise_before(vec2 const& r, vec2 const& a, vec2 const& b) {
  int ha = half(r, a), hb = half(r, b);
  if (ha != hb) return ha < hb;
  return cross(a, b) == geometry::sign::negative;
}

/// Whether the ring goes straight on at `b` (from `a`, on to `c`).
inline bool straight(point2 const& a, point2 const& b, point2 const& c) {
  vec2 u{b.x() - a.x(), b.y() - a.y()}, v{c.x() - b.x(), c.y() - b.y()};
  return cross(u, v) == geometry::sign::zero && dot(u, v) == geometry::sign::positive;
}

/// Removes vertices where the ring goes straight on, in one pass (a stack),
/// then across the seam between the last vertex and the first.
inline void drop_straight(ring& r) {
  ring out;
  out.reserve(r.size());
  for (auto& v : r) {
    while (out.size() >= 2 && straight(out[out.size() - 2], out.back(), v)) out.pop_back();
    out.push_back(std::move(v));
  }
  std::size_t first = 0; // vertices dropped at the front
  for (bool changed = true; changed && out.size() - first >= 3;) {
    changed = false;
    std::size_t n = out.size();
    if (straight(out[n - 2], out[n - 1], out[first])) {
      out.pop_back();
      changed = true;
    } else if (straight(out[n - 1], out[first], out[first + 1])) {
      ++first;
      changed = true;
    }
  }
  r.assign(std::make_move_iterator(out.begin() + static_cast<std::ptrdiff_t>(first)), std::make_move_iterator(out.end()));
}

/// A point strictly inside the ring `inner`'s closure or on it, to decide
/// whether `inner` lies within `outer`: a vertex of `inner` off `outer`, else
/// the midpoint of an edge of `inner` off `outer`.  Rings that do not cross
/// share at most isolated vertices, so one of these exists.
inline location ring_in_ring(ring const& inner, ring const& outer) {
  for (auto const& p : inner)
    if (auto l = locate(outer, p); l != location::boundary) return l;
  for (std::size_t i = 0, n = inner.size(); i < n; ++i) {
    auto const &a = inner[i], &b = inner[(i + 1) % n];
    point2 m(rational((a.x() + b.x()) / 2), rational((a.y() + b.y()) / 2));
    if (auto l = locate(outer, m); l != location::boundary) return l;
  }
  return location::boundary;
}

/// Closed walks over the directed edges `from[i] → to[i]`: at a vertex with
/// several edges leaving, the walk takes the one that `prefer(arriving, a, b)`
/// puts first.  A walk that passes twice through a vertex is cut there into
/// loops that pass once each (a hole touching its outer ring is walked as
/// one ring through the touching vertex; the simple-features rules want
/// two).  Returns each loop as its edges in order.  Throws
/// `std::invalid_argument` when the edges do not close up.
template <class Key, class Less, class Prefer>
std::vector<std::vector<std::size_t>> trace_loops(std::vector<Key> const& from, std::vector<Key> const& to, Prefer prefer) {
  std::map<Key, std::vector<std::size_t>, Less> leaving;
  for (std::size_t i = 0; i < from.size(); ++i) leaving[from[i]].push_back(i);
  std::vector<bool> used(from.size(), false);
  std::vector<std::vector<std::size_t>> loops;
  for (std::size_t start = 0; start < from.size(); ++start) {
    if (used[start]) continue;
    std::vector<std::size_t> walk;
    std::size_t e = start;
    for (;;) {
      used[e] = true;
      walk.push_back(e);
      auto it = leaving.find(to[e]);
      if (it == leaving.end()) throw std::invalid_argument("boolean: the boundary does not close");
      std::size_t best = from.size();
      for (auto c : it->second) {
        if (used[c] && c != start) continue;
        if (best == from.size() || prefer(e, c, best)) best = c;
      }
      if (best == from.size()) throw std::invalid_argument("boolean: the boundary does not close");
      if (best == start) break;
      e = best;
    }
    // Cut at repeated vertices: a stack of edges and where each vertex left it.
    std::map<Key, std::size_t, Less> at;
    std::vector<std::size_t> stack;
    for (auto f : walk) {
      auto pos = at.find(from[f]);
      if (pos != at.end()) {
        std::size_t k = pos->second;
        for (std::size_t j = k; j < stack.size(); ++j) at.erase(from[stack[j]]);
        loops.emplace_back(stack.begin() + static_cast<std::ptrdiff_t>(k), stack.end());
        stack.resize(k);
      }
      at.emplace(from[f], stack.size());
      stack.push_back(f);
    }
    if (!stack.empty()) loops.push_back(std::move(stack));
  }
  return loops;
}

/// The bounding box of a ring in doubles.  Rounding to nearest is monotone,
/// so exact containment of boxes implies containment of the rounded boxes:
/// a conservative filter.
struct box {
  double x0, y0, x1, y1;
  bool contains(box const& b) const { return x0 <= b.x0 && y0 <= b.y0 && b.x1 <= x1 && b.y1 <= y1; }
};
inline box bounds(ring const& r) {
  box b{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (auto const& p : r) {
    double x = p.x().convert_to<double>(), y = p.y().convert_to<double>();
    b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y), b.x1 = std::max(b.x1, x), b.y1 = std::max(b.y1, y);
  }
  return b;
}

} // namespace detail

/// Groups rings into polygons: counter-clockwise rings are outer rings, and
/// each clockwise ring becomes a hole of the smallest outer ring containing
/// it.  Rings must not cross (they may touch at vertices) and must bound one
/// region, as the rings of `assemble` do: then every hole lies in some outer
/// ring, so of the outer rings whose bounding box holds the hole's, the
/// largest needs no test, and a hole with one candidate (the common case)
/// costs no exact test at all.  Throws `std::invalid_argument` for a hole
/// that no outer ring's box holds.
inline multipolygon nest(std::vector<ring> rings) {
  struct shell {
    rational area;
    detail::box bounds;
    std::size_t index;
  };
  std::vector<shell> shells;
  std::vector<std::size_t> holes;
  multipolygon out;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    auto a = twice_signed_area(rings[i]);
    if (a > 0) {
      shells.push_back({a, detail::bounds(rings[i]), out.size()});
      out.push_back({std::move(rings[i]), {}});
    } else if (a < 0) {
      holes.push_back(i);
    }
  }
  std::sort(shells.begin(), shells.end(), [](shell const& a, shell const& b) { return a.area < b.area; });
  std::vector<std::size_t> candidates;
  for (auto i : holes) {
    auto b = detail::bounds(rings[i]);
    candidates.clear();
    for (std::size_t k = 0; k < shells.size(); ++k)
      if (shells[k].bounds.contains(b)) candidates.push_back(k);
    if (candidates.empty()) throw std::invalid_argument("boolean::nest: a hole lies in no outer ring");
    std::size_t chosen = candidates.back();
    for (std::size_t c = 0; c + 1 < candidates.size(); ++c)
      if (detail::ring_in_ring(rings[i], out[shells[candidates[c]].index].outer) == location::inside) {
        chosen = candidates[c];
        break;
      }
    out[shells[chosen].index].holes.push_back(std::move(rings[i]));
  }
  return out;
}

/// The polygons bounded by `edges`: the directed boundary edges of a bounded
/// regular region with the region on their left (at every vertex as many
/// edges leave as arrive).  At a vertex where the boundary touches itself a
/// ring turns as far left as it can and is then cut at the vertex, so rings
/// touch at vertices but never cross or pass twice through a point.
/// Collinear edges are joined.  Throws `std::invalid_argument` when the
/// edges do not close up.
inline multipolygon assemble(std::vector<directed_segment> const& edges) {
  std::vector<point2> from, to;
  for (auto const& e : edges) from.push_back(e.from), to.push_back(e.to);
  auto loops = detail::trace_loops<point2, detail::point_less>(from, to, [&](std::size_t in, std::size_t a, std::size_t b) {
    auto back = detail::edge_vector(edges[in]);
    back.x = -back.x;
    back.y = -back.y;
    return detail::clockwise_before(back, detail::edge_vector(edges[a]), detail::edge_vector(edges[b]));
  });
  std::vector<ring> rings;
  for (auto const& l : loops) {
    ring r;
    for (auto e : l) r.push_back(edges[e].from);
    detail::drop_straight(r);
    if (r.size() >= 3) rings.push_back(std::move(r));
  }
  return nest(std::move(rings));
}

} // namespace boolean
