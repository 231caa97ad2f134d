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

#include <algorithm>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace boolean {

using geometry::rational;
using point2 = geometry::e2::point<rational>;

/// A closed ring: vertices in order, the last joined to the first (not repeated).
using ring = std::vector<point2>;

/// A polygon with holes: an outer ring (counter-clockwise) and holes (clockwise).
struct polygon {
  ring outer;
  std::vector<ring> holes;
};

/// A set of polygons with pairwise disjoint interiors.
using multipolygon = std::vector<polygon>;

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
inline vec2 direction(directed_segment const& e) { return {e.to.x() - e.from.x(), e.to.y() - e.from.y()}; }
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

/// Removes vertices where the ring goes straight on.
inline void drop_straight(ring& r) {
  bool changed = true;
  while (changed && r.size() >= 3) {
    changed = false;
    for (std::size_t i = 0; i < r.size() && r.size() >= 3; ++i) {
      std::size_t n = r.size();
      auto const &a = r[(i + n - 1) % n], &b = r[i], &c = r[(i + 1) % n];
      vec2 u{b.x() - a.x(), b.y() - a.y()}, v{c.x() - b.x(), c.y() - b.y()};
      if (cross(u, v) == geometry::sign::zero && dot(u, v) == geometry::sign::positive) {
        r.erase(r.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        if (i > 0) --i;
      }
    }
  }
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

/// Cuts a ring that passes more than once through a vertex into loops that
/// pass once (a hole touching its outer ring is traced as one ring through
/// the touching vertex; the simple-features rules want two), drops straight
/// vertices and appends the loops of three or more vertices to `out`.
inline void split_loops(ring r, std::vector<ring>& out) {
  std::map<point2, std::size_t, point_less> at; // vertex → its place on the stack
  ring stack;
  auto flush = [&](ring loop) {
    drop_straight(loop);
    if (loop.size() >= 3) out.push_back(std::move(loop));
  };
  for (std::size_t i = 0; i <= r.size(); ++i) {
    point2 const& v = r[i % r.size()];
    auto it = at.find(v);
    if (it == at.end()) {
      if (i == r.size()) break;
      at.emplace(v, stack.size());
      stack.push_back(v);
      continue;
    }
    // A loop from the earlier visit of v to here.
    std::size_t k = it->second;
    ring loop(stack.begin() + static_cast<std::ptrdiff_t>(k), stack.end());
    for (std::size_t j = k + 1; j < stack.size(); ++j) at.erase(stack[j]);
    stack.resize(k + 1);
    flush(std::move(loop));
    if (i == r.size()) stack.clear();
  }
  if (!stack.empty()) flush(std::move(stack));
}

struct box {
  rational x0, y0, x1, y1;
  bool contains(box const& b) const { return x0 <= b.x0 && y0 <= b.y0 && b.x1 <= x1 && b.y1 <= y1; }
};
inline box bounds(ring const& r) {
  box b{r[0].x(), r[0].y(), r[0].x(), r[0].y()};
  for (auto const& p : r) {
    if (p.x() < b.x0) b.x0 = p.x();
    if (p.y() < b.y0) b.y0 = p.y();
    if (b.x1 < p.x()) b.x1 = p.x();
    if (b.y1 < p.y()) b.y1 = p.y();
  }
  return b;
}

} // namespace detail

/// Groups rings into polygons: counter-clockwise rings are outer rings, and
/// each clockwise ring becomes a hole of the smallest outer ring containing
/// it.  Rings must not cross (they may touch at vertices).  Throws
/// `std::invalid_argument` for a hole that no outer ring contains.
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
  for (auto i : holes) {
    auto b = detail::bounds(rings[i]);
    auto it = std::find_if(shells.begin(), shells.end(), [&](shell const& s) {
      return s.bounds.contains(b) && detail::ring_in_ring(rings[i], out[s.index].outer) == location::inside;
    });
    if (it == shells.end()) throw std::invalid_argument("boolean::nest: a hole lies in no outer ring");
    out[it->index].holes.push_back(std::move(rings[i]));
  }
  return out;
}

/// The polygons bounded by `edges`: the directed boundary edges of a bounded
/// regular region with the region on their left (at every vertex as many
/// edges leave as arrive).  At a vertex where the boundary touches itself the
/// ring turns as far left as it can, so rings touch at vertices but never
/// cross, and a region pinched at a vertex gives two rings.  Collinear edges
/// are joined.  Throws `std::invalid_argument` when the edges do not close up.
inline multipolygon assemble(std::vector<directed_segment> const& edges) {
  std::map<point2, std::vector<std::size_t>, detail::point_less> leaving;
  for (std::size_t i = 0; i < edges.size(); ++i) leaving[edges[i].from].push_back(i);
  std::vector<bool> used(edges.size(), false);
  std::vector<ring> rings;
  for (std::size_t start = 0; start < edges.size(); ++start) {
    if (used[start]) continue;
    ring r;
    std::size_t e = start;
    for (;;) {
      used[e] = true;
      r.push_back(edges[e].from);
      auto it = leaving.find(edges[e].to);
      if (it == leaving.end()) throw std::invalid_argument("boolean::assemble: the boundary does not close");
      auto back = detail::direction(edges[e]);
      back.x = -back.x;
      back.y = -back.y;
      std::size_t best = edges.size();
      for (auto c : it->second) {
        if (used[c] && c != start) continue;
        if (best == edges.size() ||
            detail::clockwise_before(back, detail::direction(edges[c]), detail::direction(edges[best])))
          best = c;
      }
      if (best == edges.size()) throw std::invalid_argument("boolean::assemble: the boundary does not close");
      if (best == start) break;
      e = best;
    }
    detail::split_loops(std::move(r), rings);
  }
  return nest(std::move(rings));
}

} // namespace boolean
