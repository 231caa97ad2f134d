/// @file
/// Line drawings with hidden lines: the exact visible and hidden parts of a
/// scene's edges (`svm::hidden_lines`) drawn as layers, one per class and
/// visibility, each with its pen — visible lines solid, hidden lines dashed
/// (ISO 128 proportions: dashes of 12 and gaps of 3 line widths), thin, or
/// on layers of their own that the document hides.  Polylines are joined at
/// common ends and ordered greedily to cut pen-up travel.
#pragma once

#include "../lines.hpp"
#include "drawing.hpp"

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace svm::render {

/// How hidden lines are drawn.
enum class hidden_style {
  none,   ///< not drawn
  dashed, ///< thin dashed lines
  thin,   ///< thin solid lines
  layer,  ///< dashed, on layers the document hides (to be shown in an editor, or plotted apart)
};

inline std::optional<hidden_style> hidden_style_from_name(std::string_view s) {
  if (s == "none") return hidden_style::none;
  if (s == "dashed") return hidden_style::dashed;
  if (s == "thin") return hidden_style::thin;
  if (s == "layer") return hidden_style::layer;
  return std::nullopt;
}

struct line_drawing_options {
  hidden_style hidden = hidden_style::none;
  double tolerance = 0.1; ///< pixels, for arcs subdivided on the sphere
  double width = 0;       ///< of visible outlines, pixels; 0: the image's larger side / 800
};

/// What a line drawing holds, per class: scene edges (or map edges, for
/// intersections and shadows) with a piece drawn, polylines, and length in pixels.
struct line_drawing_summary {
  struct count {
    std::size_t edges = 0, polylines = 0;
    double length = 0;
  };
  std::array<count, line_class_count> visible{}, hidden{};
  double travel_before = 0; ///< pen-up travel drawing every piece by itself, in the order found
  double travel_after = 0;  ///< after joining and ordering
};

namespace detail {

inline double polyline_length(std::vector<pixel> const& l) {
  double s = 0;
  for (std::size_t i = 1; i < l.size(); ++i) s += std::hypot(l[i].x - l[i - 1].x, l[i].y - l[i - 1].y);
  return s;
}

} // namespace detail

/// The drawing of the lines `ls` of map `vm` (both of the eye `eye`)
/// through `pr`; the map must have been built with `pr.window_options()`.
template <geometry::number FT>
drawing draw_lines(line_set<FT> const& ls, visibility_map<FT> const& vm, geometry::e3::point<FT> const& eye, projector const& pr,
                   line_drawing_options const& o, line_drawing_summary* summary = nullptr) {
  using namespace detail;
  using svm::detail::minus;
  drawing out;
  out.width = pr.cam().width;
  out.height = pr.cam().height;
  out.style = style::lines;
  out.background = rgb{1, 1, 1};
  double const w = o.width > 0 ? o.width : std::max(out.width, out.height) / 800.0;
  bool const perspective = pr.kind() == projection::perspective;

  // Pieces per class and visibility.
  std::array<std::array<std::vector<line_image>, line_class_count>, 2> pieces;
  std::array<std::array<std::vector<char>, line_class_count>, 2> edge_seen;
  for (auto& side : edge_seen)
    for (auto& v : side) v.assign(ls.edges.size(), 0);
  std::uint64_t unique = std::uint64_t{1} << 62;
  auto unit_of = [](svm::detail::iv3<FT> const& v) { return unit3(svm::detail::direction_doubles<FT>(v)); };
  // The current edge relative to the eye, on integers (`edge_frame`).
  std::optional<svm::detail::edge_frame<FT>> f;
  svm::detail::iv3<FT> BA;
  vec3 normal{};
  std::uint32_t framed = std::numeric_limits<std::uint32_t>::max();
  for (auto const& p : ls.pieces) {
    auto const& e = ls.edges[p.edge];
    if (p.hidden && o.hidden == hidden_style::none) continue;
    if (p.edge != framed) {
      framed = p.edge;
      f.emplace(svm::detail::relative(e.a, eye), svm::detail::relative(e.b, eye));
      BA = minus(f->B, f->A);
      normal = unit_of(geometry::cross(f->A, f->B));
    }
    auto at = [&](FT const& t) { return unit_of(svm::detail::point_at(f->A, BA, t)); };
    auto key = [&](FT const& t) -> std::uint64_t {
      if (geometry::sign_of(t) == geometry::sign::zero) return e.va;
      if (t == FT(1)) return e.vb;
      return unique++;
    };
    auto c = static_cast<std::size_t>(p.cls);
    pieces[p.hidden][c].push_back({key(p.t0), key(p.t1), arc_image(pr, at(p.t0), at(p.t1), o.tolerance), normal});
    edge_seen[p.hidden][c][p.edge] = 1;
  }
  auto const& m = vm.map;
  std::array<std::size_t, line_class_count> map_count{};
  for (auto const& ml : ls.map_lines) {
    index a = m.origin(ml.half_edge), b = m.target(ml.half_edge);
    auto c = static_cast<std::size_t>(ml.cls);
    pieces[0][c].push_back({(std::uint64_t{1} << 61) | a, (std::uint64_t{1} << 61) | b, arc_image(pr, unit(m, a), unit(m, b), o.tolerance),
                            unit_circle(m, ml.half_edge)});
    ++map_count[c];
  }

  // Layers: hidden lines underneath, then the visible ones, thinnest first.
  constexpr std::array<line_class, line_class_count> order{line_class::shadow, line_class::intersection, line_class::crease,
                                                           line_class::boundary, line_class::silhouette, line_class::outline};
  auto pen_of = [&](line_class c) {
    switch (c) {
    case line_class::crease:
    case line_class::intersection: return 0.7 * w;
    case line_class::shadow: return 0.35 * w;
    default: return w;
    }
  };
  line_drawing_summary s;
  for (int hidden : {1, 0})
    for (line_class c : order) {
      auto ci = static_cast<std::size_t>(c);
      auto& list = pieces[hidden][ci];
      if (list.empty()) continue;
      line_layer layer;
      layer.name = std::string(hidden ? "hidden-" : "visible-") + std::string(name_of(c));
      if (hidden) {
        layer.width = o.hidden == hidden_style::thin ? 0.35 * w : 0.5 * w;
        if (o.hidden != hidden_style::thin) layer.dash = {12 * layer.width, 3 * layer.width};
        layer.shown = o.hidden != hidden_style::layer;
      } else {
        layer.width = pen_of(c);
      }
      std::vector<std::vector<pixel>> alone;
      for (auto const& p : list) alone.push_back(p.pts);
      s.travel_before += pen_travel(alone);
      layer.edges = assemble(list, perspective, layer.lines);
      if (!hidden) out.edges += layer.edges;
      s.travel_after += pen_travel(layer.lines);
      auto& cnt = hidden ? s.hidden[ci] : s.visible[ci];
      cnt.polylines = layer.lines.size();
      for (auto const& l : layer.lines) cnt.length += polyline_length(l);
      cnt.edges = map_count[ci] && !hidden ? map_count[ci] : static_cast<std::size_t>(std::count(edge_seen[hidden][ci].begin(), edge_seen[hidden][ci].end(), 1));
      out.layers.push_back(std::move(layer));
    }
  if (summary) *summary = s;
  return out;
}

/// The drawing with only layer `k` of `d`, shown: one pen's plot.
inline drawing single_layer(drawing const& d, std::size_t k) {
  drawing out = d;
  out.layers = {d.layers.at(k)};
  out.layers[0].shown = true;
  out.edges = out.layers[0].edges;
  return out;
}

} // namespace svm::render
