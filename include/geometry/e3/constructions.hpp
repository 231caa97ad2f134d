/// @file
/// Constructions of E3: planes through points, convex polygons and polyhedra,
/// splitting by a plane, and exact evaluation of implicit vertices.
#pragma once

#include "../detail/split.hpp"
#include "predicates.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <tuple>
#include <stdexcept>
#include <vector>

namespace geometry::detail {

/// The plane through three homogeneous points (any positive multiples of
/// theirs), oriented as `plane_through`: the vector of the signed 3 × 3
/// minors, of degree 3 in the input.  A point at infinity (w = 0) is a
/// direction the plane contains.
template <number FT> hvec<FT, 4> plane_of(hvec<FT, 4> const& p, hvec<FT, 4> const& q, hvec<FT, 4> const& r) {
  return construct<4>(
      [](auto const& P, auto const& Q, auto const& R) {
        auto minor = [&](std::size_t i, std::size_t j, std::size_t k) {
          return P[i] * (Q[j] * R[k] - Q[k] * R[j]) - P[j] * (Q[i] * R[k] - Q[k] * R[i]) + P[k] * (Q[i] * R[j] - Q[j] * R[i]);
        };
        return std::array<std::remove_cvref_t<decltype(P[0])>, 4>{minor(1, 2, 3), -minor(0, 2, 3), minor(0, 1, 3), -minor(0, 1, 2)};
      },
      p, q, r);
}

/// The direction of axis `k` (a point at infinity), made once: a copy shares its numbers.
template <number FT> hvec<FT, 4> const& axis_direction(std::size_t k) {
  static hvec<FT, 4> const axes[3] = {hvec<FT, 4>(std::array<FT, 4>{FT(1), FT(0), FT(0), FT(0)}),
                                      hvec<FT, 4>(std::array<FT, 4>{FT(0), FT(1), FT(0), FT(0)}),
                                      hvec<FT, 4>(std::array<FT, 4>{FT(0), FT(0), FT(1), FT(0)})};
  return axes[k];
}

} // namespace geometry::detail

namespace geometry::e3 {

/// The plane through `p`, `q`, `r`, positive on the side from which they turn counter-clockwise.
template <number FT>
hyperplane<FT> plane_through(point<FT> const& p, point<FT> const& q, point<FT> const& r, hyperplane_tag tag = no_tag) {
  return hyperplane<FT>(detail::plane_of(p.homogeneous(), q.homogeneous(), r.homogeneous()), tag);
}

/// The plane at infinity, positive on the whole space.
template <number FT> hyperplane<FT> plane_at_infinity() {
  return hyperplane<FT>(hvec<FT, 4>(std::array<FT, 4>{FT(0), FT(0), FT(0), FT(1)}));
}

/// @name Convex polygons
/// @{

/// The whole plane `h` as a sub-hyperplane.
template <number FT> sub_hyperplane<FT> whole_plane(hyperplane<FT> const& h) {
  std::size_t k = dominant_axis(h.n);
  auto inf = plane_at_infinity<FT>();
  return {h, k, {polygon_bound<FT>{inf, restrict_to(h.n, k, inf.n)}}};
}

/// The same point set with the opposite orientation.
template <number FT> sub_hyperplane<FT> opposite(sub_hyperplane<FT> const& s) { return detail::opposite_piece(s); }

/// The parts of the polygon `s` on either side of `h`, or its coincidence with `h`.
template <number FT> split_result<sub_hyperplane<FT>> split(sub_hyperplane<FT> const& s, hyperplane<FT> const& h) {
  return detail::split_piece(s, h, detail::polygon_split);
}

/// The plane through the edge `p`–`q` that contains the direction of axis `k`
/// (degree 2 in the input), oriented so that `inside` is on its positive side.
template <number FT>
hyperplane<FT> edge_plane(point<FT> const& p, point<FT> const& q, std::size_t k, point<FT> const& inside) {
  hyperplane<FT> b(detail::plane_of(p.homogeneous(), q.homogeneous(), detail::axis_direction<FT>(k)));
  return side(b, inside) == oriented_side::negative ? b.opposite() : b;
}

} // namespace geometry::e3

namespace geometry::detail {

/// The convex polygon by splitting its plane along each edge in turn (any
/// polygon whose edge planes cut a region, strictly convex or not).
template <number FT>
e3::sub_hyperplane<FT> convex_polygon_by_splits(std::vector<e3::point<FT>> const& v, e3::hyperplane<FT> const& support, std::size_t k) {
  std::size_t n = v.size();
  std::optional<e3::sub_hyperplane<FT>> s = e3::whole_plane(support);
  for (std::size_t i = 0; i < n && s; ++i) {
    auto const& inside = v[(i + 2) % n];
    s = e3::split(*s, e3::edge_plane(v[i], v[(i + 1) % n], k, inside)).positive;
  }
  if (!s) throw std::invalid_argument("e3::convex_polygon: vertices are not convex");
  return *s;
}

} // namespace geometry::detail

namespace geometry::e3 {

/// The convex polygon with the given vertices (strictly convex, planar),
/// oriented so that they turn counter-clockwise seen from its positive side.
/// Bounding planes are input-derived (degree 2 in the vertices' coordinates,
/// degree 3 in their homogeneous ones).  Throws `std::invalid_argument` for
/// fewer than 3 vertices or collinear first three.
///
/// Each edge plane is made directly (the plane through the edge and the
/// direction of the axis eliminated by the restriction), and kept when every
/// other vertex lies strictly on its positive side; a polygon for which that
/// fails (collinear vertices, say) is cut out of its plane edge by edge.
template <number FT> sub_hyperplane<FT> convex_polygon(std::vector<point<FT>> const& v, hyperplane_tag tag = no_tag) {
  std::size_t n = v.size();
  if (n < 3) throw std::invalid_argument("e3::convex_polygon needs at least 3 vertices");
  auto support = plane_through(v[0], v[1], v[2], tag);
  if (support.n.sign_at(0) == sign::zero && support.n.sign_at(1) == sign::zero && support.n.sign_at(2) == sign::zero)
    throw std::invalid_argument("e3::convex_polygon: the first three vertices are collinear");
  // Project along the largest normal component: the edge planes then contain that axis.
  std::size_t k = 0;
  for (std::size_t i = 1; i < 3; ++i)
    if (support.n.abs_greater(i, k)) k = i;
  // The polygon's own restriction eliminates the largest of all four
  // coefficients, as `whole_plane`'s does.
  sub_hyperplane<FT> s{support, dominant_axis(support.n), {}};
  s.bounds.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    // Every other vertex strictly on the positive side, or the slow way.
    auto b = edge_plane(v[i], v[(i + 1) % n], k, v[(i + 2) % n]);
    for (std::size_t j = 2; j < n; ++j)
      if (side(b, v[(i + j) % n]) != oriented_side::positive) return detail::convex_polygon_by_splits(v, support, k);
    auto line = restrict_to(support.n, s.axis, b.n);
    s.bounds.push_back({std::move(b), std::move(line)});
  }
  return s;
}

/// The homogeneous vertices of a polygon (w = 0 at infinity); none when it has fewer than two bounds.
template <number FT> std::vector<hvec<FT, 4>> homogeneous_vertices(sub_hyperplane<FT> const& s) {
  std::vector<hvec<FT, 4>> out;
  std::size_t k = s.bounds.size();
  if (k < 2) return out;
  for (std::size_t i = 0; i < k; ++i) {
    out.push_back(lift(s.support.n, s.axis, cross(s.bounds[i].line(), s.bounds[(i + 1) % k].line())));
  }
  return out;
}

/// The vertices of a bounded polygon, exact; nothing when it is unbounded.
template <number FT> std::optional<std::vector<point<FT>>> vertices(sub_hyperplane<FT> const& s) {
  auto hv = homogeneous_vertices(s);
  if (hv.empty()) return std::nullopt;
  std::vector<point<FT>> out;
  for (auto const& x : hv) {
    if (x.sign_at(3) != sign::positive) return std::nullopt;
    if constexpr (exact_field<FT>) {
      auto const& z = x.integers(); // one canonical fraction a coordinate
      out.emplace_back(FT(z[0], z[3]), FT(z[1], z[3]), FT(z[2], z[3]));
    } else {
      out.emplace_back(FT(x[0] / x[3]), FT(x[1] / x[3]), FT(x[2] / x[3]));
    }
  }
  return out;
}

/// Signed area of a bounded polygon projected on the coordinate plane
/// perpendicular to axis `k` (exact over exact fields).
template <number FT> std::optional<FT> projected_area(sub_hyperplane<FT> const& s, std::size_t k) {
  auto v = vertices(s);
  if (!v) return std::nullopt;
  std::size_t i = (k + 1) % 3, j = (k + 2) % 3;
  FT twice(0);
  for (std::size_t a = 0; a < v->size(); ++a) {
    auto const &p = (*v)[a], &q = (*v)[(a + 1) % v->size()];
    twice = twice + (p[i] * q[j] - p[j] * q[i]);
  }
  return FT(twice / FT(2));
}

/// @}

/// @name Convex polyhedra
/// @{

/// The whole space.
template <number FT> polytope<FT> whole_space() { return {}; }

/// −1 or +1 when every vertex of the polygon `f` (three bounds or more)
/// lies strictly on that side of `h`, as `split` would see them; 0 otherwise
/// (it touches or crosses `h`, or has fewer bounds).  Constructs nothing.
template <number FT> int strict_side(sub_hyperplane<FT> const& f, hyperplane<FT> const& h) {
  std::size_t n = f.bounds.size();
  if (n < 3) return 0;
  int side = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sign s = restricted_det_sign(f.support.n, f.axis, h.n, f.bounds[i].line(), f.bounds[(i + 1) % n].line());
    int v = s == sign::positive ? 1 : s == sign::negative ? -1 : 0;
    if (v == 0 || (side != 0 && v != side)) return 0;
    side = v;
  }
  return side;
}

/// The parts of `c` on either side of `h`.  The new face of both parts is `h`
/// within `c`: the plane `h` cut by the planes of `c`'s faces.  A face whose
/// every vertex lies strictly on one side of `h` (found without constructing
/// anything) goes to that side whole, and its plane, which cannot meet `h`
/// within `c`, is left out of the new face's cuts; only the faces that touch
/// or cross `h` are cut.  When every face lies strictly on one side, `h`
/// misses `c`, which goes to that side.
template <number FT> split_result<polytope<FT>> split(polytope<FT> const& c, hyperplane<FT> const& h) {
  split_result<polytope<FT>> out;
  for (auto const& f : c.faces) {
    sign par = parallel(f.support.n, h.n);
    if (par == sign::zero) continue;
    (par == sign::positive ? out.positive : out.negative) = c;
    return out;
  }
  std::vector<int> side(c.faces.size());
  int low = 1, high = -1; // the least and greatest face sides
  for (std::size_t i = 0; i < c.faces.size(); ++i) {
    side[i] = strict_side(c.faces[i], h);
    low = std::min(low, side[i]), high = std::max(high, side[i]);
  }
  if (!c.faces.empty() && low == high && low != 0) {
    // Every face wholly on one side, strictly: h misses the polyhedron.
    (low < 0 ? out.negative : out.positive) = c;
    return out;
  }
  if (!c.faces.empty() && low != 0 && high != 0) std::fill(side.begin(), side.end(), 0); // cannot happen; cut by every face
  std::optional<sub_hyperplane<FT>> section = whole_plane(h);
  for (std::size_t i = 0; i < c.faces.size() && section; ++i)
    if (side[i] == 0) section = split(*section, c.faces[i].support).positive;
  polytope<FT> neg, pos;
  for (std::size_t i = 0; i < c.faces.size(); ++i) {
    auto const& f = c.faces[i];
    if (side[i] != 0) {
      (side[i] < 0 ? neg : pos).faces.push_back(f);
      continue;
    }
    auto r = split(f, h);
    if (r.negative) neg.faces.push_back(std::move(*r.negative));
    if (r.positive) pos.faces.push_back(std::move(*r.positive));
  }
  if (!section) {
    if (!pos.faces.empty()) out.positive = c;
    else out.negative = c;
    return out;
  }
  neg.faces.push_back(opposite(*section));
  pos.faces.push_back(std::move(*section));
  out.negative = std::move(neg);
  out.positive = std::move(pos);
  return out;
}

/// The axis-aligned box [lo, hi] (lo < hi in every coordinate).
template <number FT> polytope<FT> box(point<FT> const& lo, point<FT> const& hi) {
  polytope<FT> c = whole_space<FT>();
  for (std::size_t k = 0; k < 3; ++k) {
    std::array<FT, 4> a{FT(0), FT(0), FT(0), FT(-lo[k])}, b{FT(0), FT(0), FT(0), FT(hi[k])};
    a[k] = FT(1);
    b[k] = FT(-1);
    c = *split(c, hyperplane<FT>(hvec<FT, 4>(a))).positive;
    c = *split(c, hyperplane<FT>(hvec<FT, 4>(b))).positive;
  }
  return c;
}

/// Volume of a bounded polyhedron, exact over exact fields; nothing when unbounded.
template <number FT> std::optional<FT> volume(polytope<FT> const& c) {
  if (c.faces.empty()) return std::nullopt;
  if constexpr (exact_field<FT>) {
    // On the vertices' integer homogeneous coordinates: the pyramid from a
    // vertex o of the cell over the fan triangle (a, b, e) of a face has 6 ×
    // volume |det4(o, a, b, e)| / (w_o·w_a·w_b·w_e), and only the sum of a
    // face's fan is a rational.
    std::vector<std::vector<hvec<FT, 4>>> fv;
    for (auto const& f : c.faces) {
      auto hv = homogeneous_vertices(f);
      if (hv.empty()) return std::nullopt;
      for (auto const& x : hv)
        if (x.sign_at(3) != sign::positive) return std::nullopt;
      fv.push_back(std::move(hv));
    }
    auto const& o = fv[0][0].integers();
    FT six(0);
    for (auto const& v : fv) {
      FT face(0);
      auto const& a = v[0].integers();
      for (std::size_t i = 1; i + 1 < v.size(); ++i) {
        auto const &b = v[i].integers(), &e = v[i + 1].integers();
        integer n = det4(o, a, b, e);
        if (n == 0) continue;
        face += FT(n, integer(o[3] * a[3] * b[3] * e[3]));
      }
      six += sign_of(face) == sign::negative ? FT(-face) : face;
    }
    return FT(six / FT(6));
  }
  std::vector<std::vector<point<FT>>> fv;
  FT cx(0), cy(0), cz(0);
  std::size_t count = 0;
  for (auto const& f : c.faces) {
    auto v = vertices(f);
    if (!v) return std::nullopt;
    for (auto const& p : *v) cx = cx + p.x(), cy = cy + p.y(), cz = cz + p.z(), ++count;
    fv.push_back(std::move(*v));
  }
  point<FT> o(FT(cx / FT(static_cast<long>(count))), FT(cy / FT(static_cast<long>(count))),
              FT(cz / FT(static_cast<long>(count))));
  FT six(0);
  for (auto const& v : fv) {
    FT face(0); // 6 × signed volume of the pyramid from o over this face
    for (std::size_t i = 1; i + 1 < v.size(); ++i) {
      std::array<FT, 3> a{FT(v[0].x() - o.x()), FT(v[0].y() - o.y()), FT(v[0].z() - o.z())};
      std::array<FT, 3> b{FT(v[i].x() - o.x()), FT(v[i].y() - o.y()), FT(v[i].z() - o.z())};
      std::array<FT, 3> d{FT(v[i + 1].x() - o.x()), FT(v[i + 1].y() - o.y()), FT(v[i + 1].z() - o.z())};
      face = face + det3(a, b, d);
    }
    six = six + (sign_of(face) == sign::negative ? FT(-face) : face);
  }
  return FT(six / FT(6));
}

/// @}

} // namespace geometry::e3

namespace geometry::detail {

/// The vertices of the bounded polygon `s` in doubles, computed from the
/// doubles of its planes as `homogeneous_vertices` computes them exactly (no
/// exact construction: for estimates, such as where to cut); false when a
/// vertex is at infinity or the doubles fail.
template <number FT> bool approximate_vertices(e3::sub_hyperplane<FT> const& s, std::vector<std::array<double, 3>>& out) {
  out.clear();
  std::size_t n = s.bounds.size(), k = s.axis;
  if (n < 3) return false;
  auto P = unit_doubles(s.support.n);
  if (!P) return false;
  bool flip = restriction_flips(s.support.n, k), neg = s.support.n.sign_at(k) == sign::negative;
  std::vector<std::array<double, 3>> lines(n);
  for (std::size_t i = 0; i < n; ++i) {
    auto l = unit_doubles(s.bounds[i].line());
    if (!l) return false;
    lines[i] = *l;
  }
  for (std::size_t i = 0; i < n; ++i) {
    auto r = lift_values<4>(*P, k, flip, neg, cross(lines[i], lines[(i + 1) % n]));
    if (!(r[3] > 0)) return false;
    std::array<double, 3> v{r[0] / r[3], r[1] / r[3], r[2] / r[3]};
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) return false;
    out.push_back(v);
  }
  return true;
}

} // namespace geometry::detail

namespace geometry::e3 {

/// The free cut of `bsp::balanced` for polygons in space: of the three
/// planes perpendicular to an axis through the median of the pieces' vertex
/// coordinates along it (rounded to 24 bits of the spread: a constant of
/// bounded size, so predicates keep their degree bound), the one that
/// crosses the fewest pieces' boxes, among those leaving at least one piece
/// in eight wholly on either side; nothing when none does.  Through a
/// vertex coordinate, such a cut often crosses no piece at all: between the
/// rings of a sphere, along the lines of a grid.
template <number FT> struct axis_median_cut {
  /// `items`: a vector of sub-hyperplanes, or of objects with a member `piece` (a sub-hyperplane).
  template <class Items> std::optional<hyperplane<FT>> operator()(Items const& items) const {
    auto piece = [](auto const& item) -> sub_hyperplane<FT> const& {
      if constexpr (requires { item.piece; })
        return item.piece;
      else
        return item;
    };
    std::size_t n = items.size();
    std::vector<std::array<double, 6>> box(n); // lo x y z, hi x y z
    // Each vertex coordinate with its piece and vertex: (value, piece, index).
    std::array<std::vector<std::tuple<double, std::uint32_t, std::uint32_t>>, 3> coordinates;
    std::array<double, 3> lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    std::vector<std::array<double, 3>> vertices;
    for (std::size_t i = 0; i < n; ++i) {
      auto& b = box[i];
      b = {HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
      // Unbounded pieces (or doubles out of range): leave it to autopartition.
      if (!detail::approximate_vertices(piece(items[i]), vertices)) return std::nullopt;
      for (std::uint32_t v = 0; v < vertices.size(); ++v) {
        auto const& x = vertices[v];
        for (std::size_t k = 0; k < 3; ++k) {
          double c = x[k];
          coordinates[k].emplace_back(c, static_cast<std::uint32_t>(i), v);
          b[k] = std::min(b[k], c), b[k + 3] = std::max(b[k + 3], c);
        }
      }
      for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], b[k]), hi[k] = std::max(hi[k], b[k + 3]);
    }
    std::optional<std::pair<std::size_t, double>> best; // axis, position
    std::size_t best_crossed = n + 1;
    for (std::size_t k = 0; k < 3; ++k) {
      double spread = hi[k] - lo[k];
      if (!(spread > 0)) continue;
      auto& c = coordinates[k];
      std::nth_element(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(c.size() / 2), c.end());
      // The median vertex's coordinate, from its exact construction (the
      // doubles of a vertex between nearly parallel edges are poor).
      auto [approximate, i, v] = c[c.size() / 2];
      auto x = homogeneous_vertices(piece(items[i]))[v];
      double median = to_double(x[k]) / to_double(x[3]);
      if (!std::isfinite(median)) median = approximate;
      int e = std::ilogb(spread);
      double at = std::ldexp(std::round(std::ldexp(median, 24 - e)), e - 24);
      // Boxes from doubles: a vertex on the cut may come out a little off it.
      double tolerance = spread * 1e-9;
      std::size_t below = 0, above = 0;
      for (auto const& b : box) below += b[k + 3] <= at + tolerance, above += b[k] >= at - tolerance;
      if (below * 8 < n || above * 8 < n) continue;
      std::size_t crossed = n - below - above;
      if (crossed < best_crossed) best = std::pair{k, at}, best_crossed = crossed;
    }
    if (!best) return std::nullopt;
    std::array<FT, 4> h{FT(0), FT(0), FT(0), FT(-1) * FT(best->second)};
    h[best->first] = FT(1);
    return hyperplane<FT>(hvec<FT, 4>(h));
  }
};

} // namespace geometry::e3
