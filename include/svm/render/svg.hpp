/// @file
/// A compact SVG writer for drawings: one `<path>` per region (even–odd fill,
/// holes as further subpaths, the input face index in `data-face`), or one
/// per polyline for style `lines`.
#pragma once

#include "drawing.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

namespace svm::render {

namespace detail {

/// `x` rounded to `digits` decimals, without trailing zeros.
inline void append_number(std::string& out, double x, int digits) {
  double scale = std::pow(10.0, digits);
  double r = std::round(x * scale) / scale;
  if (r == 0) r = 0; // no "-0"
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, r, std::chars_format::fixed, digits);
  std::string_view s(buf, static_cast<std::size_t>(res.ptr - buf));
  if (s.find('.') != std::string_view::npos) {
    while (!s.empty() && s.back() == '0') s.remove_suffix(1);
    if (!s.empty() && s.back() == '.') s.remove_suffix(1);
  }
  out += s;
}

inline std::string hex(rgb c) {
  auto b = [](double v) { return static_cast<unsigned>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", b(c.r), b(c.g), b(c.b));
  return buf;
}

inline void append_path(std::string& out, std::vector<command> const& path, int digits) {
  bool first = true;
  for (auto const& c : path) {
    auto xy = [&] {
      append_number(out, c.x, digits);
      out += ',';
      append_number(out, c.y, digits);
    };
    if (!first && c.kind != command::close) out += ' ';
    first = false;
    switch (c.kind) {
    case command::move: out += 'M'; xy(); break;
    case command::line: out += 'L'; xy(); break;
    case command::arc:
      out += 'A';
      append_number(out, c.radius, digits);
      out += ',';
      append_number(out, c.radius, digits);
      out += c.large ? " 0 1," : " 0 0,";
      out += c.clockwise ? "1 " : "0 ";
      xy();
      break;
    case command::close: out += 'Z'; break;
    }
  }
}

} // namespace detail

/// The SVG text of a drawing; coordinates with `digits` decimals.
inline std::string to_svg(drawing const& d, int digits = 2) {
  std::string out;
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(d.width) + "\" height=\"" +
         std::to_string(d.height) + "\" viewBox=\"0 0 " + std::to_string(d.width) + " " + std::to_string(d.height) + "\"";
  if (d.style == style::id) out += " shape-rendering=\"crispEdges\"";
  if (!d.layers.empty()) out += " xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"";
  out += ">\n";
  if (d.background)
    out += "<rect width=\"" + std::to_string(d.width) + "\" height=\"" + std::to_string(d.height) + "\" fill=\"" +
           detail::hex(*d.background) + "\"/>\n";
  auto polyline = [&](std::vector<pixel> const& line) {
    out += "<path d=\"";
    for (std::size_t i = 0; i < line.size(); ++i) {
      out += i == 0 ? "M" : " L";
      detail::append_number(out, line[i].x, digits);
      out += ',';
      detail::append_number(out, line[i].y, digits);
    }
    out += "\"/>\n";
  };
  if (!d.layers.empty()) {
    // One Inkscape layer per kind of line, with its pen.
    for (auto const& layer : d.layers) {
      out += "<g id=\"" + layer.name + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" + layer.name +
             "\" fill=\"none\" stroke=\"#000\" stroke-width=\"";
      detail::append_number(out, layer.width, 3);
      out += "\" stroke-linejoin=\"round\"";
      if (layer.dash.empty()) out += " stroke-linecap=\"round\"";
      else {
        out += " stroke-linecap=\"butt\" stroke-dasharray=\"";
        for (std::size_t i = 0; i < layer.dash.size(); ++i) {
          if (i) out += ' ';
          detail::append_number(out, layer.dash[i], 3);
        }
        out += "\"";
      }
      if (!layer.shown) out += " style=\"display:none\"";
      out += ">\n";
      for (auto const& line : layer.lines) polyline(line);
      out += "</g>\n";
    }
    out += "</svg>\n";
    return out;
  }
  if (d.style == style::lines) {
    // Visible edges, then shadow boundaries (thin), each a group.
    auto group = [&](std::vector<std::vector<pixel>> const& lines, char const* width, char const* id) {
      if (lines.empty()) return;
      out += std::string("<g id=\"") + id + "\" fill=\"none\" stroke=\"#000\" stroke-width=\"" + width +
             "\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
      for (auto const& line : lines) polyline(line);
      out += "</g>\n";
    };
    group(d.polylines, "1", "edges");
    group(d.thin_polylines, "0.35", "shadow-boundaries");
    out += "</svg>\n";
    return out;
  }
  // Flat and shaded regions get a hairline of their own colour, so that
  // anti-aliased renderers show no background through shared edges.
  bool seams = d.style != style::id;
  out += seams ? "<g fill-rule=\"evenodd\" stroke-width=\"0.5\" stroke-linejoin=\"round\">\n" : "<g fill-rule=\"evenodd\">\n";
  for (auto const& r : d.regions) {
    std::string c = detail::hex(r.fill);
    out += "<path data-face=\"" + std::to_string(r.polygon) + "\" fill=\"" + c + "\"";
    if (seams) out += " stroke=\"" + c + "\"";
    out += " d=\"";
    detail::append_path(out, r.path, digits);
    out += "\"/>\n";
  }
  out += "</g>\n</svg>\n";
  return out;
}

} // namespace svm::render
