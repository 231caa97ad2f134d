/// @file
/// From scene faces to the convex planar polygons the algorithms take
/// (`e3::convex_polygon`), each keeping the index of the face it came from.
///
/// Everything is exact and constructs nothing: every output vertex is an input
/// vertex, so the pieces are described by input-derived planes as DESIGN.md §3
/// requires.  Faces that are already strictly convex and planar — the common
/// case — are passed on whole; non-convex and non-planar faces are cut into
/// triangles by ear clipping, and zero-area faces are dropped and counted.
#pragma once

#include "../e3/constructions.hpp"
#include "../e3/predicates.hpp"
#include "../linear.hpp"
#include "scene.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace geometry::io {

/// A strictly convex planar polygon, counter-clockwise seen from its front
/// (the side around which the face's vertex order turns counter-clockwise),
/// so `e3::convex_polygon(vertices)` orients it like the face.
struct polygon {
  std::vector<e3::point<rational>> vertices; ///< input vertices only, none constructed
  std::uint32_t face;                        ///< index of the scene face it is (a piece of)
};

/// The polygons of a scene and what had to be done to obtain them, so that
/// tools can report how much of the input was not usable as given.
struct prepared {
  std::vector<polygon> polygons;      ///< in face order; the pieces of one face are consecutive
  std::size_t degenerate_faces = 0;   ///< faces of zero area, skipped
  std::size_t triangulated_faces = 0; ///< non-convex or non-planar faces cut into triangles
};

namespace detail {

using vec3 = std::array<rational, 3>;
using point3 = e3::point<rational>;

/// Orientation of `a`, `b`, `c` projected along axis `k` onto the coordinates
/// (k+1, k+2) mod 3: positive when counter-clockwise there.  The 3 × 3
/// determinant of their homogeneous (x_{k+1}, x_{k+2}, 1) rows, filtered like
/// every predicate of the library, so no projected point is ever built and most
/// calls never touch a rational.
inline sign turn(std::size_t k, point3 const& a, point3 const& b, point3 const& c) {
  std::size_t i = (k + 1) % 3, j = (k + 2) % 3;
  return filtered_sign(
      [i, j](auto const& x, auto const& y, auto const& z) {
        using T = std::remove_cvref_t<decltype(x[0])>;
        return det3(std::array<T, 3>{x[i], x[j], x[3]}, std::array<T, 3>{y[i], y[j], y[3]},
                    std::array<T, 3>{z[i], z[j], z[3]});
      },
      a.homogeneous(), b.homogeneous(), c.homogeneous());
}

/// Whether `a`, `b`, `c` lie on one line (two of them equal included): then,
/// and only then, all three coordinate projections are flat.
inline bool collinear(point3 const& a, point3 const& b, point3 const& c) {
  return turn(0, a, b, c) == sign::zero && turn(1, a, b, c) == sign::zero && turn(2, a, b, c) == sign::zero;
}

/// Whether `a` and `b` project along axis `k` to the same point.
inline bool same_projection(std::size_t k, point3 const& a, point3 const& b) {
  return a[(k + 1) % 3] == b[(k + 1) % 3] && a[(k + 2) % 3] == b[(k + 2) % 3];
}

/// Removes repeated consecutive vertices, then, until none is left, vertices
/// collinear with their neighbours (straight vertices and spikes): neither
/// changes the face's area, and both would make degenerate edges.  Removing
/// one vertex can make its neighbours removable, hence the loop.  Repeats go
/// first so that a face still starts at its first vertex when it can.
inline void clean(std::vector<point3>& v) {
  v.erase(std::unique(v.begin(), v.end()), v.end());
  while (v.size() >= 2 && v.back() == v.front()) v.pop_back();
  std::size_t i = 0, good = 0; // `good`: consecutive vertices checked and kept
  while (v.size() >= 3 && good < v.size()) {
    std::size_t n = v.size();
    i %= n;
    if (collinear(v[(i + n - 1) % n], v[i], v[(i + 1) % n])) {
      v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
      if (i > 0) --i; // the predecessor has a new neighbour: check it again
      good = 0;
    } else {
      ++i;
      ++good;
    }
  }
}

/// Twice the vector area of the closed polygon `v` (Newell's normal), exact:
/// its k-th component is twice the signed area of the projection along axis
/// k, in the coordinates (k+1, k+2) mod 3.  Only non-convex and non-planar
/// faces need it: it is the one sum over all vertices that the filter cannot take.
inline vec3 newell(std::vector<point3> const& v) {
  vec3 n{rational(0), rational(0), rational(0)};
  for (std::size_t i = 0; i < v.size(); ++i) {
    auto const &p = v[i], &q = v[(i + 1) % v.size()];
    n[0] += p.y() * q.z() - p.z() * q.y();
    n[1] += p.z() * q.x() - p.x() * q.z();
    n[2] += p.x() * q.y() - p.y() * q.x();
  }
  return n;
}

/// The axis along which the normal `n` (x, y, z first) is largest: projecting
/// along it maps the face's plane one to one onto a coordinate plane.
template <class Normal> std::size_t dominant(Normal const& n) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < 3; ++i)
    if (abs(n[i]) > abs(n[k])) k = i;
  return k;
}

/// For a planar polygon `v` (cleaned, no flat corner) projected along `k`:
/// the sign of its area when it is strictly convex, zero otherwise.  Strictly
/// convex means every corner turns the same way and the boundary winds once —
/// it has one lexicographic maximum, which rules out the pentagram, whose
/// every corner also turns the same way.
inline sign convex_turn(std::vector<point3> const& v, std::size_t k) {
  std::size_t n = v.size(), i0 = (k + 1) % 3, i1 = (k + 2) % 3, maxima = 0;
  auto less = [i0, i1](point3 const& a, point3 const& b) { return a[i0] < b[i0] || (a[i0] == b[i0] && a[i1] < b[i1]); };
  sign s = sign::zero;
  for (std::size_t i = 0; i < n; ++i) {
    auto const &a = v[(i + n - 1) % n], &b = v[i], &c = v[(i + 1) % n];
    sign t = turn(k, a, b, c);
    if (t == sign::zero || (i > 0 && t != s)) return sign::zero;
    s = t;
    if (less(a, b) && less(c, b)) ++maxima;
  }
  return maxima == 1 ? s : sign::zero;
}

/// Cuts the polygon `v` (cleaned, at least 3 vertices) into triangles by ear
/// clipping in its projection along axis `k`, where its area has sign `s` ≠ 0.
///
/// A simple polygon always has an ear (Meisters' two-ears theorem), and only
/// a reflex vertex can lie in a candidate ear, so only those are tested.
/// Vertices that become straight in the projection are removed without loss of
/// area.  Input that is not simple in the projection (self-intersecting or
/// non-planar faces) may have no ear: then a vertex is clipped anyway, so the
/// loop always ends; for planar faces such a triangle is turned to face the
/// same side as the face.  For non-planar faces each triangle keeps the face's
/// vertex order, and one that is flat only in the projection is kept.
inline void ear_clip(std::vector<point3> const& v, std::size_t k, sign s, bool planar, std::uint32_t face,
                     std::vector<polygon>& out) {
  std::size_t n = v.size();
  std::vector<std::size_t> prev(n), next(n);
  for (std::size_t i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
  std::vector<sign> corner(n); // turn at each remaining vertex, kept up to date
  auto update = [&](std::size_t i) { corner[i] = turn(k, v[prev[i]], v[i], v[next[i]]); };
  for (std::size_t i = 0; i < n; ++i) update(i);

  auto emit = [&](std::size_t i) {
    std::size_t a = prev[i], c = next[i];
    if (planar) {
      if (corner[i] == sign::zero) return;
      if (corner[i] == s)
        out.push_back({{v[a], v[i], v[c]}, face});
      else
        out.push_back({{v[a], v[c], v[i]}, face});
    } else if (!collinear(v[a], v[i], v[c])) {
      out.push_back({{v[a], v[i], v[c]}, face});
    }
  };
  auto unlink = [&](std::size_t i) {
    std::size_t a = prev[i], c = next[i];
    next[a] = c;
    prev[c] = a;
    update(a);
    update(c);
  };
  // Closed triangle a b c of orientation s.
  auto inside = [&](point3 const& a, point3 const& b, point3 const& c, point3 const& p) {
    return turn(k, a, b, p) != -s && turn(k, b, c, p) != -s && turn(k, c, a, p) != -s;
  };
  auto is_ear = [&](std::size_t i) {
    std::size_t a = prev[i], c = next[i];
    for (std::size_t j = next[c]; j != a; j = next[j]) {
      if (corner[j] == s) continue;
      // A vertex repeated at a or c (a bridge to a hole) touches the ear without entering it.
      if (same_projection(k, v[j], v[a]) || same_projection(k, v[j], v[c])) continue;
      if (inside(v[a], v[i], v[c], v[j])) return false;
    }
    return true;
  };

  std::size_t remaining = n, i = 0, misses = 0;
  while (remaining > 3) {
    if (corner[i] == sign::zero || (corner[i] == s && is_ear(i))) {
      emit(i);
    } else if (++misses < remaining) {
      i = next[i];
      continue;
    } else {
      // No ear in a whole turn: not simple in the projection.  Prefer a convex vertex.
      std::size_t j = i;
      for (std::size_t m = 0; m < remaining && corner[j] != s; ++m) j = next[j];
      i = corner[j] == s ? j : i;
      emit(i);
    }
    std::size_t p = prev[i];
    unlink(i);
    --remaining;
    i = p;
    misses = 0;
  }
  emit(i);
}

/// The pieces of one face: at most one polygon when it is convex and planar.
/// Returns false for a face of zero area; sets `triangulated` when it was cut.
inline bool convert(std::vector<point3> v, std::uint32_t face, std::vector<polygon>& out, bool& triangulated) {
  triangulated = false;
  // Triangles, the common case (all of STL), need one test: with three points
  // "repeated or collinear" is just "collinear".
  if (v.size() == 3 && !collinear(v[0], v[1], v[2])) {
    out.push_back({std::move(v), face});
    return true;
  }
  clean(v);
  std::size_t n = v.size();
  if (n < 3) return false;
  if (n == 3) { // what is left of a cleaned face is a true triangle
    out.push_back({std::move(v), face});
    return true;
  }
  // After cleaning no corner is flat: the plane of any corner is a true plane.
  auto plane = e3::plane_through(v[n - 1], v[0], v[1]);
  bool planar = true;
  for (std::size_t i = 2; i + 1 < n && planar; ++i) planar = e3::side(plane, v[i]) == oriented_side::on;
  std::size_t before = out.size();

  if (planar) {
    std::size_t k = dominant(plane.n);
    if (convex_turn(v, k) != sign::zero) {
      out.push_back({std::move(v), face});
      return true;
    }
    vec3 nw = newell(v);
    if (nw[k] == 0) return false; // a figure eight whose lobes cancel: no area, no front
    ear_clip(v, k, sign_of(nw[k]), true, face, out);
  } else {
    bool fan = true; // a fan from the first vertex, when none of its triangles is flat
    for (std::size_t i = 1; i + 1 < n && fan; ++i) fan = !collinear(v[0], v[i], v[i + 1]);
    vec3 nw;
    if (fan) {
      for (std::size_t i = 1; i + 1 < n; ++i) out.push_back({{v[0], v[i], v[i + 1]}, face});
    } else if (nw = newell(v); nw[0] != 0 || nw[1] != 0 || nw[2] != 0) {
      std::size_t k = dominant(nw);
      ear_clip(v, k, sign_of(nw[k]), false, face, out);
    } else {
      // Every projection has zero signed area: no side to keep; the fan without its flat triangles.
      for (std::size_t i = 1; i + 1 < n; ++i)
        if (!collinear(v[0], v[i], v[i + 1])) out.push_back({{v[0], v[i], v[i + 1]}, face});
    }
  }
  triangulated = true;
  return out.size() > before;
}

} // namespace detail

/// The convex planar polygons of a scene's faces, in face order, each with its
/// face index.  Exact throughout:
///
/// 1. repeated consecutive vertices and vertices collinear with their
///    neighbours are dropped; fewer than 3 left, or zero signed area, and the
///    face is skipped and counted in `degenerate_faces`;
/// 2. a planar, strictly convex face is kept whole, its vertex order kept;
/// 3. a planar non-convex face is cut by ear clipping in its projection along
///    the dominant axis of its normal, the sign of its exact Newell normal
///    telling its front; the triangles face the same side as the face and,
///    when the face is a simple polygon (holes joined by bridges allowed),
///    their union is the face; a self-intersecting face still gives valid
///    triangles, which need not tile it exactly;
/// 4. a non-planar face is cut into the fan from its first vertex when no
///    triangle of the fan is flat, otherwise by ear clipping as in 3.
///
/// Faces cut in 3 and 4 are counted in `triangulated_faces`.  Throws
/// `std::out_of_range` for a face that refers to a missing vertex (possible
/// only for a scene built by hand: the readers check indices).
inline prepared convex_polygons(scene const& s) {
  prepared out;
  out.polygons.reserve(s.faces.size());
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    std::vector<e3::point<rational>> v;
    v.reserve(s.faces[f].vertices.size());
    for (auto i : s.faces[f].vertices) {
      if (i >= s.vertices.size())
        throw std::out_of_range(detail::cat("geometry::io::convex_polygons: face ", std::to_string(f),
                                            " refers to vertex ", std::to_string(i), " of ",
                                            std::to_string(s.vertices.size())));
      v.push_back(s.vertices[i]);
    }
    bool triangulated = false;
    if (!detail::convert(std::move(v), static_cast<std::uint32_t>(f), out.polygons, triangulated))
      ++out.degenerate_faces;
    else if (triangulated)
      ++out.triangulated_faces;
  }
  return out;
}

} // namespace geometry::io
