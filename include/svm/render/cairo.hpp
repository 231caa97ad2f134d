/// @file
/// PDF, EPS and PNG output of drawings through cairo (link with cairo, e.g.
/// `pkg_check_modules(CAIRO REQUIRED IMPORTED_TARGET cairo)`).  Regions and
/// polylines are drawn exactly as the SVG writer writes them; the id style is
/// drawn without anti-aliasing, so that every pixel holds one face's colour.
#pragma once

#include "drawing.hpp"

#include <cairo-pdf.h>
#include <cairo-ps.h>
#include <cairo.h>

#include <cmath>
#include <cstdlib>
#include <ctime>
#include <stdexcept>
#include <string>

namespace svm::render {

/// Draws `d` on a cairo context (user units = pixels).
inline void draw_cairo(cairo_t* cr, drawing const& d) {
  bool id = d.style == style::id;
  cairo_set_antialias(cr, id ? CAIRO_ANTIALIAS_NONE : CAIRO_ANTIALIAS_DEFAULT);
  if (d.background) {
    cairo_set_source_rgb(cr, d.background->r, d.background->g, d.background->b);
    cairo_paint(cr);
  }
  if (!d.layers.empty()) {
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    for (auto const& layer : d.layers) {
      if (!layer.shown) continue;
      cairo_set_line_width(cr, layer.width);
      cairo_set_line_cap(cr, layer.dash.empty() ? CAIRO_LINE_CAP_ROUND : CAIRO_LINE_CAP_BUTT);
      cairo_set_dash(cr, layer.dash.data(), static_cast<int>(layer.dash.size()), 0);
      for (auto const& line : layer.lines) {
        for (std::size_t i = 0; i < line.size(); ++i)
          (i == 0 ? cairo_move_to : cairo_line_to)(cr, line[i].x, line[i].y);
        cairo_stroke(cr);
      }
    }
    cairo_set_dash(cr, nullptr, 0, 0);
    return;
  }
  if (d.style == style::lines) {
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    for (auto const* lines : {&d.polylines, &d.thin_polylines}) {
      cairo_set_line_width(cr, lines == &d.polylines ? 1 : 0.35);
      for (auto const& line : *lines) {
        for (std::size_t i = 0; i < line.size(); ++i)
          (i == 0 ? cairo_move_to : cairo_line_to)(cr, line[i].x, line[i].y);
        cairo_stroke(cr);
      }
    }
    return;
  }
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  cairo_set_line_width(cr, 0.5);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (auto const& r : d.regions) {
    double px = 0, py = 0;
    for (auto const& c : r.path) {
      switch (c.kind) {
      case command::move: cairo_move_to(cr, c.x, c.y); break;
      case command::line: cairo_line_to(cr, c.x, c.y); break;
      case command::arc: {
        double a0 = std::atan2(py - c.cy, px - c.cx), a1 = std::atan2(c.y - c.cy, c.x - c.cx);
        (c.clockwise ? cairo_arc : cairo_arc_negative)(cr, c.cx, c.cy, c.radius, a0, a1);
        break;
      }
      case command::close: cairo_close_path(cr); break;
      }
      if (c.kind != command::close) px = c.x, py = c.y;
    }
    cairo_set_source_rgb(cr, r.fill.r, r.fill.g, r.fill.b);
    if (id) cairo_fill(cr);
    else {
      cairo_fill_preserve(cr);
      cairo_stroke(cr);
    }
  }
}

/// The output formats of cairo.
enum class cairo_format { pdf, eps, png };

/// Writes `d` to `path` as PDF, EPS or PNG.  A PDF's creation date is the
/// time of writing, or `SOURCE_DATE_EPOCH` (seconds since 1970, UTC) when
/// that is set, so that a file can be made byte for byte again.  Throws
/// `std::runtime_error` when cairo reports an error.
inline void write_cairo(drawing const& d, std::string const& path, cairo_format f) {
  cairo_surface_t* s = nullptr;
  switch (f) {
  case cairo_format::pdf:
    s = cairo_pdf_surface_create(path.c_str(), d.width, d.height);
    if (char const* epoch = std::getenv("SOURCE_DATE_EPOCH")) {
      char* end = nullptr;
      long long seconds = std::strtoll(epoch, &end, 10);
      std::time_t t = static_cast<std::time_t>(seconds);
      std::tm utc{};
      char date[32];
      if (end != epoch && *end == '\0' && gmtime_r(&t, &utc) && std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &utc))
        cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATE_DATE, date);
    }
    break;
  case cairo_format::eps:
    s = cairo_ps_surface_create(path.c_str(), d.width, d.height);
    cairo_ps_surface_set_eps(s, 1);
    break;
  case cairo_format::png: s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, d.width, d.height); break;
  }
  cairo_t* cr = cairo_create(s);
  draw_cairo(cr, d);
  cairo_status_t st = cairo_status(cr);
  cairo_destroy(cr);
  if (st == CAIRO_STATUS_SUCCESS && f == cairo_format::png) st = cairo_surface_write_to_png(s, path.c_str());
  cairo_surface_finish(s);
  if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_status(s);
  cairo_surface_destroy(s);
  if (st != CAIRO_STATUS_SUCCESS) throw std::runtime_error(path + ": " + cairo_status_to_string(st));
}

} // namespace svm::render
