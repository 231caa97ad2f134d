/// @file
/// Polygons with holes in the plane (or in longitude/latitude), exact, and
/// their text forms: WKT and GeoJSON readers and writers, and an SVG writer.
///
/// Readers keep every coordinate exact (`0.1` is 1/10) and report bad input
/// as a `read_error` whose `what()` is one line `FILE:LINE: message`.
/// Writers print each coordinate as the shortest decimal that reads back as
/// the same double (the nearest double to the exact value).
#pragma once

#include "../e2/objects.hpp"
#include "scene.hpp"

#include <charconv>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace geometry::io {

/// A point of a planar ring: exact x, y (longitude, latitude for GeoJSON on the sphere).
using point2 = e2::point<rational>;

/// A closed ring: vertices in order, the last joined to the first (not repeated).
using ring = std::vector<point2>;

/// A polygon with holes: its outer ring and its holes.
struct polygon_with_holes {
  ring outer;
  std::vector<ring> holes;
  friend bool operator==(polygon_with_holes const&, polygon_with_holes const&) = default;
};

/// A set of polygons with holes.
using multipolygon = std::vector<polygon_with_holes>;

namespace detail {

/// The shortest decimal that reads back as `x` (std::to_chars), `-0` printed as `0`.
inline std::string shortest(double x) {
  if (x == 0) x = 0;
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

/// The nearest double to `q`, printed shortest.
inline std::string shortest(rational const& q) { return shortest(q.convert_to<double>()); }

} // namespace detail

/// @name Writers
/// @{

/// WKT: `MULTIPOLYGON (((x y, …, x y)), …)`, rings closed by repeating their
/// first vertex; `MULTIPOLYGON EMPTY` for no polygon.  Ends with a newline.
inline std::string to_wkt(multipolygon const& m) {
  if (m.empty()) return "MULTIPOLYGON EMPTY\n";
  std::string s = "MULTIPOLYGON (";
  auto put_ring = [&](ring const& r) {
    s += '(';
    for (std::size_t i = 0; i <= r.size(); ++i) {
      auto const& p = r[i % r.size()];
      if (i) s += ", ";
      s += detail::shortest(p.x());
      s += ' ';
      s += detail::shortest(p.y());
    }
    s += ')';
  };
  for (std::size_t k = 0; k < m.size(); ++k) {
    s += k ? ", (" : "(";
    put_ring(m[k].outer);
    for (auto const& h : m[k].holes) s += ", ", put_ring(h);
    s += ')';
  }
  return s + ")\n";
}

/// GeoJSON: one `MultiPolygon` geometry (RFC 7946), rings closed by repeating
/// their first vertex.  Ends with a newline.
inline std::string to_geojson(multipolygon const& m) {
  std::string s = "{\"type\":\"MultiPolygon\",\"coordinates\":[";
  auto put_ring = [&](ring const& r) {
    s += '[';
    for (std::size_t i = 0; i <= r.size(); ++i) {
      auto const& p = r[i % r.size()];
      if (i) s += ',';
      s += '[';
      s += detail::shortest(p.x());
      s += ',';
      s += detail::shortest(p.y());
      s += ']';
    }
    s += ']';
  };
  for (std::size_t k = 0; k < m.size(); ++k) {
    s += k ? ",[" : "[";
    put_ring(m[k].outer);
    for (auto const& h : m[k].holes) s += ',', put_ring(h);
    s += ']';
  }
  return s + "]}\n";
}

/// SVG: one path per polygon (its rings as subpaths, filled even-odd), y
/// pointing up as in the plane, the drawing fitted into `width` pixels wide
/// with a margin.  An empty set gives an empty drawing.
inline std::string to_svg(multipolygon const& m, double width = 800) {
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
  bool first = true;
  for (auto const& p : m)
    for (auto const& v : p.outer) {
      double x = v.x().convert_to<double>(), y = v.y().convert_to<double>();
      if (first || x < x0) x0 = x;
      if (first || y < y0) y0 = y;
      if (first || x > x1) x1 = x;
      if (first || y > y1) y1 = y;
      first = false;
    }
  double w = x1 - x0 > 0 ? x1 - x0 : 1, h = y1 - y0 > 0 ? y1 - y0 : 1;
  double scale = (width - 20) / w, height = h * scale + 20;
  auto px = [&](point2 const& v) {
    std::string t = detail::shortest(10 + (v.x().convert_to<double>() - x0) * scale);
    t += ',';
    t += detail::shortest(10 + (y1 - v.y().convert_to<double>()) * scale);
    return t;
  };
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + detail::shortest(width) + "\" height=\"" +
                  detail::shortest(height) + "\" viewBox=\"0 0 " + detail::shortest(width) + ' ' +
                  detail::shortest(height) + "\">\n";
  for (auto const& p : m) {
    s += "<path fill=\"#4a7ab5\" fill-rule=\"evenodd\" stroke=\"#1f3f66\" stroke-width=\"1\" d=\"";
    auto put_ring = [&](ring const& r) {
      for (std::size_t i = 0; i < r.size(); ++i) {
        s += i ? 'L' : 'M';
        s += px(r[i]);
      }
      s += 'Z';
    };
    put_ring(p.outer);
    for (auto const& h : p.holes) put_ring(h);
    s += "\"/>\n";
  }
  return s + "</svg>\n";
}

/// @}

} // namespace geometry::io
