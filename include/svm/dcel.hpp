/// @file
/// A half-edge map on the sphere S2 (a doubly-connected edge list) whose
/// geometry is entirely implicit: every edge lies on a great circle from a
/// table of input-derived circles, and every vertex is the intersection of
/// two of them, `circle[a] × circle[b]`.  Nothing is ever normalised or
/// rounded; vertices become unit vectors only for output.
#pragma once

#include <geometry/s2.hpp>

#include <boost/pending/disjoint_sets.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace svm {

using index = std::uint32_t;
inline constexpr index none = ~index{0};

/// Where an edge of the map comes from.
enum class provenance : std::uint8_t {
  scene_edge,  ///< the silhouette of an input polygon's edge
  depth_split, ///< a cut of the depth-order tree (an input polygon's plane)
  partition,   ///< the first partition of the sphere
  cut,         ///< a circle cut in before the scene (a window's side, a panorama's seam), kept by simplify
};

/// The label of faces outside a build's window (see `build_options::window`).
inline constexpr std::int64_t clipped = -2;

/// The half-edge map.  Half-edge `e` runs counter-clockwise about its circle
/// (`circle(e)`, the table circle negated for odd half-edges … see `circle_of`)
/// with its face on the left, i.e. on the circle's positive side, seen from
/// outside the sphere.  Twins are `e ^ 1`.
template <geometry::number FT> class dcel {
public:
  using circle_type = geometry::s2::hyperplane<FT>;
  using direction = geometry::s2::point<FT>;

  struct vertex {
    index a, b; ///< the vertex is the direction `circles[a] × circles[b]`
  };
  struct half_edge {
    index origin = none, next = none, prev = none, face = none;
    index circle = none; ///< table circle; the half-edge runs about it (even) or about its opposite (odd)
  };
  struct face {
    std::int64_t label = -1; ///< the visible input polygon, or −1
    index edge = none;       ///< a half-edge of the face, none for a face without edges
  };

  /// A map of one face (the whole sphere) with no vertices or edges.
  dcel() { faces_.push_back({}); }

  /// @name Tables
  /// @{
  std::vector<circle_type> const& circles() const noexcept { return circles_; }
  std::vector<vertex> const& vertices() const noexcept { return vertices_; }
  std::vector<half_edge> const& half_edges() const noexcept { return edges_; }
  std::vector<face> const& faces() const noexcept { return faces_; }
  std::vector<provenance> const& circle_provenance() const noexcept { return provenance_; }
  face& face_at(index f) { return faces_[f]; }
  /// @}

  index add_circle(circle_type c, provenance p) {
    circles_.push_back(std::move(c));
    provenance_.push_back(p);
    return static_cast<index>(circles_.size() - 1);
  }

  static index twin(index e) noexcept { return e ^ 1u; }
  index next(index e) const { return edges_[e].next; }
  index prev(index e) const { return edges_[e].prev; }
  index origin(index e) const { return edges_[e].origin; }
  index target(index e) const { return edges_[twin(e)].origin; }
  index face_of(index e) const { return edges_[e].face; }
  /// The circle half-edge `e` runs about: its table circle for even `e`, the opposite for odd.
  bool reversed(index e) const noexcept { return (e & 1u) != 0; }

  /// The direction of vertex `v` (exact, unnormalised).
  direction point(index v) const { return cross(circles_[vertices_[v].a].n, circles_[vertices_[v].b].n); }

  /// Side of vertex `v` with respect to circle `c`: det(a, b, c), degree 3 in circle coefficients.
  geometry::sign side(index v, circle_type const& c) const {
    return det_sign(circles_[vertices_[v].a].n, circles_[vertices_[v].b].n, c.n);
  }

  /// @name Euler operators
  /// @{

  /// The first edges: the circle `c` (a table index) drawn on a map without
  /// edges, as four minor arcs between its intersections with the two
  /// coordinate planes it is least parallel to.  The one face becomes the
  /// positive side; returns the new face, the negative side.
  index make_first_circle(index c);

  /// Splits half-edge `e` (and its twin) at the new vertex `circles[a] × circles[b]`
  /// lying inside it; returns the new vertex.
  index split_edge(index e, index a, index b);

  /// Splits face `f` by the table circle `c`, which must cut its interior:
  /// edges crossed are split, and a new edge on `c` joins the two crossing
  /// points.  The positive side of `c` keeps `f`; returns the new face, the
  /// negative side.
  index split_face(index f, index c);

  /// @}

  /// The half-edges of the cycle through `e`, in order.
  std::vector<index> cycle(index e) const {
    std::vector<index> out;
    index x = e;
    do {
      out.push_back(x);
      x = edges_[x].next;
      if (out.size() > edges_.size()) throw std::logic_error("dcel: a next cycle does not close");
    } while (x != e);
    return out;
  }

  /// Replaces the whole map (used by simplification, which rebuilds it).
  void assign(std::vector<vertex> v, std::vector<half_edge> e, std::vector<face> f) {
    vertices_ = std::move(v);
    edges_ = std::move(e);
    faces_ = std::move(f);
  }

private:
  /// Whether vertices `u` and `w` (on a common circle) are antipodal.
  bool antipodal(index u, index w) const {
    auto const &U = vertices_[u], &W = vertices_[w];
    auto const& C = circles_;
    auto d = geometry::filtered_sign([](auto const& a, auto const& b, auto const& p, auto const& q) { return geometry::dot(geometry::cross(a, b), geometry::cross(p, q)); },
                                     C[U.a].n, C[U.b].n, C[W.a].n, C[W.b].n);
    if (d != geometry::sign::negative) return false;
    for (std::size_t i = 0; i < 3; ++i) {
      std::size_t j = (i + 1) % 3;
      auto minor = geometry::filtered_sign(
          [i, j](auto const& a, auto const& b, auto const& p, auto const& q) {
            auto x = geometry::cross(a, b), y = geometry::cross(p, q);
            return x[i] * y[j] - x[j] * y[i];
          },
          C[U.a].n, C[U.b].n, C[W.a].n, C[W.b].n);
      if (minor != geometry::sign::zero) return false;
    }
    return true;
  }

  /// A new vertex on circle `c` strictly inside the half circle from `from` to
  /// `to` (antipodal, counter-clockwise about `c`): `±(c × e_i)` for a
  /// coordinate axis `e_i` whose plane does not contain them.
  index middle_vertex(index c, index from, index to) {
    (void)to;
    auto p = point(from);
    std::size_t i = 0;
    while (geometry::sign_of(p[i]) == geometry::sign::zero) ++i;
    std::array<FT, 3> e{FT(0), FT(0), FT(0)};
    e[i] = FT(1);
    index axis = add_circle(circle_type(geometry::hvec<FT, 3>(e)), provenance::partition);
    index m = add_vertex(c, axis);
    // Keep it if it lies counter-clockwise within half a circle after `from`.
    if (det_sign(circles_[c].n, p, point(m)) != geometry::sign::positive) vertices_[m] = {axis, c};
    return m;
  }

  index add_vertex(index a, index b) {
    vertices_.push_back({a, b});
    return static_cast<index>(vertices_.size() - 1);
  }
  index add_edge_pair(index circle, index from, index to) {
    index e = static_cast<index>(edges_.size());
    edges_.push_back({from, none, none, none, circle});
    edges_.push_back({to, none, none, none, circle});
    return e;
  }
  void link(index a, index b) {
    edges_[a].next = b;
    edges_[b].prev = a;
  }

  std::vector<circle_type> circles_;
  std::vector<provenance> provenance_;
  std::vector<vertex> vertices_;
  std::vector<half_edge> edges_;
  std::vector<face> faces_;
};

template <geometry::number FT> index dcel<FT>::make_first_circle(index c) {
  if (!edges_.empty() || faces_.size() != 1) throw std::logic_error("dcel::make_first_circle on a map with edges");
  auto const& n = circles_[c].n;
  std::size_t k = geometry::dominant_axis(n);
  index axes[2];
  for (std::size_t i = 0, j = 0; i < 3; ++i) {
    if (i == k) continue;
    std::array<FT, 3> e{FT(0), FT(0), FT(0)};
    e[i] = FT(1);
    axes[j++] = add_circle(circle_type(geometry::hvec<FT, 3>(e)), provenance::partition);
  }
  // p = c × e₁, q = c × e₂; counter-clockwise about c: p, q, −p, −q when det(c, p, q) > 0.
  index p = add_vertex(c, axes[0]), q = add_vertex(c, axes[1]);
  index mp = add_vertex(axes[0], c), mq = add_vertex(axes[1], c);
  bool q_first = det_sign(circles_[c].n, point(p), point(q)) == geometry::sign::positive;
  std::array<index, 4> ring = q_first ? std::array<index, 4>{p, q, mp, mq} : std::array<index, 4>{p, mq, mp, q};
  index f_pos = 0, f_neg = static_cast<index>(faces_.size());
  faces_.push_back({});
  std::array<index, 4> fwd;
  for (std::size_t i = 0; i < 4; ++i) fwd[i] = add_edge_pair(c, ring[i], ring[(i + 1) % 4]);
  for (std::size_t i = 0; i < 4; ++i) {
    link(fwd[i], fwd[(i + 1) % 4]);                 // the positive side, counter-clockwise about c
    link(twin(fwd[(i + 1) % 4]), twin(fwd[i]));     // the negative side, the other way
    edges_[fwd[i]].face = f_pos;
    edges_[twin(fwd[i])].face = f_neg;
  }
  faces_[f_pos].edge = fwd[0];
  faces_[f_neg].edge = twin(fwd[0]);
  return f_neg;
}

template <geometry::number FT> index dcel<FT>::split_edge(index e, index a, index b) {
  index t = twin(e);
  index x = add_vertex(a, b);
  index w = target(e);
  // The new half-edge on e's side (x → w) runs the same way as e, so it has e's parity.
  index base = add_edge_pair(edges_[e].circle, none, none);
  index e2 = base + (e & 1u);
  edges_[e2].origin = x;
  edges_[twin(e2)].origin = w;
  index t2 = twin(e2);
  // e: u → x, e2: x → w; t2: w → x, t: x → u.
  edges_[t].origin = x;
  edges_[e2].face = edges_[e].face;
  edges_[t2].face = edges_[t].face;
  link(e2, edges_[e].next);
  link(e, e2);
  link(edges_[t].prev, t2);
  link(t2, t);
  return x;
}

template <geometry::number FT> index dcel<FT>::split_face(index f, index c) {
  auto const& circle = circles_[c];
  if (faces_[f].edge == none) throw std::logic_error("dcel::split_face on a face without edges");
  // Entry (from − to +) and exit (from + to −) points of the face boundary:
  // walking the cycle from a negative vertex, the first vertex of the zero
  // run (or the crossing inside the edge) where the sign turns positive, then
  // likewise back to negative.  Exactly, a convex face has just these two.
  auto cyc = cycle(faces_[f].edge);
  std::size_t n = cyc.size();
  std::vector<geometry::sign> s(n);
  std::size_t start = n;
  for (std::size_t i = 0; i < n; ++i) {
    s[i] = side(origin(cyc[i]), circle);
    if (s[i] == geometry::sign::negative && start == n) start = i;
  }
  if (start == n) throw std::logic_error("dcel::split_face: the circle does not cut the face");
  // A crossing: at vertex `vertex` (the origin of cyc[vertex]), or inside edge cyc[edge].
  struct crossing {
    std::size_t at = 0;
    bool inside_edge = false;
  } cross_in, cross_out;
  int found = 0;
  geometry::sign last = geometry::sign::negative;
  std::size_t zero_run = n; // first vertex of the current zero run
  for (std::size_t k = 1; k <= n && found < 2; ++k) {
    std::size_t i = (start + k) % n;
    if (s[i] == geometry::sign::zero) {
      if (zero_run == n) zero_run = i;
      continue;
    }
    if (s[i] != last) {
      crossing x = zero_run != n ? crossing{zero_run, false} : crossing{(i + n - 1) % n, true};
      (found == 0 ? cross_in : cross_out) = x;
      ++found;
      last = s[i];
    }
    zero_run = n;
  }
  if (found < 2) throw std::logic_error("dcel::split_face: the circle does not cut the face");
  // Split the crossed edges (the later one first keeps the earlier index valid).
  auto realise = [&](crossing const& x, bool entering) -> index {
    if (!x.inside_edge) return cyc[x.at];
    index e = cyc[x.at];
    index ec = edges_[e].circle;
    // Along e (about ±circles[ec]) the entry point of c's positive side is c × ec, the exit ec × c.
    if (entering != reversed(e))
      split_edge(e, c, ec);
    else
      split_edge(e, ec, c);
    return edges_[e].next; // starts at the new vertex
  };
  index enter = realise(cross_in, true);
  index exit = realise(cross_out, false);
  // New edge: exit point b → entry point a on c (positive side on its left) closes the positive part.
  index a = origin(enter), b = origin(exit);
  index pa = edges_[enter].prev, pb = edges_[exit].prev;
  index n1 = add_edge_pair(c, b, a); // even: about c, b → a
  if (antipodal(a, b)) {
    // A half circle is no minor arc: it gets a middle vertex, where c meets a
    // coordinate plane (any such point strictly between b and a).
    index m = middle_vertex(c, b, a);
    edges_[twin(n1)].origin = m; // n1: b → m
    index n3 = add_edge_pair(c, m, a); // m → a
    link(pb, n1);
    link(n1, n3);
    link(n3, enter);
    link(pa, twin(n3));
    link(twin(n3), twin(n1));
    link(twin(n1), exit);
  } else {
    link(pb, n1);
    link(n1, enter);
    link(pa, twin(n1));
    link(twin(n1), exit);
  }
  index n2 = twin(n1);
  index g = static_cast<index>(faces_.size());
  faces_.push_back({});
  for (index x : cycle(n1)) edges_[x].face = f;
  for (index x : cycle(n2)) edges_[x].face = g;
  faces_[f].edge = n1;
  faces_[g].edge = n2;
  return g;
}

} // namespace svm

namespace svm {

/// A unit vector of vertex `v`, for output and measures.
template <geometry::number FT> std::array<double, 3> unit(dcel<FT> const& m, index v) {
  return geometry::s2::to_unit(m.point(v));
}

/// The unit normal of the circle half-edge `e` runs counter-clockwise about.
template <geometry::number FT> std::array<double, 3> unit_circle(dcel<FT> const& m, index e) {
  auto n = geometry::s2::to_unit(m.circles()[m.half_edges()[e].circle].n);
  if (m.reversed(e)) n = {-n[0], -n[1], -n[2]};
  return n;
}

/// Areas of the faces in steradians, by Gauss–Bonnet: a face with `c`
/// boundary cycles has area 2π(2 − c) minus its boundary's turning angles.
template <geometry::number FT> std::vector<double> face_areas(dcel<FT> const& m) {
  using geometry::cross;
  using geometry::dot;
  std::vector<double> turn(m.faces().size(), 0.0);
  std::vector<int> cycles(m.faces().size(), 0);
  std::vector<char> seen(m.half_edges().size(), 0);
  for (index e = 0; e < m.half_edges().size(); ++e) {
    if (seen[e]) continue;
    ++cycles[m.face_of(e)];
    for (index x : m.cycle(e)) {
      seen[x] = 1;
      index y = m.next(x);
      auto v = unit(m, m.origin(y));
      auto tin = cross(unit_circle(m, x), v), tout = cross(unit_circle(m, y), v);
      turn[m.face_of(e)] += std::atan2(dot(v, cross(tin, tout)), dot(tin, tout));
    }
  }
  std::vector<double> area(m.faces().size());
  for (std::size_t f = 0; f < area.size(); ++f) area[f] = 2 * std::numbers::pi * (2 - cycles[f]) - turn[f];
  return area;
}

/// Checks the map: twins, next/prev and faces consistent, cycles closed,
/// every vertex on the circles of its edges, every edge a minor arc (less
/// than half a circle), and Euler's formula V − E + F = 1 + C with C the
/// number of connected components.  Returns the problems found (none: empty).
template <geometry::number FT> std::vector<std::string> check_invariants(dcel<FT> const& m) {
  std::vector<std::string> problems;
  auto const& he = m.half_edges();
  auto bad = [&](std::string what, index e) { problems.push_back(what + " at half-edge " + std::to_string(e)); };
  if (he.size() % 2 != 0) problems.push_back("odd number of half-edges");
  for (index e = 0; e < he.size() && problems.size() < 20; ++e) {
    auto const& h = he[e];
    if (h.next >= he.size() || h.prev >= he.size() || h.origin >= m.vertices().size() || h.face >= m.faces().size()) {
      bad("dangling index", e);
      continue;
    }
    if (he[h.next].prev != e) bad("next/prev mismatch", e);
    if (he[h.next].face != h.face) bad("face changes along a cycle", e);
    if (he[h.next].origin != m.target(e)) bad("next does not start where e ends", e);
    if (m.twin(e) == h.next && m.target(e) == h.origin) bad("a loop edge", e);
    // Both ends lie on the edge's circle, and the arc is minor.
    auto const& c = m.circles()[h.circle];
    if (m.side(h.origin, c) != geometry::sign::zero || m.side(m.target(e), c) != geometry::sign::zero) bad("vertex off its edge's circle", e);
    auto const& va = m.vertices()[h.origin];
    auto const& vb = m.vertices()[m.target(e)];
    auto const& C = m.circles();
    auto minor = geometry::filtered_sign(
        [](auto const& n, auto const& a, auto const& b, auto const& p, auto const& q) {
          return geometry::det3(n, geometry::cross(a, b), geometry::cross(p, q));
        },
        c.n, C[va.a].n, C[va.b].n, C[vb.a].n, C[vb.b].n);
    if (minor != (m.reversed(e) ? geometry::sign::negative : geometry::sign::positive)) bad("not a minor arc", e);
  }
  // Euler's formula.
  boost::disjoint_sets_with_storage<> joined(m.vertices().size());
  for (index e = 0; e < he.size(); e += 2) joined.union_set(he[e].origin, he[e + 1].origin);
  std::size_t components = 0;
  for (index i = 0; i < m.vertices().size(); ++i) components += joined.find_set(i) == i;
  long lhs = static_cast<long>(m.vertices().size()) - static_cast<long>(he.size() / 2) + static_cast<long>(m.faces().size());
  if (lhs != 1 + static_cast<long>(components))
    problems.push_back("Euler: V - E + F = " + std::to_string(lhs) + ", 1 + C = " + std::to_string(1 + components));
  return problems;
}

} // namespace svm
