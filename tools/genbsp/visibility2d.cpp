// genbsp visibility2d: the exact visibility polygon of a point among walls
// in the plane (polygons with holes and line strings, WKT or GeoJSON).
#include "visibility2d.hpp"
#include "common.hpp"

#include <geometry/io/geojson.hpp>
#include <geometry/io/planar.hpp>
#include <geometry/io/wkt.hpp>
#include <svm/visibility2d.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <sstream>

namespace genbsp_tool {

namespace {

using json = nlohmann::ordered_json;
using point2 = geometry::e2::point<rational>;
using walls = svm::wall_scene<rational>;

rational twice_area(geometry::io::ring const& r) {
  rational t(0);
  for (std::size_t i = 0; i < r.size(); ++i) {
    auto const &a = r[i], &b = r[(i + 1) % r.size()];
    t += a.x() * b.y() - a.y() * b.x();
  }
  return t;
}

/// The walls of a file, each described as the input names it: rings turned
/// so that their polygon's inside is on the left (outer rings
/// counter-clockwise, holes clockwise), line strings' segments two-sided.
struct loaded_walls {
  walls scene;
  std::vector<json> names;
};

loaded_walls load(std::string const& file) {
  auto in = geometry::io::read_walls(file);
  loaded_walls out;
  for (std::size_t k = 0; k < in.polygons.size(); ++k) {
    auto& p = in.polygons[k];
    for (std::size_t r = 0; r <= p.holes.size(); ++r) {
      auto ring = r == 0 ? p.outer : p.holes[r - 1];
      std::size_t n = ring.size();
      rational t = twice_area(ring);
      bool reverse = r == 0 ? t < 0 : t > 0;
      if (reverse) std::reverse(ring.begin(), ring.end());
      for (std::size_t i = 0; i < n; ++i) {
        // Edge i of the turned ring is the input's edge n − 2 − i (mod n).
        std::size_t edge = reverse ? (2 * n - 2 - i) % n : i;
        out.names.push_back({{"polygon", k}, {"ring", r}, {"edge", edge}});
      }
      out.scene.rings.push_back(std::move(ring));
      out.scene.ring_polygon.push_back(k);
    }
  }
  for (std::size_t k = 0; k < in.lines.size(); ++k) {
    auto const& l = in.lines[k];
    for (std::size_t i = 0; i + 1 < l.size(); ++i) {
      out.scene.segments.push_back({l[i], l[i + 1]});
      out.names.push_back({{"line", k}, {"segment", i}});
    }
  }
  return out;
}

std::string num(rational const& q) { return geometry::io::detail::shortest(q); }

std::string svg_of(walls const& s, std::vector<point2> const& boundary, point2 const& eye) {
  double x0 = eye.x().convert_to<double>(), x1 = x0, y0 = eye.y().convert_to<double>(), y1 = y0;
  auto grow = [&](point2 const& p) {
    double x = p.x().convert_to<double>(), y = p.y().convert_to<double>();
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  };
  s.for_each_wall([&](std::size_t, point2 const& a, point2 const& b) { grow(a), grow(b); });
  for (auto const& p : boundary) grow(p);
  double w = std::max(x1 - x0, 1e-9), h = std::max(y1 - y0, 1e-9), width = 800, scale = (width - 20) / w, height = h * scale + 20;
  auto px = [&](point2 const& p) {
    std::ostringstream t;
    t << 10 + (p.x().convert_to<double>() - x0) * scale << ',' << 10 + (y1 - p.y().convert_to<double>()) * scale;
    return t.str();
  };
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 " << width
    << ' ' << height << "\">\n";
  o << "<path id=\"visible\" fill=\"#f3d36b\" fill-opacity=\"0.8\" stroke=\"#b08a10\" stroke-width=\"1\" d=\"";
  for (std::size_t i = 0; i < boundary.size(); ++i) o << (i ? " L" : "M") << px(boundary[i]);
  o << (boundary.empty() ? "" : " Z") << "\"/>\n<g id=\"walls\" stroke=\"#222\" stroke-width=\"2\" stroke-linecap=\"round\">\n";
  s.for_each_wall([&](std::size_t, point2 const& p, point2 const& q) {
    auto a = px(p), b = px(q);
    auto ca = a.find(','), cb = b.find(',');
    o << "<line x1=\"" << a.substr(0, ca) << "\" y1=\"" << a.substr(ca + 1) << "\" x2=\"" << b.substr(0, cb) << "\" y2=\""
      << b.substr(cb + 1) << "\"/>\n";
  });
  auto e = px(eye);
  auto ce = e.find(',');
  o << "</g>\n<circle id=\"eye\" cx=\"" << e.substr(0, ce) << "\" cy=\"" << e.substr(ce + 1) << "\" r=\"4\" fill=\"#c0392b\"/>\n</svg>\n";
  return o.str();
}

/// The eyes of a file (or "-", standard input): one "x y" or "x,y" a line.
std::vector<point2> read_eyes(std::string const& path) {
  std::vector<point2> out;
  for (auto& l : read_number_lines(path, 2, "'x y'")) out.emplace_back(l.values[0], l.values[1]);
  if (out.empty()) throw usage_error((path == "-" ? std::string("<stdin>") : path) + ": no eye");
  return out;
}

} // namespace

void visibility2d_job::add_to(CLI::App& app) {
  command = app.add_subcommand("visibility2d", "the exact visibility polygon of a point among walls in the plane; prints a JSON summary");
  command->add_option("SCENE", scene,
                      "walls: a WKT or GeoJSON file of polygons (with holes) and line strings; every edge is an opaque wall, and "
                      "an eye on a polygon's boundary looks into the polygon")
      ->required();
  command->add_option("--eye", eye, "the point X,Y that looks around (exact decimals)");
  command->add_option("--eyes", eyes,
                      "or a file of eyes, one 'x y' a line (- for standard input): the walls' tree is built once, and the output "
                      "holds one polygon per eye (WKT GEOMETRYCOLLECTION or GeoJSON FeatureCollection), the summary one entry per eye");
  command->add_option("--box", box,
                      "XMIN,YMIN,XMAX,YMAX: a room around everything that bounds the view; without it an unbounded view is "
                      "clipped to a box twice the scene's size and reported as \"bounded\": false");
  command->add_option("-o,--output", output, "OUT.wkt, OUT.geojson (or .json: a Feature with each boundary piece's wall) or OUT.svg; - writes WKT to standard output")
      ->required();
  command->add_option("--seed", seed, "splitter choice of the depth-order tree (the result does not depend on it)");
}

void visibility2d_job::run() const {
  auto start = std::chrono::steady_clock::now();
  std::string ext = output == "-" ? ".wkt" : extension(output);
  bool geojson = ext == ".geojson" || ext == ".json";
  if (ext != ".wkt" && !geojson && ext != ".svg")
    throw usage_error(output + ": unknown output format '" + ext + "' (use .wkt, .geojson or .svg)");
  if (eye.empty() == eyes.empty()) throw usage_error("visibility2d: give --eye X,Y or --eyes FILE");
  bool const batch = !eyes.empty();
  if (batch && ext == ".svg") throw usage_error("--eyes: one polygon per eye goes to .wkt or .geojson, not .svg");
  std::vector<point2> os;
  if (!batch) {
    auto e = parse_numbers(eye, 2, "--eye", "two numbers X,Y");
    os.emplace_back(e[0], e[1]);
  } else {
    os = read_eyes(eyes);
  }
  auto in = load(scene);
  // Ring walls come first in the scene's numbering, then segments: the
  // names were made in that order.
  auto add_box = [&](rational x0, rational y0, rational x1, rational y1) {
    // The box is the last ring: its walls go before the segments' names.
    std::size_t ring_walls = 0;
    for (auto const& r : in.scene.rings) ring_walls += r.size();
    in.scene.rings.push_back({point2(x0, y0), point2(x1, y0), point2(x1, y1), point2(x0, y1)});
    in.scene.ring_polygon.push_back(in.scene.ring_polygon.empty() ? 0 : in.scene.ring_polygon.back() + 1);
    std::vector<json> box_names;
    for (int j = 0; j < 4; ++j) box_names.push_back({{"box", j}});
    in.names.insert(in.names.begin() + static_cast<std::ptrdiff_t>(ring_walls), box_names.begin(), box_names.end());
  };
  json box_json = nullptr;
  if (!box.empty()) {
    auto b = parse_numbers(box, 4, "--box", "four numbers XMIN,YMIN,XMAX,YMAX");
    if (!(b[0] < b[2] && b[1] < b[3])) throw usage_error("--box: expected XMIN < XMAX and YMIN < YMAX, got '" + box + "'");
    for (std::size_t k = 0; k < os.size(); ++k)
      if (os[k].x() < b[0] || os[k].x() > b[2] || os[k].y() < b[1] || os[k].y() > b[3])
        throw usage_error(batch ? eyes + ": eye " + std::to_string(k + 1) + " is outside --box" : "--eye: the eye is outside --box");
    add_box(b[0], b[1], b[2], b[3]);
    box_json = {b[0].convert_to<double>(), b[1].convert_to<double>(), b[2].convert_to<double>(), b[3].convert_to<double>()};
  }
  svm::visibility2d_options options;
  options.seed = seed;
  auto index = std::make_unique<svm::wall_index<rational>>(in.scene, options);
  double preprocessing = index->preprocessing_seconds(), query = 0;
  std::vector<svm::visibility_region<rational>> regions;
  auto look = [&] {
    regions.clear();
    for (auto const& o : os) {
      regions.push_back(index->view(o));
      query += regions.back().stats.seconds;
    }
  };
  look();
  std::vector<char> bounded;
  for (auto const& r : regions) bounded.push_back(r.bounded());
  std::size_t unbounded = static_cast<std::size_t>(std::count(bounded.begin(), bounded.end(), 0));
  if (unbounded > 0) {
    // Clipped to a box twice the size of the scene and the eyes.
    rational x0 = os[0].x(), x1 = os[0].x(), y0 = os[0].y(), y1 = os[0].y();
    auto grow = [&](point2 const& p) { x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y()); };
    for (auto const& o : os) grow(o);
    in.scene.for_each_wall([&](std::size_t, point2 const& a, point2 const& b) { grow(a), grow(b); });
    rational m = std::max({x1 - x0, y1 - y0, rational(1)}) / 2;
    add_box(x0 - m, y0 - m, x1 + m, y1 + m);
    box_json = {(x0 - m).convert_to<double>(), (y0 - m).convert_to<double>(), (x1 + m).convert_to<double>(), (y1 + m).convert_to<double>()};
    std::cerr << "genbsp: " << (batch ? std::to_string(unbounded) + " of the views are" : std::string("the view is"))
              << " unbounded; clipped to the box " << box_json.dump() << " (give --box to choose one)\n";
    index = std::make_unique<svm::wall_index<rational>>(in.scene, options);
    preprocessing += index->preprocessing_seconds();
    look();
  }
  // Each view's boundary and exact area; an eye that sees no area (on a
  // spike's tip, say) has a region of one point: written empty.
  std::vector<std::vector<point2>> boundaries;
  std::vector<rational> areas;
  for (auto const& r : regions) {
    auto b = svm::boundary(r, in.scene);
    auto a = svm::area(r, in.scene);
    if (!b || !a) throw std::logic_error("visibility2d: the view inside a box is unbounded");
    if (b->size() < 3) b->clear();
    boundaries.push_back(std::move(*b));
    areas.push_back(std::move(*a));
  }
  auto feature = [&](std::size_t k) {
    auto const& o = os[k];
    auto const& boundary = boundaries[k];
    json ring = json::array();
    for (std::size_t i = 0; !boundary.empty() && i <= boundary.size(); ++i) {
      auto const& p = boundary[i % boundary.size()];
      ring.push_back({p.x().convert_to<double>(), p.y().convert_to<double>()});
    }
    json pieces = json::array();
    svm::wall_table<rational> table(in.scene);
    for (auto const& a : regions[k].arcs) {
      if (a.wall < 0) continue;
      auto w = table(static_cast<std::size_t>(a.wall));
      auto p = svm::hit_point(o, a.start(), w), q = svm::hit_point(o, a.end(), w);
      pieces.push_back({{"wall", in.names[static_cast<std::size_t>(a.wall)]},
                        {"from", {p.x().convert_to<double>(), p.y().convert_to<double>()}},
                        {"to", {q.x().convert_to<double>(), q.y().convert_to<double>()}}});
    }
    return json{{"type", "Feature"},
                {"geometry", {{"type", "Polygon"}, {"coordinates", boundary.empty() ? json::array() : json::array({ring})}}},
                {"properties",
                 {{"eye", {o.x().convert_to<double>(), o.y().convert_to<double>()}},
                  {"area", areas[k].convert_to<double>()},
                  {"bounded", bounded[k] != 0},
                  {"pieces", pieces}}}};
  };
  auto wkt = [&](std::size_t k) {
    auto const& boundary = boundaries[k];
    if (boundary.empty()) return std::string("POLYGON EMPTY");
    std::string s = "POLYGON ((";
    for (std::size_t i = 0; i <= boundary.size(); ++i) {
      auto const& p = boundary[i % boundary.size()];
      if (i) s += ", ";
      s += num(p.x()) + ' ' + num(p.y());
    }
    return s + "))";
  };
  std::string text;
  if (ext == ".svg") {
    text = svg_of(in.scene, boundaries[0], os[0]);
  } else if (geojson) {
    if (!batch) {
      text = feature(0).dump() + "\n";
    } else {
      json fs = json::array();
      for (std::size_t k = 0; k < os.size(); ++k) fs.push_back(feature(k));
      text = json{{"type", "FeatureCollection"}, {"features", std::move(fs)}}.dump() + "\n";
    }
  } else if (!batch) {
    text = wkt(0) + "\n";
  } else {
    text = "GEOMETRYCOLLECTION (";
    for (std::size_t k = 0; k < os.size(); ++k) text += (k ? ", " : "") + wkt(k);
    text += ")\n";
  }
  write_file(output, text);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  json summary;
  if (!batch) {
    auto const& st = regions[0].stats;
    summary = {{"area", areas[0].convert_to<double>()},
               {"area_exact", exact_text(areas[0])},
               {"vertices", boundaries[0].size()},
               {"bounded", bounded[0] != 0},
               {"box", box_json},
               {"walls", st.walls},
               {"arcs", st.arcs},
               {"fragments", st.fragments},
               {"visible_pieces", st.visible_pieces},
               {"hidden_pieces", st.hidden_pieces},
               {"preprocessing_seconds", preprocessing},
               {"query_seconds", query},
               {"seconds", seconds}};
  } else {
    json views = json::array();
    for (std::size_t k = 0; k < os.size(); ++k)
      views.push_back({{"eye", {os[k].x().convert_to<double>(), os[k].y().convert_to<double>()}},
                       {"area", areas[k].convert_to<double>()},
                       {"area_exact", exact_text(areas[k])},
                       {"vertices", boundaries[k].size()},
                       {"bounded", bounded[k] != 0}});
    summary = {{"eyes", os.size()},
               {"views", std::move(views)},
               {"box", box_json},
               {"walls", regions[0].stats.walls},
               {"preprocessing_seconds", preprocessing},
               {"query_seconds", query},
               {"seconds", seconds}};
  }
  summary["genbsp"] = version();
  (output == "-" ? std::cerr : out()) << summary.dump() << "\n";
}

} // namespace genbsp_tool
