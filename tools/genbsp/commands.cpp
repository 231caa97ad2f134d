// genbsp: the command-line program.  Subcommands map, locate, stats, render,
// view, shadow, scene (here), bool, csg (boolean.cpp), visibility2d
// (visibility2d.cpp) and batch (batch.cpp).
// Bad input gets one line on stderr (naming file and line where there is
// one) and exit status 2; output files are written whole or not at all.
#include <geometry/gmp_pool.hpp>
#include <geometry/io/polygons.hpp>
#include <geometry/io/scene.hpp>
#include <svm/camera.hpp>
#include <svm/lines.hpp>
#include <svm/parallel.hpp>
#include <svm/query.hpp>
#include <svm/render/cairo.hpp>
#include <svm/render/lines.hpp>
#include <svm/render/svg.hpp>
#include <svm/scenes.hpp>
#include <svm/shadow.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "batch.hpp"
#include "boolean.hpp"
#include "commands.hpp"
#include "visibility2d.hpp"
#include "explain.hpp"
#include "common.hpp"
#include "viewer_html.hpp"

#include <gmp.h>
#include <sys/resource.h>
#include <cstdlib>
#include <cstring>
#include <new>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

namespace {

using namespace genbsp_tool;

using geometry::rational;
using json = nlohmann::ordered_json;

/// "X,Y,Z" read exactly.
geometry::e3::point<rational> parse_point(std::string const& text, std::string const& option) {
  std::array<rational, 3> c;
  std::size_t start = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    std::size_t end = text.find(',', start);
    if ((i < 2) != (end != std::string::npos))
      throw usage_error(option + ": expected three numbers X,Y,Z, got '" + text + "'");
    try {
      c[i] = geometry::parse_number<rational>(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    } catch (geometry::parse_error const& e) {
      throw usage_error(option + ": " + e.what());
    }
    start = end + 1;
  }
  return {c[0], c[1], c[2]};
}


std::size_t peak_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<std::size_t>(u.ru_maxrss) * 1024;
}

/// What map, locate and stats share: the scene, the eye and the build options.
struct map_job {
  std::string scene_path, eye_text, number = "exact";
  bool no_simplify = false, cull = false, no_solid_culling = false, progress = false;

  void add_options(CLI::App& app, bool eye_required = true) {
    app.add_flag("--progress", progress, "report the build's progress on standard error (always on a terminal, after a second)");
    app.add_option("SCENE", scene_path, "scene file: OFF, OBJ or STL (face index = order in the file)")->required();
    auto* eye = app.add_option("--eye", eye_text, eye_required ? "the observer, X,Y,Z (read exactly)"
                                                               : "the observer, X,Y,Z (read exactly; not for --projection orthographic)");
    if (eye_required) eye->required();
    app.add_option("--number", number, "arithmetic: exact (default) or double")->check(CLI::IsMember({"exact", "double"}));
    app.add_flag("--no-simplify", no_simplify, "keep the partition edges between faces of the same polygon");
    app.add_flag("--cull-backfaces", cull, "drop polygons facing away (closed, outward-oriented solids only)");
    app.add_flag("--no-solid-culling", no_solid_culling,
                 "keep the back faces of closed convex solids seen from outside (proven hidden: culled by default; same map)");
  }
};

/// A scene as the map subcommands use it: its convex polygons, shared with
/// the batch that read it (when one did).
struct loaded {
  std::shared_ptr<scene_data const> data;
  geometry::io::prepared const& prepared;
  std::size_t input_faces;
};

loaded load(map_job const& job) {
  if (!job.eye_text.empty()) parse_point(job.eye_text, "--eye");
  if (parse_only()) throw options_checked{};
  auto d = scene_data_of(job.scene_path);
  return {d, d->prepared, d->scene.faces.size()};
}

/// The scene's convex polygons in the number type `FT`.
template <class FT> std::vector<svm::polygon<FT>> polygons_in(loaded const& l) { return genbsp_tool::polygons_in<FT>(l.prepared); }

/// Lights in the number type `FT`.
template <class FT> std::vector<svm::light_source<FT>> lights_in(std::vector<svm::light_source<rational>> const& lights) {
  if constexpr (std::is_same_v<FT, rational>) return lights;
  else {
    std::vector<svm::light_source<FT>> out;
    auto d = [](rational const& x) { return x.convert_to<double>(); };
    for (auto const& l : lights)
      out.push_back(l.point ? svm::light_source<FT>::at({d(l.point->x()), d(l.point->y()), d(l.point->z())})
                            : svm::light_source<FT>::sun({d(l.direction[0]), d(l.direction[1]), d(l.direction[2])}));
    return out;
  }
}

/// Point lights for shadows: with any, the map is built from the scene's
/// lit and shadowed pieces, its labels indices in `regions`.
struct shadow_job {
  std::vector<svm::light_source<rational>> lights;
  std::vector<svm::lit_region>* regions = nullptr;
  svm::shadow_statistics* stats = nullptr;
};

/// The lit pieces of `polygons` and each polygon with a shadow, labelled by
/// region (`svm::label_regions`); the regions and statistics go to `shadows`.
template <class FT>
std::vector<svm::convex_piece<FT>> shadowed_pieces(std::vector<svm::polygon<FT>> const& polygons, shadow_job const& shadows,
                                                   std::uint64_t seed) {
  auto sh = svm::compute_shadows<FT>(polygons, lights_in<FT>(shadows.lights), {.seed = seed, .shadowed_pieces = false});
  if (shadows.stats) *shadows.stats = sh.stats;
  auto scene = svm::label_regions(sh, polygons);
  if (shadows.regions) *shadows.regions = std::move(scene.regions);
  return std::move(scene.pieces);
}

/// The map of `polygons` from `eye`, or of their shadow pieces.
template <class FT>
svm::visibility_map<FT> map_of(std::vector<svm::polygon<FT>> const& polygons, geometry::e3::point<FT> const& eye, svm::build_options const& o,
                               shadow_job const& shadows) {
  if (shadows.lights.empty()) return svm::build<FT>(polygons, eye, o);
  return svm::build<FT>(shadowed_pieces(polygons, shadows, o.seed), eye, o);
}

/// The build options a map job asks for: simplification, culling, progress.
void configure(map_job const& job, svm::build_options& o) {
  o.simplify = !job.no_simplify;
  o.cull_backfaces = job.cull;
  o.cull_convex_solids = !job.no_solid_culling;
  // Progress: on a terminal, one updated line once the build has run a
  // second; with --progress elsewhere, a line every 10 %.
  // A batch reports progress per job, not per build.
  bool tty = !batch_worker() && ::isatty(2) != 0;
  if (tty || (job.progress && !batch_worker())) {
    auto start = std::chrono::steady_clock::now();
    o.progress = [tty, start, shown = false, last = -10](double f) mutable {
      double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      int percent = static_cast<int>(f * 100);
      if (tty) {
        if (elapsed < 1 && !shown) return;
        shown = true;
        std::fprintf(stderr, "\rgenbsp: mapping %3d%% (%.0f s)%s", percent, elapsed, f >= 1 ? "\n" : "");
      } else if (percent / 10 != last / 10 || f >= 1) {
        std::fprintf(stderr, "genbsp: mapping %d%% (%.1f s)\n", percent, elapsed);
      }
      last = percent;
      std::fflush(stderr);
    };
  }
}

/// The map in either number type, then a function of it.
template <class F> auto with_map(map_job const& job, loaded const& l, F&& f, svm::build_options o = {}, shadow_job const& shadows = {}) {
  auto eye = parse_point(job.eye_text, "--eye");
  configure(job, o);
  if (job.number == "double") {
    geometry::e3::point<double> e(eye.x().convert_to<double>(), eye.y().convert_to<double>(), eye.z().convert_to<double>());
    return f(map_of<double>(polygons_in<double>(l), e, o, shadows));
  }
  return f(map_of<rational>(polygons_in<rational>(l), eye, o, shadows));
}

/// A hidden-line drawing of one view: the map of the polygons `seen` (the
/// scene `scene`, or its image in a parallel view, each polygon labelled by
/// its own index) from `eye`, and the lines read off it; with lights, the
/// map of the scene's lit pieces (`carry` takes them to where they are seen).
/// What it drew goes to `summary`.
template <class FT, class Carry>
svm::render::drawing line_view(std::vector<svm::polygon<FT>> const& scene, std::vector<svm::polygon<FT>> const& seen,
                               geometry::e3::point<FT> const& eye, svm::build_options const& o, shadow_job shadows, Carry&& carry,
                               svm::projector const& pr, svm::render::line_drawing_options const& lo, double crease, json& summary) {
  auto t0 = std::chrono::steady_clock::now();
  std::vector<svm::lit_region> regions;
  svm::visibility_map<FT> vm;
  if (shadows.lights.empty()) {
    vm = svm::build<FT>(seen, eye, o);
  } else {
    shadows.regions = &regions;
    auto pieces = shadowed_pieces(scene, shadows, o.seed);
    for (auto& p : pieces) carry(p);
    vm = svm::build<FT>(pieces, eye, o);
  }
  auto t1 = std::chrono::steady_clock::now();
  auto polygon_of = [&](std::int64_t label) -> std::int64_t {
    return regions.empty() ? label : static_cast<std::int64_t>(regions[static_cast<std::size_t>(label)].face);
  };
  auto lines = svm::hidden_lines(vm, eye, seen, polygon_of, {.crease = crease});
  svm::render::line_drawing_summary s;
  auto d = svm::render::draw_lines(lines, vm, eye, pr, lo, &s);
  auto counts = [](std::array<svm::render::line_drawing_summary::count, svm::line_class_count> const& c) {
    json out = json::object();
    for (std::size_t k = 0; k < c.size(); ++k)
      if (c[k].edges || c[k].polylines)
        out[std::string(svm::name_of(static_cast<svm::line_class>(k)))] = {
            {"edges", c[k].edges}, {"polylines", c[k].polylines}, {"length_px", std::round(c[k].length * 100) / 100}};
    return out;
  };
  summary = {{"edges", lines.stats.edges},
             {"edges_through_eye", lines.stats.edges_through_eye},
             {"visible", counts(s.visible)},
             {"hidden", counts(s.hidden)},
             {"pen_travel_px", {{"before", std::round(s.travel_before * 100) / 100}, {"after", std::round(s.travel_after * 100) / 100}}},
             {"seconds", {{"map", std::chrono::duration<double>(t1 - t0).count()}, {"lines", lines.stats.seconds}}}};
  return d;
}

/// The map of a parallel view: the central map of the scene's image from
/// the finite eye of `view` (with shadows, of its pieces carried there).
svm::visibility_map<rational> orthographic_map(map_job const& job, svm::view_from_infinity<rational> const& view,
                                               std::vector<svm::polygon<rational>> const& image, loaded const& l, svm::build_options o,
                                               shadow_job const& shadows) {
  o.simplify = !job.no_simplify;
  o.cull_backfaces = job.cull;
  o.cull_convex_solids = !job.no_solid_culling;
  if (shadows.lights.empty()) return svm::build<rational>(image, view.eye(), o);
  auto pieces = shadowed_pieces(polygons_in<rational>(l), shadows, o.seed);
  for (auto& p : pieces) p.shape = view.carry(p.shape, true);
  return svm::build<rational>(pieces, view.eye(), o);
}


/// The parallel view along `dir_text` (exact), about the centre of the
/// scene's bounding box, keeping `also` on the scene's side.
svm::view_from_infinity<rational> parallel_view(loaded const& l, std::vector<svm::polygon<rational>> const& polys, std::string const& dir_text,
                                                std::vector<geometry::e3::point<rational>> const& also) {
  auto d = parse_point(dir_text, "--view-dir");
  if (d.x() == 0 && d.y() == 0 && d.z() == 0) throw usage_error("--view-dir: the zero vector is no direction");
  auto [lo, hi, any] = exact_box(l.prepared);
  if (!any) throw usage_error("--view-dir: the scene has no faces");
  geometry::e3::point<rational> centre((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
  return svm::view_from_infinity<rational>(polys, {-d.x(), -d.y(), -d.z()}, centre, also);
}

svm::build_options parallel_options(map_job const& job) {
  if (job.number != "exact") throw usage_error("--view-dir: exact arithmetic only, for now");
  svm::build_options o;
  o.simplify = !job.no_simplify;
  o.cull_backfaces = job.cull;
  o.cull_convex_solids = !job.no_solid_culling;
  return o;
}

json size_json(svm::map_size const& s) { return {{"vertices", s.vertices}, {"edges", s.edges}, {"faces", s.faces}}; }

template <class FT> json stats_json(svm::visibility_map<FT> const& vm, loaded const& l) {
  auto const& st = vm.stats;
  return {{"genbsp", version()},
          {"input_faces", l.input_faces},
          {"polygons", st.input_polygons},
          {"degenerate_faces", l.prepared.degenerate_faces},
          {"triangulated_faces", l.prepared.triangulated_faces},
          {"discarded_faces", st.discarded_edge_on + st.discarded_backfacing},
          {"discarded_edge_on", st.discarded_edge_on},
          {"discarded_backfacing", st.discarded_backfacing},
          {"convex_solids", st.convex_solids},
          {"discarded_outside_window", st.discarded_outside_window},
          {"fragments", st.fragments},
          {"hidden_pieces", st.hidden_pieces},
          {"v_nodes", st.v_nodes},
          {"v_nodes_peak", st.v_nodes_peak},
          {"locator_nodes", st.locator_nodes},
          {"locator_seconds", st.locator_seconds},
          {"depth_order_seconds", st.depth_order_seconds},
          {"visible_seconds", st.visible_seconds},
          {"map_seconds", st.map_seconds},
          {"simplify_seconds", st.simplify_seconds},
          {"rebuilds", st.rebuilds},
          {"visible_pieces", st.visible_pieces},
          {"map_pieces", st.map_pieces},
          {"map_tree_nodes", st.map_tree_nodes},
          {"map", size_json(st.simplified)},
          {"map_unsimplified", size_json(st.unsimplified)},
          {"filter_fallbacks", st.filter_fallbacks},
          {"seconds", st.seconds},
          {"peak_bytes", peak_bytes()}};
}

/// MAP.json: unit vertices, faces with their cycles (counter-clockwise seen
/// from outside the sphere, face on the left; the outer cycle first: the one
/// whose left side is smallest).
template <class FT>
json map_json(svm::visibility_map<FT> const& vm, geometry::e3::point<rational> const& eye, loaded const& l,
              std::vector<svm::lit_region> const* regions = nullptr) {
  auto const& m = vm.map;
  json vertices = json::array();
  for (svm::index v = 0; v < m.vertices().size(); ++v) {
    auto u = svm::unit(m, v);
    vertices.push_back({u[0], u[1], u[2]});
  }
  auto cycles = svm::face_cycles(m);
  json faces = json::array();
  for (svm::index f = 0; f < m.faces().size(); ++f) {
    std::vector<std::pair<double, json>> cs;
    for (auto const& c : cycles[f]) {
      double turn = 0;
      json ids = json::array();
      for (auto e : c) {
        ids.push_back(m.origin(e));
        auto v = svm::unit(m, m.target(e));
        auto tin = geometry::cross(svm::unit_circle(m, e), v), tout = geometry::cross(svm::unit_circle(m, m.next(e)), v);
        turn += std::atan2(geometry::dot(v, geometry::cross(tin, tout)), geometry::dot(tin, tout));
      }
      cs.emplace_back(2 * std::numbers::pi - turn, std::move(ids));
    }
    std::sort(cs.begin(), cs.end(), [](auto const& a, auto const& b) { return a.first < b.first; });
    json jc = json::array();
    for (auto& c : cs) jc.push_back(std::move(c.second));
    std::int64_t label = m.faces()[f].label;
    if (regions && label >= 0) {
      auto const& r = (*regions)[static_cast<std::size_t>(label)];
      json lit = json::array();
      for (std::size_t k = 0; k < svm::max_lights; ++k)
        if ((r.lights >> k) & 1u) lit.push_back(k);
      faces.push_back({{"polygon", r.face}, {"lights", std::move(lit)}, {"cycles", std::move(jc)}});
    } else {
      faces.push_back({{"polygon", label}, {"cycles", std::move(jc)}});
    }
  }
  return {{"eye", {eye.x().convert_to<double>(), eye.y().convert_to<double>(), eye.z().convert_to<double>()}},
          {"vertices", std::move(vertices)},
          {"faces", std::move(faces)},
          {"stats", stats_json(vm, l)}};
}

svm::vec3 parse_vec(std::string const& text, std::string const& option);

/// MAP.json of a parallel view: the map's vertices where their rays meet
/// the view plane through the scene's centre, in that plane's coordinates
/// (`right`, `up`); cycles counter-clockwise in them, the outer one first.
json parallel_map_json(svm::visibility_map<rational> const& vm, svm::view_from_infinity<rational> const& view, std::string const& up_text,
                       loaded const& l) {
  auto const& m = vm.map;
  auto d = [](rational const& x) { return x.convert_to<double>(); };
  auto const& e = view.direction(); // towards the viewer
  svm::vec3 f{-d(e[0]), -d(e[1]), -d(e[2])};
  auto norm = [](svm::vec3 v) {
    double n = std::sqrt(geometry::dot(v, v));
    return svm::vec3{v[0] / n, v[1] / n, v[2] / n};
  };
  f = norm(f);
  svm::vec3 up = up_text.empty() ? (f[0] == 0 && f[1] == 0 ? svm::vec3{0, 1, 0} : svm::vec3{0, 0, 1}) : parse_vec(up_text, "--up");
  double along = geometry::dot(up, f);
  up = {up[0] - along * f[0], up[1] - along * f[1], up[2] - along * f[2]};
  if (geometry::dot(up, up) < 1e-24) throw usage_error("--up: parallel to the view direction");
  up = norm(up);
  svm::vec3 right = geometry::cross(f, up);
  // The ray from the image's eye along the unit vector u meets the fixed
  // plane e·(x − c) = 0 at c + s·e/|e|² − s·u/(e·u): its coordinates are
  // −s·(u·right)/(e·u) and −s·(u·up)/(e·u).
  double s = d(view.s());
  svm::vec3 ed{d(e[0]), d(e[1]), d(e[2])};
  json vertices = json::array();
  std::vector<std::array<double, 2>> xy;
  for (svm::index v = 0; v < m.vertices().size(); ++v) {
    auto u = svm::unit(m, v);
    double eu = geometry::dot(ed, u);
    if (!(eu < 0)) throw std::logic_error("map --view-dir: a vertex of the map does not face the view plane");
    xy.push_back({-s * geometry::dot(u, right) / eu, -s * geometry::dot(u, up) / eu});
    vertices.push_back({xy.back()[0], xy.back()[1]});
  }
  auto cycles = svm::face_cycles(m);
  json faces = json::array();
  for (svm::index f2 = 0; f2 < m.faces().size(); ++f2) {
    // Counter-clockwise on the sphere seen from outside is clockwise seen from the eye: reversed.
    std::vector<std::pair<double, json>> cs;
    for (auto const& c : cycles[f2]) {
      std::vector<svm::index> ids;
      for (auto it = c.rbegin(); it != c.rend(); ++it) ids.push_back(m.origin(*it));
      double twice = 0;
      for (std::size_t i = 0; i < ids.size(); ++i) {
        auto const &a = xy[ids[i]], &b = xy[ids[(i + 1) % ids.size()]];
        twice += a[0] * b[1] - a[1] * b[0];
      }
      cs.emplace_back(-twice, json(ids));
    }
    std::sort(cs.begin(), cs.end(), [](auto const& a, auto const& b) { return a.first < b.first; });
    json jc = json::array();
    for (auto& c : cs) jc.push_back(std::move(c.second));
    faces.push_back({{"polygon", m.faces()[f2].label}, {"cycles", std::move(jc)}});
  }
  auto v3 = [](svm::vec3 const& v) { return json{v[0], v[1], v[2]}; };
  auto const& c = view.centre();
  return {{"view",
           {{"direction", v3(f)}, {"centre", {d(c.x()), d(c.y()), d(c.z())}}, {"right", v3(right)}, {"up", v3(up)}}},
          {"vertices", std::move(vertices)},
          {"faces", std::move(faces)},
          {"stats", stats_json(vm, l)}};
}

std::string off_text(svm::scenes::scene const& s) {
  std::ostringstream out;
  std::size_t nv = 0;
  for (auto const& p : s.polygons) nv += p.vertices.size();
  out << "OFF\n# genbsp scene; exact coordinates (p/q where a decimal would not terminate)\n";
  out << nv << ' ' << s.polygons.size() << " 0\n";
  for (auto const& p : s.polygons)
    for (auto const& v : p.vertices) out << exact_text(v.x()) << ' ' << exact_text(v.y()) << ' ' << exact_text(v.z()) << '\n';
  std::size_t k = 0;
  for (std::size_t f = 0; f < s.polygons.size(); ++f) {
    auto const& p = s.polygons[f];
    out << p.vertices.size();
    for (std::size_t i = 0; i < p.vertices.size(); ++i) out << ' ' << k++;
    if (f < s.colours.size()) out << ' ' << int(s.colours[f][0]) << ' ' << int(s.colours[f][1]) << ' ' << int(s.colours[f][2]);
    out << '\n';
  }
  return out.str();
}

/// "X,Y,Z" as doubles (directions and points of the camera).
svm::vec3 parse_vec(std::string const& text, std::string const& option) { return vec_of(parse_point(text, option)); }

/// The lights of `--light X,Y,Z` (points) and then `--sun DX,DY,DZ`
/// (directions towards lights at infinity), at most `svm::max_lights`.
std::vector<svm::light_source<rational>> lights_from(std::vector<std::string> const& points, std::vector<std::string> const& suns) {
  std::vector<svm::light_source<rational>> out;
  for (auto const& t : points) out.push_back(svm::light_source<rational>::at(parse_point(t, "--light")));
  for (auto const& t : suns) {
    auto d = parse_point(t, "--sun");
    if (d.x() == 0 && d.y() == 0 && d.z() == 0) throw usage_error("--sun: the zero vector is no direction");
    out.push_back(svm::light_source<rational>::sun({d.x(), d.y(), d.z()}));
  }
  if (out.size() > svm::max_lights) throw usage_error("--light, --sun: at most 64 lights");
  return out;
}

} // namespace

std::vector<svm::render::face_info> genbsp_tool::face_infos(scene_data const& d) {
  std::vector<svm::render::face_info> out(d.scene.faces.size());
  std::vector<char> seen(out.size(), 0);
  for (auto const& p : d.prepared.polygons) {
    if (p.face >= out.size() || seen[p.face]) continue;
    seen[p.face] = 1;
    auto& fi = out[p.face];
    std::vector<svm::vec3> v;
    for (auto const& q : p.vertices) v.push_back(vec_of(q));
    using namespace svm::detail;
    svm::vec3 n{0, 0, 0}, c{0, 0, 0};
    for (std::size_t i = 0; i < v.size(); ++i) n = add3(n, cross3(v[i], v[(i + 1) % v.size()])), c = add3(c, v[i]);
    if (norm3(n) > 0) fi.normal = unit3(n);
    fi.centre = mul3(c, 1.0 / static_cast<double>(v.size()));
    fi.offset = dot3(fi.normal, v[0]);
    if (auto const& colour = d.scene.faces[p.face].colour) fi.colour = svm::render::rgb{colour->r, colour->g, colour->b};
  }
  return out;
}

std::tuple<std::array<rational, 3>, std::array<rational, 3>, bool> genbsp_tool::exact_box(geometry::io::prepared const& scene) {
  std::array<rational, 3> lo{}, hi{};
  bool any = false;
  for (auto const& p : scene.polygons)
    for (auto const& q : p.vertices) {
      for (int k = 0; k < 3; ++k) {
        if (!any || q[k] < lo[k]) lo[k] = q[k];
        if (!any || q[k] > hi[k]) hi[k] = q[k];
      }
      any = true;
    }
  return {lo, hi, any};
}

svm::vec3 genbsp_tool::vec_of(geometry::e3::point<rational> const& p) {
  return {p.x().convert_to<double>(), p.y().convert_to<double>(), p.z().convert_to<double>()};
}

svm::camera genbsp_tool::parallel_fit(svm::view_from_infinity<rational> const& view, std::array<rational, 3> const& lo,
                                      std::array<rational, 3> const& hi, svm::vec3 const& up, int width, int height) {
  svm::camera cam;
  auto const& d = view.direction();
  cam.forward = {-d[0].convert_to<double>(), -d[1].convert_to<double>(), -d[2].convert_to<double>()};
  cam.up = up;
  cam.width = width, cam.height = height;
  svm::projector base(cam, svm::projection::perspective);
  svm::vec3 c = vec_of(view.centre());
  // The box's corners, seen along the view, with a margin.
  double half_w = 0, half_h = 0;
  for (int corner = 0; corner < 8; ++corner) {
    svm::vec3 p{(corner & 1 ? hi : lo)[0].convert_to<double>(), (corner & 2 ? hi : lo)[1].convert_to<double>(),
                (corner & 4 ? hi : lo)[2].convert_to<double>()};
    auto v = svm::detail::sub3(p, c);
    half_w = std::max(half_w, std::abs(svm::detail::dot3(v, base.right())));
    half_h = std::max(half_h, std::abs(svm::detail::dot3(v, base.up())));
  }
  double extent = 2.1 * std::max({half_w, half_h * width / height, 1e-300});
  return svm::parallel_camera(view, up, extent, width, height);
}

namespace {

/// Writes a drawing to `path`, the format from its extension, whole or not at all.
void write_drawing(svm::render::drawing const& d, std::string const& path, int digits) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (ext == ".svg") return write_file(path, svm::render::to_svg(d, digits));
  svm::render::cairo_format f = ext == ".pdf" ? svm::render::cairo_format::pdf
                                : ext == ".eps" ? svm::render::cairo_format::eps
                                                : svm::render::cairo_format::png;
  std::filesystem::path target(path), tmp = target;
  tmp += ".tmp" + std::to_string(::getpid()) + ext;
  {
    // Made here first, so that a file that cannot be made is told by its cause.
    std::ofstream probe(tmp, std::ios::binary);
    if (!probe) {
      int code = errno;
      throw file_error(path + ": cannot write", code);
    }
  }
  try {
    svm::render::write_cairo(d, tmp.string(), f);
  } catch (std::runtime_error const& e) {
    std::filesystem::remove(tmp);
    throw file_error(path + ": cannot write (" + e.what() + ")", 0);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, target, ec);
  if (ec) {
    std::filesystem::remove(tmp);
    throw file_error(path + ": " + ec.message(), ec.value());
  }
}

/// `genbsp shadow`: the pieces as coloured OFF or OBJ (decimal vertices,
/// 17 significant digits), or a JSON summary of areas per face.
std::string shadow_output(map_job const& job, std::vector<std::string> const& light_texts, std::vector<std::string> const& sun_texts,
                          std::string const& out) {
  std::string ext = std::filesystem::path(out).extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (ext != ".off" && ext != ".obj" && ext != ".json")
    throw usage_error(out + ": unknown output format '" + ext + "' (use .off, .obj or .json)");
  auto l = load(job);
  auto lights = lights_from(light_texts, sun_texts);
  if (lights.empty()) throw usage_error("shadow: give at least one --light X,Y,Z or --sun DX,DY,DZ");
  auto colours = [&] {
    std::vector<std::optional<geometry::io::rgb>> c;
    for (auto const& f : l.data->scene.faces) c.push_back(f.colour);
    return c;
  }();
  svm::shadow_options so;
  if (job.progress)
    so.progress = [](double f) { std::fprintf(stderr, "genbsp: shadows %d%%\n", static_cast<int>(f * 100)); };
  // Areas need only the lit pieces (the rest of each face is in shadow).
  so.shadowed_pieces = ext != ".json";
  auto write = [&]<class FT>(std::vector<svm::polygon<FT>> const& polygons, std::vector<svm::light_source<FT>> const& ls) {
    auto sh = svm::compute_shadows<FT>(polygons, ls, so);
    auto d = [](FT const& x) {
      if constexpr (std::is_same_v<FT, double>) return x;
      else return x.template convert_to<double>();
    };
    // The area in space of a polygon given by its vertices (Newell).
    auto area_of = [](std::vector<std::array<double, 3>> const& v) {
      std::array<double, 3> n{0, 0, 0};
      for (std::size_t i = 0; i < v.size(); ++i) {
        auto const &a = v[i], &b = v[(i + 1) % v.size()];
        n[0] += (a[1] - b[1]) * (a[2] + b[2]), n[1] += (a[2] - b[2]) * (a[0] + b[0]), n[2] += (a[0] - b[0]) * (a[1] + b[1]);
      }
      return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) / 2;
    };
    // Per piece: its vertices in doubles and its area.
    struct shown {
      std::vector<std::array<double, 3>> v;
      double area = 0;
    };
    std::vector<shown> pieces;
    for (auto const& p : sh.pieces) {
      shown s;
      if (auto vs = geometry::e3::vertices(p.shape))
        for (auto const& q : *vs) s.v.push_back({d(q.x()), d(q.y()), d(q.z())});
      s.area = area_of(s.v);
      pieces.push_back(std::move(s));
    }
    auto face_of = [&](std::size_t i) { return polygons[sh.pieces[i].polygon].face; };
    auto rgb = [&](std::size_t i) {
      std::uint32_t f = face_of(i);
      geometry::io::rgb c = f < colours.size() && colours[f] ? *colours[f] : geometry::io::rgb{0.85, 0.85, 0.85};
      double k = sh.pieces[i].lights != 0 ? 1.0 : 0.3;
      auto byte = [k](double x) { return static_cast<int>(std::lround(std::clamp(x * k, 0.0, 1.0) * 255)); };
      return std::array<int, 3>{byte(c.r), byte(c.g), byte(c.b)};
    };
    char buf[160];
    std::string text;
    if (ext == ".off") {
      std::size_t nv = 0;
      for (auto const& p : pieces) nv += p.v.size();
      text = "OFF\n# genbsp shadow: lit pieces in their colour, shadowed ones dark\n" + std::to_string(nv) + " " +
             std::to_string(pieces.size()) + " 0\n";
      for (auto const& p : pieces)
        for (auto const& v : p.v) std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", v[0], v[1], v[2]), text += buf;
      std::size_t k = 0;
      for (std::size_t i = 0; i < pieces.size(); ++i) {
        text += std::to_string(pieces[i].v.size());
        for (std::size_t j = 0; j < pieces[i].v.size(); ++j) text += " " + std::to_string(k++);
        auto c = rgb(i);
        std::snprintf(buf, sizeof buf, " %d %d %d\n", c[0], c[1], c[2]);
        text += buf;
      }
      return text;
    }
    if (ext == ".obj") {
      text = "# genbsp shadow: lit pieces in their colour, shadowed ones dark (vertex colours)\n";
      std::size_t k = 1;
      for (std::size_t i = 0; i < pieces.size(); ++i) {
        auto c = rgb(i);
        for (auto const& v : pieces[i].v)
          std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g %.6g %.6g %.6g\n", v[0], v[1], v[2], c[0] / 255.0, c[1] / 255.0, c[2] / 255.0),
              text += buf;
        text += "f";
        for (std::size_t j = 0; j < pieces[i].v.size(); ++j) text += " " + std::to_string(k++);
        text += "\n";
      }
      return text;
    }
    // JSON: per input face, its area, the area each light reaches, the area
    // no light reaches.
    std::size_t nf = l.input_faces;
    std::vector<double> area(nf, 0), dark(nf, 0);
    std::vector<std::vector<double>> lit(nf, std::vector<double>(ls.size(), 0));
    std::vector<char> present(nf, 0);
    for (auto const& p : polygons) {
      std::vector<std::array<double, 3>> v;
      for (auto const& q : p.vertices) v.push_back({d(q.x()), d(q.y()), d(q.z())});
      present[p.face] = 1;
      area[p.face] += area_of(v);
      dark[p.face] += area_of(v);
    }
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      std::uint32_t f = face_of(i);
      if (sh.pieces[i].lights != 0) dark[f] -= pieces[i].area;
      for (std::size_t k = 0; k < ls.size(); ++k)
        if ((sh.pieces[i].lights >> k) & 1u) lit[f][k] += pieces[i].area;
    }
    for (auto& x : dark) x = std::max(0.0, x);
    json faces = json::array();
    for (std::size_t f = 0; f < nf; ++f)
      if (present[f]) faces.push_back({{"face", f}, {"area", area[f]}, {"lit_area", lit[f]}, {"shadowed_area", dark[f]}});
    json jl = json::array();
    auto d3 = [](auto const& x, auto const& y, auto const& z) {
      return json{x.template convert_to<double>(), y.template convert_to<double>(), z.template convert_to<double>()};
    };
    for (auto const& t : lights)
      jl.push_back(t.point ? d3(t.point->x(), t.point->y(), t.point->z()) : json{{"sun", d3(t.direction[0], t.direction[1], t.direction[2])}});
    auto const& st = sh.stats;
    json stats{{"input_faces", l.input_faces}, {"polygons", st.input_polygons},     {"lights", st.lights},
               {"fragments", st.fragments},   {"lit_parts", st.lit_parts},         {"shadowed_parts", st.shadowed_parts},
               {"pieces", st.pieces},         {"filter_fallbacks", st.filter_fallbacks}, {"seconds", st.seconds},
               {"peak_bytes", peak_bytes()}};
    return json{{"lights", std::move(jl)}, {"faces", std::move(faces)}, {"stats", std::move(stats)}}.dump(1) + "\n";
  };
  if (job.number == "double") return write(polygons_in<double>(l), lights_in<double>(lights));
  return write(polygons_in<rational>(l), lights);
}

} // namespace

namespace genbsp_tool {

std::string suffixed(std::string const& path, std::string_view what) {
  std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "-" + std::string(what) + p.extension().string())).string();
}

std::vector<std::string> render_files(std::string const& out, bool cube, bool split_layers) {
  std::vector<std::string> views;
  if (cube)
    for (auto face : cube_faces) views.push_back(suffixed(out, face));
  else
    views.push_back(out);
  std::vector<std::string> files = views;
  if (split_layers)
    for (auto const& v : views)
      for (char const* seen : {"visible-", "hidden-"})
        for (std::size_t c = 0; c < svm::line_class_count; ++c)
          files.push_back(suffixed(v, std::string(seen) + std::string(svm::name_of(static_cast<svm::line_class>(c)))));
  return files;
}

std::shared_ptr<scene_data const> read_scene_data(std::string const& path, bool prepare) {
  auto d = std::make_shared<scene_data>();
  d->path = path;
  d->scene = geometry::io::read_scene(path);
  if (prepare) d->prepared = geometry::io::convex_polygons(d->scene), d->has_prepared = true;
  return d;
}

namespace {
scene_data const*& preloaded() {
  thread_local scene_data const* p = nullptr;
  return p;
}
} // namespace

scene_scope::scene_scope(std::shared_ptr<scene_data const> d) : data_(std::move(d)), previous_(preloaded()) { preloaded() = data_.get(); }
scene_scope::~scene_scope() { preloaded() = previous_; }

std::shared_ptr<scene_data const> scene_data_of(std::string const& path, bool prepare) {
  if (auto const* p = preloaded(); p && p->path == path && (p->has_prepared || !prepare))
    return std::shared_ptr<scene_data const>(std::shared_ptr<scene_data const>{}, p); // borrowed: the scope owns it
  return read_scene_data(path, prepare);
}

std::string map_json_text(svm::visibility_map<rational> const& vm, geometry::e3::point<rational> const& eye,
                          std::shared_ptr<scene_data const> const& scene) {
  return map_json(vm, eye, loaded{scene, scene->prepared, scene->scene.faces.size()}).dump(1) + "\n";
}
std::string map_json_text(svm::visibility_map<double> const& vm, geometry::e3::point<rational> const& eye,
                          std::shared_ptr<scene_data const> const& scene) {
  return map_json(vm, eye, loaded{scene, scene->prepared, scene->scene.faces.size()}).dump(1) + "\n";
}

svm::view_from_infinity<rational> parallel_view_of(std::shared_ptr<scene_data const> const& scene,
                                                   std::vector<svm::polygon<rational>> const& polygons, std::string const& direction) {
  return parallel_view(loaded{scene, scene->prepared, scene->scene.faces.size()}, polygons, direction, {});
}

std::string parallel_map_json_text(svm::visibility_map<rational> const& vm, svm::view_from_infinity<rational> const& view,
                                   std::string const& up, std::shared_ptr<scene_data const> const& scene) {
  return parallel_map_json(vm, view, up, loaded{scene, scene->prepared, scene->scene.faces.size()}).dump(1) + "\n";
}

int run(std::vector<std::string> const& args) {
  std::vector<char*> argv;
  for (auto const& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  return run(static_cast<int>(args.size()), argv.data());
}

namespace {

/// "SIZE": bytes, or a number with K, M, G or T (powers of 1024), as bytes.
std::uint64_t memory_size(std::string const& text) {
  std::size_t used = 0;
  double x = 0;
  try {
    x = std::stod(text, &used);
  } catch (std::exception const&) {
    used = 0;
  }
  std::string unit = text.substr(used);
  for (auto& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (unit.size() == 2 && unit[1] == 'B') unit.pop_back();
  static std::map<std::string, double> const scale{{"", 1}, {"B", 1}, {"K", 0x1p10}, {"M", 0x1p20}, {"G", 0x1p30}, {"T", 0x1p40}};
  auto it = scale.find(unit);
  if (used == 0 || it == scale.end() || !(x > 0) || !(x * it->second < 0x1p62))
    throw usage_error("--max-memory: expected a size such as 512M or 2G, got '" + text + "'");
  auto bytes = static_cast<std::uint64_t>(x * it->second);
  if (bytes < (std::uint64_t{64} << 20)) throw usage_error("--max-memory: at least 64M (the program itself needs that much address space)");
  return bytes;
}

/// GMP's allocation, throwing `std::bad_alloc` when memory runs out instead
/// of aborting: the program then ends with its one-line message.
void* gmp_allocate(std::size_t n) {
  if (void* p = std::malloc(n)) return p;
  throw std::bad_alloc();
}
void* gmp_reallocate(void* p, std::size_t, std::size_t n) {
  if (void* q = std::realloc(p, n)) return q;
  throw std::bad_alloc();
}
void gmp_free(void* p, std::size_t) { std::free(p); }

} // namespace

int run(int argc, char** argv) {
  CLI::App app{"genbsp: binary space partitioning for exact geometric computing"};
  app.require_subcommand(1);
  app.fallthrough(); // --max-memory after the subcommand too
  app.set_version_flag("--version", "genbsp " + version(), "print the version and the source revision, and exit");
  std::string max_memory;
  app.add_option("--max-memory", max_memory,
                 "stop with one line and exit status 2, writing nothing, rather than use more than SIZE of memory (address space): "
                 "bytes, or a number with K, M, G or T (powers of 1024)")
      ->envname("GENBSP_MAX_MEMORY");

  map_job mj;
  std::string map_out;
  auto* map = app.add_subcommand("map", "the spherical visibility map of a scene seen from an eye, as MAP.json");
  mj.add_options(*map, false);
  std::string map_view_dir, map_up;
  map->add_option("--view-dir", map_view_dir,
                  "or the map of a parallel view along DX,DY,DZ (no --eye; exact): vertices in the view plane's coordinates");
  map->add_option("--up", map_up, "with --view-dir: the view plane's vertical, X,Y,Z (default 0,0,1, or 0,1,0 when looking along z)");
  map->add_option("-o,--output", map_out, "output MAP.json (- for standard output)")->required();
  bool map_stats = false;
  map->add_flag("--stats", map_stats, "also print the map's sizes and times (as genbsp stats does) on standard output");

  map_job lj;
  std::string dirs;
  auto* locate = app.add_subcommand("locate", "the input face visible in each direction (one 'dx dy dz' per line) or -1");
  lj.add_options(*locate, false);
  std::string locate_view_dir;
  locate->add_option("--view-dir", locate_view_dir,
                     "or a parallel view along DX,DY,DZ (no --eye): each line of --dirs is then a point 'x y z', and the answer is the "
                     "face seen along the line through it");
  locate->add_option("--dirs", dirs, "file of directions, - for standard input")->required();

  map_job sj;
  auto* stats = app.add_subcommand("stats", "sizes and times of a map, as one JSON object");
  sj.add_options(*stats, false);
  std::string stats_view_dir;
  stats->add_option("--view-dir", stats_view_dir, "or the map of a parallel view along DX,DY,DZ (no --eye; exact)");
  std::vector<std::string> stats_lights, stats_suns;
  stats->add_option("--light", stats_lights, "the map of the scene's lit and shadowed pieces from these point lights (repeatable)");
  stats->add_option("--sun", stats_suns, "and from these lights at infinity, DX,DY,DZ towards each (repeatable)");

  map_job rj;
  std::string render_out, look_text, dir_text, up_text, size_text, projection_name = "perspective",
                           style_name = "shaded", shift_text;
  std::vector<std::string> render_lights, render_suns;
  bool render_shadows = false;
  double fov = 0, crease = 0, tolerance = 0.1;
  int digits = 2;
  auto* render = app.add_subcommand("render", "draw a scene from an eye as SVG, PDF, EPS or PNG, hidden parts removed exactly");
  rj.add_options(*render, false);
  std::string extent_text;
  render->add_option("--look", look_text, "a point to look at, X,Y,Z (default: the scene's centre)");
  render->add_option("--dir", dir_text, "or a direction to look in, X,Y,Z");
  render->add_option("--up", up_text, "the image's vertical, X,Y,Z (default 0,0,1, or 0,1,0 when looking along z)");
  render->add_option("--fov", fov, "horizontal field of view in degrees (default 60; 360 for equirectangular)")->check(CLI::Range(0.001, 360.0));
  render->add_option("--size", size_text, "image size WxH in pixels (default 800x600; 1600x800 for equirectangular)");
  render->add_option("--projection", projection_name,
                     "perspective, stereographic, fisheye (equidistant), fisheye-equisolid, equirectangular, cube (six perspective files OUT-front, -right, -back, -left, -up, -down), "
                     "or orthographic (a parallel view along --dir, exact: no --eye)")
      ->check(CLI::IsMember({"perspective", "stereographic", "fisheye", "fisheye-equidistant", "fisheye-equisolid", "equirectangular", "cube", "orthographic"}));
  render->add_option("--extent", extent_text, "orthographic: the width of the scene shown, in its units (default: the scene fits)");
  std::string named_view;
  render->add_option("--view", named_view,
                     "a named parallel view (orthographic): front (along +y), back (-y), left (+x), right (-x), top (along -z, up +y), "
                     "bottom (+z, up -y) or iso (along -1,1,-1); up +z unless said")
      ->check(CLI::IsMember({"front", "back", "left", "right", "top", "bottom", "iso"}));
  render->add_option("--style", style_name, "shaded (default), flat, lines or id")->check(CLI::IsMember({"shaded", "flat", "lines", "id"}));
  render->add_option("--light", render_lights, "a point light at X,Y,Z (read exactly; repeat for more, up to 64; default: a head light at the eye)");
  render->add_option("--sun", render_suns, "a light at infinity: the direction towards it, DX,DY,DZ (repeatable)");
  render->add_flag("--shadows", render_shadows, "cast the lights' shadows, exactly (lit parts shaded per light, the rest ambient)");
  render->add_option("--crease", crease, "lines: draw edges between polygons only where their planes meet at more than this angle (degrees)")->check(CLI::Range(0.0, 180.0));
  std::string hidden_name = "none";
  bool split_layers = false;
  double line_width = 0;
  render->add_option("--hidden", hidden_name,
                     "lines: hidden edges not drawn (none, default), dashed, thin, or dashed on layers the document hides (layer)")
      ->check(CLI::IsMember({"none", "dashed", "thin", "layer"}));
  render->add_flag("--split-layers", split_layers, "lines: also write each layer (one pen) to OUT-LAYER.EXT, e.g. out-visible-outline.svg");
  render->add_option("--line-width", line_width, "lines: width of visible outlines in pixels (default: the larger image side / 800)")
      ->check(CLI::Range(0.001, 1000.0));
  render->add_option("--shift", shift_text, "perspective image-plane shift SX,SY in image half-widths (keeps verticals vertical)");
  render->add_option("--tolerance", tolerance, "fisheye and panorama: arcs subdivided to this many pixels (default 0.1)")->check(CLI::Range(0.001, 100.0));
  render->add_option("--precision", digits, "SVG coordinate decimals (default 2)")->check(CLI::Range(0, 9));
  render->add_option("-o,--output", render_out, "output OUT.svg, .pdf, .eps or .png (format from the extension)")->required();

  map_job vj;
  std::string view_out;
  auto* view = app.add_subcommand("view", "write one self-contained HTML page that looks around from the eye (docs/viewer.md)");
  vj.add_options(*view);
  view->add_option("-o,--output", view_out, "output VIEWER.html (opens from disk, no network)")->required();
  std::vector<std::string> view_lights, view_suns;
  view->add_option("--light", view_lights, "a point light at X,Y,Z whose shadows the page shows (repeat for more, up to 64)");
  view->add_option("--sun", view_suns, "a light at infinity, DX,DY,DZ towards it, whose shadows the page shows (repeatable)");

  map_job hj;
  std::vector<std::string> shadow_lights, shadow_suns;
  std::string shadow_out;
  auto* shadow = app.add_subcommand("shadow", "split every face into lit and shadowed pieces, exactly, as OFF, OBJ (coloured) or JSON (areas)");
  shadow->add_flag("--progress", hj.progress, "report progress on standard error");
  shadow->add_option("SCENE", hj.scene_path, "scene file: OFF, OBJ or STL (face index = order in the file)")->required();
  shadow->add_option("--light", shadow_lights, "a point light at X,Y,Z (read exactly; repeat for more, up to 64 lights in all)");
  shadow->add_option("--sun", shadow_suns, "a light at infinity: the direction towards it, DX,DY,DZ (repeatable; after the points in the lights' order)");
  shadow->add_option("--number", hj.number, "arithmetic: exact (default) or double")->check(CLI::IsMember({"exact", "double"}));
  shadow->add_option("-o,--output", shadow_out, "output OUT.off or OUT.obj (pieces coloured lit or dark), or OUT.json (areas per face)")->required();

  std::string family, scene_out;
  std::size_t n = 8;
  std::uint64_t seed = 1;
  auto* scene = app.add_subcommand("scene", "write a scene of the paper's families; prints the suggested eye X,Y,Z");
  scene->add_option("FAMILY", family, "bricks, hidden-bricks, platforms, random, terrain, sphere, or room (a furnished room with colours; --n is ignored)")
      ->required()
      ->check(CLI::IsMember({"bricks", "hidden-bricks", "platforms", "random", "terrain", "sphere", "room"}));
  scene->add_option("--n", n, "size: boxes (bricks), slabs (platforms), cubes (random), grid side (terrain), bands (sphere: 4n(n-1) triangles)")->check(CLI::Range(1, 1000000));
  scene->add_option("--seed", seed, "random seed");
  scene->add_option("-o,--output", scene_out, "output SCENE.off")->required();

  bool_job bj;
  bj.add_to(app);
  visibility2d_job v2j;
  v2j.add_to(app);
  csg_job cj;
  cj.add_to(app);
  batch_job batch;
  batch.add_to(app);
  explain_job ej;
  ej.add_to(app);

  try {
    app.parse(argc, argv);
  } catch (CLI::CallForHelp const& e) {
    return app.exit(e);
  } catch (CLI::CallForAllHelp const& e) {
    return app.exit(e);
  } catch (CLI::CallForVersion const& e) {
    return app.exit(e);
  } catch (CLI::ParseError const& e) {
    std::string what = e.what();
    throw usage_error(what.substr(0, what.find('\n')) + " (try --help)");
  }
  if (!max_memory.empty()) {
    auto bytes = memory_size(max_memory);
    if (!program_owns_process())
      throw usage_error("--max-memory: only for the genbsp program, which owns its process (from Python: resource.setrlimit)");
    rlimit r{};
    getrlimit(RLIMIT_AS, &r);
    if (r.rlim_max != RLIM_INFINITY && bytes > r.rlim_max) bytes = r.rlim_max;
    r.rlim_cur = static_cast<rlim_t>(bytes);
    if (setrlimit(RLIMIT_AS, &r) != 0) throw usage_error("--max-memory: the system refused the limit (" + std::string(std::strerror(errno)) + ")");
    memory_limit_text() = max_memory;
  }
  // map, stats and render check what they can before reading the scene (see `load`).
  if (parse_only() && !*map && !*stats && !*render) return 0;

  if (*ej.command) {
    ej.run();
  } else if (*batch.command) {
    return batch.run();
  } else if (*v2j.command) {
    v2j.run();
  } else if (*bj.command) {
    bj.run();
  } else if (*cj.command) {
    cj.run();
  } else if (*map) {
    if (mj.eye_text.empty() == map_view_dir.empty()) throw usage_error("map: give --eye X,Y,Z or --view-dir DX,DY,DZ");
    if (!map_up.empty() && map_view_dir.empty()) throw usage_error("--up is for --view-dir");
    auto l = load(mj);
    if (!map_view_dir.empty()) {
      auto polys = polygons_in<rational>(l);
      auto view = parallel_view(l, polys, map_view_dir, {});
      auto vm = svm::build<rational>(view.image(polys), view.eye(), parallel_options(mj));
      auto j = parallel_map_json(vm, view, map_up, l);
      write_file(map_out, j.dump(1) + "\n");
      if (map_stats) out() << j["stats"].dump() << "\n";
      return 0;
    }
    auto eye = parse_point(mj.eye_text, "--eye");
    auto j = with_map(mj, l, [&](auto const& vm) { return map_json(vm, eye, l); });
    write_file(map_out, j.dump(1) + "\n");
    if (map_stats) out() << j["stats"].dump() << "\n";
  } else if (*stats) {
    if (sj.eye_text.empty() == stats_view_dir.empty()) throw usage_error("stats: give --eye X,Y,Z or --view-dir DX,DY,DZ");
    if (!stats_view_dir.empty() && (!stats_lights.empty() || !stats_suns.empty()))
      throw usage_error("--view-dir: no lights yet (render --projection orthographic has them)");
    auto l = load(sj);
    if (!stats_view_dir.empty()) {
      auto polys = polygons_in<rational>(l);
      auto view = parallel_view(l, polys, stats_view_dir, {});
      out() << stats_json(svm::build<rational>(view.image(polys), view.eye(), parallel_options(sj)), l).dump() << "\n";
      return 0;
    }
    shadow_job shadows;
    svm::shadow_statistics sst;
    std::vector<svm::lit_region> regions;
    shadows.lights = lights_from(stats_lights, stats_suns);
    shadows.stats = &sst;
    shadows.regions = &regions;
    out() << with_map(
                     sj, l,
                     [&](auto const& vm) {
                       auto j = stats_json(vm, l);
                       if (!shadows.lights.empty())
                         j["shadows"] = {{"lights", sst.lights},           {"fragments", sst.fragments}, {"lit_parts", sst.lit_parts},
                                         {"shadowed_parts", sst.shadowed_parts}, {"pieces", sst.pieces},       {"regions", regions.size()},
                                         {"filter_fallbacks", sst.filter_fallbacks}, {"seconds", sst.seconds}};
                       return j.dump();
                     },
                     {}, shadows)
              << "\n";
  } else if (*locate) {
    auto l = load(lj);
    // Read every direction before building, so that bad input fails fast.
    std::vector<std::array<rational, 3>> ds;
    for (auto& l : read_number_lines(dirs, 3, "'dx dy dz'")) {
      std::array<rational, 3> d{l.values[0], l.values[1], l.values[2]};
      if (locate_view_dir.empty() && d[0] == 0 && d[1] == 0 && d[2] == 0)
        throw usage_error((dirs == "-" ? std::string("<stdin>") : dirs) + ":" + std::to_string(l.line) + ": the zero vector is no direction");
      ds.push_back(d);
    }
    if (lj.eye_text.empty() == locate_view_dir.empty()) throw usage_error("locate: give --eye X,Y,Z or --view-dir DX,DY,DZ");
    if (!locate_view_dir.empty()) {
      auto polys = polygons_in<rational>(l);
      std::vector<geometry::e3::point<rational>> points;
      for (auto const& d : ds) points.emplace_back(d[0], d[1], d[2]);
      auto view = parallel_view(l, polys, locate_view_dir, points);
      auto vm = svm::build<rational>(view.image(polys), view.eye(), parallel_options(lj));
      std::string text;
      for (auto const& p : points) text += std::to_string(svm::locate(vm, view.direction_of(p))) + "\n";
      out() << text;
      return 0;
    }
    out() << with_map(lj, l, [&](auto const& vm) {
      using FT = typename std::remove_cvref_t<decltype(vm)>::number_type;
      std::string out;
      for (auto const& d : ds) {
        std::array<FT, 3> c;
        for (std::size_t i = 0; i < 3; ++i) {
          if constexpr (std::is_same_v<FT, rational>)
            c[i] = d[i];
          else
            c[i] = d[i].template convert_to<double>();
        }
        out += std::to_string(svm::locate(vm, geometry::s2::point<FT>(c))) + "\n";
      }
      return out;
    });
  } else if (*render) {
    std::string ext = std::filesystem::path(render_out).extension().string();
    for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext != ".svg" && ext != ".pdf" && ext != ".eps" && ext != ".png")
      throw usage_error(render_out + ": unknown output format '" + ext + "' (use .svg, .pdf, .eps or .png)");
    if (!look_text.empty() && !dir_text.empty()) throw usage_error("--look and --dir: give one of them");
    if (!named_view.empty()) {
      if (render->count("--projection") && projection_name != "orthographic") throw usage_error("--view is an orthographic view; leave out --projection");
      if (!dir_text.empty() || (!look_text.empty() && !rj.eye_text.empty())) throw usage_error("--view gives the direction; leave out --dir");
      static std::map<std::string, std::pair<char const*, char const*>> const named{
          {"front", {"0,1,0", "0,0,1"}}, {"back", {"0,-1,0", "0,0,1"}}, {"left", {"1,0,0", "0,0,1"}}, {"right", {"-1,0,0", "0,0,1"}},
          {"top", {"0,0,-1", "0,1,0"}},  {"bottom", {"0,0,1", "0,-1,0"}}, {"iso", {"-1,1,-1", "0,0,1"}}};
      projection_name = "orthographic";
      dir_text = named.at(named_view).first;
      if (up_text.empty()) up_text = named.at(named_view).second;
    }
    bool equirect = projection_name == "equirectangular", cube = projection_name == "cube";
    int w = equirect ? 1600 : 800, h = equirect ? 800 : 600;
    if (cube) w = h = 512;
    if (!size_text.empty()) {
      auto x = size_text.find('x');
      try {
        std::size_t used1 = 0, used2 = 0;
        if (x == std::string::npos) throw std::invalid_argument("x");
        w = std::stoi(size_text.substr(0, x), &used1);
        h = std::stoi(size_text.substr(x + 1), &used2);
        if (used1 != x || used2 != size_text.size() - x - 1) throw std::invalid_argument("x");
      } catch (std::exception const&) {
        throw usage_error("--size: expected WxH in pixels, got '" + size_text + "'");
      }
      if (w < 1 || h < 1 || w > 20000 || h > 20000) throw usage_error("--size: each side must be 1 to 20000 pixels");
    }
    bool const ortho = projection_name == "orthographic";
    if (!ortho && rj.eye_text.empty()) throw usage_error("--eye is required (except for --projection orthographic)");
    if (ortho && !rj.eye_text.empty() && look_text.empty())
      throw usage_error("--projection orthographic: the view has no eye; give --dir DX,DY,DZ (or --eye with --look)");
    if (!ortho && !extent_text.empty()) throw usage_error("--extent is for --projection orthographic");
    if (ortho && !shift_text.empty()) throw usage_error("--shift is for perspective views");
    if (ortho && rj.number != "exact") throw usage_error("--projection orthographic: exact arithmetic only, for now");
    auto l = load(rj);
    auto infos = face_infos(*l.data);
    auto [lo_q, hi_q, any] = exact_box(l.prepared);
    if (ortho && !any) throw usage_error(rj.scene_path + ": an orthographic view needs a scene with faces");
    std::optional<svm::view_from_infinity<rational>> parallel;
    std::vector<svm::polygon<rational>> image_polygons;
    svm::vec3 eye{0, 0, 0};
    if (!rj.eye_text.empty()) eye = parse_vec(rj.eye_text, "--eye");
    if (ortho) {
      // The view from the point at infinity behind the camera: the central
      // view of the scene's image from a finite point (svm/parallel.hpp).
      geometry::e3::point<rational> centre = look_text.empty()
                                                 ? geometry::e3::point<rational>((lo_q[0] + hi_q[0]) / 2, (lo_q[1] + hi_q[1]) / 2, (lo_q[2] + hi_q[2]) / 2)
                                                 : parse_point(look_text, "--look");
      std::array<rational, 3> d;
      if (!dir_text.empty()) {
        auto v = parse_point(dir_text, "--dir");
        d = {v.x(), v.y(), v.z()};
      } else if (!rj.eye_text.empty()) {
        auto e = parse_point(rj.eye_text, "--eye");
        d = {centre.x() - e.x(), centre.y() - e.y(), centre.z() - e.z()};
      } else {
        throw usage_error("--projection orthographic: give --dir DX,DY,DZ");
      }
      if (d[0] == 0 && d[1] == 0 && d[2] == 0) throw usage_error("--dir: the zero vector is no direction");
      auto polys = polygons_in<rational>(l);
      parallel.emplace(polys, std::array<rational, 3>{-d[0], -d[1], -d[2]}, centre);
      image_polygons = parallel->image(polys);
      dir_text = exact_text(d[0]) + "," + exact_text(d[1]) + "," + exact_text(d[2]);
      look_text.clear();
      // A far point towards the eye at infinity, for shading only.
      svm::vec3 c = vec_of(centre);
      svm::vec3 back = svm::detail::unit3({-d[0].convert_to<double>(), -d[1].convert_to<double>(), -d[2].convert_to<double>()});
      double size = 0;
      for (int k = 0; k < 3; ++k) size = std::max(size, (hi_q[k] - lo_q[k]).convert_to<double>());
      eye = svm::detail::add3(c, svm::detail::mul3(back, 1e6 * (size + 1)));
    }
    svm::vec3 forward;
    if (!dir_text.empty()) forward = parse_vec(dir_text, "--dir");
    else {
      svm::vec3 target{0, 0, 0};
      if (!look_text.empty()) target = parse_vec(look_text, "--look");
      else {
        // The centre of the scene's bounding box.
        svm::vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
        for (auto const& p : l.prepared.polygons)
          for (auto const& q : p.vertices) {
            svm::vec3 v = vec_of(q);
            for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
          }
        if (lo[0] <= hi[0]) target = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
        else target = svm::detail::add3(eye, {1, 0, 0});
      }
      forward = svm::detail::sub3(target, eye);
    }
    svm::camera cam;
    cam.forward = forward;
    if (!up_text.empty()) cam.up = parse_vec(up_text, "--up");
    else {
      using namespace svm::detail;
      double along = std::abs(forward[2]) / norm3(forward);
      cam.up = along > 1 - 1e-9 ? svm::vec3{0, 1, 0} : svm::vec3{0, 0, 1};
    }
    cam.width = w;
    cam.height = h;
    cam.hfov = fov > 0 ? fov : (equirect ? 360 : cube ? 90 : 60);
    if (ortho) {
      if (!extent_text.empty()) {
        double extent = parse_point(extent_text + ",0,0", "--extent").x().convert_to<double>();
        if (!(extent > 0)) throw usage_error("--extent: the width shown must be positive");
        cam = svm::parallel_camera(*parallel, cam.up, extent, w, h);
      } else {
        cam = parallel_fit(*parallel, lo_q, hi_q, cam.up, w, h);
      }
    }
    if (!shift_text.empty()) {
      auto sh = parse_point(shift_text + ",0", "--shift");
      cam.shift_x = sh.x().convert_to<double>();
      cam.shift_y = sh.y().convert_to<double>();
    }
    svm::render::options ro;
    ro.style = *svm::render::style_from_name(style_name);
    if (ro.style != svm::render::style::lines && (hidden_name != "none" || line_width > 0))
      throw usage_error(std::string(hidden_name != "none" ? "--hidden" : "--line-width") + " is for --style lines");
    if (split_layers && ro.style != svm::render::style::lines) throw usage_error("--split-layers is for --style lines");
    ro.crease = crease;
    ro.tolerance = tolerance;
    ro.eye = eye;
    shadow_job shadows;
    std::vector<svm::lit_region> regions;
    shadows.lights = lights_from(render_lights, render_suns);
    if (render_shadows && shadows.lights.empty()) throw usage_error("--shadows: give at least one --light X,Y,Z or --sun DX,DY,DZ");
    for (auto const& t : render_lights) ro.lights.push_back(parse_vec(t, "--light"));
    for (auto const& t : render_suns) ro.suns.push_back(parse_vec(t, "--sun"));
    if (!render_shadows) shadows.lights.clear();
    else ro.regions = &regions, shadows.regions = &regions;
    // The views to draw: one, or the six faces of a cube.
    std::vector<std::pair<svm::camera, std::string>> views;
    if (cube) {
      if (cam.width != cam.height) throw usage_error("--size: a cube map's faces are square");
      cam.hfov = 90;
      svm::projector base(cam, svm::projection::perspective);
      auto f = base.forward(), r = base.right(), u = base.up();
      auto neg = [](svm::vec3 v) { return svm::detail::mul3(v, -1); };
      std::array<std::pair<svm::vec3, svm::vec3>, 6> faces{{{f, u}, {r, u}, {neg(f), u}, {neg(r), u}, {u, neg(f)}, {neg(u), f}}};
      for (std::size_t k = 0; k < faces.size(); ++k) {
        svm::camera c = cam;
        c.forward = faces[k].first;
        c.up = faces[k].second;
        views.push_back({c, suffixed(render_out, cube_faces[k])});
      }
    } else {
      views.push_back({cam, render_out});
    }
    auto kind = cube || ortho ? svm::projection::perspective : *svm::projection_from_name(projection_name);
    std::vector<std::pair<svm::render::drawing, std::string>> drawings;
    std::vector<json> line_summaries;
    for (auto const& [c, path] : views) {
      std::optional<svm::projector> pr;
      try {
        pr.emplace(c, kind);
      } catch (std::invalid_argument const& e) {
        throw usage_error(e.what());
      }
      svm::build_options o = pr->window_options();
      if (ro.style == svm::render::style::lines) {
        configure(rj, o);
        svm::render::line_drawing_options lo{.hidden = *svm::render::hidden_style_from_name(hidden_name), .tolerance = tolerance, .width = line_width};
        json s;
        svm::render::drawing d;
        auto relabel = [](auto polygons) {
          for (std::uint32_t i = 0; i < polygons.size(); ++i) polygons[i].face = i;
          return polygons;
        };
        if (ortho) {
          auto scene = relabel(polygons_in<rational>(l));
          d = line_view<rational>(scene, parallel->image(scene), parallel->eye(), o, shadows,
                                  [&](svm::convex_piece<rational>& p) { p.shape = parallel->carry(p.shape, true); }, *pr, lo, crease, s);
        } else if (rj.number == "double") {
          auto e = parse_point(rj.eye_text, "--eye");
          geometry::e3::point<double> ed(e.x().convert_to<double>(), e.y().convert_to<double>(), e.z().convert_to<double>());
          auto scene = relabel(polygons_in<double>(l));
          d = line_view<double>(scene, scene, ed, o, shadows, [](svm::convex_piece<double>&) {}, *pr, lo, crease, s);
        } else {
          auto scene = relabel(polygons_in<rational>(l));
          d = line_view<rational>(scene, scene, parse_point(rj.eye_text, "--eye"), o, shadows, [](svm::convex_piece<rational>&) {}, *pr, lo,
                                  crease, s);
        }
        json entry{{"output", path}};
        entry.update(s);
        line_summaries.push_back(std::move(entry));
        drawings.push_back({std::move(d), path});
        continue;
      }
      auto d = ortho ? svm::render::draw(orthographic_map(rj, *parallel, image_polygons, l, o, shadows), *pr, infos, ro)
                     : with_map(rj, l, [&](auto const& vm) { return svm::render::draw(vm, *pr, infos, ro); }, o, shadows);
      drawings.push_back({std::move(d), path});
    }
    // Every file is made before any is written, so that a failure leaves none half-done.
    std::vector<std::pair<svm::render::drawing, std::string>> layer_files;
    if (split_layers) {
      for (auto const& [d, path] : drawings)
        for (std::size_t k = 0; k < d.layers.size(); ++k) layer_files.push_back({svm::render::single_layer(d, k), suffixed(path, d.layers[k].name)});
    }
    for (auto const& [d, path] : drawings) write_drawing(d, path, digits);
    for (auto const& [d, path] : layer_files) write_drawing(d, path, digits);
    if (ro.style == svm::render::style::lines) {
      json layers = json::array();
      for (auto const& [d, path] : layer_files) layers.push_back(path);
      json summary{{"genbsp", version()}, {"views", line_summaries}};
      if (split_layers) summary["layer_files"] = layers;
      out() << summary.dump() << "\n";
    }
  } else if (*view) {
    std::string ext = std::filesystem::path(view_out).extension().string();
    for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext != ".html" && ext != ".htm") throw usage_error(view_out + ": the viewer is an .html file");
    auto l = load(vj);
    auto eye = parse_point(vj.eye_text, "--eye");
    json colours = json::array();
    for (auto const& f : l.data->scene.faces) {
      if (!f.colour) {
        colours.push_back(nullptr);
        continue;
      }
      char hex[8];
      auto byte = [](double c) { return static_cast<unsigned>(std::lround(std::clamp(c, 0.0, 1.0) * 255)); };
      std::snprintf(hex, sizeof hex, "#%02x%02x%02x", byte(f.colour->r), byte(f.colour->g), byte(f.colour->b));
      colours.push_back(hex);
    }
    shadow_job shadows;
    std::vector<svm::lit_region> regions;
    shadows.lights = lights_from(view_lights, view_suns);
    shadows.regions = &regions;
    auto map_text = with_map(
        vj, l, [&](auto const& vm) { return map_json(vm, eye, l, shadows.lights.empty() ? nullptr : &regions).dump(); }, {}, shadows);
    std::string page(genbsp_tool::viewer_html());
    auto put = [&](std::string const& placeholder, std::string const& value) {
      auto at = page.find(placeholder);
      if (at == std::string::npos || page.find(placeholder, at + 1) != std::string::npos)
        throw std::logic_error("the viewer page must hold " + placeholder + " once");
      page.replace(at, placeholder.size(), value);
    };
    // JSON text never holds "</script" unescaped: dump() writes '/' as is, so escape it.
    auto safe = [](std::string t) {
      for (std::size_t at = 0; (at = t.find("</", at)) != std::string::npos; at += 3) t.replace(at, 2, "<\\/");
      return t;
    };
    put("/*GENBSP_MAP*/null", safe(map_text));
    put("/*GENBSP_COLORS*/null", safe(colours.dump()));
    write_file(view_out, page);
  } else if (*shadow) {
    write_file(shadow_out, shadow_output(hj, shadow_lights, shadow_suns, shadow_out));
  } else if (*scene) {
    svm::scenes::scene s = family == "bricks"          ? svm::scenes::bricks(n)
                           : family == "hidden-bricks" ? svm::scenes::hidden_bricks(n)
                           : family == "platforms"     ? svm::scenes::platforms(n)
                           : family == "random"        ? svm::scenes::random_cubes(n, seed)
                           : family == "terrain"       ? svm::scenes::terrain(n, seed)
                           : family == "room"          ? svm::scenes::room()
                                                       : svm::scenes::sphere(n);
    write_file(scene_out, off_text(s));
    out() << exact_text(s.eye.x()) << ',' << exact_text(s.eye.y()) << ',' << exact_text(s.eye.z()) << "\n";
  }
  return 0;
}


int run_main(int argc, char** argv) {
  program_owns_process() = true;
  mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free);
  geometry::use_gmp_pool(); // in front of those
  try {
    return run(argc, argv);
  } catch (std::bad_alloc const&) {
    std::cerr << "genbsp: " << out_of_memory_text() << "; nothing was written\n";
    return 2;
  } catch (usage_error const& e) {
    std::cerr << "genbsp: " << e.what() << "\n";
    return 2;
  } catch (geometry::io::read_error const& e) {
    std::cerr << "genbsp: " << e.what() << "\n";
    return 2;
  } catch (std::exception const& e) {
    std::cerr << "genbsp: internal error: " << e.what() << "\n";
    return 1;
  }
}

} // namespace genbsp_tool
