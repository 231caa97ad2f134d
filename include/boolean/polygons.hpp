/// @file
/// Boolean operations on polygons in the plane, exact: polygons with holes
/// (simple-features rules) or paths with a fill rule become point-set trees
/// over `geometry::e2`, trees are merged (`bsp::merge`), and the result is
/// read back as valid polygons with holes.
///
/// Input vertices are exact rationals; no point is ever constructed while the
/// trees are built and merged, only when the output rings are read off.
#pragma once

#include "rings.hpp"

#include <bsp/boolean.hpp>
#include <bsp/point_set.hpp>
#include <geometry/e2.hpp>
#include <geometry/hash.hpp>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace boolean {

/// The plane, exact, as the trees see it.
using plane_kernel = geometry::e2::exact_kernel;
/// A region of the plane: a point-set tree, `true` inside.
using region2 = bsp::point_set<plane_kernel, bool>;

/// How the rings of a path set decide which points are inside, from the
/// winding number `w` of the point (a counter-clockwise ring winds +1 around
/// the points it encloses): odd `w`, `w ≠ 0`, `w > 0`, `w < 0`.
enum class fill_rule { evenodd, nonzero, positive, negative };

/// The four Boolean operations (`difference` is the first operand minus the second).
enum class set_op { union_, intersection, difference, symmetric_difference };

/// Input that does not describe a valid polygon set.
struct invalid_polygon : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

namespace detail {

/// Removes repeated consecutive vertices (and a repeated first vertex at the end).
inline ring without_repeats(ring r) {
  r.erase(std::unique(r.begin(), r.end()), r.end());
  while (r.size() >= 2 && r.back() == r.front()) r.pop_back();
  return r;
}

/// The segments of the ring `r` with the region on its left, as the tree
/// builder wants them: the region on their negative side.
inline void add_edges(ring const& r, std::vector<plane_kernel::sub_hyperplane>& out) {
  for (std::size_t i = 0, n = r.size(); i < n; ++i) out.push_back(geometry::e2::segment(r[(i + 1) % n], r[i]));
}

/// The winding number of the rings around `p`, which lies on none of them.
inline long winding(std::vector<ring> const& rings, point2 const& p) {
  long w = 0;
  for (auto const& r : rings)
    for (std::size_t i = 0, n = r.size(); i < n; ++i) {
      auto const &a = r[i], &b = r[(i + 1) % n];
      if (a.y() <= p.y()) {
        if (b.y() > p.y() && geometry::e2::orientation(a, b, p) == geometry::sign::positive) ++w;
      } else if (b.y() <= p.y() && geometry::e2::orientation(a, b, p) == geometry::sign::negative) {
        --w;
      }
    }
  return w;
}

/// A ring of zero signed area is either flat (all its vertices on one line:
/// no interior, dropped) or a self-intersecting figure whose lobes cancel.
inline void refuse_flat_figures(ring const& r) {
  for (std::size_t i = 2; i < r.size(); ++i)
    if (geometry::e2::orientation(r[0], r[1], r[i]) != geometry::sign::zero)
      throw invalid_polygon("the polygons are not valid: a ring crosses itself (read it as a path with a fill rule "
                            "instead)");
}

inline bool filled(long w, fill_rule rule) {
  switch (rule) {
  case fill_rule::evenodd: return w % 2 != 0;
  case fill_rule::nonzero: return w != 0;
  case fill_rule::positive: return w > 0;
  case fill_rule::negative: return w < 0;
  }
  return false;
}

} // namespace detail

/// An operand of a Boolean operation in geometry `G`: its tree and pieces
/// covering its boundary (the input edges it was built from), which the
/// fast path of `combine` classifies instead of walking the merged tree.
template <bsp::geometry G> struct basic_operand {
  bsp::point_set<G, bool> tree;
  std::vector<typename G::sub_hyperplane> boundary;
};
/// An operand in the plane.
using operand = basic_operand<plane_kernel>;

/// The region of a set of polygons with holes, read by the simple-features
/// rules: each polygon is its outer ring's interior minus its holes', and the
/// set is the union of its polygons.  Ring orientation in the input does not
/// matter (outer rings are turned counter-clockwise, holes clockwise);
/// repeated vertices and zero-area rings are dropped.
///
/// The input must be valid: rings simple, holes inside their outer ring,
/// polygons with disjoint interiors; rings may touch at vertices, and
/// polygons may share edges.  A hole that shares part of an edge with its
/// outer ring or another hole (the region on neither side there) is not
/// handled yet: it is refused as invalid.  Validity is checked after the
/// build, exactly: the area enclosed by the rings must equal the area of the
/// region the tree bounds, which fails for crossing rings, overlapping
/// polygons, holes outside their outer ring and holes sharing part of an
/// edge with it.  Throws `invalid_polygon` then (read such input with a fill
/// rule).
/// Returns the tree with the edges it was built from.
inline operand operand_of(multipolygon const& m) {
  std::vector<plane_kernel::sub_hyperplane> edges;
  rational enclosed(0);
  for (auto const& p : m) {
    ring outer = detail::without_repeats(p.outer);
    auto a = twice_signed_area(outer);
    if (a == 0) { // no interior (then its holes are meaningless), unless it is a figure eight
      detail::refuse_flat_figures(outer);
      continue;
    }
    if (a < 0) std::reverse(outer.begin(), outer.end());
    enclosed += abs(a);
    detail::add_edges(outer, edges);
    for (auto const& h0 : p.holes) {
      ring h = detail::without_repeats(h0);
      auto b = twice_signed_area(h);
      if (b == 0) {
        detail::refuse_flat_figures(h);
        continue;
      }
      if (b > 0) std::reverse(h.begin(), h.end());
      enclosed -= abs(b);
      detail::add_edges(h, edges);
    }
  }
  auto t = bsp::build_point_set<plane_kernel>(edges, true, false, bsp::random_order(20261128));
  auto measured = bsp::measure(t, true);
  if (!measured || *measured * 2 != enclosed)
    throw invalid_polygon("the polygons are not valid: rings cross or overlap, or a hole lies outside its outer "
                          "ring or shares part of an edge with it (read them as paths with a fill rule instead)");
  return {std::move(t), std::move(edges)};
}

/// The region of a set of polygons with holes (see `operand_of`).
inline region2 region(multipolygon const& m) { return operand_of(m).tree; }

/// The region of closed paths under a fill rule, as Clipper reads them:
/// rings may self-intersect, overlap and run in either direction.  Built
/// from all edges, each cell of the tree labelled by the rule applied to its
/// winding number (exact, at a rational point inside the cell; the cost is
/// the number of cells times the number of edges).
inline region2 region(std::vector<ring> const& paths, fill_rule rule) {
  std::vector<ring> rings;
  std::vector<plane_kernel::sub_hyperplane> edges;
  for (auto const& p : paths) {
    ring r = detail::without_repeats(p);
    if (r.size() < 2) continue;
    detail::add_edges(r, edges);
    rings.push_back(std::move(r));
  }
  auto t = bsp::build_point_set<plane_kernel>(std::move(edges), true, false, bsp::random_order(20261128));
  for (auto const& c : bsp::cells(t)) {
    auto v = geometry::e2::vertices(c.region);
    bool inside = false;
    if (v) { // bounded: the centroid of its vertices is inside it, off every edge
      rational sx(0), sy(0);
      for (auto const& q : *v) sx += q.x(), sy += q.y();
      rational n(static_cast<long>(v->size()));
      inside = detail::filled(detail::winding(rings, point2(rational(sx / n), rational(sy / n))), rule);
    }
    t.leaf_data(c.leaf) = inside;
  }
  return bsp::reduce(t);
}

/// The region of closed paths under a fill rule with its boundary read off
/// the tree (overlapping path edges make no boundary of their own).
inline operand operand_of(std::vector<ring> const& paths, fill_rule rule) {
  auto t = region(paths, rule);
  auto b = bsp::oriented_boundary(t);
  return {std::move(t), std::move(b)};
}

/// `op` applied to the regions `a` and `b` (of any geometry: the plane, the sphere, space).
template <bsp::geometry G>
bsp::point_set<G, bool> apply(set_op op, bsp::point_set<G, bool> const& a, bsp::point_set<G, bool> const& b) {
  switch (op) {
  case set_op::union_: return bsp::set_union(a, b);
  case set_op::intersection: return bsp::set_intersection(a, b);
  case set_op::difference: return bsp::set_difference(a, b);
  case set_op::symmetric_difference: return bsp::set_symmetric_difference(a, b);
  }
  throw std::invalid_argument("boolean::apply: unknown operation");
}

namespace detail {

inline bool label_op(set_op op, bool x, bool y) {
  switch (op) {
  case set_op::union_: return x || y;
  case set_op::intersection: return x && y;
  case set_op::difference: return x && !y;
  case set_op::symmetric_difference: return x != y;
  }
  return false;
}

/// Directed segments, region on the left, from pieces with the region on their negative side.
inline std::vector<directed_segment> left_edges(std::vector<plane_kernel::sub_hyperplane> const& pieces) {
  std::vector<directed_segment> edges;
  edges.reserve(pieces.size());
  for (auto const& p : pieces) {
    auto ends = geometry::e2::endpoints(p);
    if (!ends) throw std::invalid_argument("boolean::polygons: the region is unbounded");
    edges.push_back({ends->second, ends->first});
  }
  return edges;
}

/// The signs of the cross and dot products of two lines' directions, from
/// their coefficients: a line's direction is its normal turned a quarter
/// turn, which keeps both products.
inline geometry::sign normal_cross(geometry::hvec<rational, 3> const& m, geometry::hvec<rational, 3> const& n) {
  return geometry::filtered_sign([](auto const& A, auto const& B) { return A[0] * B[1] - A[1] * B[0]; }, m, n);
}
inline geometry::sign normal_dot(geometry::hvec<rational, 3> const& m, geometry::hvec<rational, 3> const& n) {
  return geometry::filtered_sign([](auto const& A, auto const& B) { return A[0] * B[0] + A[1] * B[1]; }, m, n);
}

/// The polygons bounded by `pieces`, each with the region on its negative
/// side, as `assemble(left_edges(pieces))` gives them, without a rational
/// operation until the rings are nested: vertices are numbered by their
/// primitive integer homogeneous coordinates, each edge runs along its
/// piece's support line (region on its left: the direction (−b, a) of the
/// line ax + by + c = 0), loops are traced on numbers with the turns decided
/// from the lines' coefficients, a vertex between two edges of one line is
/// dropped, and each remaining vertex is made a rational point once.
inline multipolygon assemble_pieces(std::vector<plane_kernel::sub_hyperplane> const& pieces) {
  using geometry::sign;
  geometry::welder<3> vertex_id, line_id;
  std::vector<std::uint32_t> from, to, line;
  from.reserve(pieces.size()), to.reserve(pieces.size()), line.reserve(pieces.size());
  for (auto const& p : pieces) {
    auto h = geometry::e2::homogeneous_endpoints(p);
    if (h.empty() || h[0].sign_at(2) != sign::positive || h[1].sign_at(2) != sign::positive)
      throw std::invalid_argument("boolean::polygons: the region is unbounded");
    if (h[0] == h[1]) continue;
    from.push_back(vertex_id(h[1]));
    to.push_back(vertex_id(h[0]));
    line.push_back(line_id(p.support.n));
  }
  auto const& lines = line_id.vertex;
  auto loops = trace_loops(vertex_id.vertex.size(), from, to, [&](std::size_t in, std::size_t a, std::size_t b) {
    return clockwise_before(-lines[line[in]], lines[line[a]], lines[line[b]], normal_cross, normal_dot);
  });
  std::vector<std::optional<point2>> point(vertex_id.vertex.size());
  std::vector<ring> rings;
  for (auto const& l : loops) {
    ring r;
    for (std::size_t i = 0, k = l.size(); i < k; ++i) {
      std::size_t e = l[i], before = l[(i + k - 1) % k];
      if (line[before] == line[e]) continue; // straight on
      auto& q = point[from[e]];
      if (!q) q = point2::from_homogeneous(vertex_id.vertex[from[e]]);
      r.push_back(*q);
    }
    if (r.size() >= 3) rings.push_back(std::move(r));
  }
  return nest(std::move(rings));
}

} // namespace detail

/// The valid polygons with holes of `op(a, b)`, from the operands'
/// boundaries classified against both trees (`bsp::merged_boundary`): the
/// merged tree is never built.  The same polygons as
/// `polygons(apply(op, a.tree, b.tree))`, at a cost that grows with the input
/// edges and not with the merged tree.  Throws `std::invalid_argument` for
/// an unbounded result.
inline multipolygon combine(set_op op, operand const& a, operand const& b) {
  auto pieces = bsp::merged_boundary(a.tree, a.boundary, b.tree, b.boundary,
                                     [op](bool x, bool y) { return detail::label_op(op, x, y); });
  return detail::assemble_pieces(pieces);
}

/// The exact area of a region; nothing when it is unbounded.
inline std::optional<rational> area(region2 const& r) { return bsp::measure(r, true); }

/// The valid polygons with holes of a bounded region (see rings.hpp for the
/// rules they follow).  Throws `std::invalid_argument` for an unbounded region.
inline multipolygon polygons(region2 const& r) { return detail::assemble_pieces(bsp::oriented_boundary(r)); }

} // namespace boolean
