// genbsp bool: Boolean operations on polygons in the plane (WKT, GeoJSON,
// exact) and on the sphere (GeoJSON longitude/latitude, great-circle edges);
// genbsp csg: on closed polyhedra (OFF, OBJ, STL).
#include "boolean.hpp"
#include "common.hpp"

#include <boolean/polygons.hpp>
#include <boolean/polyhedra.hpp>
#include <boolean/spherical.hpp>
#include <geometry/io/geojson.hpp>
#include <geometry/io/scene.hpp>
#include <geometry/io/wkt.hpp>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

namespace genbsp_tool {

namespace {

using json = nlohmann::ordered_json;

/// Stages of a long run on standard error: on a terminal one updated line
/// once the run has taken a second; with --progress elsewhere, a line each.
class stages {
public:
  explicit stages(bool asked) : tty_(::isatty(2) != 0), on_(tty_ || asked) {}
  ~stages() {
    if (shown_ && tty_) std::fprintf(stderr, "\n");
  }
  void operator()(std::string const& what) {
    if (!on_) return;
    double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (tty_) {
      if (t < 1 && !shown_) return;
      std::fprintf(stderr, "\rgenbsp: %-60s (%.1f s)", what.c_str(), t);
    } else {
      std::fprintf(stderr, "genbsp: %s (%.1f s)\n", what.c_str(), t);
    }
    shown_ = true;
    std::fflush(stderr);
  }

private:
  bool tty_, on_, shown_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

boolean::set_op operation(std::string const& op) {
  if (op == "union") return boolean::set_op::union_;
  if (op == "intersection") return boolean::set_op::intersection;
  if (op == "difference") return boolean::set_op::difference;
  return boolean::set_op::symmetric_difference;
}

boolean::fill_rule rule(std::string const& r) {
  if (r == "evenodd") return boolean::fill_rule::evenodd;
  if (r == "nonzero") return boolean::fill_rule::nonzero;
  if (r == "positive") return boolean::fill_rule::positive;
  return boolean::fill_rule::negative;
}

/// The plane: an operand from a file, as polygons with holes or as paths.
boolean::operand plane_operand(std::string const& file, std::string const& fill) {
  auto m = geometry::io::read_polygons(file);
  try {
    if (fill.empty()) return boolean::operand_of(m);
    std::vector<boolean::ring> paths;
    for (auto& p : m) {
      paths.push_back(std::move(p.outer));
      for (auto& h : p.holes) paths.push_back(std::move(h));
    }
    return boolean::operand_of(paths, rule(fill));
  } catch (boolean::invalid_polygon const& e) {
    throw usage_error(file + ": " + e.what());
  }
}

boolean::spherical_operand sphere_operand(std::string const& file) {
  auto m = geometry::io::read_polygons(file);
  auto check = [&](boolean::ring const& ring) {
    for (auto const& v : ring)
      if (v.y() < -90 || v.y() > 90)
        throw usage_error(file + ": a latitude is outside [-90, 90] (positions are [longitude, latitude] in degrees)");
  };
  for (auto const& p : m) {
    check(p.outer);
    for (auto const& h : p.holes) check(h);
  }
  try {
    return boolean::spherical_operand_of(m);
  } catch (boolean::invalid_polygon const& e) {
    throw usage_error(file + ": " + e.what());
  }
}

json counts(geometry::io::multipolygon const& m) {
  std::size_t rings = 0, vertices = 0;
  for (auto const& p : m) {
    rings += 1 + p.holes.size();
    vertices += p.outer.size();
    for (auto const& h : p.holes) vertices += h.size();
  }
  return {{"polygons", m.size()}, {"rings", rings}, {"vertices", vertices}};
}

} // namespace

void bool_job::add_to(CLI::App& app) {
  command = app.add_subcommand("bool", "Boolean operation on two polygon sets (plane or sphere); prints a JSON summary");
  command->add_option("A", a, "first operand: WKT or GeoJSON file (POLYGON, MULTIPOLYGON, Feature(Collection) …)")->required();
  command->add_option("B", b, "second operand, same formats")->required();
  command->add_option("--op", op, "union, intersection, difference (A minus B) or xor")
      ->required()
      ->check(CLI::IsMember({"union", "intersection", "difference", "xor"}));
  command->add_option("--geometry", geometry, "e2: the plane (default); s2: the sphere, positions are longitude, latitude in degrees and edges great-circle arcs, each ring's region on its left (RFC 7946 orientation)")
      ->check(CLI::IsMember({"e2", "s2"}));
  command->add_option("--fill-rule", fill_rule, "e2: read every ring as a closed path (self-intersections allowed) and fill by evenodd, nonzero, positive or negative winding, instead of the polygons-with-holes rules")
      ->check(CLI::IsMember({"evenodd", "nonzero", "positive", "negative"}));
  command->add_option("-o,--output", output, "output OUT.wkt, OUT.geojson (or .json) or OUT.svg (plane only), format from the extension; - writes WKT to standard output")
      ->required();
  command->add_flag("--progress", progress, "report the stages on standard error (always on a terminal, after a second)");
}

void bool_job::run() const {
  auto start = std::chrono::steady_clock::now();
  std::string ext = output == "-" ? ".wkt" : extension(output);
  bool geojson = ext == ".geojson" || ext == ".json";
  if (ext != ".wkt" && !geojson && ext != ".svg")
    throw usage_error(output + ": unknown output format '" + ext + "' (use .wkt, .geojson or .svg)");
  json summary;
  std::string text;
  if (geometry == "e2") {
    stages say(progress);
    say("reading and building " + a);
    auto A = plane_operand(a, fill_rule);
    say("reading and building " + b);
    auto B = plane_operand(b, fill_rule);
    say(op + " of the boundaries");
    auto m = boolean::combine(operation(op), A, B);
    say("writing " + output);
    auto area = boolean::area(m);
    text = ext == ".svg" ? geometry::io::to_svg(m) : geojson ? geometry::io::to_geojson(m) : geometry::io::to_wkt(m);
    summary = {{"area", area.convert_to<double>()}, {"area_exact", exact_text(area)}};
    summary.update(counts(m));
  } else {
    if (!fill_rule.empty()) throw usage_error("--fill-rule: only for --geometry e2");
    if (ext == ".svg") throw usage_error(output + ": SVG output is for --geometry e2 (use .geojson or .wkt)");
    stages say(progress);
    say("reading and building " + a);
    auto A = sphere_operand(a);
    say("reading and building " + b);
    auto B = sphere_operand(b);
    say(op + " of the boundaries");
    std::vector<boolean::spherical_polygon> polygons;
    try {
      polygons = boolean::combine(operation(op), A, B);
    } catch (std::invalid_argument const& e) {
      throw usage_error("the result is the whole sphere, which no ring can bound");
    }
    say("writing " + output);
    auto m = boolean::lonlat_polygons(polygons);
    text = geojson ? geometry::io::to_geojson(m) : geometry::io::to_wkt(m);
    double sr = boolean::area(polygons);
    summary = {{"area", sr}, {"area_km2", sr * boolean::earth_radius_km * boolean::earth_radius_km}};
    summary.update(counts(m));
  }
  write_file(output, text);
  summary["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary["genbsp"] = version();
  if (output == "-")
    std::cerr << summary.dump() << "\n";
  else
    out() << summary.dump() << "\n";
}

namespace {

/// A solid from a mesh file; a mesh that is not a closed surface is bad input.
boolean::solid read_solid(std::string const& file) {
  auto scene = geometry::io::read_scene(file);
  try {
    auto s = boolean::from_scene(scene);
    if (s.flipped) std::cerr << "genbsp: " << file << ": the faces turn clockwise seen from outside; read inside out\n";
    return s;
  } catch (std::invalid_argument const& e) {
    throw usage_error(file + ": " + e.what());
  }
}

} // namespace

void csg_job::add_to(CLI::App& app) {
  command = app.add_subcommand("csg", "Boolean operation on two closed polyhedra; writes the result's mesh and prints a JSON summary");
  command->add_option("A", a, "first solid: a closed, consistently oriented OFF, OBJ or STL mesh")->required();
  command->add_option("B", b, "second solid, same formats")->required();
  command->add_option("--op", op, "union, intersection or difference (A minus B)")
      ->required()
      ->check(CLI::IsMember({"union", "intersection", "difference"}));
  command->add_option("-o,--output", output, "output OUT.off, OUT.obj or OUT.stl (ASCII; triangulated), format from the extension")
      ->required();
  command->add_flag("--progress", progress, "report the stages on standard error (always on a terminal, after a second)");
}

void csg_job::run() const {
  auto start = std::chrono::steady_clock::now();
  std::string ext = extension(output);
  if (ext != ".off" && ext != ".obj" && ext != ".stl")
    throw usage_error(output + ": unknown output format '" + ext + "' (use .off, .obj or .stl)");
  stages say(progress);
  say("reading and checking " + a);
  auto A = read_solid(a);
  say("reading and checking " + b);
  auto B = read_solid(b);
  auto o = op == "union" ? boolean::csg_op::union_ : op == "intersection" ? boolean::csg_op::intersection : boolean::csg_op::difference;
  say(op + " of the faces");
  auto m = boolean::combine(o, A, B);
  say("writing " + output);
  auto volume = boolean::volume(m);
  auto edges = boolean::inspect_edges(m);
  write_file(output, ext == ".off" ? boolean::to_off(m) : ext == ".obj" ? boolean::to_obj(m) : boolean::to_stl(m));
  json summary = {{"genbsp", version()},
                  {"volume", volume.convert_to<double>()},
                  {"volume_exact", exact_text(volume)},
                  {"faces", m.faces.size()},
                  {"vertices", m.vertices.size()},
                  {"closed", edges.unmatched == 0 && edges.non_manifold == 0},
                  {"non_manifold_edges", edges.non_manifold},
                  {"seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()}};
  out() << summary.dump() << "\n";
}

} // namespace genbsp_tool
