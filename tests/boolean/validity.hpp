// An independent checker of the simple-features rules for polygons with
// holes: plain rational arithmetic on coordinates, none of the library's
// predicates.  Returns the first rule broken, or an empty string.
#pragma once

#include "../support.hpp"

#include <boolean/rings.hpp>

#include <algorithm>
#include <string>

namespace test {

using geometry::rational;
using pt = boolean::point2;

inline rational cross3(pt const& a, pt const& b, pt const& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}
inline bool on_segment(pt const& a, pt const& b, pt const& p) {
  return cross3(a, b, p) == 0 && std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

/// Whether segments ab and cd share a point other than a common endpoint.
inline bool improper_contact(pt const& a, pt const& b, pt const& c, pt const& d) {
  int d1 = sgn(cross3(a, b, c)), d2 = sgn(cross3(a, b, d)), d3 = sgn(cross3(c, d, a)), d4 = sgn(cross3(c, d, b));
  if (d1 * d2 < 0 && d3 * d4 < 0) return true; // proper crossing
  auto shared = [](pt const& p, pt const& q, pt const& r, pt const& s) { return p == r || p == s || q == r || q == s; };
  // Touching: an endpoint of one on the other, other than at a shared endpoint.
  if (on_segment(a, b, c) && c != a && c != b) return true;
  if (on_segment(a, b, d) && d != a && d != b) return true;
  if (on_segment(c, d, a) && a != c && a != d) return true;
  if (on_segment(c, d, b) && b != c && b != d) return true;
  // Collinear overlap with both ends shared: the same segment twice.
  return shared(a, b, c, d) && ((a == c && b == d) || (a == d && b == c));
}

/// Whether collinear segments pq and rs overlap in more than a point.
inline bool overlap_length(pt const& p, pt const& q, pt const& r, pt const& s) {
  bool use_x = p.x() != q.x();
  auto key = [&](pt const& a) { return use_x ? a.x() : a.y(); };
  rational lo = std::max(std::min(key(p), key(q)), std::min(key(r), key(s)));
  rational hi = std::min(std::max(key(p), key(q)), std::max(key(r), key(s)));
  return lo < hi;
}

inline rational twice_area(boolean::ring const& r) {
  rational s(0);
  for (std::size_t i = 0; i < r.size(); ++i) s += r[i].x() * r[(i + 1) % r.size()].y() - r[i].y() * r[(i + 1) % r.size()].x();
  return s;
}

/// Even-odd crossing test; `p` must not lie on the ring.
inline bool strictly_inside(boolean::ring const& r, pt const& p) {
  bool in = false;
  for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
    auto const &a = r[i], &b = r[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      rational x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) in = !in;
    }
  }
  return in;
}
inline bool on_ring(boolean::ring const& r, pt const& p) {
  for (std::size_t i = 0; i < r.size(); ++i)
    if (on_segment(r[i], r[(i + 1) % r.size()], p)) return true;
  return false;
}

inline std::string ring_problem(boolean::ring const& r) {
  std::size_t n = r.size();
  if (n < 3) return "a ring with fewer than 3 vertices";
  for (std::size_t i = 0; i < n; ++i) {
    if (r[i] == r[(i + 1) % n]) return "a repeated vertex";
    if (cross3(r[(i + n - 1) % n], r[i], r[(i + 1) % n]) == 0) return "a collinear vertex or a spike";
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      auto const &a = r[i], &b = r[(i + 1) % n], &c = r[j], &d = r[(j + 1) % n];
      if (adjacent) {
        if (on_segment(a, b, j == i + 1 ? d : c) && n > 3) return "a ring folds back on itself";
        continue;
      }
      if (improper_contact(a, b, c, d)) return "a ring touches or crosses itself";
      if (a == c || a == d || b == c || b == d) return "a ring passes twice through a vertex";
    }
  return {};
}

/// The first rule that `m` breaks, or "".
inline std::string validity_problem(boolean::multipolygon const& m) {
  std::vector<boolean::ring const*> all;
  for (auto const& p : m) {
    if (auto s = ring_problem(p.outer); !s.empty()) return s;
    if (twice_area(p.outer) <= 0) return "an outer ring that is not counter-clockwise";
    all.push_back(&p.outer);
    for (auto const& h : p.holes) {
      if (auto s = ring_problem(h); !s.empty()) return s;
      if (twice_area(h) >= 0) return "a hole that is not clockwise";
      bool some_inside = false;
      for (auto const& v : h) {
        if (on_ring(p.outer, v)) continue;
        if (!strictly_inside(p.outer, v)) return "a hole outside its outer ring";
        some_inside = true;
      }
      if (!some_inside) return "a hole with no vertex strictly inside its outer ring";
      all.push_back(&h);
    }
  }
  // Rings of the set never cross or overlap along edges (touching at vertices is allowed).
  struct box {
    rational x0, y0, x1, y1;
  };
  std::vector<box> boxes;
  for (auto const* r : all) {
    box b{(*r)[0].x(), (*r)[0].y(), (*r)[0].x(), (*r)[0].y()};
    for (auto const& v : *r) {
      b.x0 = std::min(b.x0, v.x()), b.y0 = std::min(b.y0, v.y());
      b.x1 = std::max(b.x1, v.x()), b.y1 = std::max(b.y1, v.y());
    }
    boxes.push_back(b);
  }
  auto apart = [&](std::size_t a, std::size_t b) {
    return boxes[a].x1 < boxes[b].x0 || boxes[b].x1 < boxes[a].x0 || boxes[a].y1 < boxes[b].y0 || boxes[b].y1 < boxes[a].y0;
  };
  for (std::size_t a = 0; a < all.size(); ++a)
    for (std::size_t b = a + 1; b < all.size(); ++b)
      if (!apart(a, b))
      for (std::size_t i = 0; i < all[a]->size(); ++i)
        for (std::size_t j = 0; j < all[b]->size(); ++j) {
          auto const &p = (*all[a])[i], &q = (*all[a])[(i + 1) % all[a]->size()];
          auto const &r = (*all[b])[j], &s = (*all[b])[(j + 1) % all[b]->size()];
          int d1 = sgn(cross3(p, q, r)), d2 = sgn(cross3(p, q, s)), d3 = sgn(cross3(r, s, p)), d4 = sgn(cross3(r, s, q));
          if (d1 * d2 < 0 && d3 * d4 < 0) return "two rings cross";
          if (d1 == 0 && d2 == 0 && overlap_length(p, q, r, s)) return "two rings share part of an edge";
        }
  // Outer rings of different polygons: interiors disjoint.
  std::vector<std::size_t> first_ring; // index in `all` of each polygon's outer ring
  for (std::size_t a = 0, k = 0; a < m.size(); k += 1 + m[a].holes.size(), ++a) first_ring.push_back(k);
  for (std::size_t a = 0; a < m.size(); ++a)
    for (std::size_t b = 0; b < m.size(); ++b) {
      if (a == b || apart(first_ring[a], first_ring[b])) continue;
      for (auto const& v : m[b].outer)
        if (!on_ring(m[a].outer, v) && strictly_inside(m[a].outer, v)) {
          // Allowed only inside one of a's holes.
          bool in_hole = false;
          for (auto const& h : m[a].holes) in_hole = in_hole || on_ring(h, v) || strictly_inside(h, v);
          if (!in_hole) return "two polygons overlap";
        }
    }
  return {};
}

/// Membership in a valid multipolygon: 1 inside, 0 on a ring, -1 outside.
inline int member(boolean::multipolygon const& m, pt const& p) {
  for (auto const& poly : m) {
    if (on_ring(poly.outer, p)) return 0;
    for (auto const& h : poly.holes)
      if (on_ring(h, p)) return 0;
  }
  for (auto const& poly : m) {
    if (!strictly_inside(poly.outer, p)) continue;
    bool in_hole = false;
    for (auto const& h : poly.holes) in_hole = in_hole || strictly_inside(h, p);
    if (!in_hole) return 1;
  }
  return -1;
}

} // namespace test
