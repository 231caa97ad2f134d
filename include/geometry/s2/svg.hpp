/// @file
/// SVG pictures of S2 point-set trees: the sphere seen from above (z > 0) and
/// from below (z < 0), side by side, its cells coloured by label — for teaching.
#pragma once

#include "kernel.hpp"

#include <bsp/point_set.hpp>

#include <cmath>
#include <functional>
#include <ostream>
#include <string>

namespace geometry::s2 {

/// Writes the cells of `t` in two orthographic disks of radius `radius`
/// pixels: the upper hemisphere on the left, the lower one (seen from below,
/// mirrored) on the right.  Great arcs are drawn as polylines of `steps`
/// segments per radian.
template <number FT, class L>
void write_svg(std::ostream& out, bsp::point_set<kernel<FT>, L> const& t, std::function<std::string(L const&)> colour,
               double radius = 250, int steps = 48) {
  double w = 4 * radius + 30, h = 2 * radius + 20;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h << "\" viewBox=\"0 0 " << w << ' ' << h
      << "\">\n";
  for (int half = 0; half < 2; ++half) {
    double cx = 10 + radius + half * (2 * radius + 10), cy = 10 + radius;
    out << "<circle cx=\"" << cx << "\" cy=\"" << cy << "\" r=\"" << radius << "\" fill=\"none\" stroke=\"gray\"/>\n";
    hyperplane<FT> cap(point<FT>(std::array<FT, 3>{FT(0), FT(0), FT(half ? -1 : 1)}));
    for (auto const& c : bsp::cells(t)) {
      auto r = split(c.region, cap).positive;
      if (!r || r->bounds.size() < 2) continue;
      auto v = vertices(*r);
      std::size_t k = v.size();
      out << "<polygon fill=\"" << colour(t.leaf_data(c.leaf)) << "\" stroke=\"black\" stroke-width=\"0.5\" points=\"";
      for (std::size_t i = 0; i < k; ++i) {
        // Edge i + 1 runs on bound i + 1 from vertex i to vertex i + 1, counter-clockwise about its normal.
        auto n = to_unit(r->bounds[(i + 1) % k].n);
        auto a = to_unit(v[i]), b = to_unit(v[(i + 1) % k]);
        auto wv = cross(n, a);
        double angle = std::atan2(dot(cross(a, b), n), dot(a, b));
        if (angle <= 0) angle += 2 * std::acos(-1.0);
        int m = std::max(1, static_cast<int>(angle * steps));
        for (int j = 0; j < m; ++j) {
          double s = angle * j / m;
          double px = std::cos(s) * a[0] + std::sin(s) * wv[0], py = std::cos(s) * a[1] + std::sin(s) * wv[1];
          out << cx + (half ? -px : px) * radius << ',' << cy - py * radius << ' ';
        }
      }
      out << "\"/>\n";
    }
  }
  out << "</svg>\n";
}

} // namespace geometry::s2
