/// @file
/// SVG pictures of E2 point-set trees: the cells coloured by label, and each
/// node's splitting line drawn within its cell and numbered — for teaching.
#pragma once

#include "kernel.hpp"

#include <bsp/point_set.hpp>

#include <functional>
#include <ostream>
#include <sstream>
#include <string>

namespace geometry::e2 {

/// The window of a picture, in scene coordinates.
struct svg_view {
  double x0 = -10, y0 = -10, x1 = 10, y1 = 10;
  double pixels = 600; ///< width of the picture
};

namespace detail {
template <number FT> polytope<FT> clip_to(polytope<FT> c, svg_view const& v) {
  auto line = [](double a, double b, double cc) { return hyperplane<FT>(hvec<FT, 3>(std::array<FT, 3>{FT(a), FT(b), FT(cc)})); };
  for (auto const& h : {line(1, 0, -v.x0), line(-1, 0, v.x1), line(0, 1, -v.y0), line(0, -1, v.y1)}) {
    auto r = split(c, h);
    if (!r.positive) return polytope<FT>{{}};
    c = std::move(*r.positive);
  }
  return c;
}
} // namespace detail

/// Writes an SVG picture of `t`: cells within `view` filled with
/// `colour(label)` (an SVG colour), splitting lines in black with their node
/// number (pre-order, from 0).
template <number FT, class L>
void write_svg(std::ostream& out, bsp::point_set<kernel<FT>, L> const& t, svg_view const& view,
               std::function<std::string(L const&)> colour) {
  double scale = view.pixels / (view.x1 - view.x0), height = (view.y1 - view.y0) * scale;
  auto X = [&](double x) { return (x - view.x0) * scale; };
  auto Y = [&](double y) { return height - (y - view.y0) * scale; };
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << view.pixels << "\" height=\"" << height << "\" viewBox=\"0 0 "
      << view.pixels << ' ' << height << "\">\n";
  for (auto const& c : bsp::cells(t)) {
    auto clipped = detail::clip_to(c.region, view);
    auto v = vertices(clipped);
    if (!v) continue;
    out << "<polygon fill=\"" << colour(t.leaf_data(c.leaf)) << "\" points=\"";
    for (auto const& p : *v) out << X(to_double(p.x())) << ',' << Y(to_double(p.y())) << ' ';
    out << "\"/>\n";
  }
  // Splitting lines: each node's line within its cell, then within the window.
  std::size_t number = 0;
  std::vector<std::pair<bsp::node_id, polytope<FT>>> stack{{t.root(), detail::clip_to(whole_plane<FT>(), view)}};
  while (!stack.empty()) {
    auto [n, c] = std::move(stack.back());
    stack.pop_back();
    if (t.is_leaf(n)) continue;
    auto const& h = t.splitter(n);
    std::optional<sub_hyperplane<FT>> s = whole_line(h);
    for (auto const& b : c.bounds) {
      if (!s) break;
      auto r = split(*s, b);
      s = r.is_coincident() ? std::nullopt : r.positive;
    }
    if (s)
      if (auto e = endpoints(*s)) {
        double ax = X(to_double(e->first.x())), ay = Y(to_double(e->first.y()));
        double bx = X(to_double(e->second.x())), by = Y(to_double(e->second.y()));
        out << "<line stroke=\"black\" stroke-width=\"1.5\" x1=\"" << ax << "\" y1=\"" << ay << "\" x2=\"" << bx << "\" y2=\"" << by
            << "\"/>\n<text font-size=\"12\" x=\"" << (ax + bx) / 2 << "\" y=\"" << (ay + by) / 2 << "\">" << number << "</text>\n";
      }
    ++number;
    auto r = split(c, h);
    if (r.positive) stack.emplace_back(t.positive(n), std::move(*r.positive));
    if (r.negative) stack.emplace_back(t.negative(n), std::move(*r.negative));
  }
  out << "</svg>\n";
}

} // namespace geometry::e2
