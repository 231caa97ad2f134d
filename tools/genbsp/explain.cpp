// genbsp explain: an algorithm of the generic tree, step by step, on a small
// input of the user's: numbered SVG pictures, an index.html that steps
// through them with the keyboard, and a JSON trace.  The steps are read from
// the finished trees (bsp/explain.hpp), so the pictures show what the library
// computed, not a re-enactment of it.
#include "explain.hpp"
#include "commands.hpp"
#include "common.hpp"

#include <boolean/polygons.hpp>
#include <boolean/polyhedra.hpp>
#include <boolean/spherical.hpp>
#include <bsp/depth_order.hpp>
#include <bsp/explain.hpp>
#include <geometry/e1.hpp>
#include <geometry/e2/svg.hpp>
#include <geometry/io/geojson.hpp>
#include <geometry/io/wkt.hpp>
#include <geometry/s1.hpp>
#include <svm/build.hpp>
#include <svm/camera.hpp>
#include <svm/render/drawing.hpp>
#include <svm/render/svg.hpp>
#include <svm/visibility2d.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <tuple>
#include <type_traits>

namespace genbsp_tool {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;
using point2 = geometry::io::point2;

/// Pictures with more hyperplanes than this are not readable.
constexpr std::size_t most_pieces = 200;

std::string fmt(double x) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << x;
  return s.str();
}

std::string node_name(bsp::node_id n) { return (n.is_leaf() ? "leaf " : "node ") + std::to_string(n.index()); }

/// A signed term of a linear form, e.g. " - 2y", for the hyperplanes' text.
std::string linear_text(std::vector<std::pair<rational, std::string>> const& terms) {
  std::string s;
  for (auto const& [c, v] : terms) {
    if (c == 0) continue;
    rational a = c < 0 ? rational(-c) : c;
    std::string num = (a == 1 && !v.empty()) ? "" : exact_text(a);
    if (s.empty())
      s = (c < 0 ? "-" : "") + num + v;
    else
      s += (c < 0 ? " - " : " + ") + num + v;
  }
  return (s.empty() ? "0" : s) + " = 0";
}

// --- The geometries: reading an input, naming a hyperplane, drawing -------

/// Calls `f(first, second, where)` for each line of `file` that holds two
/// words ('#' starts a comment; blank lines are skipped); `form` names the
/// line's form in the error for any other line.
template <class F> void for_each_pair(std::string const& file, std::string const& form, F f) {
  std::ifstream in(file);
  if (!in) throw file_error(file + ": cannot open", errno);
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream s(line);
    std::string a, b, extra;
    if (!(s >> a)) continue;
    std::string where = file + ":" + std::to_string(number);
    if (!(s >> b) || (s >> extra)) throw usage_error(where + ": expected " + form);
    f(a, b, where);
  }
}

/// Colours of a cell: inside, outside, still to be built.
char const* fill_of(std::optional<bool> label) { return !label ? "#d9d9d9" : *label ? "#7fb2e5" : "#ffffff"; }

/// The attributes that tie a drawn cell to its trace entry: its node and its label.
std::string cell_attributes(std::string const& name, std::optional<bool> label) {
  return "data-cell=\"" + name + "\" data-label=\"" + (label ? (*label ? "in" : "out") : "pending") + "\"";
}

/// The part of hyperplane `h` inside the convex cell `c` (the intersection of
/// the positive sides of its bounds), where a node's hyperplane is drawn.
template <class G> std::optional<typename G::sub_hyperplane> section_in(typename G::hyperplane const& h, typename G::polytope const& c) {
  std::optional<typename G::sub_hyperplane> s = G::whole(h);
  for (auto const& b : c.bounds) {
    if (!s) break;
    auto r = G::split(*s, b);
    s = r.is_coincident() ? std::nullopt : r.positive;
  }
  return s;
}

/// E1: intervals of the line.
struct line_geometry {
  using G = geometry::e1::exact_kernel;
  static constexpr char const* name = "e1";
  double lo = 0, hi = 1;
  static constexpr double width = 640, height = 150, margin = 30;
  std::vector<std::pair<rational, rational>> input;

  double X(double x) const { return margin + (x - lo) / (hi - lo) * (width - 2 * margin); }

  std::vector<G::sub_hyperplane> read(std::string const& file) {
    std::vector<G::sub_hyperplane> out;
    rational total(0);
    for_each_pair(file, "an interval 'A B'", [&](std::string const& a, std::string const& b, std::string const& where) {
      rational x, y;
      try {
        x = geometry::parse_number<rational>(a), y = geometry::parse_number<rational>(b);
      } catch (geometry::parse_error const& e) {
        throw usage_error(where + ": " + e.what());
      }
      if (!(x < y)) throw usage_error(where + ": an interval 'A B' needs A < B");
      input.emplace_back(x, y);
      total += y - x;
      out.push_back({geometry::e1::hyperplane_at(x, false)});
      out.push_back({geometry::e1::hyperplane_at(y, true)});
    });
    if (input.empty()) throw usage_error(file + ": no interval");
    double a = input.front().first.convert_to<double>(), b = a;
    for (auto const& [x, y] : input) a = std::min(a, x.convert_to<double>()), b = std::max(b, y.convert_to<double>());
    double pad = std::max((b - a) * 0.15, 0.5);
    lo = a - pad, hi = b + pad;
    auto t = bsp::build_point_set<G>(out);
    if (auto m = bsp::measure(t, true); !m || *m != total) throw usage_error(file + ": the intervals overlap");
    return out;
  }
  std::string text(G::hyperplane const& h) const {
    rational at = -h.n[1] / h.n[0];
    return "x = " + exact_text(at) + (h.n[0] > 0 ? " (positive side above)" : " (positive side below)");
  }
  std::string short_text(G::hyperplane const& h) const { return "x = " + exact_text(rational(-h.n[1] / h.n[0])); }
  json region(G::polytope const& c) const {
    auto [a, b] = geometry::e1::ends(c);
    auto len = geometry::e1::length(c);
    return {{"from", a ? json(exact_text(*a)) : json(nullptr)}, {"to", b ? json(exact_text(*b)) : json(nullptr)},
            {"length", len ? json(exact_text(*len)) : json(nullptr)}};
  }
  void add(line_geometry const& o) { input.insert(input.end(), o.input.begin(), o.input.end()); }
  void draw_input(std::ostream& o) const {
    for (auto const& [a, b] : input)
      o << "<line stroke=\"#1f4e99\" stroke-width=\"3\" x1=\"" << fmt(X(a.convert_to<double>())) << "\" y1=\"105\" x2=\""
        << fmt(X(b.convert_to<double>())) << "\" y2=\"105\"/>\n";
  }
  void draw_cell(std::ostream& o, G::polytope const& c, std::optional<bool> label, std::string const& name) const {
    auto [a, b] = geometry::e1::ends(c);
    double x0 = a ? X(a->convert_to<double>()) : 0, x1 = b ? X(b->convert_to<double>()) : width;
    o << "<rect " << cell_attributes(name, label) << " fill=\""
      << fill_of(label) << "\" stroke=\"#555\" x=\"" << fmt(x0) << "\" y=\"60\" width=\"" << fmt(std::max(x1 - x0, 0.0))
      << "\" height=\"30\"/>\n";
  }
  void draw_split(std::ostream& o, G::hyperplane const& h, G::polytope const&, long number, bool newest) const {
    double x = X((-h.n[1] / h.n[0]).convert_to<double>());
    o << "<line stroke=\"" << (newest ? "#d62728" : "black") << "\" stroke-width=\"" << (newest ? 3 : 1.5) << "\" x1=\"" << fmt(x)
      << "\" y1=\"50\" x2=\"" << fmt(x) << "\" y2=\"100\"/>\n<text font-size=\"12\" text-anchor=\"middle\" x=\"" << fmt(x)
      << "\" y=\"45\">" << (number >= 0 ? std::to_string(number) : "") << "</text>\n";
  }
};

/// S1: arcs of the circle of directions.
struct circle_geometry {
  using G = geometry::s1::exact_kernel;
  using D = geometry::s1::point<rational>;
  static constexpr char const* name = "s1";
  static constexpr double width = 420, height = 420, cx = 210, cy = 225, r = 150;
  std::vector<std::pair<D, D>> input;

  static double angle(D const& d) { return std::atan2(d[1].convert_to<double>(), d[0].convert_to<double>()); }
  /// The arc from angle a counter-clockwise to b as an SVG path at radius `radius`.
  static std::string arc_path(double a, double b, double radius) {
    double sweep = b - a;
    while (sweep <= 0) sweep += 2 * std::numbers::pi;
    if (sweep >= 2 * std::numbers::pi - 1e-12) { // the whole circle: two halves
      return "M " + fmt(cx + radius) + " " + fmt(cy) + " A " + fmt(radius) + " " + fmt(radius) + " 0 1 0 " + fmt(cx - radius) + " " +
             fmt(cy) + " A " + fmt(radius) + " " + fmt(radius) + " 0 1 0 " + fmt(cx + radius) + " " + fmt(cy);
    }
    auto px = [&](double t) { return fmt(cx + radius * std::cos(t)); };
    auto py = [&](double t) { return fmt(cy - radius * std::sin(t)); };
    // Counter-clockwise in the plane is clockwise on the page (y down): sweep flag 0.
    return "M " + px(a) + " " + py(a) + " A " + fmt(radius) + " " + fmt(radius) + " 0 " + (sweep > std::numbers::pi ? "1" : "0") +
           " 0 " + px(a + sweep) + " " + py(a + sweep);
  }

  std::vector<G::sub_hyperplane> read(std::string const& file) {
    std::vector<G::sub_hyperplane> out;
    double total = 0;
    auto arc = [&](std::string const& a, std::string const& b, std::string const& where) {
      auto dir = [&](std::string const& t) {
        auto comma = t.find(',');
        if (comma == std::string::npos) throw usage_error(where + ": expected a direction X,Y, got '" + t + "'");
        try {
          D d(std::array<rational, 2>{geometry::parse_number<rational>(t.substr(0, comma)), geometry::parse_number<rational>(t.substr(comma + 1))});
          if (d[0] == 0 && d[1] == 0) throw usage_error(where + ": the zero vector is no direction");
          return d;
        } catch (geometry::parse_error const& e) {
          throw usage_error(where + ": " + e.what());
        }
      };
      D p = dir(a), q = dir(b);
      if (p[0] * q[1] - p[1] * q[0] == 0 && p[0] * q[0] + p[1] * q[1] > 0)
        throw usage_error(where + ": the two directions are the same (no arc, or the whole circle)");
      input.emplace_back(p, q);
      double sweep = angle(q) - angle(p);
      while (sweep <= 0) sweep += 2 * std::numbers::pi;
      total += sweep;
      out.push_back(geometry::s1::opposite(G::sub_hyperplane{geometry::s1::hyperplane_at(p), true, false}));
      out.push_back(G::sub_hyperplane{geometry::s1::hyperplane_at(q), true, false});
    };
    for_each_pair(file, "an arc 'X1,Y1 X2,Y2' (counter-clockwise from the first direction)", arc);
    if (input.empty()) throw usage_error(file + ": no arc");
    auto t = bsp::build_point_set<G>(out);
    if (std::abs(bsp::measure(t, true) - total) > 1e-9) throw usage_error(file + ": the arcs overlap");
    return out;
  }
  std::string text(G::hyperplane const& h) const {
    auto s = geometry::s1::start_point(h);
    return "directions ±(" + exact_text(s[0]) + ", " + exact_text(s[1]) + "), positive side counter-clockwise from (" + exact_text(s[0]) +
           ", " + exact_text(s[1]) + ")";
  }
  std::string short_text(G::hyperplane const& h) const {
    auto s = geometry::s1::start_point(h);
    return "the directions ±(" + exact_text(s[0]) + ", " + exact_text(s[1]) + ")";
  }
  json region(G::polytope const& c) const {
    auto e = geometry::s1::endpoints(c);
    auto d = [](D const& p) { return json::array({exact_text(p[0]), exact_text(p[1])}); };
    json j{{"from", e.empty() ? json(nullptr) : d(e[0])}, {"to", e.empty() ? json(nullptr) : d(e[1])}};
    j["length"] = geometry::s1::length(c);
    return j;
  }
  void add(circle_geometry const& o) { input.insert(input.end(), o.input.begin(), o.input.end()); }
  void draw_input(std::ostream& o) const {
    o << "<circle cx=\"" << cx << "\" cy=\"" << cy << "\" r=\"" << r << "\" fill=\"none\" stroke=\"#999\"/>\n";
    for (auto const& [p, q] : input)
      o << "<path fill=\"none\" stroke=\"#1f4e99\" stroke-width=\"3\" d=\"" << arc_path(angle(p), angle(q), r - 22) << "\"/>\n";
  }
  void draw_cell(std::ostream& o, G::polytope const& c, std::optional<bool> label, std::string const& name) const {
    auto e = geometry::s1::endpoints(c);
    double a = e.empty() ? 0 : angle(e[0]), b = e.empty() ? 2 * std::numbers::pi : angle(e[1]);
    if (c.bounds.size() == 1) b = a + std::numbers::pi;
    o << "<path " << cell_attributes(name, label) << " fill=\"none\" stroke=\"" << (label && !*label ? "#eeeeee" : fill_of(label)) << "\" stroke-width=\"16\" d=\""
      << arc_path(a, e.empty() ? a + 2 * std::numbers::pi : b, r) << "\"/>\n";
  }
  void draw_split(std::ostream& o, G::hyperplane const& h, G::polytope const&, long number, bool newest) const {
    double t = angle(geometry::s1::start_point(h));
    double x0 = cx + (r + 12) * std::cos(t), y0 = cy - (r + 12) * std::sin(t);
    double x1 = cx - (r + 12) * std::cos(t), y1 = cy + (r + 12) * std::sin(t);
    o << "<line stroke=\"" << (newest ? "#d62728" : "black") << "\" stroke-width=\"" << (newest ? 2.5 : 1) << "\" stroke-dasharray=\"6 4\" x1=\""
      << fmt(x0) << "\" y1=\"" << fmt(y0) << "\" x2=\"" << fmt(x1) << "\" y2=\"" << fmt(y1) << "\"/>\n<text font-size=\"12\" x=\""
      << fmt(cx + (r + 26) * std::cos(t) - 4) << "\" y=\"" << fmt(cy - (r + 26) * std::sin(t) + 4) << "\">" << (number >= 0 ? std::to_string(number) : "")
      << "</text>\n";
  }
};

/// E2: polygons with holes (WKT or GeoJSON).
struct plane_geometry {
  using G = boolean::plane_kernel;
  static constexpr char const* name = "e2";
  geometry::e2::svg_view view;
  static constexpr double pixels = 480;
  double width = pixels, height = pixels;
  std::vector<G::sub_hyperplane> edges;

  double X(double x) const { return (x - view.x0) / (view.x1 - view.x0) * width; }
  double Y(double y) const { return height - (y - view.y0) / (view.y1 - view.y0) * height; }

  std::vector<G::sub_hyperplane> read(std::string const& file) {
    auto m = geometry::io::read_polygons(file);
    try {
      auto op = boolean::operand_of(m);
      edges = op.boundary;
    } catch (boolean::invalid_polygon const& e) {
      throw usage_error(file + ": " + e.what());
    }
    if (edges.empty()) throw usage_error(file + ": no polygon with an area");
    std::vector<geometry::e2::point<rational>> corners;
    for (auto const& p : m) corners.insert(corners.end(), p.outer.begin(), p.outer.end());
    frame(corners);
    return edges;
  }
  /// The window of the pictures: around `points`, with a margin.
  void frame(std::vector<geometry::e2::point<rational>> const& points) {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool first = true;
    for (auto const& v : points) {
      double x = v.x().convert_to<double>(), y = v.y().convert_to<double>();
      if (first) x0 = x1 = x, y0 = y1 = y, first = false;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    double pad = std::max(std::max(x1 - x0, y1 - y0) * 0.15, 0.5);
    view = {x0 - pad, y0 - pad, x1 + pad, y1 + pad, pixels};
    height = pixels * (view.y1 - view.y0) / (view.x1 - view.x0);
  }
  /// A segment drawn over the picture (a fragment of a depth-order tree).
  void draw_segment(std::ostream& o, G::sub_hyperplane const& s, std::string const& colour, std::string const& attributes) const {
    if (auto e = geometry::e2::endpoints(s))
      o << "<line " << attributes << " stroke=\"" << colour << "\" stroke-width=\"5\" stroke-linecap=\"round\" x1=\""
        << fmt(X(geometry::to_double(e->first.x()))) << "\" y1=\"" << fmt(Y(geometry::to_double(e->first.y()))) << "\" x2=\""
        << fmt(X(geometry::to_double(e->second.x()))) << "\" y2=\"" << fmt(Y(geometry::to_double(e->second.y()))) << "\"/>\n";
  }
  /// The tree the library builds for the polygons (the order its Boolean operations use).
  static bsp::point_set<G, bool> tree_of(std::vector<G::sub_hyperplane> const& e) {
    return bsp::build_point_set<G>(e, true, false, bsp::random_order(20261128));
  }
  std::string text(G::hyperplane const& h) const {
    return linear_text({{h.n[0], "x"}, {h.n[1], "y"}, {h.n[2], ""}}) + " (positive side where the left side is > 0)";
  }
  /// The line alone (its equation with a positive first coefficient); `text` tells its orientation.
  std::string short_text(G::hyperplane const& h) const {
    rational s = h.n[0] != 0 ? h.n[0] : h.n[1];
    int k = s < 0 ? -1 : 1;
    return linear_text({{rational(k * h.n[0]), "x"}, {rational(k * h.n[1]), "y"}, {rational(k * h.n[2]), ""}});
  }
  json region(G::polytope const& c) const {
    json j;
    auto v = geometry::e2::vertices(c);
    if (v) {
      json pts = json::array();
      for (auto const& p : *v) pts.push_back(json::array({exact_text(p.x()), exact_text(p.y())}));
      j["vertices"] = pts;
    } else {
      j["vertices"] = nullptr; // unbounded
    }
    auto a = geometry::e2::area(c);
    j["area"] = a ? json(exact_text(*a)) : json(nullptr);
    return j;
  }
  void add(plane_geometry const& o) { edges.insert(edges.end(), o.edges.begin(), o.edges.end()); }
  void draw_input(std::ostream& o) const {
    for (auto const& s : edges)
      if (auto e = geometry::e2::endpoints(s))
        o << "<line stroke=\"#1f4e99\" stroke-width=\"3\" stroke-opacity=\"0.55\" x1=\"" << fmt(X(geometry::to_double(e->first.x())))
          << "\" y1=\"" << fmt(Y(geometry::to_double(e->first.y()))) << "\" x2=\"" << fmt(X(geometry::to_double(e->second.x())))
          << "\" y2=\"" << fmt(Y(geometry::to_double(e->second.y()))) << "\"/>\n";
  }
  void draw_cell(std::ostream& o, G::polytope const& c, std::optional<bool> label, std::string const& name) const {
    auto v = geometry::e2::vertices(geometry::e2::detail::clip_to(c, view));
    o << "<polygon " << cell_attributes(name, label) << " fill=\""
      << fill_of(label) << "\" stroke=\"#bbb\" stroke-width=\"0.5\" points=\"";
    if (v)
      for (auto const& p : *v) o << fmt(X(geometry::to_double(p.x()))) << ',' << fmt(Y(geometry::to_double(p.y()))) << ' ';
    o << "\"/>\n";
  }
  void draw_split(std::ostream& o, G::hyperplane const& h, G::polytope const& cell, long number, bool newest) const {
    auto s = section_in<G>(h, geometry::e2::detail::clip_to(cell, view));
    if (!s) return;
    auto e = geometry::e2::endpoints(*s);
    if (!e) return;
    double ax = X(geometry::to_double(e->first.x())), ay = Y(geometry::to_double(e->first.y()));
    double bx = X(geometry::to_double(e->second.x())), by = Y(geometry::to_double(e->second.y()));
    o << "<line stroke=\"" << (newest ? "#d62728" : "black") << "\" stroke-width=\"" << (newest ? 3 : 1.5) << "\" x1=\"" << fmt(ax)
      << "\" y1=\"" << fmt(ay) << "\" x2=\"" << fmt(bx) << "\" y2=\"" << fmt(by) << "\"/>\n<text font-size=\"12\" x=\""
      << fmt((ax + bx) / 2 + 3) << "\" y=\"" << fmt((ay + by) / 2 - 3) << "\">" << (number >= 0 ? std::to_string(number) : "")
      << "</text>\n";
  }
};

std::string html_escape(std::string const& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else if (c == '"') o += "&quot;";
    else o += c;
  }
  return o;
}

/// S2: spherical polygons (GeoJSON in longitude and latitude, great-circle
/// edges), drawn on a globe seen from outside, facing the input.
struct sphere_geometry {
  using G = boolean::sphere_kernel;
  using D = boolean::direction;
  using vec = std::array<double, 3>;
  static constexpr char const* name = "s2";
  static constexpr double width = 440, height = 440, cx = 220, cy = 220, r = 200;
  std::vector<G::sub_hyperplane> edges;
  vec u{1, 0, 0}, v{0, 1, 0}, w{0, 0, 1}; ///< right, up, towards the viewer
  G::hyperplane front{D(std::array<rational, 3>{rational(0), rational(0), rational(1)})};

  static vec cross3(vec const& a, vec const& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
  static double dot3(vec const& a, vec const& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  static vec unit(vec a) {
    double l = std::sqrt(dot3(a, a));
    return {a[0] / l, a[1] / l, a[2] / l};
  }
  std::string px(vec const& p) const { return fmt(cx + r * dot3(p, u)) + "," + fmt(cy - r * dot3(p, v)); }
  /// The points of the arc from `a` turning about `n` to `b` (or a whole turn when `whole`).
  std::string arc_points(vec const& a, vec const& b, vec const& n, bool whole = false) const {
    double angle = whole ? 2 * std::numbers::pi : std::atan2(dot3(cross3(a, b), n), dot3(a, b));
    if (angle <= 0) angle += 2 * std::numbers::pi;
    auto side = cross3(n, a);
    int m = std::max(2, static_cast<int>(angle * 40));
    std::string s;
    for (int j = 0; j <= m; ++j) {
      double t = angle * j / m;
      s += px({std::cos(t) * a[0] + std::sin(t) * side[0], std::cos(t) * a[1] + std::sin(t) * side[1], std::cos(t) * a[2] + std::sin(t) * side[2]}) + " ";
    }
    return s;
  }

  std::vector<G::sub_hyperplane> read(std::string const& file) {
    auto m = geometry::io::read_polygons(file);
    vec sum{0, 0, 0};
    try {
      for (auto const& p : m) {
        std::vector<boolean::loop> loops;
        auto convert = [&](geometry::io::ring const& ring) {
          boolean::loop l;
          for (auto const& c : ring) {
            l.push_back(boolean::from_lonlat(c.x(), c.y()));
            auto d = geometry::s2::to_unit(l.back());
            for (int k = 0; k < 3; ++k) sum[static_cast<std::size_t>(k)] += d[static_cast<std::size_t>(k)];
          }
          return l;
        };
        boolean::detail::add_arcs(convert(p.outer), edges);
        for (auto const& h : p.holes) boolean::detail::add_arcs(convert(h), edges);
      }
    } catch (boolean::invalid_polygon const& e) {
      throw usage_error(file + ": " + e.what());
    }
    if (edges.empty()) throw usage_error(file + ": no polygon with an area");
    // One build of every loop, as for one polygon: polygons must not overlap.
    if (std::abs(bsp::measure(tree_of(edges), true) - boolean::area(boolean::spherical_region(m))) > 1e-9)
      throw usage_error(file + ": the polygons overlap");
    face(sum);
    return edges;
  }
  /// Turns the globe so that direction `d` faces the viewer, north up where it can.
  void face(vec d) {
    if (dot3(d, d) < 1e-12) d = {1, 0, 0};
    w = unit(d);
    vec north{0, 0, 1};
    if (std::abs(dot3(w, north)) > 0.99) north = {0, 1, 0};
    u = unit(cross3(north, w));
    v = cross3(w, u);
    front = G::hyperplane(D(std::array<rational, 3>{rational(w[0]), rational(w[1]), rational(w[2])}));
  }
  void add(sphere_geometry const& o) { edges.insert(edges.end(), o.edges.begin(), o.edges.end()); }
  static bsp::point_set<G, bool> tree_of(std::vector<G::sub_hyperplane> const& e) {
    return bsp::build_point_set<G>(e, true, false, bsp::random_order(20261128));
  }
  std::string short_text(G::hyperplane const& h) const {
    auto n = geometry::s2::to_unit(h.n);
    std::ostringstream s;
    s << std::fixed << std::setprecision(2) << "the circle ⊥ (" << n[0] << ", " << n[1] << ", " << n[2] << ")";
    return s.str();
  }
  std::string text(G::hyperplane const& h) const {
    return "the great circle " + linear_text({{h.n[0], "x"}, {h.n[1], "y"}, {h.n[2], "z"}}) + " (positive side where the left side is > 0)";
  }
  json region(G::polytope const& c) const {
    json pts = json::array();
    for (auto const& p : geometry::s2::vertices(c)) {
      auto [lon, lat] = boolean::to_lonlat(p);
      pts.push_back(json::array({lon, lat}));
    }
    return {{"vertices", std::move(pts)}, {"area", geometry::s2::area(c)}};
  }
  /// The part of a cell facing the viewer, as an SVG polygon's points.
  std::string outline(G::polytope const& c) const {
    auto part = geometry::s2::split(c, front).positive;
    if (!part) return "";
    if (part->bounds.size() == 1) return arc_points(u, u, w, true); // the whole disk
    auto vs = geometry::s2::vertices(*part);
    std::string s;
    for (std::size_t i = 0, k = vs.size(); i < k; ++i)
      s += arc_points(geometry::s2::to_unit(vs[i]), geometry::s2::to_unit(vs[(i + 1) % k]), geometry::s2::to_unit(part->bounds[(i + 1) % k].n));
    return s;
  }
  void draw_input(std::ostream& o) const {
    o << "<circle cx=\"" << cx << "\" cy=\"" << cy << "\" r=\"" << r << "\" fill=\"none\" stroke=\"#999\"/>\n";
    for (auto const& e : edges) draw_arc(o, e, "#1f4e99", 3, 0.55);
  }
  void draw_arc(std::ostream& o, G::sub_hyperplane const& s, char const* colour, double width, double opacity) const {
    auto part = geometry::s2::split(s, front);
    if (!part.positive) return;
    auto e = geometry::s2::endpoints(*part.positive);
    if (e.size() != 2) return;
    o << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"" << width << "\" stroke-opacity=\"" << opacity << "\" points=\""
      << arc_points(geometry::s2::to_unit(e[0]), geometry::s2::to_unit(e[1]), geometry::s2::to_unit(s.support.n)) << "\"/>\n";
  }
  void draw_cell(std::ostream& o, G::polytope const& c, std::optional<bool> label, std::string const& name) const {
    o << "<polygon " << cell_attributes(name, label) << " fill=\""
      << fill_of(label) << "\" stroke=\"#bbb\" stroke-width=\"0.5\" points=\"" << outline(c) << "\"/>\n";
  }
  void draw_split(std::ostream& o, G::hyperplane const& h, G::polytope const& cell, long number, bool newest) const {
    auto s = section_in<G>(h, cell);
    if (!s) return;
    draw_arc(o, *s, newest ? "#d62728" : "black", newest ? 3 : 1.5, 1);
    if (number < 0) return;
    auto part = geometry::s2::split(*s, front).positive;
    if (!part) return;
    auto e = geometry::s2::endpoints(*part);
    if (e.size() != 2) return;
    auto a = geometry::s2::to_unit(e[0]), b = geometry::s2::to_unit(e[1]);
    vec mid = unit({a[0] + b[0], a[1] + b[1], a[2] + b[2]});
    if (!std::isfinite(mid[0])) mid = a;
    auto at = px(mid);
    auto comma = at.find(',');
    o << "<text font-size=\"12\" x=\"" << at.substr(0, comma) << "\" y=\"" << at.substr(comma + 1) << "\">" << number << "</text>\n";
  }
};

/// The camera of a picture of `points` from `eye`: `auto` looks at the
/// middle of their box in perspective when every vertex is within
/// 60 degrees of that direction, else takes the panorama (equirectangular).
svm::projector camera_of(std::string const& name, std::vector<svm::vec3> const& points, svm::vec3 const& eye) {
  using namespace svm::detail;
  svm::vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (auto const& v : points)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
  svm::vec3 forward = sub3({(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2}, eye);
  double widest = 0; // the largest angle between `forward` and a vertex's direction
  if (norm3(forward) > 0) {
    for (auto const& v : points) {
      auto d = sub3(v, eye);
      widest = norm3(d) > 0 ? std::max(widest, std::acos(std::clamp(dot3(unit3(d), unit3(forward)), -1.0, 1.0))) : std::numbers::pi;
    }
  } else {
    forward = {1, 0, 0}, widest = std::numbers::pi;
  }
  svm::camera cam;
  cam.forward = forward;
  cam.up = std::abs(forward[2]) > (1 - 1e-9) * norm3(forward) ? svm::vec3{0, 1, 0} : svm::vec3{0, 0, 1};
  bool panorama = name == "equirectangular" || (name == "auto" && widest > std::numbers::pi / 3);
  if (panorama) {
    cam.width = 720, cam.height = 360, cam.hfov = 360;
    return svm::projector(cam, svm::projection::equirectangular);
  }
  cam.width = 480, cam.height = 360;
  // The smallest view that holds every vertex, with a margin: a vertex at
  // (x, y, z) in the camera's frame is at (x / z, y / z) in the image plane,
  // whose half width is tan(hfov / 2) and half height that · height / width.
  // Aimed at the middle of the vertices' image, then fitted again.
  double half = 1e-3;
  for (int round = 0; round < 3; ++round) {
    svm::projector frame(cam, svm::projection::perspective);
    double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
    for (auto const& v : points)
      if (auto l = frame.local(sub3(v, eye)); l[2] > 0) {
        x0 = std::min(x0, l[0] / l[2]), x1 = std::max(x1, l[0] / l[2]);
        y0 = std::min(y0, l[1] / l[2]), y1 = std::max(y1, l[1] / l[2]);
      }
    if (!(x0 <= x1)) break;
    half = std::max({1e-3, (x1 - x0) / 2, (y1 - y0) / 2 * cam.width / cam.height});
    if (round < 2) {
      cam.forward = frame.world({(x0 + x1) / 2, (y0 + y1) / 2, 1});
      cam.up = std::abs(cam.forward[2]) > (1 - 1e-9) * norm3(cam.forward) ? svm::vec3{0, 1, 0} : svm::vec3{0, 0, 1};
    }
  }
  cam.hfov = std::clamp(2 * std::atan(1.15 * half) * 180 / std::numbers::pi, 1.0, 150.0);
  return svm::projector(cam, svm::projection::perspective);
}

/// A drawing as an `<svg>` element to nest in a picture (no XML
/// declaration), placed `top` pixels down.
std::string nested_svg(svm::render::drawing const& d, int top = 0) {
  std::string inner = svm::render::to_svg(d);
  inner.erase(0, inner.find("<svg"));
  if (top != 0) inner.insert(4, " y=\"" + std::to_string(top) + "\"");
  return inner;
}

/// The colour of cell `k` of a picture: the palette's, a little darker.
svm::render::rgb cell_colour(std::size_t k) {
  auto c = svm::render::palette(static_cast<std::int64_t>(k));
  return {c.r * 0.85, c.g * 0.85, c.b * 0.85};
}

/// E3: closed polyhedra (OFF, OBJ, STL), drawn by the library's
/// own renderer from a fixed eye: the inside cells, clipped to a box around
/// the input, as solids (each its colour); the input's edges as a wireframe
/// over them; the newest cut as a red section of its cell.  A cell alone
/// cannot be drawn (what hides what needs them all), so `draw_cell` collects
/// the inside cells and `draw_input`, which comes after them, draws them.
struct space_geometry {
  using G = boolean::space_kernel;
  static constexpr char const* name = "e3";
  double width = 480, height = 360;
  std::vector<G::sub_hyperplane> faces;
  std::vector<std::vector<svm::vec3>> outlines; ///< the input's faces, for the wireframe
  std::array<rational, 3> lo{}, hi{};
  bool framed = false;
  mutable std::vector<G::polytope> inside;

  std::vector<G::sub_hyperplane> read(std::string const& file) {
    auto scene = geometry::io::read_scene(file);
    boolean::solid s;
    try {
      s = boolean::from_scene(scene);
    } catch (std::invalid_argument const& e) {
      throw usage_error(file + ": " + e.what());
    }
    faces = s.boundary;
    for (auto const& f : faces) {
      auto v = geometry::e3::vertices(f);
      if (!v) continue;
      std::vector<svm::vec3> line;
      for (auto const& p : *v) {
        line.push_back(vec_of(p));
        for (std::size_t k = 0; k < 3; ++k) {
          if (!framed || p[k] < lo[k]) lo[k] = p[k];
          if (!framed || p[k] > hi[k]) hi[k] = p[k];
        }
        framed = true;
      }
      outlines.push_back(std::move(line));
    }
    return faces;
  }
  static bsp::point_set<G, bool> tree_of(std::vector<G::sub_hyperplane> const& pieces) { return boolean::solid_tree_of(pieces); }
  /// The box the pictures show: the input's, with a margin.
  G::polytope clip_box() const {
    rational pad(0);
    for (std::size_t k = 0; k < 3; ++k) pad = std::max(pad, (hi[k] - lo[k]) * rational(3, 20));
    return geometry::e3::box<rational>({lo[0] - pad, lo[1] - pad, lo[2] - pad}, {hi[0] + pad, hi[1] + pad, hi[2] + pad});
  }
  static std::optional<G::polytope> clipped(G::polytope c, G::polytope const& box) {
    for (auto const& f : box.faces) {
      auto r = geometry::e3::split(c, f.support);
      if (!r.positive) return std::nullopt;
      c = std::move(*r.positive);
    }
    return c;
  }
  /// The eye: in front of the box, to the right and above (exact).
  geometry::e3::point<rational> eye() const {
    rational size(0);
    for (std::size_t k = 0; k < 3; ++k) size = std::max(size, hi[k] - lo[k]);
    return {(lo[0] + hi[0]) / 2 + size * rational(3, 2), (lo[1] + hi[1]) / 2 - size * 2, (lo[2] + hi[2]) / 2 + size * rational(5, 4)};
  }
  svm::projector projector() const {
    std::vector<svm::vec3> corners;
    for (auto const& l : outlines) corners.insert(corners.end(), l.begin(), l.end());
    return camera_of("perspective", corners, vec_of(eye()));
  }
  std::string text(G::hyperplane const& h) const {
    return linear_text({{h.n[0], "x"}, {h.n[1], "y"}, {h.n[2], "z"}, {h.n[3], ""}}) + " (positive side where the left side is > 0)";
  }
  std::string short_text(G::hyperplane const& h) const {
    rational s = h.n[0] != 0 ? h.n[0] : h.n[1] != 0 ? h.n[1] : h.n[2];
    int k = s < 0 ? -1 : 1;
    return linear_text({{rational(k * h.n[0]), "x"}, {rational(k * h.n[1]), "y"}, {rational(k * h.n[2]), "z"}, {rational(k * h.n[3]), ""}});
  }
  json region(G::polytope const& c) const {
    auto v = geometry::e3::volume(c);
    return {{"faces", c.faces.size()}, {"volume", v ? json(exact_text(*v)) : json(nullptr)}};
  }
  void add(space_geometry const& o) {
    faces.insert(faces.end(), o.faces.begin(), o.faces.end());
    outlines.insert(outlines.end(), o.outlines.begin(), o.outlines.end());
  }
  void draw_cell(std::ostream& o, G::polytope const& c, std::optional<bool> label, std::string const& name) const {
    if (label && *label) {
      inside.push_back(c);
      o << "<desc " << cell_attributes(name, label) << "/>\n";
    }
  }
  void draw_input(std::ostream& o) const {
    using namespace svm::detail;
    auto pr = projector();
    auto e = eye();
    auto box = clip_box();
    // The inside cells' faces, each labelled by its cell.
    std::vector<svm::convex_piece<rational>> pieces;
    std::vector<svm::render::face_info> infos;
    for (std::size_t k = 0; k < inside.size(); ++k) {
      auto c = clipped(inside[k], box);
      if (!c) continue;
      for (auto const& f : c->faces) {
        auto v = geometry::e3::vertices(f);
        if (!v || v->size() < 3) continue;
        svm::render::face_info fi;
        fi.colour = cell_colour(k);
        svm::vec3 n{geometry::to_double(f.support.n[0]), geometry::to_double(f.support.n[1]), geometry::to_double(f.support.n[2])};
        fi.normal = unit3(n);
        fi.centre = vec_of(v->front());
        fi.offset = dot3(fi.normal, fi.centre);
        pieces.push_back({f, static_cast<std::int64_t>(infos.size())});
        infos.push_back(fi);
      }
    }
    inside.clear();
    svm::render::options ro;
    ro.eye = vec_of(e);
    auto d = svm::render::draw(svm::build(pieces, e, pr.window_options()), pr, infos, ro);
    d.background.reset();
    o << nested_svg(d);
    // The input's edges, hidden ones too, over the solids.
    o << "<path fill=\"none\" stroke=\"#1f4e99\" stroke-width=\"1\" stroke-opacity=\"0.7\" d=\"";
    for (auto const& l : outlines)
      for (std::size_t i = 0; i < l.size(); ++i) {
        auto a = pr.project(unit3(sub3(l[i], ro.eye))), b = pr.project(unit3(sub3(l[(i + 1) % l.size()], ro.eye)));
        o << 'M' << fmt(a.x) << ',' << fmt(a.y) << " L" << fmt(b.x) << ',' << fmt(b.y) << ' ';
      }
    o << "\"/>\n";
  }
  void draw_split(std::ostream& o, G::hyperplane const& h, G::polytope const& cell, long, bool newest) const {
    if (!newest) return;
    auto c = clipped(cell, clip_box());
    if (!c) return;
    std::optional<G::sub_hyperplane> s = geometry::e3::whole_plane(h);
    for (auto const& f : c->faces) {
      if (!s) break;
      s = geometry::e3::split(*s, f.support).positive;
    }
    if (!s) return;
    auto v = geometry::e3::vertices(*s);
    if (!v) return;
    auto pr = projector();
    auto e = vec_of(eye());
    o << "<polygon fill=\"#d62728\" fill-opacity=\"0.18\" stroke=\"#d62728\" stroke-width=\"2\" data-split=\"newest\" points=\"";
    for (auto const& p : *v) {
      auto q = pr.project(svm::detail::unit3(svm::detail::sub3(vec_of(p), e)));
      o << fmt(q.x) << ',' << fmt(q.y) << ' ';
    }
    o << "\"/>\n";
  }
};

// --- Steps ---------------------------------------------------------------

struct step {
  json trace;
  std::string svg;
};

/// The picture and trace entry of tree `t` after `placed` of its nodes.
/// A picture: `body` (in the geometry's coordinates) under a caption.
template <class Geo> std::string framed(Geo const& geo, std::string const& caption, std::string const& body) {
  std::ostringstream o;
  double w = geo.width, h = geo.height + 28;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fmt(w) << "\" height=\"" << fmt(h) << "\" viewBox=\"0 0 " << fmt(w) << ' '
    << fmt(h) << "\" font-family=\"sans-serif\">\n<title>" << html_escape(caption) << "</title>\n<g transform=\"translate(0,28)\">\n"
    << body << "</g>\n<text font-size=\"12\" x=\"6\" y=\"18\">" << html_escape(caption) << "</text>\n</svg>\n";
  return o.str();
}

/// A leaf's label in a picture: a point set's own, and outside (no
/// fragment) for a depth-order tree, whose leaves have none.
template <class Tree> bool leaf_label(Tree const& t, bsp::node_id n) {
  if constexpr (std::is_same_v<typename Tree::leaf_data_type, bool>)
    return t.leaf_data(n);
  else
    return false;
}

/// Draws nothing more on a picture.
struct nothing_more {
  void operator()(std::ostream&, std::size_t) const {}
};

/// The picture and trace entry of tree `t` after `placed` of its nodes;
/// `more(out, placed)` draws over it (a depth-order tree's fragments).
template <class Geo, class Tree, class More = nothing_more>
step picture(Geo const& geo, Tree const& t, std::size_t placed, bool replaying, bool show_input, std::string const& caption,
             More more = {}) {
  auto state = bsp::state_after(t, placed);
  std::ostringstream o;
  json cells = json::array();
  for (auto const& c : state.cells) {
    std::optional<bool> label;
    if (!c.pending) label = leaf_label(t, c.node);
    geo.draw_cell(o, c.region, label, node_name(c.node));
    json j{{"node", node_name(c.node)}, {"label", label ? json(*label) : json(nullptr)}, {"pending", c.pending}};
    j.update(geo.region(c.region));
    cells.push_back(std::move(j));
  }
  if (show_input) geo.draw_input(o);
  // While replaying, nodes are numbered in the order they were placed, the newest in red.
  for (auto const& [n, cell] : state.splits)
    geo.draw_split(o, t.splitter(n), cell, replaying ? static_cast<long>(n.index()) : -1, replaying && n.index() + 1 == placed);
  more(o, placed);
  return {json{{"cells", std::move(cells)}}, framed(geo, caption, o.str())};
}

/// Every step of the tree `t`'s making: the whole space, then one node at a time.
template <class Geo, class Tree, class More = nothing_more>
void replay(Geo const& geo, Tree const& t, std::string const& phase, bool show_input, std::vector<step>& out, More more = {}) {
  auto places = bsp::interior_places(t);
  for (std::size_t k = 0; k <= t.interior_count(); ++k) {
    std::string caption;
    json head{{"phase", phase}};
    if (k == 0) {
      std::string g = Geo::name;
      caption = phase + ": the whole " + (g == "e1" ? "line" : g == "s1" ? "circle" : g == "s2" ? "sphere" : g == "e3" ? "space" : "plane") +
                ", one cell to build";
      head["operation"] = "start";
    } else {
      auto n = bsp::node_id::interior(static_cast<std::uint32_t>(k - 1));
      auto const& p = places[k - 1];
      head["operation"] = "split";
      head["node"] = node_name(n);
      head["parent"] = p.parent.valid() ? json(node_name(p.parent)) : json(nullptr);
      head["side"] = p.side;
      head["depth"] = p.depth;
      head["hyperplane"] = geo.text(t.splitter(n));
      caption = phase + ", step " + std::to_string(k) + ": node " + std::to_string(k - 1) + " splits its cell by " + geo.short_text(t.splitter(n));
    }
    auto s = picture(geo, t, k, true, show_input, caption, more);
    head.update(s.trace);
    head["caption"] = caption;
    out.push_back({std::move(head), std::move(s.svg)});
  }
}

/// One picture of a finished tree.
template <class Geo>
void whole(Geo const& geo, bsp::point_set<typename Geo::G, bool> const& t, std::string const& phase, std::string const& operation,
           std::string const& caption, std::vector<step>& out) {
  auto s = picture(geo, t, t.interior_count(), false, true, caption);
  json head{{"phase", phase}, {"operation", operation}};
  head.update(s.trace);
  head["caption"] = caption;
  out.push_back({std::move(head), std::move(s.svg)});
}

/// The page that steps through the pictures (← and →, Home and End).
std::string index_html(std::vector<std::string> const& files, std::vector<std::string> const& captions, std::string const& title) {
  json f = files, c = captions;
  // "</" would end the script element early.
  auto safe = [](std::string s) {
    for (std::size_t i; (i = s.find("</")) != std::string::npos;) s.replace(i, 2, "<\\/");
    return s;
  };
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << html_escape(title)
    << "</title>\n<style>body{font-family:sans-serif;margin:1em}img{border:1px solid #ccc;max-width:100%}"
       "#bar{margin:.5em 0}button{margin-right:.3em}</style>\n</head>\n<body>\n<h1>"
    << html_escape(title)
    << "</h1>\n<div id=\"bar\"><button id=\"first\">&#x23EE;</button><button id=\"prev\">&#x25C0;</button><button "
       "id=\"next\">&#x25B6;</button><button id=\"last\">&#x23ED;</button> <span id=\"at\"></span></div>\n<p id=\"caption\"></p>\n"
       "<img id=\"picture\" alt=\"\">\n<p>Keys: &larr; &rarr; step, Home and End. The trace is <a href=\"trace.json\">trace.json</a>.</p>\n"
       "<script>\nconst files = "
    << safe(f.dump()) << ";\nconst captions = " << safe(c.dump())
    << ";\nlet at = 0;\nfunction show(k) {\n  at = Math.max(0, Math.min(files.length - 1, k));\n"
       "  document.getElementById('picture').src = files[at];\n  document.getElementById('caption').textContent = captions[at];\n"
       "  document.getElementById('at').textContent = 'step ' + at + ' of ' + (files.length - 1);\n  location.hash = at;\n}\n"
       "document.addEventListener('keydown', e => {\n  if (e.key === 'ArrowRight') show(at + 1);\n  else if (e.key === 'ArrowLeft') show(at - "
       "1);\n  else if (e.key === 'Home') show(0);\n  else if (e.key === 'End') show(files.length - 1);\n});\n"
       "for (const [id, d] of [['first', -1e9], ['prev', -1], ['next', 1], ['last', 1e9]])\n"
       "  document.getElementById(id).onclick = () => show(Math.abs(d) > 1 ? (d < 0 ? 0 : files.length - 1) : at + d);\n"
       "show(parseInt(location.hash.slice(1)) || 0);\n</script>\n</body>\n</html>\n";
  return o.str();
}

/// The geometry of an input file: `--geometry`, or its extension.
std::string geometry_of(std::string const& given, std::string const& file) {
  if (!given.empty()) return given;
  std::string ext = fs::path(file).extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (ext == ".e1") return "e1";
  if (ext == ".s1") return "s1";
  if (ext == ".wkt") return "e2";
  if (ext == ".geojson" || ext == ".json") return "s2";
  if (ext == ".off" || ext == ".obj" || ext == ".stl") return "e3";
  throw usage_error(file + ": cannot tell the geometry from '" + ext +
                    "' (.e1 intervals, .s1 arcs, .wkt polygons, .geojson spherical polygons, .off/.obj/.stl solids; or give --geometry)");
}

template <class Geo> bsp::point_set<typename Geo::G, bool> tree_of(std::vector<typename Geo::G::sub_hyperplane> const& pieces) {
  if constexpr (requires { Geo::tree_of(pieces); })
    return Geo::tree_of(pieces);
  else
    return bsp::build_point_set<typename Geo::G>(pieces);
}

bool label_op(std::string const& op, bool a, bool b) {
  if (op == "union") return a || b;
  if (op == "intersection") return a && b;
  if (op == "difference") return a && !b;
  return a != b;
}

/// Every step of the command, for the geometry `Geo`.
template <class Geo> std::vector<step> steps_of(explain_job const& job, json& trace) {
  Geo a;
  auto pa = a.read(job.input);
  std::size_t pieces = pa.size();
  std::vector<step> out;
  trace["geometry"] = Geo::name;
  if (*job.build) {
    if (pieces > most_pieces)
      throw usage_error(job.input + ": " + std::to_string(pieces) + " boundary pieces; explain draws at most " + std::to_string(most_pieces) +
                        " (a picture with more is not readable)");
    auto t = tree_of<Geo>(pa);
    replay(a, t, "build", true, out);
    trace["result"] = {{"interior_nodes", t.interior_count()}, {"cells", bsp::cells(t).size()}};
    return out;
  }
  Geo b;
  auto pb = b.read(job.other);
  pieces += pb.size();
  if (pieces > most_pieces)
    throw usage_error(job.input + ", " + job.other + ": " + std::to_string(pieces) + " boundary pieces; explain draws at most " +
                      std::to_string(most_pieces) + " (a picture with more is not readable)");
  // Both operands in one picture frame: the second's window takes the first's.
  if constexpr (requires { a.view; }) {
    auto& v = a.view;
    v.x0 = std::min(v.x0, b.view.x0), v.y0 = std::min(v.y0, b.view.y0), v.x1 = std::max(v.x1, b.view.x1), v.y1 = std::max(v.y1, b.view.y1);
    a.height = a.pixels * (v.y1 - v.y0) / (v.x1 - v.x0);
    b.view = a.view, b.height = a.height;
  } else if constexpr (requires { a.clip_box(); }) {
    // Coordinate by coordinate (arrays compare lexicographically).
    for (std::size_t k = 0; k < 3; ++k) a.lo[k] = std::min(a.lo[k], b.lo[k]), a.hi[k] = std::max(a.hi[k], b.hi[k]);
    b.lo = a.lo, b.hi = a.hi;
  } else if constexpr (requires { a.lo; }) {
    a.lo = std::min(a.lo, b.lo), a.hi = std::max(a.hi, b.hi);
    b.lo = a.lo, b.hi = a.hi;
  } else if constexpr (requires { a.w; }) {
    a.face({a.w[0] + b.w[0], a.w[1] + b.w[1], a.w[2] + b.w[2]});
    b.u = a.u, b.v = a.v, b.w = a.w, b.front = a.front;
  }
  auto ta = tree_of<Geo>(pa), tb = tree_of<Geo>(pb);
  std::string inside = std::string(Geo::name) == "e3" ? "(coloured: inside)" : "(blue: inside)";
  whole(a, ta, "a", "operand", "operand A: its tree's cells " + inside, out);
  whole(b, tb, "b", "operand", "operand B: its tree's cells " + inside, out);
  std::string op = job.op;
  auto f = [&](bool x, bool y) { return label_op(op, x, y); };
  auto merged = bsp::merge_unreduced(ta, tb, f);
  Geo both = a; // draws both operands' boundaries
  both.add(b);
  replay(both, merged, "merge " + op, true, out);
  auto result = bsp::merge(ta, tb, f);
  whole(both, result, "reduce", "reduce",
        "reduced: " + std::to_string(merged.interior_count()) + " nodes before, " + std::to_string(result.interior_count()) + " after", out);
  trace["result"] = {{"interior_nodes", result.interior_count()}, {"cells", bsp::cells(result).size()}};
  return out;
}

/// A colour from dark (rank 0, the front) to light (the back).
std::string rank_colour(std::size_t rank, std::size_t count) {
  double t = count > 1 ? static_cast<double>(rank) / static_cast<double>(count - 1) : 0;
  auto mix = [&](int a, int b) { return static_cast<int>(std::lround(a + (b - a) * t)); };
  char c[8];
  std::snprintf(c, sizeof c, "#%02x%02x%02x", mix(0x8c, 0xf4), mix(0x1d, 0xa5), mix(0x18, 0x82));
  return c;
}

/// The segments of a plane scene (polygons' edges and line strings), in file order.
std::vector<std::pair<point2, point2>> segments_of(std::string const& file) {
  auto walls = geometry::io::read_walls(file);
  std::vector<std::pair<point2, point2>> out;
  auto path = [&](geometry::io::ring const& r, bool closed) {
    for (std::size_t i = 0; i + (closed ? 0 : 1) < r.size(); ++i) {
      auto const &a = r[i], &b = r[(i + 1) % r.size()];
      if (!(a == b)) out.emplace_back(a, b);
    }
  };
  for (auto const& p : walls.polygons) {
    auto outer = p.outer;
    if (outer.size() > 1 && outer.front() == outer.back()) outer.pop_back();
    path(outer, true);
    for (auto h : p.holes) {
      if (h.size() > 1 && h.front() == h.back()) h.pop_back();
      path(h, true);
    }
  }
  for (auto const& l : walls.lines) path(l, false);
  return out;
}

using plane = boolean::plane_kernel;

/// The segments of a scene seen from an eye, in a depth-order tree, with
/// the window of their pictures.
struct segment_scene {
  point2 eye;
  std::vector<std::pair<point2, point2>> segments;
  plane_geometry geo;
  bsp::depth_order_tree<plane> tree;
  std::vector<bsp::fragment<plane>> order; ///< the fragments front to back from the eye
};

segment_scene segment_scene_of(explain_job const& job, json& trace) {
  segment_scene s;
  auto c = parse_numbers(job.eye, 2, "--eye", "X,Y");
  s.eye = point2(c[0], c[1]);
  s.segments = segments_of(job.input);
  if (s.segments.empty()) throw usage_error(job.input + ": no segment");
  if (s.segments.size() > most_pieces)
    throw usage_error(job.input + ": " + std::to_string(s.segments.size()) + " segments; explain draws at most " +
                      std::to_string(most_pieces) + " (a picture with more is not readable)");
  trace["geometry"] = "e2";
  trace["eye"] = json::array({exact_text(s.eye.x()), exact_text(s.eye.y())});
  std::vector<point2> points{s.eye};
  bsp::fragment_list<plane> input;
  for (std::size_t i = 0; i < s.segments.size(); ++i) {
    auto piece = geometry::e2::segment(s.segments[i].first, s.segments[i].second);
    s.geo.edges.push_back(piece);
    input.push_back({piece, i});
    points.push_back(s.segments[i].first), points.push_back(s.segments[i].second);
  }
  s.geo.frame(points);
  s.tree = bsp::build_depth_order<plane>(input);
  bsp::for_each_front_to_back(s.tree, s.eye, [&](bsp::fragment<plane> const& f) { s.order.push_back(f); });
  return s;
}

/// A piece's ends, exactly.
json ends_of(plane::sub_hyperplane const& s) {
  auto e = geometry::e2::endpoints(s);
  return json::array({json::array({exact_text(e->first.x()), exact_text(e->first.y())}),
                      json::array({exact_text(e->second.x()), exact_text(e->second.y())})});
}

/// The eye, drawn as a red dot.
void draw_eye(std::ostream& o, plane_geometry const& geo, point2 const& eye) {
  o << "<circle cx=\"" << fmt(geo.X(geometry::to_double(eye.x()))) << "\" cy=\"" << fmt(geo.Y(geometry::to_double(eye.y())))
    << "\" r=\"5\" fill=\"#d62728\"/>\n";
}

/// Depth order from a point: the tree's making, then its fragments front to back.
std::vector<step> depth_order_steps(explain_job const& job, json& trace) {
  auto scene = segment_scene_of(job, trace);
  auto const& geo = scene.geo;
  auto const& t = scene.tree;
  auto const& order = scene.order;
  auto const& eye = scene.eye;
  std::vector<step> out;
  // While building, each placed node's fragments are drawn over its line.
  auto at_nodes = [&](std::ostream& o, std::size_t placed) {
    for (std::uint32_t n = 0; n < placed; ++n)
      for (auto const& f : t.node_data(bsp::node_id::interior(n)))
        geo.draw_segment(o, f.piece, "#333333", "data-fragment=\"" + std::to_string(f.id) + "\"");
  };
  replay(geo, t, "build", true, out, at_nodes);
  json listed = json::array();
  for (std::size_t k = 1; k <= order.size(); ++k) {
    auto drawn = [&](std::ostream& o, std::size_t) {
      for (std::size_t r = 0; r < order.size(); ++r)
        geo.draw_segment(o, order[r].piece, r < k ? rank_colour(r, order.size()) : "#bbbbbb",
                         "data-rank=\"" + (r < k ? std::to_string(r) : std::string("later")) + "\"");
      for (std::size_t r = 0; r < k; ++r)
        if (auto e = geometry::e2::endpoints(order[r].piece))
          o << "<text font-size=\"11\" font-weight=\"bold\" x=\"" << fmt((geo.X(geometry::to_double(e->first.x())) + geo.X(geometry::to_double(e->second.x()))) / 2 + 4)
            << "\" y=\"" << fmt((geo.Y(geometry::to_double(e->first.y())) + geo.Y(geometry::to_double(e->second.y()))) / 2 - 4) << "\">" << r
            << "</text>\n";
      draw_eye(o, geo, eye);
    };
    auto const& f = order[k - 1];
    std::string caption = "front to back, step " + std::to_string(k) + ": number " + std::to_string(k - 1) + " is (part of) input segment " +
                          std::to_string(f.id);
    auto s = picture(geo, t, t.interior_count(), false, false, caption, drawn);
    json head{{"phase", "front to back"}, {"operation", "emit"}, {"rank", k - 1}, {"segment", f.id}, {"piece", ends_of(f.piece)}};
    head.update(s.trace);
    head["caption"] = caption;
    out.push_back({std::move(head), std::move(s.svg)});
    listed.push_back({{"rank", k - 1}, {"segment", f.id}, {"piece", ends_of(f.piece)}});
  }
  trace["result"] = {{"interior_nodes", t.interior_count()}, {"cells", bsp::cells(t).size()}, {"fragments", order.size()},
                     {"order", std::move(listed)}};
  return out;
}

/// A piece of a view at one step: the directions from `from` to `to`
/// (counter-clockwise), in which input segment `segment` is seen between
/// `near_from` and `near_to`, through the piece of rank `rank`; or nothing
/// (`segment` empty), the whole circle when `whole`.
struct view_piece {
  std::array<rational, 2> from, to;
  std::optional<std::size_t> segment, rank;
  point2 near_from, near_to;
  bool whole = false;
};

/// The final view split where its walls' pieces meet: each wall's arc of
/// the library's view (`svm::visibility` of the input segments, bounded
/// degree) cut at the ends of the pieces the depth order made of that wall,
/// each part labelled with its piece's rank.  The cut points (constructed)
/// serve the pictures and the ranks only, compared exactly along their wall;
/// the view itself is computed from the input.
std::vector<view_piece> ranked_view(segment_scene const& s, svm::visibility_region<rational> const& region, svm::wall_scene<rational> const& walls) {
  std::vector<view_piece> out;
  auto direction = [&](point2 const& p) { return std::array<rational, 2>{p.x() - s.eye.x(), p.y() - s.eye.y()}; };
  for (auto const& a : region.arcs) {
    if (a.wall < 0) {
      view_piece v;
      v.whole = a.whole;
      if (!a.whole) v.from = {a.start()[0], a.start()[1]}, v.to = {a.end()[0], a.end()[1]};
      out.push_back(v);
      continue;
    }
    auto w = static_cast<std::size_t>(a.wall);
    auto [p, q] = walls.wall(w);
    auto along = [&](point2 const& x) { return ((x.x() - p.x()) * (q.x() - p.x()) + (x.y() - p.y()) * (q.y() - p.y())) / ((q.x() - p.x()) * (q.x() - p.x()) + (q.y() - p.y()) * (q.y() - p.y())); };
    auto at = [&](rational const& t) { return point2(p.x() + t * (q.x() - p.x()), p.y() + t * (q.y() - p.y())); };
    rational t0 = along(svm::hit_point(s.eye, a.start(), walls.wall(w))), t1 = along(svm::hit_point(s.eye, a.end(), walls.wall(w)));
    // The wall's pieces as parameter ranges, with their ranks.
    std::vector<std::tuple<rational, rational, std::size_t>> pieces;
    std::vector<rational> cuts{t0, t1};
    for (std::size_t r = 0; r < s.order.size(); ++r)
      if (s.order[r].id == w) {
        auto e = geometry::e2::endpoints(s.order[r].piece);
        auto u = along(e->first), v = along(e->second);
        if (v < u) std::swap(u, v);
        pieces.emplace_back(u, v, r);
        for (auto const& c : {u, v})
          if ((c - t0) * (c - t1) < 0) cuts.push_back(c);
      }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end()); // two pieces of a wall share their meeting point
    if (t1 < t0) std::reverse(cuts.begin(), cuts.end());
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      rational mid = (cuts[i] + cuts[i + 1]) / 2;
      view_piece v;
      v.segment = w;
      for (auto const& [u, x, r] : pieces)
        if (u <= mid && mid <= x) v.rank = r;
      if (!v.rank) throw std::logic_error("explain visibility2d: a seen part of a wall in none of its pieces");
      v.near_from = at(cuts[i]), v.near_to = at(cuts[i + 1]);
      // The arc's own ends are input-derived directions; the cuts between are not.
      v.from = i == 0 ? std::array<rational, 2>{a.start()[0], a.start()[1]} : direction(v.near_from);
      v.to = i + 2 == cuts.size() ? std::array<rational, 2>{a.end()[0], a.end()[1]} : direction(v.near_to);
      out.push_back(v);
    }
  }
  return out;
}

/// The view after the first `k` pieces front to back: the final view's
/// parts seen through pieces of rank below `k`, nothing elsewhere.  A later
/// piece never hides an earlier one (that is what front to back means), so
/// no piece of rank below `k` lies where the final view sees a later one.
std::vector<view_piece> view_after(std::vector<view_piece> const& ranked, std::size_t k) {
  std::vector<view_piece> out;
  for (auto v : ranked) {
    if (v.rank && *v.rank >= k) v.segment.reset(), v.rank.reset();
    if (!v.segment && !out.empty() && !out.back().segment && !out.back().whole) {
      out.back().to = v.to;
      continue;
    }
    out.push_back(v);
  }
  // The first and the last meet across the start direction.
  if (out.size() > 1 && !out.front().segment && !out.back().segment) {
    out.front().from = out.back().from;
    out.pop_back();
  }
  if (out.size() == 1 && !out.front().segment) out.front().whole = true;
  return out;
}

/// A view drawn in the plane: what each part sees, from the eye to its wall,
/// and the unbounded parts as wedges out of the picture.
void draw_view(std::ostream& o, plane_geometry const& geo, point2 const& eye, std::vector<view_piece> const& view) {
  double ex = geo.X(geometry::to_double(eye.x())), ey = geo.Y(geometry::to_double(eye.y()));
  double far = 4 * (geo.width + geo.height);
  auto angle = [](std::array<rational, 2> const& d) { return std::atan2(geometry::to_double(d[1]), geometry::to_double(d[0])); };
  for (auto const& v : view) {
    // Seen parts get an outline of their own colour, so that neighbours show no seam.
    o << "<polygon fill=\"#ffe98a\" "
      << (v.segment ? "stroke=\"#ffe98a\" stroke-width=\"0.8\" data-segment=\"" + std::to_string(*v.segment) + "\" data-rank=\"" + std::to_string(*v.rank) + "\""
                    : std::string("fill-opacity=\"0.45\" data-segment=\"none\""))
      << " points=\"" << fmt(ex) << ',' << fmt(ey);
    if (!v.segment) {
      double t0 = v.whole ? 0 : angle(v.from), t1 = v.whole ? 2 * std::numbers::pi : angle(v.to);
      while (t1 <= t0) t1 += 2 * std::numbers::pi;
      for (int k = 0; k <= 16; ++k) {
        double t = t0 + (t1 - t0) * k / 16;
        o << ' ' << fmt(ex + far * std::cos(t)) << ',' << fmt(ey - far * std::sin(t));
      }
    } else {
      for (auto const& p : {v.near_from, v.near_to}) o << ' ' << fmt(geo.X(geometry::to_double(p.x()))) << ',' << fmt(geo.Y(geometry::to_double(p.y())));
    }
    o << "\"/>\n";
  }
}

/// 2D visibility: the pieces arrive front to back from the eye, and what
/// they leave visible grows; the last step is the library's region.
std::vector<step> visibility2d_steps(explain_job const& job, json& trace) {
  auto scene = segment_scene_of(job, trace);
  auto const& geo = scene.geo;
  auto const& order = scene.order;
  for (std::size_t i = 0; i < scene.segments.size(); ++i) {
    auto const& [a, b] = scene.segments[i];
    auto side = geometry::e2::side(geometry::e2::line_through(a, b), scene.eye);
    bool between = (a.x() - scene.eye.x()) * (b.x() - scene.eye.x()) + (a.y() - scene.eye.y()) * (b.y() - scene.eye.y()) <= 0;
    if (side == geometry::oriented_side::on && between)
      throw usage_error("--eye: on segment " + std::to_string(i) + " of " + job.input +
                        "; explain shows eyes off the walls (genbsp visibility2d takes eyes on them)");
  }
  // The library's view of the input segments, once; each step shows the
  // part of it seen through the pieces arrived so far.
  svm::wall_scene<rational> walls;
  for (auto const& [a, b] : scene.segments) walls.segments.push_back({a, b});
  auto region = svm::visibility(walls, scene.eye);
  auto ranked = ranked_view(scene, region, walls);
  auto exact_pair = [](std::array<rational, 2> const& d) { return json::array({exact_text(d[0]), exact_text(d[1])}); };
  std::vector<step> out;
  for (std::size_t k = 0; k <= order.size(); ++k) {
    auto view = view_after(ranked, k);
    json arcs = json::array();
    for (auto const& v : view)
      arcs.push_back({{"from", v.whole ? json(nullptr) : exact_pair(v.from)},
                      {"to", v.whole ? json(nullptr) : exact_pair(v.to)},
                      {"segment", v.segment ? json(*v.segment) : json(nullptr)},
                      {"rank", v.rank ? json(*v.rank) : json(nullptr)}});
    bool seen = k > 0 && std::any_of(view.begin(), view.end(), [&](auto const& v) { return v.rank == k - 1; });
    std::string caption = k == 0 ? "visibility: no piece yet, every direction free"
                                 : "visibility, step " + std::to_string(k) + ": piece " + std::to_string(k - 1) + " (segment " +
                                       std::to_string(order[k - 1].id) + ") arrives, " + (seen ? "partly visible" : "hidden");
    // The picture is of the view, not of a tree: no cells.
    std::ostringstream body;
    draw_view(body, geo, scene.eye, view);
    for (std::size_t r = 0; r < order.size(); ++r)
      geo.draw_segment(body, order[r].piece, r + 1 == k ? "#d62728" : r < k ? "#333333" : "#cccccc",
                       "data-piece=\"" + (r < k ? std::to_string(r) : std::string("later")) + "\"");
    draw_eye(body, geo, scene.eye);
    json head{{"phase", "visibility"}, {"operation", k == 0 ? "start" : "insert"}};
    if (k > 0) head["piece"] = ends_of(order[k - 1].piece), head["segment"] = order[k - 1].id, head["visible"] = seen;
    head["arcs"] = std::move(arcs);
    head["caption"] = caption;
    out.push_back({std::move(head), framed(geo, caption, body.str())});
  }
  json result{{"fragments", order.size()}, {"arcs", region.arcs.size()}, {"bounded", region.bounded()}};
  if (auto a = svm::area(region, walls)) result["area"] = exact_text(*a);
  trace["result"] = std::move(result);
  return out;
}

/// The vertices of polygons, in doubles.
std::vector<svm::vec3> points_of(std::vector<svm::polygon<rational>> const& polys) {
  std::vector<svm::vec3> out;
  for (auto const& p : polys)
    for (auto const& q : p.vertices) out.push_back(vec_of(q));
  return out;
}

/// The camera of a parallel view's picture: looking along the view at its
/// image, fitted to the scene's bounding box as `genbsp render --projection
/// orthographic` fits it, up along z (y when looking along z).
svm::projector parallel_camera_of(svm::view_from_infinity<rational> const& view, geometry::io::prepared const& scene) {
  auto forward = vec_of(geometry::e3::point<rational>(-view.direction()[0], -view.direction()[1], -view.direction()[2]));
  svm::vec3 up = std::abs(forward[2]) > (1 - 1e-9) * svm::detail::norm3(forward) ? svm::vec3{0, 1, 0} : svm::vec3{0, 0, 1};
  auto [lo, hi, any] = exact_box(scene);
  return svm::projector(parallel_fit(view, lo, hi, up, 480, 360), svm::projection::perspective);
}

/// The spherical visibility map growing: the scene's convex polygons go into
/// the depth-order tree (as the map's build puts them), its fragments arrive
/// front to back, and each step shows the library's map of the fragments
/// arrived so far.  No later fragment hides an earlier one, so what a step
/// shows stays to the end.  The fragments' planes are the scene's and the
/// tree's cuts (rounded constants), so every map keeps the degree bound.
std::vector<step> visibility_steps(explain_job const& job, json& trace, std::vector<std::pair<std::string, std::string>>& files) {
  using K3 = geometry::e3::kernel<rational>;
  using namespace svm::detail;
  if (job.eye.empty() == job.view_dir.empty()) throw usage_error("explain visibility: give --eye X,Y,Z or --view-dir DX,DY,DZ");
  if (!job.view_dir.empty() && job.projection != "auto") throw usage_error("--view-dir is a parallel view; leave out --projection");
  auto data = scene_data_of(job.input);
  auto polys = polygons_in<rational>(data->prepared);
  if (polys.empty()) throw usage_error(job.input + ": no face to see");
  if (polys.size() > most_pieces)
    throw usage_error(job.input + ": " + std::to_string(polys.size()) + " convex polygons; explain draws at most " +
                      std::to_string(most_pieces) + " (a picture with more is not readable)");
  trace["geometry"] = "e3";
  // A parallel view is the central view of the scene's image from a finite
  // eye (svm::view_from_infinity): the same steps on the image.
  std::optional<svm::view_from_infinity<rational>> parallel;
  geometry::e3::point<rational> eye;
  svm::vec3 light; // the head light, for shading
  if (!job.view_dir.empty()) {
    parallel.emplace(parallel_view_of(data, polys, job.view_dir));
    auto scene = polys;
    polys = parallel->image(scene);
    eye = parallel->eye();
    auto d = parse_numbers(job.view_dir, 3, "--view-dir", "DX,DY,DZ");
    trace["view_dir"] = json::array({exact_text(d[0]), exact_text(d[1]), exact_text(d[2])});
    // A far point behind the viewer.
    double size = 1;
    for (auto const& p : scene)
      for (auto const& q : p.vertices) size = std::max(size, norm3(sub3(vec_of(q), vec_of(parallel->centre()))));
    light = add3(vec_of(parallel->centre()), mul3(unit3({-geometry::to_double(d[0]), -geometry::to_double(d[1]), -geometry::to_double(d[2])}), 1e6 * size));
  } else {
    auto c = parse_numbers(job.eye, 3, "--eye", "X,Y,Z");
    eye = geometry::e3::point<rational>(c[0], c[1], c[2]);
    trace["eye"] = json::array({exact_text(c[0]), exact_text(c[1]), exact_text(c[2])});
    light = vec_of(eye);
  }
  svm::vec3 eye_d = vec_of(eye);
  // The fragments front to back, as `svm::build` makes them.
  bsp::fragment_list<K3, std::uint32_t> input;
  std::size_t edge_on = 0;
  for (std::uint32_t i = 0; i < polys.size(); ++i) {
    auto piece = svm::detail::scene_polygon(polys[i]);
    if (geometry::e3::side(piece.support, eye) == geometry::oriented_side::on) {
      ++edge_on;
      continue;
    }
    input.push_back({std::move(piece), i});
  }
  auto tree = bsp::build_depth_order<K3>(std::move(input), bsp::few_splits(geometry::e3::axis_median_cut<rational>{}, 1));
  std::vector<svm::convex_piece<rational>> order;
  std::vector<std::uint32_t> face_of; // the input face of each fragment
  bsp::for_each_front_to_back(tree, eye, [&](bsp::fragment<K3, std::uint32_t> const& f) {
    order.push_back({f.piece, static_cast<std::int64_t>(order.size())});
    face_of.push_back(polys[f.id].face);
  });
  std::optional<svm::projector> made;
  try {
    made.emplace(parallel ? parallel_camera_of(*parallel, data->prepared) : camera_of(job.projection, points_of(polys), eye_d));
  } catch (std::invalid_argument const& e) {
    throw usage_error(std::string("--projection: ") + e.what());
  }
  auto const& pr = *made;
  trace["projection"] = parallel ? "orthographic" : pr.kind() == svm::projection::perspective ? "perspective" : "equirectangular";
  // Each fragment drawn in its polygon's colour (the file's, else the palette's).
  auto by_face = face_infos(*data);
  std::vector<svm::render::face_info> infos;
  for (auto f : face_of) {
    infos.push_back(by_face[f]);
    if (!infos.back().colour) infos.back().colour = svm::render::palette(f);
  }
  svm::render::options ro;
  ro.eye = light;
  ro.tolerance = 0.25;
  int const top = 28, w = pr.cam().width, h = pr.cam().height;
  auto outline = [&](std::ostream& o, svm::convex_piece<rational> const& piece) {
    std::vector<svm::vec3> d;
    for (auto const& q : geometry::e3::homogeneous_vertices(piece.shape)) {
      double w4 = geometry::to_double(q[3]);
      d.push_back(unit3(sub3({geometry::to_double(q[0]) / w4, geometry::to_double(q[1]) / w4, geometry::to_double(q[2]) / w4}, eye_d)));
    }
    o << "<path fill=\"none\" stroke=\"#d62728\" stroke-width=\"2\" stroke-dasharray=\"6 3\" data-outline=\"arriving\" d=\"";
    for (std::size_t i = 0; i < d.size(); ++i) {
      auto const &p = d[i], &q = d[(i + 1) % d.size()];
      if (pr.kind() == svm::projection::perspective && (pr.local(p)[2] <= 0 || pr.local(q)[2] <= 0)) continue;
      auto line = svm::render::detail::arc_image(pr, p, q, 0.5);
      for (std::size_t k = 0; k < line.size(); ++k) o << (k == 0 ? "M" : " L") << fmt(line[k].x) << ',' << fmt(line[k].y);
      o << ' ';
    }
    o << "\"/>\n";
  };
  // Which fragments are visible at all, in every direction (the pictures'
  // maps see only the frame's): front to back, a fragment is visible when it
  // arrives exactly when it is in the final map.
  std::vector<char> visible(order.size(), 0);
  {
    auto all = svm::build(order, eye);
    for (auto const& f : all.map.faces())
      if (f.label >= 0) visible[static_cast<std::size_t>(f.label)] = 1;
  }
  std::vector<step> out;
  for (std::size_t k = 0; k <= order.size(); ++k) {
    std::vector<svm::convex_piece<rational>> arrived(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k));
    auto vm = svm::build(arrived, eye, pr.window_options());
    auto areas = svm::face_areas(vm.map);
    std::map<std::int64_t, double> by_label;
    for (std::size_t f = 0; f < areas.size(); ++f) by_label[vm.map.faces()[f].label] += areas[f];
    bool seen = k > 0 && visible[k - 1];
    json shown = json::array();
    for (auto const& [label, area] : by_label)
      if (label >= 0) shown.push_back({{"rank", label}, {"polygon", face_of[static_cast<std::size_t>(label)]}, {"area", area}});
    std::string caption = k == 0 ? "visibility map: no fragment yet, every direction free"
                                 : "visibility map, step " + std::to_string(k) + ": fragment " + std::to_string(k - 1) + " (of face " +
                                       std::to_string(face_of[k - 1]) + ") arrives, " + (seen ? "visible" : "hidden");
    std::string inner = nested_svg(svm::render::draw(vm, pr, infos, ro), top);
    std::ostringstream o;
    o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h + top << "\" viewBox=\"0 0 " << w << ' ' << h + top
      << "\" font-family=\"sans-serif\">\n<title>" << html_escape(caption) << "</title>\n"
      << inner << "<g transform=\"translate(0," << top << ")\">\n<rect x=\"0.5\" y=\"0.5\" width=\"" << w - 1 << "\" height=\"" << h - 1
      << "\" fill=\"none\" stroke=\"#cccccc\"/>\n";
    if (k > 0) outline(o, order[k - 1]);
    o << "</g>\n<text font-size=\"12\" x=\"6\" y=\"18\">" << html_escape(caption) << "</text>\n</svg>\n";
    json head{{"phase", "visibility"}, {"operation", k == 0 ? "start" : "insert"}};
    if (k > 0) head["rank"] = k - 1, head["polygon"] = face_of[k - 1], head["visible"] = seen;
    head["faces"] = vm.map.faces().size();
    head["seen"] = std::move(shown);
    head["free_area"] = by_label.count(-1) ? by_label[-1] : 0.0;
    head["clipped_area"] = by_label.count(svm::clipped) ? by_label[svm::clipped] : 0.0;
    head["caption"] = caption;
    out.push_back({std::move(head), o.str()});
  }
  // The last step's map over the whole sphere, labelled by input face: as
  // `genbsp map` writes it.
  auto labelled = order;
  for (std::size_t r = 0; r < labelled.size(); ++r) labelled[r].label = face_of[r];
  auto vm = svm::build(labelled, eye);
  files.emplace_back("map.json", parallel ? parallel_map_json_text(vm, *parallel, "", data) : map_json_text(vm, eye, data));
  trace["result"] = {{"polygons", polys.size()}, {"discarded_edge_on", edge_on}, {"fragments", order.size()},
                     {"faces", vm.map.faces().size()}, {"map", "map.json"}};
  return out;
}

} // namespace

void explain_job::add_to(CLI::App& app) {
  command = app.add_subcommand("explain", "an algorithm of the tree step by step on a small input: numbered SVG pictures, index.html, trace.json");
  command->require_subcommand(1);
  auto common = [&](CLI::App* c) {
    c->add_option("--geometry", geometry,
                  "e1 (intervals 'A B' per line), s1 (arcs 'X1,Y1 X2,Y2' per line), e2 (WKT or GeoJSON polygons), s2 (GeoJSON or WKT "
                  "polygons in longitude and latitude) or e3 (closed polyhedra: OFF, OBJ or STL); default from the extension")
        ->check(CLI::IsMember({"e1", "s1", "e2", "s2", "e3"}));
    c->add_option("-o,--output", output, "the folder to write (made if missing; its earlier pictures are replaced)")->required();
  };
  build = command->add_subcommand("build", "building a point-set tree from a boundary (Thibault and Naylor), one node at a time");
  build->add_option("input", input, "the region: .e1, .s1, .wkt, .geojson, or a closed polyhedron (.off, .obj, .stl)")->required();
  common(build);
  merge = command->add_subcommand("merge", "a Boolean operation by merging two trees (Naylor, Amanatides and Thibault), then reducing");
  merge->add_option("a", input, "the first region")->required();
  merge->add_option("b", other, "the second region")->required();
  merge->add_option("--op", op, "union, intersection, difference or xor")->check(CLI::IsMember({"union", "intersection", "difference", "xor"}));
  common(merge);
  depth = command->add_subcommand("depth-order", "a depth-order tree of segments (Fuchs, Kedem and Naylor), then its segments front to back from an eye");
  depth->add_option("input", input, "the segments: polygons' edges and line strings (.wkt or GeoJSON)")->required();
  depth->add_option("--eye", eye, "the eye X,Y, read exactly")->required();
  depth->add_option("-o,--output", output, "the folder to write (made if missing; its earlier pictures are replaced)")->required();
  seen = command->add_subcommand("visibility2d", "the visibility region of an eye among segments, growing as they arrive front to back");
  seen->add_option("input", input, "the walls: polygons' edges and line strings (.wkt or GeoJSON)")->required();
  seen->add_option("--eye", eye, "the eye X,Y, read exactly, on no wall")->required();
  seen->add_option("-o,--output", output, "the folder to write (made if missing; its earlier pictures are replaced)")->required();
  space = command->add_subcommand("visibility", "the spherical visibility map of an eye in a scene, growing as fragments arrive front to back");
  space->add_option("input", input, "the scene: OFF, OBJ or STL, at most 200 convex polygons")->required();
  space->add_option("--eye", eye, "the eye X,Y,Z, read exactly");
  space->add_option("--view-dir", view_dir, "or a parallel view along DX,DY,DZ (exact; no --eye)");
  space->add_option("--projection", projection,
                    "auto (perspective towards the scene when it fits in 120 degrees, else equirectangular), perspective or equirectangular")
      ->check(CLI::IsMember({"auto", "perspective", "equirectangular"}));
  space->add_option("-o,--output", output, "the folder to write (made if missing; its earlier pictures are replaced); map.json is the last step's map")
      ->required();
}

void explain_job::run() const {
  json trace{{"genbsp", version()}, {"command", *build ? "build" : *merge ? "merge" : *depth ? "depth-order" : *seen ? "visibility2d" : "visibility"}};
  trace["inputs"] = *merge ? json::array({input, other}) : json::array({input});
  if (*merge) trace["op"] = op;
  std::vector<step> steps;
  std::vector<std::pair<std::string, std::string>> extra; // more files to write: name, text
  if (*space) {
    steps = visibility_steps(*this, trace, extra);
  } else if (*depth) {
    steps = depth_order_steps(*this, trace);
  } else if (*seen) {
    steps = visibility2d_steps(*this, trace);
  } else {
    std::string g = geometry_of(geometry, input);
    if (*merge && geometry.empty() && geometry_of("", other) != g)
      throw usage_error(input + ", " + other + ": the two inputs are of different geometries");
    steps = g == "e1"   ? steps_of<line_geometry>(*this, trace)
            : g == "s1" ? steps_of<circle_geometry>(*this, trace)
            : g == "s2" ? steps_of<sphere_geometry>(*this, trace)
            : g == "e3" ? steps_of<space_geometry>(*this, trace)
                        : steps_of<plane_geometry>(*this, trace);
  }
  // Written only once everything is made; earlier pictures in the folder go first.
  std::error_code ec;
  fs::create_directories(output, ec);
  if (ec || !fs::is_directory(output)) throw file_error(output + ": cannot make the folder" + (ec ? " (" + ec.message() + ")" : ""), ec.value());
  for (auto const& e : fs::directory_iterator(output)) {
    auto name = e.path().filename().string();
    if (name.starts_with("step-") && name.ends_with(".svg")) fs::remove(e.path());
  }
  std::vector<std::string> files, captions;
  json list = json::array();
  for (std::size_t k = 0; k < steps.size(); ++k) {
    std::ostringstream name;
    name << "step-" << std::setw(3) << std::setfill('0') << k << ".svg";
    write_file((fs::path(output) / name.str()).string(), steps[k].svg);
    files.push_back(name.str());
    captions.push_back(steps[k].trace["caption"].get<std::string>());
    json s{{"step", k}, {"picture", name.str()}};
    s.update(steps[k].trace);
    list.push_back(std::move(s));
  }
  trace["steps"] = std::move(list);
  for (auto const& [name, text] : extra) write_file((fs::path(output) / name).string(), text);
  write_file((fs::path(output) / "trace.json").string(), trace.dump(1) + "\n");
  std::string title = std::string("genbsp explain ") + (*build   ? "build " + input
                                                        : *merge ? "merge " + input + " " + other + " --op " + op
                                                        : *depth ? "depth-order " + input + " --eye " + eye
                                                        : *seen  ? "visibility2d " + input + " --eye " + eye
                                                                 : "visibility " + input + (eye.empty() ? " --view-dir " + view_dir : " --eye " + eye));
  write_file((fs::path(output) / "index.html").string(), index_html(files, captions, title));
  out() << json{{"genbsp", version()}, {"steps", steps.size()}, {"output", output}}.dump() << "\n";
}

} // namespace genbsp_tool
