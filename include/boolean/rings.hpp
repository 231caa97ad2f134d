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

namespace detail {
/// The sum of `terms` (which it overwrites), added pairwise along a balanced
/// tree.  Fractions with unrelated denominators make ever longer partial
/// sums: added in order, n of them cost about n² times a term's length;
/// pairwise, about n log n.
inline rational balanced_sum(std::vector<rational>& terms) {
  std::size_t const n = terms.size();
  if (n == 0) return rational(0);
  for (std::size_t step = 1; step < n; step *= 2)
    for (std::size_t i = 0; i + step < n; i += 2 * step) terms[i] += terms[i + step];
  return terms[0];
}
} // namespace detail

/// Twice the signed area of `r` (positive when counter-clockwise), exact.
inline rational twice_signed_area(ring const& r) {
  // Terms between two vertices of integer coordinates below 2^40 (most input
  // vertices) are summed in 128 bits, at most 2^40 of them at a time; the
  // others in rationals.
  using geometry::detail::int128;
  auto small_integer = [](point2 const& p) { return geometry::detail::small_plane_point(p.homogeneous()); };
  std::vector<rational> fractions;
  int128 z = 0;
  std::size_t terms = 0;
  auto flush = [&] {
    if (z != 0) {
      geometry::integer w;
      geometry::detail::set_integer(w, z);
      fractions.emplace_back(w);
    }
    z = 0;
    terms = 0;
  };
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    auto const &a = r[i], &b = r[(i + 1) % n];
    if (small_integer(a) && small_integer(b)) {
      auto const &u = a.homogeneous().approx().v, &v = b.homogeneous().approx().v;
      z += static_cast<int128>(static_cast<std::int64_t>(u[0])) * static_cast<std::int64_t>(v[1]) -
           static_cast<int128>(static_cast<std::int64_t>(u[1])) * static_cast<std::int64_t>(v[0]);
      if (++terms == (std::size_t(1) << 40)) flush();
    } else {
      fractions.push_back(a.x() * b.y() - a.y() * b.x());
    }
  }
  flush();
  return detail::balanced_sum(fractions);
}

/// The signed area of `r` (positive when counter-clockwise), exact.
inline rational signed_area(ring const& r) { return twice_signed_area(r) / 2; }

/// The area of a multipolygon, exact (its rings are assumed valid).
inline rational area(multipolygon const& m) {
  std::vector<rational> rings;
  for (auto const& p : m) {
    rings.push_back(twice_signed_area(p.outer));
    for (auto const& h : p.holes) rings.push_back(twice_signed_area(h));
  }
  return detail::balanced_sum(rings) / 2;
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

/// Clockwise angle from a direction `r` to a direction `d` in (0, 2π], as
/// an order, from the signs of their cross and dot products: 0 for (0, π),
/// 1 for π, 2 for (π, 2π), 3 for 2π (the direction of `r` itself).
inline int half(geometry::sign cross_rd, geometry::sign dot_rd) {
  if (cross_rd == geometry::sign::negative) return 0;
  if (cross_rd == geometry::sign::positive) return 2;
  return dot_rd == geometry::sign::negative ? 1 : 3;
}

/// Whether `a` comes before `b` turning clockwise from `r`, for directions
/// of any representation with the signs of their `cross` and `dot` products.
template <class V, class Cross, class Dot>
bool clockwise_before(V const& r, V const& a, V const& b, Cross const& cross, Dot const& dot) {
  int ha = half(cross(r, a), dot(r, a)), hb = half(cross(r, b), dot(r, b));
  if (ha != hb) return ha < hb;
  return cross(a, b) == geometry::sign::negative;
}

/// The same for exact vectors.
inline bool clockwise_before(vec2 const& r, vec2 const& a, vec2 const& b) {
  return clockwise_before(r, a, b, [](vec2 const& u, vec2 const& v) { return cross(u, v); },
                          [](vec2 const& u, vec2 const& v) { return dot(u, v); });
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

/// Closed walks over the directed edges `from[i] → to[i]` between vertices
/// numbered below `vertices`: at a vertex with several edges leaving, the
/// walk takes the one that `prefer(arriving, a, b)` puts first.  A walk that
/// passes twice through a vertex is cut there into loops that pass once each
/// (a hole touching its outer ring is walked as one ring through the
/// touching vertex; the simple-features rules want two).  Returns each loop
/// as its edges in order.  Throws `std::invalid_argument` when the edges do
/// not close up.
template <class Prefer>
std::vector<std::vector<std::size_t>> trace_loops(std::size_t vertices, std::vector<std::uint32_t> const& from,
                                                  std::vector<std::uint32_t> const& to, Prefer prefer) {
  std::size_t m = from.size();
  // The edges leaving each vertex, packed: those of v are leaving[first[v] … first[v + 1]).
  std::vector<std::uint32_t> first(vertices + 1, 0), leaving(m);
  for (auto v : from) ++first[v + 1];
  for (std::size_t v = 0; v < vertices; ++v) first[v + 1] += first[v];
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::size_t i = 0; i < m; ++i) leaving[fill[from[i]]++] = static_cast<std::uint32_t>(i);
  }
  constexpr std::uint32_t none = ~std::uint32_t{0};
  std::vector<bool> used(m, false);
  std::vector<std::uint32_t> at(vertices, none); // where a vertex left the stack below
  std::vector<std::vector<std::size_t>> loops;
  std::vector<std::size_t> walk, stack;
  for (std::size_t start = 0; start < m; ++start) {
    if (used[start]) continue;
    walk.clear();
    std::size_t e = start;
    for (;;) {
      used[e] = true;
      walk.push_back(e);
      std::size_t best = m;
      for (auto k = first[to[e]]; k < first[to[e] + 1]; ++k) {
        std::size_t c = leaving[k];
        if (used[c] && c != start) continue;
        if (best == m || prefer(e, c, best)) best = c;
      }
      if (best == m) throw std::invalid_argument("boolean: the boundary does not close");
      if (best == start) break;
      e = best;
    }
    // Cut at repeated vertices: a stack of edges and where each vertex left it.
    stack.clear();
    for (auto f : walk) {
      if (std::size_t k = at[from[f]]; k != none) {
        for (std::size_t j = k; j < stack.size(); ++j) at[from[stack[j]]] = none;
        loops.emplace_back(stack.begin() + static_cast<std::ptrdiff_t>(k), stack.end());
        stack.resize(k);
      }
      at[from[f]] = static_cast<std::uint32_t>(stack.size());
      stack.push_back(f);
    }
    for (auto f : stack) at[from[f]] = none;
    if (!stack.empty()) loops.push_back(stack);
  }
  return loops;
}

/// The same over vertices given by keys ordered by `Less`: equal keys, one vertex.
template <class Key, class Less, class Prefer>
std::vector<std::vector<std::size_t>> trace_loops(std::vector<Key> const& from, std::vector<Key> const& to, Prefer prefer) {
  std::map<Key, std::uint32_t, Less> number;
  auto id = [&](Key const& k) { return number.try_emplace(k, static_cast<std::uint32_t>(number.size())).first->second; };
  std::vector<std::uint32_t> f, t;
  f.reserve(from.size()), t.reserve(to.size());
  for (auto const& k : from) f.push_back(id(k));
  for (auto const& k : to) t.push_back(id(k));
  return trace_loops(number.size(), f, t, prefer);
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
    // Truncated towards zero, which keeps order: a ring's box of doubles
    // lies in another's when its exact box does.
    double x = mpq_get_d(p.x().backend().data()), y = mpq_get_d(p.y().backend().data());
    b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y), b.x1 = std::max(b.x1, x), b.y1 = std::max(b.y1, y);
  }
  return b;
}

/// The orientation of a ring that passes through no point twice (positive:
/// counter-clockwise): the turn at its lowest vertex of least x.  No
/// neighbour of that vertex is below it in that order, so the turn there is
/// strict unless the ring is flat (zero).  Filtered signs on the vertices'
/// homogeneous coordinates (x_a < x_b when X_a·W_b − X_b·W_a < 0, W > 0), so
/// that no vertex's rational coordinates are divided out, and one
/// orientation predicate, where the signed area costs a term per vertex.
inline geometry::sign orientation(ring const& r) {
  std::size_t const n = r.size();
  if (n < 3) return geometry::sign::zero;
  auto less = [](point2 const& a, point2 const& b) {
    auto const &p = a.homogeneous(), &q = b.homogeneous();
    auto x = geometry::filtered_sign([](auto const& u, auto const& v) { return u[0] * v[2] - v[0] * u[2]; }, p, q);
    if (x != geometry::sign::zero) return x == geometry::sign::negative;
    return geometry::filtered_sign([](auto const& u, auto const& v) { return u[1] * v[2] - v[1] * u[2]; }, p, q) ==
           geometry::sign::negative;
  };
  std::size_t m = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (less(r[i], r[m])) m = i;
  return geometry::e2::orientation(r[(m + n - 1) % n], r[m], r[(m + 1) % n]);
}

} // namespace detail

/// A polygon of `nest_indices`: the index of its outer ring and of its holes.
struct nested_rings {
  std::size_t outer;
  std::vector<std::size_t> holes;
};

/// Groups rings into polygons: counter-clockwise rings are outer rings, and
/// each clockwise ring becomes a hole of the smallest outer ring containing
/// it.  Rings must not cross or pass twice through a point (they may touch
/// at vertices) and must bound one region, as the rings of `assemble` do:
/// then every hole lies in some outer ring, so of the outer rings whose
/// bounding box holds the hole's, the largest needs no test, and a hole with
/// one candidate (the common case) costs no exact test at all.  Flat rings
/// are dropped.  Areas and boxes are taken only of outer rings, and only
/// when there are holes to place in more than one.  Returns the polygons as
/// indices into `rings`, outer rings and holes each in the order given.
/// Throws `std::invalid_argument` for a hole that no outer ring's box holds.
inline std::vector<nested_rings> nest_indices(std::vector<ring> const& rings) {
  struct shell {
    rational area;
    detail::box bounds;
    std::size_t index; ///< into `out`
  };
  std::vector<shell> shells;
  std::vector<std::size_t> holes;
  std::vector<nested_rings> out;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    auto turn = detail::orientation(rings[i]);
    if (turn == geometry::sign::positive) {
      shells.push_back({rational(0), {}, out.size()});
      out.push_back({i, {}});
    } else if (turn == geometry::sign::negative) {
      holes.push_back(i);
    }
  }
  if (holes.empty()) return out;
  if (shells.empty()) throw std::invalid_argument("boolean::nest: a hole lies in no outer ring");
  if (shells.size() == 1) { // every hole lies in some outer ring: this one
    out.front().holes = std::move(holes);
    return out;
  }
  for (auto& s : shells) {
    s.area = twice_signed_area(rings[out[s.index].outer]);
    s.bounds = detail::bounds(rings[out[s.index].outer]);
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
      if (detail::ring_in_ring(rings[i], rings[out[shells[candidates[c]].index].outer]) == location::inside) {
        chosen = candidates[c];
        break;
      }
    out[shells[chosen].index].holes.push_back(i);
  }
  return out;
}

/// The polygons of `nest_indices(rings)`.
inline multipolygon nest(std::vector<ring> rings) {
  auto groups = nest_indices(rings);
  multipolygon out;
  out.reserve(groups.size());
  for (auto& g : groups) {
    polygon p{std::move(rings[g.outer]), {}};
    p.holes.reserve(g.holes.size());
    for (auto h : g.holes) p.holes.push_back(std::move(rings[h]));
    out.push_back(std::move(p));
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
