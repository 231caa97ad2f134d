/// @file
/// A drawing of a visibility map: the map's faces as closed paths in image
/// coordinates (one path per visible region, holes included, even–odd fill),
/// or its visible edges as polylines.  The writers (`svg.hpp`, `cairo.hpp`)
/// turn a drawing into a file.
///
/// Great arcs become straight segments in a perspective view and exact
/// circular arcs (or straight segments, for circles through the projection's
/// pole) in a stereographic one; in the fisheye and panorama projections they
/// are subdivided on the sphere until the chord is within `tolerance` pixels
/// of the image of the arc.
#pragma once

#include "../camera.hpp"
#include "../query.hpp"
#include "../shadow.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace svm::render {

/// A colour, components in [0, 1].
struct rgb {
  double r = 0, g = 0, b = 0;
};

enum class style {
  shaded, ///< Lambert shading of each polygon's colour
  flat,   ///< each polygon's colour
  lines,  ///< visible edges only, black polylines
  id,     ///< fill colour = polygon index + 1 as \#RRGGBB (+ 0x800000 in shadow), no stroke, no background
};

inline std::optional<style> style_from_name(std::string_view s) {
  if (s == "shaded") return style::shaded;
  if (s == "flat") return style::flat;
  if (s == "lines") return style::lines;
  if (s == "id") return style::id;
  return std::nullopt;
}

/// One drawing command.  An arc runs about `centre` with radius `radius`
/// from the current point to (`x`, `y`), turning in the direction of
/// increasing image angle (clockwise on screen, y down) when `clockwise`;
/// `large` says it spans more than half a turn.
struct command {
  enum kind_t : std::uint8_t { move, line, arc, close } kind;
  double x = 0, y = 0;
  double cx = 0, cy = 0, radius = 0;
  bool clockwise = false, large = false;
};

/// A filled region: one face of the map.
struct region {
  std::vector<command> path;
  std::int64_t polygon = -1; ///< the input face seen there
  rgb fill;
  /// With shadows: the lights that reach it (bit k: light k), else all ones.
  std::uint64_t lights = ~std::uint64_t{0};
};

/// One layer of a line drawing: the lines of one class, visible or hidden,
/// with their pen (stroke width and dash pattern, in pixels).
struct line_layer {
  std::string name;  ///< e.g. "visible-outline", "hidden-crease"
  bool shown = true; ///< false: written, but hidden in the document (SVG display:none)
  double width = 1;
  std::vector<double> dash; ///< on, off, … lengths; empty: solid
  std::size_t edges = 0;    ///< edges drawn (pieces of one great circle joined end to end count once)
  std::vector<std::vector<pixel>> lines;
};

/// A drawing: regions, polylines (style `lines`), size and background.
struct drawing {
  int width = 0, height = 0;
  render::style style = render::style::shaded;
  std::optional<rgb> background; ///< none: transparent
  std::vector<region> regions;
  std::vector<std::vector<pixel>> polylines;
  /// Style `lines` with shadows: shadow boundaries, drawn thin.
  std::vector<std::vector<pixel>> thin_polylines;
  /// Style `lines`: visible edges drawn, an edge being a maximal piece of one
  /// great circle (pieces of one circle joined end to end count once).
  std::size_t edges = 0;
  /// Hidden-line drawings (`draw_lines`): one layer per kind of line, drawn
  /// in order; when there are any, `polylines` and `thin_polylines` are empty.
  std::vector<line_layer> layers;
};

/// What the drawing knows of each input face: colour and plane.
struct face_info {
  std::optional<rgb> colour;
  vec3 normal{0, 0, 0}; ///< unit normal (front side), zero when unknown
  double offset = 0;    ///< the plane is `normal · x = offset`
  vec3 centre{0, 0, 0}; ///< a point of the face (for a head light)
};

struct options {
  render::style style = render::style::shaded;
  double tolerance = 0.1; ///< pixels, for arcs subdivided on the sphere
  /// Style `lines`: an edge between two polygons is drawn only when the
  /// angle between their planes exceeds this (degrees); at 0, only edges
  /// between polygons in one plane are left out.
  double crease = 0;
  std::vector<vec3> lights; ///< point lights (lights 0, 1, … of `regions`)
  std::vector<vec3> suns;   ///< directions towards lights at infinity (the lights after the points); with neither, a head light at the eye
  vec3 eye{0, 0, 0};         ///< the observer (for the head light)
  rgb background{1, 1, 1};
  /// A map built from shadow pieces (`svm::label_regions`): its labels are
  /// indices here, each an input face and the lights that reach it.  Lit
  /// parts are shaded by the lights that reach them, the rest by the ambient
  /// term alone; in style `lines`, shadow boundaries are drawn thin.
  std::vector<lit_region> const* regions = nullptr;
};

/// The id style's colour of polygon `p`: p + 1 as 24-bit RGB, plus 0x800000
/// when `shadowed`.
inline rgb id_colour(std::int64_t p, bool shadowed = false) {
  auto v = static_cast<std::uint32_t>(p + 1) + (shadowed ? 0x800000u : 0u);
  return {((v >> 16) & 255) / 255.0, ((v >> 8) & 255) / 255.0, (v & 255) / 255.0};
}

/// A neutral palette: soft colours of varied hue, from the polygon index.
inline rgb palette(std::int64_t p) {
  double h = std::fmod(static_cast<double>(p) * 0.618033988749895, 1.0) * 6;
  double s = 0.28, v = 0.88, c = v * s, x = c * (1 - std::abs(std::fmod(h, 2.0) - 1)), m = v - c;
  int k = static_cast<int>(h) % 6;
  double r[6] = {c, x, 0, 0, x, c}, g[6] = {x, c, c, x, 0, 0}, b[6] = {0, 0, x, c, c, x};
  return {r[k] + m, g[k] + m, b[k] + m};
}

namespace detail {

using svm::detail::add3;
using svm::detail::cross3;
using svm::detail::dot3;
using svm::detail::mul3;
using svm::detail::norm3;
using svm::detail::unit3;

/// Appends the image of the minor arc p → q (about the unit normal `n`) as
/// points after the current one, subdividing on the sphere.
inline void subdivide(projector const& pr, vec3 const& p, vec3 const& q, int side, double tol, std::vector<pixel>& out,
                      int depth = 0) {
  vec3 m = unit3(add3(p, q));
  pixel P = pr.project(p, side), Q = pr.project(q, side), M = pr.project(m, side);
  double dx = Q.x - P.x, dy = Q.y - P.y, len = std::hypot(dx, dy);
  double dev = len > 0 ? std::abs((M.x - P.x) * dy - (M.y - P.y) * dx) / len : std::hypot(M.x - P.x, M.y - P.y);
  double mx = (P.x + Q.x) / 2 - M.x, my = (P.y + Q.y) / 2 - M.y;
  dev = std::max(dev, std::hypot(mx, my) * 0.5);
  bool wide = dot3(p, q) < std::cos(0.15);
  if (depth < 24 && (dev > tol || wide)) {
    subdivide(pr, p, m, side, tol, out, depth + 1);
    subdivide(pr, m, q, side, tol, out, depth + 1);
    return;
  }
  out.push_back(Q);
}

/// Whether a unit vector is a pole of the panorama (its longitude undefined).
inline bool is_pole(projector const& pr, vec3 const& d) { return std::abs(dot3(d, pr.up())) > 1 - 1e-12; }

/// The side of the panorama's seam that the points of one face lie on.
inline int seam_side(projector const& pr, std::vector<vec3> const& pts) {
  double best = 0;
  for (auto const& p : pts) {
    double x = dot3(p, pr.right());
    if (std::abs(x) > std::abs(best)) best = x;
  }
  return best >= 0 ? 1 : -1;
}

/// Appends one cycle of the map (its vertices `v`, edge normals `n`) to `path`.
inline void cycle_path(projector const& pr, std::vector<vec3> const& v, std::vector<vec3> const& n, double tol,
                       std::vector<command>& path) {
  std::size_t k = v.size();
  if (k == 0) return;
  auto const kind = pr.kind();
  if (kind == projection::perspective) {
    for (std::size_t i = 0; i < k; ++i) {
      pixel P = pr.project(v[i]);
      path.push_back({i == 0 ? command::move : command::line, P.x, P.y});
    }
    path.push_back({command::close});
    return;
  }
  if (kind == projection::stereographic) {
    pixel P0 = pr.project(v[0]);
    path.push_back({command::move, P0.x, P0.y});
    for (std::size_t i = 0; i < k; ++i) {
      vec3 const &p = v[i], &q = v[(i + 1) % k];
      pixel P = pr.project(p), Q = pr.project(q), M = pr.project(unit3(add3(p, q)));
      // The circle through P, M, Q; a straight segment when they are collinear
      // (a great circle through the pole of the projection).
      double ax = M.x - P.x, ay = M.y - P.y, bx = Q.x - P.x, by = Q.y - P.y;
      double d = 2 * (ax * by - ay * bx);
      double chord = std::hypot(bx, by);
      double sag = chord > 0 ? std::abs(ax * by - ay * bx) / chord : 0;
      (void)n;
      if (sag < 1e-3 || std::abs(d) < 1e-12) {
        path.push_back({command::line, Q.x, Q.y});
        continue;
      }
      double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by;
      double ux = (by * a2 - ay * b2) / d, uy = (ax * b2 - bx * a2) / d;
      double cx = P.x + ux, cy = P.y + uy, r = std::hypot(ux, uy);
      // P → M → Q turning clockwise on screen (y down) means increasing angle.
      bool cw = (M.x - P.x) * (Q.y - M.y) - (M.y - P.y) * (Q.x - M.x) > 0;
      // Large when the centre is on M's side of the chord.
      double sm = bx * (M.y - P.y) - by * (M.x - P.x), sc = bx * (cy - P.y) - by * (cx - P.x);
      bool large = (sm > 0) == (sc > 0) && std::abs(sc) > 1e-12 * r * chord;
      command c{command::arc, Q.x, Q.y, cx, cy, r, cw, large};
      path.push_back(c);
    }
    path.push_back({command::close});
    return;
  }
  // Fisheye and panorama: subdivide on the sphere.
  int side = kind == projection::equirectangular ? seam_side(pr, v) : 0;
  std::vector<pixel> pts;
  for (std::size_t i = 0; i < k; ++i) {
    vec3 const &p = v[i], &q = v[(i + 1) % k];
    if (kind == projection::equirectangular && (is_pole(pr, p) || is_pole(pr, q))) {
      // An arc from or to a pole is a meridian: a vertical segment; at the
      // pole itself the boundary runs along the image's top or bottom edge
      // from the longitude of the arc before to that of the arc after.
      vec3 const& pole = is_pole(pr, p) ? p : q;
      vec3 const& other = is_pole(pr, p) ? q : p;
      double lon = projector::longitude(pr.local(other), side);
      double lat = std::asin(std::clamp(dot3(pole, pr.up()), -1.0, 1.0));
      pixel at_pole{pr.cam().width / 2.0 + pr.scale() * lon, pr.cam().height / 2.0 - pr.scale() * lat};
      if (is_pole(pr, p)) {
        pts.push_back(at_pole); // the pole, at the outgoing arc's longitude
        pts.push_back(pr.project(q, side));
      } else {
        if (i == 0) pts.push_back(pr.project(p, side));
        pts.push_back(at_pole); // the pole, at the incoming arc's longitude
      }
      continue;
    }
    if (i == 0) pts.push_back(pr.project(p, side));
    subdivide(pr, p, q, side, tol, pts);
  }
  for (std::size_t i = 0; i < pts.size(); ++i) path.push_back({i == 0 ? command::move : command::line, pts[i].x, pts[i].y});
  path.push_back({command::close});
}

/// The image of the minor arc from unit vector `p` to `q`: its ends in a
/// perspective view, else points along it within `tol` pixels.
inline std::vector<pixel> arc_image(projector const& pr, vec3 const& p, vec3 const& q, double tol) {
  std::vector<pixel> pts;
  if (pr.kind() == projection::perspective) pts = {pr.project(p), pr.project(q)};
  else {
    int side = pr.kind() == projection::equirectangular ? seam_side(pr, {p, q}) : 0;
    if (pr.kind() == projection::equirectangular && (is_pole(pr, p) || is_pole(pr, q))) {
      vec3 const& pole = is_pole(pr, p) ? p : q;
      vec3 const& other = is_pole(pr, p) ? q : p;
      double lon = projector::longitude(pr.local(other), side);
      double lat = std::asin(std::clamp(dot3(pole, pr.up()), -1.0, 1.0));
      pixel at_pole{pr.cam().width / 2.0 + pr.scale() * lon, pr.cam().height / 2.0 - pr.scale() * lat};
      pts = is_pole(pr, p) ? std::vector<pixel>{at_pole, pr.project(q, side)} : std::vector<pixel>{pr.project(p, side), at_pole};
    } else {
      pts.push_back(pr.project(p, side));
      subdivide(pr, p, q, side, tol, pts);
    }
  }
  return pts;
}

/// A piece of a line in the image: its ends' keys (equal keys: the same
/// point, where pieces may join), its points, and its great circle.
struct line_image {
  std::uint64_t from, to;
  std::vector<pixel> pts;
  vec3 circle; ///< unit normal of the piece's great circle
};

/// Pen-up travel of drawing `lines` in order, starting at the image's origin.
inline double pen_travel(std::vector<std::vector<pixel>> const& lines) {
  double d = 0;
  pixel pen{0, 0};
  for (auto const& l : lines) {
    if (l.empty()) continue;
    d += std::hypot(l.front().x - pen.x, l.front().y - pen.y);
    pen = l.back();
  }
  return d;
}

/// Appends `lines` to `result` in greedy order: from the image's origin,
/// next the line with an end nearest the pen (ties: the lower index, its
/// start first), drawn from that end.  The ends are kept in a uniform grid
/// searched ring by ring, so that n lines take about n·√n steps at worst,
/// not n².
inline void order_for_travel(std::vector<std::vector<pixel>>& lines, std::vector<std::vector<pixel>>& result) {
  std::size_t n = lines.size();
  if (n == 0) return;
  double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  for (auto const& l : lines)
    for (auto const* p : {&l.front(), &l.back()}) x0 = std::min(x0, p->x), y0 = std::min(y0, p->y), x1 = std::max(x1, p->x), y1 = std::max(y1, p->y);
  auto g = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n) / 2)));
  double cell = std::max({(x1 - x0) / static_cast<double>(g), (y1 - y0) / static_cast<double>(g), 1e-9});
  auto cell_of = [&](double v, double lo) {
    return static_cast<std::ptrdiff_t>(std::clamp(std::floor((v - lo) / cell), 0.0, static_cast<double>(g - 1)));
  };
  // Each cell: the ends in it, as line index · 2 + (1 for the back end).
  std::vector<std::vector<std::size_t>> grid(g * g);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t back : {0, 1}) {
      auto const& p = back ? lines[i].back() : lines[i].front();
      grid[static_cast<std::size_t>(cell_of(p.y, y0)) * g + static_cast<std::size_t>(cell_of(p.x, x0))].push_back(2 * i + back);
    }
  std::vector<char> done(n, 0);
  pixel pen{0, 0};
  auto const G = static_cast<std::ptrdiff_t>(g);
  for (std::size_t k = 0; k < n; ++k) {
    std::ptrdiff_t cx = cell_of(pen.x, x0), cy = cell_of(pen.y, y0);
    double bd = HUGE_VAL;
    std::size_t best = SIZE_MAX; // line index · 2 + back
    for (std::ptrdiff_t r = 0; r < G; ++r) {
      // Cells at Chebyshev distance r from the pen's (clamped) cell.
      auto visit = [&](std::ptrdiff_t x, std::ptrdiff_t y) {
        auto& bucket = grid[static_cast<std::size_t>(y * G + x)];
        for (std::size_t j = 0; j < bucket.size();) {
          std::size_t e = bucket[j];
          if (done[e / 2]) {
            bucket[j] = bucket.back(), bucket.pop_back();
            continue;
          }
          auto const& p = e % 2 ? lines[e / 2].back() : lines[e / 2].front();
          double d = std::hypot(p.x - pen.x, p.y - pen.y);
          if (d < bd || (d == bd && e < best)) bd = d, best = e;
          ++j;
        }
      };
      for (std::ptrdiff_t y = std::max<std::ptrdiff_t>(0, cy - r); y <= std::min(G - 1, cy + r); ++y) {
        if (y == cy - r || y == cy + r) {
          for (std::ptrdiff_t x = std::max<std::ptrdiff_t>(0, cx - r); x <= std::min(G - 1, cx + r); ++x) visit(x, y);
        } else {
          if (cx - r >= 0) visit(cx - r, y);
          if (cx + r <= G - 1) visit(cx + r, y);
        }
      }
      // Unvisited cells are at least r cells away from the pen.
      if (best != SIZE_MAX && bd < static_cast<double>(r) * cell) break;
    }
    if (best == SIZE_MAX) break; // (not reached: a line is left)
    std::size_t i = best / 2;
    done[i] = 1;
    if (best % 2) std::reverse(lines[i].begin(), lines[i].end());
    pen = lines[i].back();
    result.push_back(std::move(lines[i]));
  }
}

/// Joins `pieces` into polylines at ends where exactly two meet (and their
/// images agree: not across the panorama's seam), then orders them greedily
/// (nearest end next) to shorten pen travel, appending them to `result`.
/// Returns the number of edges: pieces of one great circle joined end to end
/// count once (and, in a `perspective` image, their joint is no corner).
inline std::size_t assemble(std::vector<line_image> const& pieces, bool perspective, std::vector<std::vector<pixel>>& result) {
  std::size_t straight_joins = 0;
  std::map<std::uint64_t, std::vector<std::size_t>> at;
  for (std::size_t i = 0; i < pieces.size(); ++i) at[pieces[i].from].push_back(i), at[pieces[i].to].push_back(i);
  std::vector<char> used(pieces.size(), 0);
  auto close_to = [](pixel a, pixel b) { return std::hypot(a.x - b.x, a.y - b.y) < 1e-6; };
  auto same_circle = [&](std::size_t a, std::size_t b) { return norm3(cross3(pieces[a].circle, pieces[b].circle)) < 1e-12; };
  // Extends `line`, whose last piece is `last`, from the end `end`; returns the last piece and end.
  auto extend = [&](std::vector<pixel>& line, std::size_t last, std::uint64_t end) -> std::pair<std::size_t, std::uint64_t> {
    while (true) {
      auto const& list = at[end];
      if (list.size() != 2) return {last, end};
      std::size_t next = used[list[0]] ? list[1] : list[0];
      if (used[next]) return {last, end};
      auto const& pc = pieces[next];
      bool fwd = pc.from == end;
      pixel start = fwd ? pc.pts.front() : pc.pts.back();
      if (!close_to(start, line.back())) return {last, end};
      used[next] = 1;
      if (same_circle(next, last)) {
        ++straight_joins;
        if (perspective && line.size() >= 2) line.pop_back();
      }
      last = next;
      if (fwd) line.insert(line.end(), pc.pts.begin() + 1, pc.pts.end());
      else line.insert(line.end(), pc.pts.rbegin() + 1, pc.pts.rend());
      end = fwd ? pc.to : pc.from;
    }
  };
  std::vector<std::vector<pixel>> lines;
  auto run = [&](std::size_t i) {
    used[i] = 1;
    auto const& pc = pieces[i];
    std::vector<pixel> line = pc.pts;
    auto [tail, end] = extend(line, i, pc.to);
    if (end == pc.from && tail != i && close_to(line.front(), line.back())) {
      // A closed loop: its start is a joint too.
      if (same_circle(tail, i)) {
        ++straight_joins;
        if (perspective && line.size() >= 3) {
          line.erase(line.begin());
          line.back() = line.front();
        }
      }
      lines.push_back(std::move(line));
      return;
    }
    std::reverse(line.begin(), line.end());
    extend(line, i, pc.from);
    lines.push_back(std::move(line));
  };
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (!used[i] && (at[pieces[i].from].size() != 2 || at[pieces[i].to].size() != 2)) run(i);
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (!used[i]) run(i);
  order_for_travel(lines, result);
  return pieces.size() - straight_joins;
}

inline rgb shade(rgb c, double intensity) { return {c.r * intensity, c.g * intensity, c.b * intensity}; }

} // namespace detail

/// The drawing of map `vm` through projector `pr`.  The map must have been
/// built with `pr.window_options()` (faces labelled `clipped` are not drawn,
/// and each face must lie in one quarter of the panorama).  `faces[p]`
/// describes input face `p` (may be shorter: unknown faces get the palette).
template <geometry::number FT>
drawing draw(visibility_map<FT> const& vm, projector const& pr, std::vector<face_info> const& faces, options const& o) {
  using namespace detail;
  auto const& m = vm.map;
  drawing out;
  out.width = pr.cam().width;
  out.height = pr.cam().height;
  out.style = o.style;
  if (o.style != style::id) out.background = o.background;
  std::vector<vec3> vertex(m.vertices().size());
  for (index v = 0; v < vertex.size(); ++v) vertex[v] = unit(m, v);
  auto info = [&](std::int64_t p) -> face_info const* {
    return p >= 0 && static_cast<std::size_t>(p) < faces.size() ? &faces[static_cast<std::size_t>(p)] : nullptr;
  };
  // A map label: the input face, and the lights that reach it (all, without shadows).
  auto face_of = [&](std::int64_t label) -> std::int64_t {
    if (!o.regions || label < 0) return label;
    return (*o.regions)[static_cast<std::size_t>(label)].face;
  };
  auto lights_of = [&](std::int64_t label) -> std::uint64_t {
    if (!o.regions || label < 0) return ~std::uint64_t{0};
    return (*o.regions)[static_cast<std::size_t>(label)].lights;
  };
  auto colour = [&](std::int64_t label) {
    std::int64_t p = face_of(label);
    if (o.style == style::id) return id_colour(p, o.regions && lights_of(label) == 0);
    auto const* fi = info(p);
    rgb c = fi && fi->colour ? *fi->colour : palette(p);
    if (o.style == style::flat || !fi || norm3(fi->normal) == 0) return c;
    if (o.lights.empty() && o.suns.empty()) return shade(c, 0.2 + 0.8 * std::abs(dot3(unit3(svm::detail::sub3(o.eye, fi->centre)), fi->normal)));
    // Without shadows each light lights the side it faces; with shadows, a
    // light lights the front where it reaches, which the eye sees only from
    // the front.
    double sum = 0;
    bool eye_in_front = dot3(fi->normal, o.eye) > fi->offset;
    std::uint64_t reach = lights_of(label);
    for (std::size_t k = 0; k < o.lights.size() + o.suns.size(); ++k) {
      vec3 l = k < o.lights.size() ? unit3(svm::detail::sub3(o.lights[k], fi->centre)) : unit3(o.suns[k - o.lights.size()]);
      double d = dot3(l, fi->normal);
      if (!o.regions) sum += std::abs(d);
      else if (k < 64 && ((reach >> k) & 1u) && eye_in_front) sum += std::max(0.0, d);
    }
    return shade(c, 0.2 + 0.8 * std::min(1.0, sum));
  };

  if (o.style == style::lines) {
    // Visible edges: different polygons on the two sides, neither clipped, and
    // (between two polygons) a crease sharper than `o.crease`.
    double const cos_crease = std::cos(o.crease * std::numbers::pi / 180);
    auto drawn = [&](std::int64_t a, std::int64_t b) {
      if (a == b || a == clipped || b == clipped) return false;
      a = face_of(a), b = face_of(b);
      if (a == b) return false;
      if (a < 0 || b < 0) return true;
      auto const *fa = info(a), *fb = info(b);
      if (!fa || !fb || norm3(fa->normal) == 0 || norm3(fb->normal) == 0) return true;
      double c = dot3(fa->normal, fb->normal);
      bool same_plane = c > 1 - 1e-12 && std::abs(fa->offset - fb->offset) <= 1e-9 * (1 + std::abs(fa->offset));
      if (o.crease <= 0) return !same_plane;
      return c < cos_crease;
    };
    std::vector<line_image> solid, thin;
    auto const& he = m.half_edges();
    for (index e = 0; e < he.size(); e += 2) {
      std::int64_t a = m.faces()[he[e].face].label, b = m.faces()[he[e + 1].face].label;
      // A shadow boundary: one face on both sides, lit by different lights.
      bool shadow_edge = o.regions && a >= 0 && b >= 0 && a != b && face_of(a) == face_of(b);
      if (!shadow_edge && !drawn(a, b)) continue;
      vec3 p = vertex[m.origin(e)], q = vertex[m.target(e)];
      auto pts = arc_image(pr, p, q, o.tolerance);
      (shadow_edge ? thin : solid).push_back({m.origin(e), m.target(e), std::move(pts), unit_circle(m, e)});
    }
    out.edges = assemble(solid, pr.kind() == projection::perspective, out.polylines);
    assemble(thin, pr.kind() == projection::perspective, out.thin_polylines);
    return out;
  }

  auto cycles = face_cycles(m);
  for (index f = 0; f < m.faces().size(); ++f) {
    std::int64_t label = m.faces()[f].label;
    if (label < 0) continue;
    region rg;
    rg.polygon = face_of(label);
    rg.lights = lights_of(label);
    rg.fill = colour(label);
    if (cycles[f].empty()) {
      // The whole sphere: the whole image.
      rg.path = {{command::move, 0, 0}, {command::line, double(out.width), 0}, {command::line, double(out.width), double(out.height)},
                 {command::line, 0, double(out.height)}, {command::close}};
    }
    for (auto const& c : cycles[f]) {
      std::vector<vec3> v, n;
      for (index e : c) v.push_back(vertex[m.origin(e)]), n.push_back(unit_circle(m, e));
      cycle_path(pr, v, n, o.tolerance, rg.path);
    }
    out.regions.push_back(std::move(rg));
  }
  return out;
}

} // namespace svm::render
