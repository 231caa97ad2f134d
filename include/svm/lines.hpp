/// @file
/// Hidden lines: the exact visible and hidden parts of every edge of a
/// scene, read off its visibility map, and the classes a technical drawing
/// keeps apart (outlines, silhouettes, creases, open boundaries, intersection
/// curves, shadow boundaries).
///
/// An edge a → b seen from the eye O is the minor arc of the circle through
/// O, a and b.  The arc goes down the map's locator twice, once taking the
/// cells on its right where it lies on a node's circle and once those on its
/// left; each piece it ends up in has one map face on either side, and the
/// pieces are cut only by the locator's circles (input-derived), so no
/// constructed point feeds a construction.  A point x of a piece is hidden
/// when a polygon seen on either side lies strictly between O and x: the
/// sign of that polygon's plane at x is linear along the edge, so pieces are
/// cut where it is zero, and a piece's sign is read off which side of that
/// zero it lies on (its ends are parameters read off its bounds' circles:
/// degree bounded).  Polygons seen edge-on (the eye in their plane) are not
/// in the map; an edge in such a plane is cut at their vertices' directions
/// and tested against them directly, at each piece's midpoint.
#pragma once

#include "build.hpp"

#include <bsp/point_set.hpp>
#include <geometry/hash.hpp>
#include <geometry/linear.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <type_traits>
#include <unordered_map>
#include <string_view>
#include <utility>
#include <vector>

namespace svm {

/// What a drawn line is.
enum class line_class : std::uint8_t {
  outline,      ///< an edge seen against empty space or a polygon it does not bound
  silhouette,   ///< an edge whose two polygons lie on one side of it in the view (a fold: the contour of a surface)
  crease,       ///< an edge where two polygons meet at more than the crease angle
  boundary,     ///< an edge of one polygon only (an open mesh's border)
  intersection, ///< where two polygons cross (visible parts only)
  shadow,       ///< a shadow's boundary on a polygon (visible parts only)
};
inline constexpr std::size_t line_class_count = 6;

inline std::string_view name_of(line_class c) {
  constexpr std::array<std::string_view, line_class_count> names{"outline", "silhouette", "crease", "boundary", "intersection", "shadow"};
  return names[static_cast<std::size_t>(c)];
}

/// An edge of the scene: a side of one or more polygons, once however many
/// polygons have it (vertices are welded by their exact coordinates).
template <geometry::number FT> struct scene_edge {
  geometry::e3::point<FT> a, b;
  std::uint32_t va = 0, vb = 0;         ///< welded vertex numbers of `a` and `b`
  std::vector<std::uint32_t> polygons; ///< indices of the polygons it is a side of
};

/// How an edge is drawn, from its polygons and the eye (the view's part is
/// the silhouette test only).
enum class edge_kind : std::uint8_t {
  never,      ///< between two polygons of one plane on either side of it (a diagonal): never drawn
  smooth,     ///< between two polygons meeting at no more than the crease angle: drawn only as an outline
  crease,     ///< drawn, visible and hidden
  silhouette, ///< drawn, visible and hidden
  boundary,   ///< drawn, visible and hidden
};

/// A maximal run of one edge, visible or hidden, of one class: the points
/// a + t·(b − a) for t in [t0, t1], exactly.
template <geometry::number FT> struct line_piece {
  std::uint32_t edge = 0;
  FT t0, t1;
  bool hidden = false;
  line_class cls = line_class::crease;
};

/// A visible map edge drawn for itself: an intersection curve or a shadow
/// boundary (the map's even half-edge `half_edge`).
struct map_line {
  index half_edge = none;
  line_class cls = line_class::intersection;
};

struct line_options {
  /// Edges where polygons meet at no more than this angle (degrees) are
  /// smooth: drawn only where they are seen against something else.  At 0,
  /// only edges between polygons of one plane are left out.
  double crease = 0;
};

struct line_statistics {
  std::size_t edges = 0;             ///< scene edges
  std::size_t edges_through_eye = 0; ///< edges on a line through the eye (no length in the view)
  std::size_t arc_pieces = 0;        ///< pieces of edges between map cells, before merging
  std::size_t edge_on_tests = 0;     ///< edges tested against polygons seen edge-on
  std::size_t hidden_whole = 0;      ///< edges between two hidden back faces (`visibility_map::hidden_backfaces`): no map descent
  double seconds = 0;
};

/// The lines of a view.
template <geometry::number FT> struct line_set {
  std::vector<scene_edge<FT>> edges;
  std::vector<edge_kind> kinds; ///< per edge
  std::vector<line_piece<FT>> pieces;
  std::vector<map_line> map_lines;
  line_statistics stats;
};

namespace detail {

template <class FT> using v3 = std::array<FT, 3>;

template <class FT> v3<FT> minus(geometry::e3::point<FT> const& p, geometry::e3::point<FT> const& q) {
  return {p.x() - q.x(), p.y() - q.y(), p.z() - q.z()};
}
template <class FT> v3<FT> minus(v3<FT> const& p, v3<FT> const& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
template <class FT> int sgn(FT const& x) { return static_cast<int>(geometry::sign_of(x)); }
template <class FT> bool is_zero3(v3<FT> const& v) { return sgn(v[0]) == 0 && sgn(v[1]) == 0 && sgn(v[2]) == 0; }

/// The integers the lines are computed on: over an exact field, GMP
/// integers (no rational is normalised on the way), over `double` doubles.
template <class FT> using frame_int = std::conditional_t<geometry::exact_field<FT>, geometry::integer, FT>;
template <class FT> using iv3 = v3<frame_int<FT>>;

/// A point relative to the eye: x − O = p / w, with w > 0 (over `double`,
/// w = 1).  Every test below is a sign of an expression homogeneous in each
/// such point, or a ratio of two of them, so positive factors drop out.
template <class FT> struct eye_relative {
  iv3<FT> p;
  frame_int<FT> w;
};

template <class FT> eye_relative<FT> relative(geometry::e3::point<FT> const& x, geometry::e3::point<FT> const& eye) {
  if constexpr (geometry::exact_field<FT>) {
    // x = X / W and O = P / V (homogeneous integers, W, V > 0):
    // x − O = (X·V − P·W) / (W·V).
    auto const &z = x.homogeneous().integers(), &o = eye.homogeneous().integers();
    eye_relative<FT> r;
    for (std::size_t k = 0; k < 3; ++k) r.p[k] = z[k] * o[3] - o[k] * z[3];
    r.w = z[3] * o[3];
    return r;
  } else {
    return {minus(x, eye), FT(1)};
  }
}

/// A positive multiple of b − a.
template <class FT> iv3<FT> difference(eye_relative<FT> const& b, eye_relative<FT> const& a) {
  iv3<FT> r;
  for (std::size_t k = 0; k < 3; ++k) r[k] = b.p[k] * a.w - a.p[k] * b.w;
  return r;
}

/// num / den in the field (den ≠ 0).
template <class FT> FT ratio(frame_int<FT> const& num, frame_int<FT> const& den) {
  if constexpr (geometry::exact_field<FT>) {
    FT r;
    mpq_set_num(r.backend().data(), num.backend().data());
    mpq_set_den(r.backend().data(), den.backend().data());
    mpq_canonicalize(r.backend().data());
    return r;
  } else {
    return num / den;
  }
}

template <class FT> v3<FT> to_field(iv3<FT> const& v) {
  if constexpr (geometry::exact_field<FT>) return {FT(v[0]), FT(v[1]), FT(v[2])};
  else return v;
}

/// A positive multiple of `v` in doubles, scaled so that no coordinate
/// overflows (for angles only).
template <class FT> v3<double> direction_doubles(iv3<FT> const& v) {
  if constexpr (geometry::exact_field<FT>) {
    std::array<double, 3> m{};
    std::array<long, 3> e{};
    long top = std::numeric_limits<long>::min();
    for (std::size_t k = 0; k < 3; ++k) {
      m[k] = mpz_get_d_2exp(&e[k], v[k].backend().data());
      if (m[k] != 0) top = std::max(top, e[k]);
    }
    v3<double> r{};
    for (std::size_t k = 0; k < 3; ++k)
      if (m[k] != 0) r[k] = std::ldexp(m[k], static_cast<int>(std::max(e[k] - top, -1000L)));
    return r;
  } else {
    return v;
  }
}

/// A positive multiple of A + t·BA.
template <class FT> iv3<FT> point_at(iv3<FT> const& A, iv3<FT> const& BA, FT const& t) {
  if constexpr (geometry::exact_field<FT>) {
    // t = p / q with q > 0: q·A + p·BA.
    geometry::integer p(mpq_numref(t.backend().data())), q(mpq_denref(t.backend().data()));
    iv3<FT> r;
    for (std::size_t k = 0; k < 3; ++k) r[k] = q * A[k] + p * BA[k];
    return r;
  } else {
    return {A[0] + t * BA[0], A[1] + t * BA[1], A[2] + t * BA[2]};
  }
}

/// An edge a → b relative to the eye on one scale: a − O = A / L and
/// b − O = B / L, so that A + t·(B − A) is L times the edge's point of
/// parameter t.
template <class FT> struct edge_frame {
  iv3<FT> A, B;
  frame_int<FT> L;
  edge_frame(eye_relative<FT> const& ra, eye_relative<FT> const& rb) : A(ra.p), B(rb.p), L(ra.w * rb.w) {
    for (auto& x : A) x *= rb.w;
    for (auto& x : B) x *= ra.w;
  }
};

/// The integer coordinates of a map vector (a positive multiple of it).
template <class FT> iv3<FT> const& integers_of(geometry::hvec<FT, 3> const& v) {
  if constexpr (geometry::exact_field<FT>) return v.integers();
  else return v.exact();
}

/// The direction of `v` as a point of the sphere.
template <class FT> geometry::s2::point<FT> direction_of(iv3<FT> v) {
  if constexpr (geometry::exact_field<FT>) {
    geometry::detail::make_primitive(v);
    return geometry::s2::point<FT>::from_integers(geometry::detail::integer_vector<3>(std::move(v)));
  } else {
    return geometry::s2::point<FT>(v);
  }
}

/// A polygon's plane relative to the eye, up to a positive factor: its value
/// at x − O = p / w is (n · p + d·w) / w; positive on the polygon's front,
/// `d` its value at the eye.
template <class FT> struct eye_plane {
  iv3<FT> n;
  frame_int<FT> d;
  /// A positive multiple of the plane's value at `x`.
  frame_int<FT> at(eye_relative<FT> const& x) const { return geometry::dot(n, x.p) + d * x.w; }
};

/// (From the first vertex and two others not on a line with it: a polygon
/// may have vertices in the middle of its sides.)  `v` are the polygon's
/// vertices relative to the eye.
template <class FT> eye_plane<FT> plane_of(std::vector<eye_relative<FT>> const& v) {
  auto u = difference(v[1], v[0]);
  iv3<FT> n{};
  for (std::size_t k = 2; k < v.size() && is_zero3(n); ++k) n = geometry::cross(u, difference(v[k], v[0]));
  // n·(x − a) with a = p0 / w0, times w0.
  eye_plane<FT> r{n, -geometry::dot(n, v[0].p)};
  for (auto& x : r.n) x *= v[0].w;
  if constexpr (geometry::exact_field<FT>) {
    std::array<geometry::integer, 4> z{r.n[0], r.n[1], r.n[2], r.d};
    geometry::detail::make_primitive(z);
    r = {{z[0], z[1], z[2]}, z[3]};
  }
  return r;
}

template <class FT> std::vector<eye_relative<FT>> relative_vertices(polygon<FT> const& p, geometry::e3::point<FT> const& eye) {
  std::vector<eye_relative<FT>> r;
  r.reserve(p.vertices.size());
  for (auto const& v : p.vertices) r.push_back(relative(v, eye));
  return r;
}

/// The line through the eye's plane `n` up to scale and orientation, as a
/// key: divided by its first non-zero coordinate.
template <class FT> v3<FT> line_key(v3<FT> n) {
  std::size_t k = 0;
  while (sgn(n[k]) == 0) ++k;
  FT s = n[k];
  for (auto& x : n) x /= s;
  return n;
}

/// The unit bend between polygons p and q along the edge a–b (0: flat, π:
/// folded back), in doubles (it only meets the crease threshold).
inline double bend(v3<double> const& e, v3<double> const& u, v3<double> const& w) {
  auto perp = [&](v3<double> x) {
    double k = geometry::dot(x, e) / geometry::dot(e, e);
    return v3<double>{x[0] - k * e[0], x[1] - k * e[1], x[2] - k * e[2]};
  };
  auto pu = perp(u), pw = perp(w);
  double c = geometry::dot(pu, pw) / std::sqrt(geometry::dot(pu, pu) * geometry::dot(pw, pw));
  return std::numbers::pi - std::acos(std::clamp(c, -1.0, 1.0));
}

} // namespace detail

/// The edges of `polygons`, each once: vertices welded by exact
/// coordinates.  Sides no other polygon has whole are then cut at each
/// other's ends along their lines, so that a side meeting several sides of
/// neighbours (a T-junction, as Boolean operations leave them) makes one
/// edge per run shared by the same polygons.  A run no other side covers is
/// a boundary edge.  (Sides shared whole are not cut again by a third
/// polygon's side along them: only a non-manifold mesh has those.)
template <geometry::number FT> std::vector<scene_edge<FT>> scene_edges(std::vector<polygon<FT>> const& polygons) {
  using namespace detail;
  using key = std::array<FT, 3>;
  // Vertices welded by their exact coordinates: over an exact field by their
  // homogeneous integers (no rational is made).
  auto ids = [] {
    if constexpr (geometry::exact_field<FT>) return std::unordered_map<geometry::hvec<FT, 4>, std::uint32_t, geometry::hvec_hash>{};
    else return std::map<key, std::uint32_t>{};
  }();
  auto id = [&](geometry::e3::point<FT> const& p) {
    if constexpr (geometry::exact_field<FT>) return ids.try_emplace(p.homogeneous(), static_cast<std::uint32_t>(ids.size())).first->second;
    else return ids.try_emplace({p.x(), p.y(), p.z()}, static_cast<std::uint32_t>(ids.size())).first->second;
  };
  // Sides welded by their ends.
  struct welded {
    geometry::e3::point<FT> const *a, *b;
    std::uint32_t ia, ib;
    std::vector<std::uint32_t> polygons;
  };
  std::unordered_map<std::uint64_t, std::size_t> at; // by (ia, ib) in one word
  std::vector<welded> sides;
  for (std::uint32_t i = 0; i < polygons.size(); ++i) {
    auto const& v = polygons[i].vertices;
    for (std::size_t k = 0; k < v.size(); ++k) {
      auto const *a = &v[k], *b = &v[(k + 1) % v.size()];
      std::uint32_t ia = id(*a), ib = id(*b);
      if (ia == ib) continue;
      if (ib < ia) std::swap(a, b), std::swap(ia, ib);
      auto [it, fresh] = at.try_emplace(std::uint64_t{ia} << 32 | ib, sides.size());
      if (fresh) sides.push_back({a, b, ia, ib, {i}});
      else if (sides[it->second].polygons.back() != i) sides[it->second].polygons.push_back(i);
    }
  }
  std::vector<scene_edge<FT>> out;
  // The lonely sides on each line, the line keyed by its direction (scaled
  // to a first non-zero coordinate of 1) and its moment about the origin.
  struct run {
    FT t0, t1; // along the direction, t0 < t1
    geometry::e3::point<FT> const *a, *b;
    std::uint32_t ia, ib, polygon;
  };
  std::map<std::pair<key, key>, std::vector<run>> lines;
  for (auto const& s : sides) {
    if (s.polygons.size() != 1) {
      out.push_back({*s.a, *s.b, s.ia, s.ib, s.polygons});
      continue;
    }
    auto const *a = s.a, *b = s.b;
    auto ia = s.ia, ib = s.ib;
    auto d = line_key(minus(*b, *a));
    key pa{a->x(), a->y(), a->z()};
    FT ta = geometry::dot(d, pa), tb = geometry::dot(d, key{b->x(), b->y(), b->z()});
    if (tb < ta) std::swap(a, b), std::swap(ia, ib), std::swap(ta, tb);
    lines[{d, geometry::cross(pa, d)}].push_back({ta, tb, a, b, ia, ib, s.polygons[0]});
  }
  for (auto& [line, runs] : lines) {
    if (runs.size() == 1) {
      auto const& r = runs[0];
      out.push_back({*r.a, *r.b, r.ia, r.ib, {r.polygon}});
      continue;
    }
    // Cut at every end: between consecutive ends, the sides that cover the run.
    std::map<FT, std::pair<geometry::e3::point<FT> const*, std::uint32_t>> ends;
    for (auto const& r : runs) ends.emplace(r.t0, std::pair{r.a, r.ia}), ends.emplace(r.t1, std::pair{r.b, r.ib});
    for (auto it = ends.begin(); std::next(it) != ends.end(); ++it) {
      auto next = std::next(it);
      std::vector<std::uint32_t> on;
      for (auto const& r : runs)
        if (r.t0 <= it->first && next->first <= r.t1 && std::find(on.begin(), on.end(), r.polygon) == on.end()) on.push_back(r.polygon);
      if (on.empty()) continue;
      out.push_back({*it->second.first, *next->second.first, it->second.second, next->second.second, std::move(on)});
    }
  }
  return out;
}

namespace detail {

/// `kind_of`, given the edge's ends relative to the eye `ra` and `rb`, the
/// normal `n` of its plane through the eye (a positive multiple of
/// (a − O) × (b − O)), the polygons' vertices relative to the eye (`rel`,
/// indexed as `polygons`) and their planes.
template <geometry::number FT>
edge_kind kind_from(scene_edge<FT> const& e, std::vector<polygon<FT>> const& polygons, line_options const& o,
                    std::vector<eye_plane<FT>> const& planes, std::vector<std::vector<eye_relative<FT>>> const& rel,
                    eye_relative<FT> const& ra, eye_relative<FT> const& rb, iv3<FT> const& n) {
  if (e.polygons.size() == 1) return edge_kind::boundary;
  if (e.polygons.size() > 2) return edge_kind::crease;
  // (b − a, and the other vectors below, are made only where needed.)
  std::optional<iv3<FT>> E_;
  auto E = [&]() -> iv3<FT> const& {
    if (!E_) E_ = difference(rb, ra);
    return *E_;
  };
  // A vertex of each polygon off the edge's line: where the edge is a whole
  // side, any other vertex (the polygon is strictly convex); where it is
  // part of a side (a T-junction), one not on its line.
  auto off = [&](std::uint32_t pi) -> eye_relative<FT> const& {
    auto const& p = polygons[pi];
    int ends = 0;
    for (auto const& v : p.vertices) ends += (v == e.a) + (v == e.b);
    for (std::size_t k = 0; k < p.vertices.size(); ++k) {
      auto const& v = p.vertices[k];
      if (!(v == e.a) && !(v == e.b) && (ends == 2 || !is_zero3(geometry::cross(E(), difference(rel[pi][k], ra))))) return rel[pi][k];
    }
    return rel[pi][0];
  };
  auto const &cp = off(e.polygons[0]), &cq = off(e.polygons[1]);
  int sp = sgn(geometry::dot(n, cp.p)), sq = sgn(geometry::dot(n, cq.p));
  bool coplanar = sgn(planes[e.polygons[0]].at(cq)) == 0;
  // Both polygons on one side of the edge in the view: the surface folds there.
  if (sp == 0 || sq == 0 || sp == sq) {
    // A flat pair seen exactly edge-on is still a diagonal.
    if (coplanar && sp == 0 && sq == 0)
      if (sgn(geometry::dot(geometry::cross(E(), difference(cp, ra)), geometry::cross(E(), difference(cq, ra)))) < 0) return edge_kind::never;
    return edge_kind::silhouette;
  }
  if (coplanar) return edge_kind::never;
  if (o.crease <= 0) return edge_kind::crease;
  double b = bend(direction_doubles<FT>(E()), direction_doubles<FT>(difference(cp, ra)), direction_doubles<FT>(difference(cq, ra)));
  return b > o.crease * std::numbers::pi / 180 ? edge_kind::crease : edge_kind::smooth;
}

} // namespace detail

/// How edge `e` is drawn from `eye` (see `edge_kind`).
template <geometry::number FT>
edge_kind kind_of(scene_edge<FT> const& e, std::vector<polygon<FT>> const& polygons, geometry::e3::point<FT> const& eye, line_options const& o) {
  using namespace detail;
  std::vector<eye_plane<FT>> planes;
  std::vector<std::vector<eye_relative<FT>>> rel;
  for (auto i : e.polygons) {
    if (planes.size() <= i) planes.resize(i + 1), rel.resize(i + 1);
    rel[i] = relative_vertices(polygons[i], eye);
    planes[i] = plane_of(rel[i]);
  }
  auto ra = relative(e.a, eye), rb = relative(e.b, eye);
  edge_frame<FT> f(ra, rb);
  return kind_from(e, polygons, o, planes, rel, ra, rb, geometry::cross(f.A, f.B));
}

/// The visible and hidden lines of `polygons` seen from `eye`, from their map
/// `vm`.  `polygon_of(label)` gives the polygon (an index into `polygons`) a
/// map label shows, or −1 for none; faces labelled `clipped` are outside the
/// view.  `polygons` must be the build's input (the map's labels their
/// indices, or regions of them).
template <geometry::number FT, class PolygonOf>
line_set<FT> hidden_lines(visibility_map<FT> const& vm, geometry::e3::point<FT> const& eye, std::vector<polygon<FT>> const& polygons,
                          PolygonOf&& polygon_of, line_options const& o = {}) {
  using namespace detail;
  using S = geometry::s2::sub_hyperplane<FT>;
  auto t_start = std::chrono::steady_clock::now();
  line_set<FT> out;
  out.edges = scene_edges(polygons);
  out.stats.edges = out.edges.size();
  auto const& m = vm.map;

  // Every vertex relative to the eye, on integers (see `eye_relative`).
  std::vector<std::vector<eye_relative<FT>>> rel;
  std::vector<eye_plane<FT>> planes;
  rel.reserve(polygons.size());
  planes.reserve(polygons.size());
  for (auto const& p : polygons) {
    rel.push_back(relative_vertices(p, eye));
    planes.push_back(plane_of(rel.back()));
  }
  // The edges' ends, by welded vertex number, made when first needed.
  std::size_t welded = 0;
  for (auto const& e : out.edges) welded = std::max<std::size_t>({welded, e.va + std::size_t{1}, e.vb + std::size_t{1}});
  std::vector<std::optional<eye_relative<FT>>> welded_rel(welded);
  auto rel_of = [&](std::uint32_t id, geometry::e3::point<FT> const& x) -> eye_relative<FT> const& {
    if (!welded_rel[id]) welded_rel[id] = relative(x, eye);
    return *welded_rel[id];
  };
  // Polygons seen edge-on, by the line of their plane.
  std::map<v3<FT>, std::vector<std::uint32_t>> edge_on;
  for (std::uint32_t i = 0; i < polygons.size(); ++i)
    if (sgn(planes[i].d) == 0) edge_on[line_key(to_field<FT>(planes[i].n))].push_back(i);

  auto label_at = [&](index face) -> std::int64_t {
    std::int64_t l = m.faces()[face].label;
    if (l == clipped) return clipped;
    return l < 0 ? -1 : static_cast<std::int64_t>(polygon_of(l));
  };

  // An edge between two polygons culled as hidden back faces is hidden
  // whole, when it lies wholly in view: the map clips nothing, or both its
  // ends lie strictly inside the build's window (a convex cone).
  bool const whole_view = std::none_of(m.faces().begin(), m.faces().end(), [](auto const& f) { return f.label == clipped; });
  // The window's circles as integer multiples (over an exact field), so
  // that a point's side is the sign of an integer dot product (w > 0).
  std::vector<iv3<FT>> window;
  for (auto const& c : vm.window) {
    if constexpr (geometry::exact_field<FT>) window.push_back(geometry::detail::integer_multiple(v3<FT>{FT(c[0]), FT(c[1]), FT(c[2])}));
    else window.push_back({FT(c[0]), FT(c[1]), FT(c[2])});
  }
  auto in_window = [&](eye_relative<FT> const& x) {
    return std::all_of(window.begin(), window.end(), [&](iv3<FT> const& c) { return sgn(geometry::dot(c, x.p)) > 0; });
  };
  auto hidden_whole = [&](scene_edge<FT> const& e, eye_relative<FT> const& ra, eye_relative<FT> const& rb) {
    if (vm.hidden_backfaces.size() != polygons.size() || e.polygons.size() != 2) return false;
    if (!vm.hidden_backfaces[e.polygons[0]] || !vm.hidden_backfaces[e.polygons[1]]) return false;
    return whole_view || (!window.empty() && !vm.excluded && in_window(ra) && in_window(rb));
  };
  std::vector<std::pair<S, index>> below, across;
  struct run {
    FT t0, t1;
    std::int64_t side[2];
  };
  std::vector<run> runs;
  // A side polygon's plane along an edge: its value fa + t·df at the point
  // of parameter t, zero at t = zero (when df ≠ 0); kept per polygon for the
  // edge's runs.
  struct along {
    std::int64_t q;
    FT zero;
    int sign_fa, sign_df, sign_eye;
  };
  std::vector<along> sides;
  out.kinds.reserve(out.edges.size());
  for (std::uint32_t ei = 0; ei < out.edges.size(); ++ei) {
    auto const& e = out.edges[ei];
    // The edge's ends relative to the eye, a − O = A / L and b − O = B / L:
    // the points A + t·(B − A) are L times those of the edge, t the same.
    auto const &ra = rel_of(e.va, e.a), &rb = rel_of(e.vb, e.b);
    edge_frame<FT> f(ra, rb);
    auto const &A = f.A, &B = f.B;
    auto const& L = f.L;
    auto n = geometry::cross(A, B);
    auto kind = kind_from(e, polygons, o, planes, rel, ra, rb, n);
    out.kinds.push_back(kind);
    if (is_zero3(n)) {
      ++out.stats.edges_through_eye;
      continue;
    }
    if (kind == edge_kind::never) continue;
    if (hidden_whole(e, ra, rb)) {
      ++out.stats.hidden_whole;
      if (kind != edge_kind::smooth)
        out.pieces.push_back({ei, FT(0), FT(1), true, kind == edge_kind::silhouette ? line_class::silhouette : line_class::crease});
      continue;
    }
    auto BA = minus(B, A);
    // The parameter along the edge where a circle through the eye meets it.
    auto t_at = [&](iv3<FT> const& c) { return ratio<FT>(-geometry::dot(c, A), geometry::dot(c, BA)); };

    // Pieces with the faces on their two sides.
    runs.clear();
    below.clear();
    S arc = geometry::s2::arc(direction_of<FT>(A), direction_of<FT>(B));
    bsp::detail::push_down(vm.locator, std::move(arc), vm.locator.root(), -1, below);
    for (auto& [piece, right] : below) {
      across.clear();
      bsp::detail::push_down(vm.locator, std::move(piece), vm.locator.root(), +1, across);
      for (auto& [p, left] : across) {
        if (p.bounds.size() != 2) continue;
        FT t0 = t_at(integers_of(p.bounds.front().original.n)), t1 = t_at(integers_of(p.bounds.back().original.n));
        if (t1 < t0) std::swap(t0, t1);
        if (!(t0 < t1)) continue;
        runs.push_back({std::move(t0), std::move(t1), {label_at(right), label_at(left)}});
      }
    }
    out.stats.arc_pieces += runs.size();
    std::sort(runs.begin(), runs.end(), [](run const& x, run const& y) { return x.t0 < y.t0; });

    // Polygons seen edge-on in the plane of the edge and the eye.
    std::vector<std::uint32_t> const* flat = nullptr;
    if (!edge_on.empty())
      if (auto it = edge_on.find(line_key(to_field<FT>(n))); it != edge_on.end()) flat = &it->second, ++out.stats.edge_on_tests;
    auto incident = [&](std::int64_t q) { return std::find(e.polygons.begin(), e.polygons.end(), static_cast<std::uint32_t>(q)) != e.polygons.end(); };
    // Against edge-on polygons (rare), in the field: the edge's ends and
    // points relative to the eye.
    v3<FT> Af, BAf, nf;
    if (flat) {
      Af = minus(e.a, eye);
      auto Bf = minus(e.b, eye);
      BAf = minus(Bf, Af);
      nf = geometry::cross(Af, Bf);
    }
    auto x_at = [&](FT const& t) { return v3<FT>{Af[0] + t * BAf[0], Af[1] + t * BAf[1], Af[2] + t * BAf[2]}; };
    // Whether the open segment from the eye to x meets edge-on polygon g.
    auto blocks = [&](std::uint32_t g, v3<FT> const& x) {
      auto const& v = polygons[g].vertices;
      auto const N = to_field<FT>(planes[g].n);
      FT lo(0), hi(1);
      for (std::size_t k = 0; k < v.size(); ++k) {
        auto gk = minus(v[k], eye), gl = minus(v[(k + 1) % v.size()], eye);
        // Inside edge k where det(N, gl − gk, s·x − gk) ≥ 0: α + s·β.
        auto w = geometry::cross(N, minus(gl, gk));
        FT alpha = -geometry::dot(w, gk), beta = geometry::dot(w, x);
        if (sgn(beta) == 0) {
          if (sgn(alpha) < 0) return false;
          continue;
        }
        FT s = -alpha / beta;
        if (sgn(beta) > 0) lo = std::max(lo, s);
        else hi = std::min(hi, s);
      }
      return lo < hi;
    };
    sides.clear();
    auto along_of = [&](std::int64_t q) -> along const& {
      for (auto const& s : sides)
        if (s.q == q) return s;
      // L times the plane's value at a, and its change from a to b.
      auto const& pl = planes[q];
      frame_int<FT> fa = geometry::dot(pl.n, A) + pl.d * L, df = geometry::dot(pl.n, BA);
      int sd = sgn(df);
      FT zero = sd == 0 ? FT(0) : ratio<FT>(-fa, df);
      sides.push_back({q, std::move(zero), sgn(fa), sd, sgn(pl.d)});
      return sides.back();
    };
    // Hidden on the open interval (t0, t1), which no cut is inside: a side's
    // plane separates the eye from the points there (its sign there is read
    // off where the interval lies against the plane's zero), or an edge-on
    // polygon blocks the ray to its midpoint.
    auto hidden_on = [&](run const& r, FT const& t0, FT const& t1) {
      for (auto q : r.side) {
        if (q < 0) continue;
        auto const& s = along_of(q);
        int sign = s.sign_df == 0 ? s.sign_fa : (t0 < s.zero ? -s.sign_df : s.sign_df);
        if (sign == -s.sign_eye) return true;
      }
      if (flat) {
        auto x = x_at(FT((t0 + t1) / 2));
        for (auto g : *flat)
          if (!incident(g) && blocks(g, x)) return true;
      }
      return false;
    };
    std::vector<FT> cuts;
    for (auto const& r : runs) {
      if (r.side[0] == clipped || r.side[1] == clipped) continue;
      // Where the sign of a side's plane, or of an edge-on polygon's side, changes inside the run.
      cuts.clear();
      cuts.push_back(r.t0);
      for (auto q : r.side) {
        if (q < 0) continue;
        auto const& s = along_of(q);
        if (s.sign_df != 0 && r.t0 < s.zero && s.zero < r.t1) cuts.push_back(s.zero);
      }
      if (flat)
        for (auto g : *flat)
          for (auto const& vtx : polygons[g].vertices) {
            auto gv = minus(vtx, eye);
            auto c = geometry::cross(nf, gv); // a circle through the vertex's direction
            if (sgn(geometry::dot(c, BAf)) == 0) continue;
            FT t = FT(-geometry::dot(c, Af) / geometry::dot(c, BAf));
            if (r.t0 < t && t < r.t1) cuts.push_back(t);
          }
      cuts.push_back(r.t1);
      std::sort(cuts.begin(), cuts.end());
      cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
      bool outline = false;
      for (auto q : r.side)
        if (q < 0 || !incident(q)) outline = true;
      for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        bool hidden = hidden_on(r, cuts[k], cuts[k + 1]);
        line_class c;
        if (hidden) {
          if (kind == edge_kind::smooth) continue;
          c = kind == edge_kind::silhouette ? line_class::silhouette : kind == edge_kind::boundary ? line_class::boundary : line_class::crease;
        } else {
          if (kind == edge_kind::silhouette) c = line_class::silhouette;
          else if (kind == edge_kind::boundary) c = line_class::boundary;
          else if (outline) c = line_class::outline;
          else if (kind == edge_kind::crease) c = line_class::crease;
          else continue;
        }
        auto& ps = out.pieces;
        if (!ps.empty() && ps.back().edge == ei && ps.back().hidden == hidden && ps.back().cls == c && ps.back().t1 == cuts[k])
          ps.back().t1 = cuts[k + 1];
        else ps.push_back({ei, cuts[k], cuts[k + 1], hidden, c});
      }
    }
  }

  // Visible map edges that are no scene edge: intersection curves, and
  // shadow boundaries (the same polygon on both sides, lit differently).
  // Whether map edge `he` lies on the side a–b of a polygon (its sides
  // whole: a run of scene edges cut at T-junctions may hold one map edge).
  // (Positive multiples of a − O, b − O and the map's vectors will do.)
  // The circle of each polygon side a → b, a positive multiple of
  // (a − O) × (b − O) (primitive over an exact field, as the map's circles
  // are, so that one circle is one vector up to sign), made when first needed.
  std::vector<std::vector<std::optional<iv3<FT>>>> side_circles(polygons.size());
  auto side_circle = [&](std::size_t p, std::size_t k) -> iv3<FT> const& {
    auto& sc = side_circles[p];
    if (sc.empty()) sc.resize(rel[p].size());
    if (!sc[k]) {
      auto const& v = rel[p];
      auto n = geometry::cross(v[k].p, v[(k + 1) % v.size()].p);
      if constexpr (geometry::exact_field<FT>) geometry::detail::make_primitive(n);
      sc[k] = std::move(n);
    }
    return *sc[k];
  };
  auto same_circle = [](iv3<FT> const& c, iv3<FT> const& n) {
    if constexpr (geometry::exact_field<FT>) {
      bool plus = true, minus = true;
      for (std::size_t k = 0; k < 3; ++k) {
        plus = plus && c[k] == n[k];
        minus = minus && c[k] == -n[k];
      }
      return plus || minus;
    } else {
      return is_zero3(geometry::cross(c, n));
    }
  };
  auto on_side = [&](index he, std::size_t p, std::size_t k) {
    auto const& v = rel[p];
    auto const &A = v[k].p, &B = v[(k + 1) % v.size()].p;
    auto const& n = side_circle(p, k);
    if (is_zero3(n)) return false;
    auto const& c = integers_of(m.circles()[m.half_edges()[he].circle].n);
    if (!same_circle(c, n)) return false;
    for (index v : {m.origin(he), m.target(he)}) {
      auto const point = m.point(v);
      auto const& d = integers_of(point);
      if (sgn(geometry::dot(geometry::cross(A, d), n)) < 0 || sgn(geometry::dot(geometry::cross(d, B), n)) < 0) return false;
    }
    return true;
  };
  auto const& he = m.half_edges();
  for (index h = 0; h < he.size(); h += 2) {
    std::int64_t la = m.faces()[he[h].face].label, lb = m.faces()[he[h + 1].face].label;
    if (la == lb || la == clipped || lb == clipped) continue;
    std::int64_t pa = la < 0 ? -1 : static_cast<std::int64_t>(polygon_of(la)), pb = lb < 0 ? -1 : static_cast<std::int64_t>(polygon_of(lb));
    if (pa == pb) {
      if (pa >= 0) out.map_lines.push_back({h, line_class::shadow});
      continue;
    }
    bool known = false;
    for (auto p : {pa, pb}) {
      if (p < 0 || known) continue;
      auto const pi = static_cast<std::size_t>(p);
      for (std::size_t k = 0; k < rel[pi].size() && !known; ++k) known = on_side(h, pi, k);
    }
    if (!known) out.map_lines.push_back({h, line_class::intersection});
  }
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  return out;
}

/// The lines of `polygons` labelled by their own indices in `vm`.
template <geometry::number FT>
line_set<FT> hidden_lines(visibility_map<FT> const& vm, geometry::e3::point<FT> const& eye, std::vector<polygon<FT>> const& polygons,
                          line_options const& o = {}) {
  return hidden_lines(vm, eye, polygons, [](std::int64_t l) { return l; }, o);
}

} // namespace svm
