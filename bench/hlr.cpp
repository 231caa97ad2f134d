// Hidden-line removal against Open CASCADE's, on the same scene and view in
// one run:
//   * genbsp: the exact visibility map of the view (clipped to the image), the scene's edges cut by it (`svm::hidden_lines`) and the
//     drawing (`svm::render::draw_lines`, hidden lines dashed), as
//     `genbsp render --style lines --hidden dashed` makes it, through the
//     exact projective map that brings the eye from infinity;
//   * OCCT's polygonal HLR (`HLRBRep_PolyAlgo`, the one meant for meshes)
//     and, with --occt-exact, its exact HLR on the B-rep (`HLRBRep_Algo`),
//     on a shape of planar faces sharing their edges, each timed from
//     loading the shape to the visible and hidden compounds.
// Both draw the same lines: sharp edges and outlines, not the edges between
// coplanar faces (OCCT: `BRepLib::EncodeRegularity`; genbsp: never drawn).
// Agreement: OCCT's lines, mapped to genbsp's pixels, sampled every pixel;
// a sample agrees when a line of genbsp's of the same kind (visible or
// hidden) passes within `--tolerance` pixels; and the other way round.
// The view is parallel (OCCT's HLR is for drawings of parts: front, top,
// iso views), along --dir about the centre of the scene's bounding box, z
// up, a square image 1.05 times the box's diagonal wide: `genbsp render
// --projection orthographic --dir … --style lines --hidden dashed`.
// Prints one JSON object.
#include <geometry/gmp_pool.hpp>
#include "common.hpp"

#include <geometry/io/polygons.hpp>
#include <svm/build.hpp>
#include <svm/camera.hpp>
#include <svm/lines.hpp>
#include <svm/parallel.hpp>
#include <svm/render/lines.hpp>

#include <CLI/CLI.hpp>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <TopoDS_Builder.hxx>
#include <HLRAlgo_Projector.hxx>
#include <HLRBRep_Algo.hxx>
#include <HLRBRep_HLRToShape.hxx>
#include <HLRBRep_PolyAlgo.hxx>
#include <HLRBRep_PolyHLRToShape.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Ax2.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace {

using vec3 = std::array<double, 3>;
using segment = std::array<svm::pixel, 2>;

/// Segments of both kinds (visible, hidden) in pixels.
struct lines2d {
  std::vector<segment> visible, hidden;
};

/// A uniform grid over the image holding segments, to ask whether one passes
/// near a point.
class segment_grid {
public:
  segment_grid(std::vector<segment> const& s, double cell, int size) : segs_(s), cell_(cell), n_(static_cast<int>(size / cell) + 3) {
    cells_.resize(static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_));
    // Each segment goes into the cells of points along it every half cell
    // (a point within a cell of the segment is then in a neighbouring cell).
    for (std::size_t i = 0; i < s.size(); ++i) {
      auto [a, b] = s[i];
      double len = std::hypot(b.x - a.x, b.y - a.y);
      int n = static_cast<int>(std::min(1e5, std::ceil(len / (cell_ / 2)))) + 1;
      std::size_t last = SIZE_MAX;
      for (int k = 0; k <= n; ++k) {
        double t = static_cast<double>(k) / n;
        std::size_t c = index(clampi(std::floor((a.x + t * (b.x - a.x)) / cell_)), clampi(std::floor((a.y + t * (b.y - a.y)) / cell_)));
        if (c != last && (cells_[c].empty() || cells_[c].back() != i)) cells_[c].push_back(static_cast<std::uint32_t>(i));
        last = c;
      }
    }
  }
  bool near(svm::pixel p, double tol) const {
    int x = clampi(std::floor(p.x / cell_)), y = clampi(std::floor(p.y / cell_));
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        int cx = std::clamp(x + dx, 0, n_ - 1), cy = std::clamp(y + dy, 0, n_ - 1);
        for (auto i : cells_[index(cx, cy)])
          if (distance(p, segs_[i]) <= tol) return true;
      }
    return false;
  }

private:
  int clampi(double v) const { return static_cast<int>(std::clamp(v + 1, 0.0, static_cast<double>(n_ - 1))); }
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(n_) + static_cast<std::size_t>(x); }
  static double distance(svm::pixel p, segment const& s) {
    double vx = s[1].x - s[0].x, vy = s[1].y - s[0].y, wx = p.x - s[0].x, wy = p.y - s[0].y;
    double l = vx * vx + vy * vy, t = l > 0 ? std::clamp((vx * wx + vy * wy) / l, 0.0, 1.0) : 0;
    return std::hypot(wx - t * vx, wy - t * vy);
  }
  std::vector<segment> const& segs_;
  double cell_;
  int n_;
  std::vector<std::vector<std::uint32_t>> cells_;
};

/// The length of `from` (inside the image) within `tol` pixels of a segment
/// of `to`, and its whole length, sampled every half pixel.
std::pair<double, double> covered(std::vector<segment> const& from, std::vector<segment> const& to, int size, double tol) {
  segment_grid g(to, std::max(2 * tol, 4.0), size);
  double in = 0, all = 0;
  for (auto const& s : from) {
    double len = std::hypot(s[1].x - s[0].x, s[1].y - s[0].y);
    int n = std::max(1, static_cast<int>(std::ceil(len / 0.5)));
    for (int k = 0; k < n; ++k) {
      double t = (k + 0.5) / n;
      svm::pixel p{s[0].x + t * (s[1].x - s[0].x), s[0].y + t * (s[1].y - s[0].y)};
      if (p.x < 1 || p.y < 1 || p.x > size - 1 || p.y > size - 1) continue;
      all += len / n;
      if (g.near(p, tol)) in += len / n;
    }
  }
  return {in, all};
}

/// The scene as OCCT faces: one planar face per polygon, edges shared
/// between the faces that have them (vertices welded by coordinates), and
/// edges between coplanar faces marked regular.
TopoDS_Compound occt_shape(std::vector<std::vector<vec3>> const& scene) {
  std::map<vec3, TopoDS_Vertex> vertices;
  std::map<std::pair<vec3, vec3>, TopoDS_Edge> edges;
  TopoDS_Builder b; // (not BRep_Builder: Debian's 7.6.3 headers for it are incomplete)
  TopoDS_Compound c;
  b.MakeCompound(c);
  for (auto const& poly : scene) {
    BRepBuilderAPI_MakeWire wire;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      vec3 p = poly[i], q = poly[(i + 1) % poly.size()];
      for (auto const& v : {p, q})
        if (!vertices.count(v)) vertices[v] = BRepBuilderAPI_MakeVertex(gp_Pnt(v[0], v[1], v[2]));
      auto key = p < q ? std::pair{p, q} : std::pair{q, p};
      auto it = edges.find(key);
      if (it == edges.end()) it = edges.emplace(key, BRepBuilderAPI_MakeEdge(vertices[key.first], vertices[key.second]).Edge()).first;
      wire.Add(it->second);
    }
    if (!wire.IsDone()) continue;
    BRepBuilderAPI_MakeFace face(wire.Wire(), Standard_True);
    if (face.IsDone()) b.Add(c, face.Face());
  }
  BRepLib::EncodeRegularity(c, 1e-9);
  return c;
}

/// Every edge of `s` (OCCT's projected lines: straight, in the projector's
/// plane), as pixels through `to_pixel`; curves are cut into 16 segments.
template <class ToPixel> void add_segments(TopoDS_Shape const& s, ToPixel const& to_pixel, std::vector<segment>& out, std::size_t& count) {
  if (s.IsNull()) return;
  for (TopExp_Explorer e(s, TopAbs_EDGE); e.More(); e.Next()) {
    BRepAdaptor_Curve c(TopoDS::Edge(e.Current()));
    double t0 = c.FirstParameter(), t1 = c.LastParameter();
    int n = c.GetType() == GeomAbs_Line ? 1 : 16;
    ++count;
    for (int k = 0; k < n; ++k) {
      gp_Pnt a = c.Value(t0 + (t1 - t0) * k / n), b = c.Value(t0 + (t1 - t0) * (k + 1) / n);
      out.push_back({to_pixel(a.X(), a.Y()), to_pixel(b.X(), b.Y())});
    }
  }
}

/// The sharp edges and outlines of an HLR result (`HLRBRep_PolyHLRToShape`
/// or `HLRBRep_HLRToShape`), visible and hidden, counting the edges.
template <class Result, class ToPixel> lines2d collect(Result& out, ToPixel const& to_pixel, std::size_t& visible, std::size_t& hidden) {
  lines2d l;
  visible = hidden = 0;
  add_segments(out.VCompound(), to_pixel, l.visible, visible);
  add_segments(out.OutLineVCompound(), to_pixel, l.visible, visible);
  add_segments(out.HCompound(), to_pixel, l.hidden, hidden);
  add_segments(out.OutLineHCompound(), to_pixel, l.hidden, hidden);
  return l;
}

} // namespace

int main(int argc, char** argv) {
  geometry::use_gmp_pool(); // as the genbsp tool runs
  CLI::App app{"Hidden-line removal of one scene and view: genbsp's exact lines and Open CASCADE's polygonal (and, with "
               "--occt-exact, exact) HLR; prints one JSON object"};
  std::string path, dir_text = "-1,1,-1";
  int size = 1024, runs = 3;
  double tolerance = 1;
  bool occt_exact = false, genbsp_only = false;
  app.add_option("SCENE", path, "scene file: OFF, OBJ or STL")->required();
  app.add_option("--dir", dir_text, "the view direction DX,DY,DZ (default -1,1,-1: genbsp's iso view)");
  app.add_option("--size", size, "image width and height in pixels (default 1024)")->check(CLI::Range(16, 16384));
  app.add_option("--runs", runs, "runs of each method; the median is reported (default 3)")->check(CLI::Range(1, 100));
  app.add_option("--tolerance", tolerance, "pixels: how near two lines must be to agree (default 1)")->check(CLI::Range(0.01, 100.0));
  app.add_flag("--genbsp-only", genbsp_only, "time genbsp only (for profiling it)");
  app.add_flag("--occt-exact", occt_exact, "also time OCCT's exact HLR on the B-rep (slow on large scenes)");
  CLI11_PARSE(app, argc, argv);
  try {
    using Q = geometry::rational;
    auto s = geometry::io::read_scene(path);
    auto prepared = geometry::io::convex_polygons(s);
    auto dir_q = bench::parse_point(dir_text, "--dir");
    vec3 dir{dir_q[0].convert_to<double>(), dir_q[1].convert_to<double>(), dir_q[2].convert_to<double>()};
    std::vector<std::vector<vec3>> scene;
    vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    std::vector<svm::polygon<Q>> polys;
    std::array<Q, 3> lo_q{}, hi_q{};
    bool any = false;
    for (auto const& p : prepared.polygons) {
      std::vector<vec3> q;
      for (auto const& v : p.vertices) {
        vec3 d{v.x().convert_to<double>(), v.y().convert_to<double>(), v.z().convert_to<double>()};
        for (std::size_t k = 0; k < 3; ++k) {
          lo[k] = std::min(lo[k], d[k]), hi[k] = std::max(hi[k], d[k]);
          if (!any || v[k] < lo_q[k]) lo_q[k] = v[k];
          if (!any || v[k] > hi_q[k]) hi_q[k] = v[k];
        }
        any = true;
        q.push_back(d);
      }
      scene.push_back(std::move(q));
      polys.push_back({p.vertices, static_cast<std::uint32_t>(polys.size())});
    }
    if (polys.empty()) throw std::invalid_argument(path + ": no polygons");
    // The parallel view along `dir`, about the exact centre of the bounding
    // box, as `genbsp render --dir` makes it.
    geometry::e3::point<Q> centre((lo_q[0] + hi_q[0]) / 2, (lo_q[1] + hi_q[1]) / 2, (lo_q[2] + hi_q[2]) / 2);
    svm::view_from_infinity<Q> view(polys, {-dir_q[0], -dir_q[1], -dir_q[2]}, centre);
    vec3 centre_d{centre.x().convert_to<double>(), centre.y().convert_to<double>(), centre.z().convert_to<double>()};
    vec3 up{0, 0, 1};
    if (std::abs(dir[2]) > (1 - 1e-9) * std::hypot(dir[0], dir[1], dir[2])) up = {0, 1, 0};
    double extent = 1.05 * std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    svm::projector pr(svm::parallel_camera(view, up, extent, size, size), svm::projection::perspective);
    auto eye_q = view.eye();

    std::printf("{\"scene\": %s, \"polygons\": %zu, \"size\": %d, \"runs\": %d, \"compiler\": %s, \"optimised\": %s",
                bench::json_string(path).c_str(), scene.size(), size, runs, bench::json_string(bench::compiler()).c_str(),
                bench::optimised() ? "true" : "false");

    // genbsp.
    lines2d ours;
    svm::render::line_drawing_summary summary;
    double map_seconds = 0, line_seconds = 0, draw_seconds = 0;
    std::size_t scene_edges = 0;
    double total = bench::median_seconds(runs, [&] {
      auto t0 = std::chrono::steady_clock::now();
      auto image = view.image(polys);
      auto vm = svm::build<Q>(image, eye_q, pr.window_options());
      auto t1 = std::chrono::steady_clock::now();
      auto ls = svm::hidden_lines(vm, eye_q, image);
      auto t2 = std::chrono::steady_clock::now();
      auto d = svm::render::draw_lines(ls, vm, eye_q, pr, {.hidden = svm::render::hidden_style::dashed}, &summary);
      auto t3 = std::chrono::steady_clock::now();
      map_seconds = std::chrono::duration<double>(t1 - t0).count();
      line_seconds = std::chrono::duration<double>(t2 - t1).count();
      draw_seconds = std::chrono::duration<double>(t3 - t2).count();
      scene_edges = ls.edges.size();
      ours = {};
      for (auto const& l : d.layers) {
        auto& to = l.name.starts_with("hidden") ? ours.hidden : ours.visible;
        for (auto const& line : l.lines)
          for (std::size_t i = 1; i < line.size(); ++i) to.push_back({line[i - 1], line[i]});
      }
    });
    std::size_t visible_edges = 0, hidden_edges = 0;
    for (auto const& c : summary.visible) visible_edges += c.edges;
    for (auto const& c : summary.hidden) hidden_edges += c.edges;
    std::printf(", \"genbsp\": {\"seconds\": %.6g, \"map_seconds\": %.6g, \"lines_seconds\": %.6g, \"draw_seconds\": %.6g, "
                "\"scene_edges\": %zu, \"visible_edges\": %zu, \"hidden_edges\": %zu, \"visible_segments\": %zu, \"hidden_segments\": %zu}",
                total, map_seconds, line_seconds, draw_seconds, scene_edges, visible_edges, hidden_edges, ours.visible.size(),
                ours.hidden.size());
    if (genbsp_only) {
      std::printf("}\n");
      return 0;
    }

    // OCCT: the shape and its mesh are made once, outside the timing.
    auto t0 = std::chrono::steady_clock::now();
    TopoDS_Compound shape = occt_shape(scene);
    auto t1 = std::chrono::steady_clock::now();
    double diameter = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    BRepMesh_IncrementalMesh mesh(shape, diameter * 1e-3);
    auto t2 = std::chrono::steady_clock::now();
    std::printf(", \"occt_shape_seconds\": %.6g, \"occt_mesh_seconds\": %.6g", std::chrono::duration<double>(t1 - t0).count(),
                std::chrono::duration<double>(t2 - t1).count());
    // The projector: parallel, its plane through the centre, its axes the
    // image's right and up, the view along −Z.
    auto r = pr.right();
    gp_Ax2 frame(gp_Pnt(centre_d[0], centre_d[1], centre_d[2]), gp_Dir(-dir[0], -dir[1], -dir[2]), gp_Dir(r[0], r[1], r[2]));
    HLRAlgo_Projector projector(frame);
    // The projector's image coordinates to genbsp's pixels.
    double ppu = size / extent;
    auto to_pixel = [&](double x, double y) { return svm::pixel{size / 2.0 + ppu * x, size / 2.0 - ppu * y}; };
    // The polygonal algorithm's lines, and `Project`, are in a frame whose
    // origin is where the centre projects, not at 0 as the exact one's.
    gp_Pnt2d origin;
    projector.Project(gp_Pnt(centre_d[0], centre_d[1], centre_d[2]), origin);
    auto to_pixel_poly = [&](double x, double y) { return to_pixel(x - origin.X(), y - origin.Y()); };
    // Check the correspondence on the scene's vertices: OCCT's projection
    // against genbsp's camera at the image of the vertex.
    double frame_error = 0;
    auto eye_d = [&](std::size_t k) { return eye_q[k].template convert_to<double>(); };
    for (auto const& p : polys)
      for (auto const& v : p.vertices) {
        gp_Pnt2d q;
        projector.Project(gp_Pnt(v.x().convert_to<double>(), v.y().convert_to<double>(), v.z().convert_to<double>()), q);
        auto a2 = to_pixel_poly(q.X(), q.Y());
        auto w = view.image(v);
        auto b2 = pr.project({w.x().convert_to<double>() - eye_d(0), w.y().convert_to<double>() - eye_d(1), w.z().convert_to<double>() - eye_d(2)});
        frame_error = std::max(frame_error, std::hypot(a2.x - b2.x, a2.y - b2.y));
      }
    lines2d theirs;
    std::size_t their_visible = 0, their_hidden = 0;
    double occt_seconds = bench::median_seconds(runs, [&] {
      Handle(HLRBRep_PolyAlgo) algo = new HLRBRep_PolyAlgo();
      algo->Load(shape);
      algo->Projector(projector);
      algo->Update();
      HLRBRep_PolyHLRToShape out;
      out.Update(algo);
      theirs = collect(out, to_pixel_poly, their_visible, their_hidden);
    });
    auto agree = [&](lines2d const& a, lines2d const& b) {
      auto [vi, va] = covered(a.visible, b.visible, size, tolerance);
      auto [hi2, ha] = covered(a.hidden, b.hidden, size, tolerance);
      return std::array<double, 4>{vi, va, hi2, ha};
    };
    auto theirs_in_ours = agree(theirs, ours), ours_in_theirs = agree(ours, theirs);
    std::printf(", \"occt_poly\": {\"seconds\": %.6g, \"visible_edges\": %zu, \"hidden_edges\": %zu, \"frame_error_px\": %.3g, "
                "\"visible_length_px\": %.6g, \"visible_agreeing\": %.6g, \"hidden_length_px\": %.6g, \"hidden_agreeing\": %.6g, "
                "\"genbsp_visible_length_px\": %.6g, \"genbsp_visible_agreeing\": %.6g, \"genbsp_hidden_length_px\": %.6g, "
                "\"genbsp_hidden_agreeing\": %.6g}",
                occt_seconds, their_visible, their_hidden, frame_error, theirs_in_ours[1], theirs_in_ours[0], theirs_in_ours[3],
                theirs_in_ours[2], ours_in_theirs[1], ours_in_theirs[0], ours_in_theirs[3], ours_in_theirs[2]);
    if (occt_exact) {
      lines2d exact;
      std::size_t ev = 0, eh = 0;
      double te = bench::median_seconds(runs, [&] {
        Handle(HLRBRep_Algo) algo = new HLRBRep_Algo();
        algo->Add(shape);
        algo->Projector(projector);
        algo->Update();
        algo->Hide();
        HLRBRep_HLRToShape out(algo);
        exact = collect(out, to_pixel, ev, eh);
      });
      if (char const* svg = std::getenv("GENBSP_BENCH_SVG")) {
        FILE* out = std::fopen(svg, "w");
        std::fprintf(out, "<svg xmlns='http://www.w3.org/2000/svg' width='%d' height='%d'><rect width='100%%' height='100%%' fill='white'/>\n", size, size);
        auto put = [&](std::vector<segment> const& v, char const* colour, double w) {
          for (auto const& g : v) std::fprintf(out, "<line x1='%g' y1='%g' x2='%g' y2='%g' stroke='%s' stroke-width='%g'/>\n", g[0].x, g[0].y, g[1].x, g[1].y, colour, w);
        };
        put(exact.hidden, "#f99", 5), put(exact.visible, "#f00", 5), put(ours.hidden, "#99f", 1.5), put(ours.visible, "#00f", 1.5);
        std::fprintf(out, "</svg>\n");
        std::fclose(out);
      }
      auto a = agree(exact, ours);
      std::printf(", \"occt_exact\": {\"seconds\": %.6g, \"visible_edges\": %zu, \"hidden_edges\": %zu, \"visible_length_px\": %.6g, "
                  "\"visible_agreeing\": %.6g, \"hidden_length_px\": %.6g, \"hidden_agreeing\": %.6g}",
                  te, ev, eh, a[1], a[0], a[3], a[2]);
    }
    std::printf("}\n");
  } catch (std::exception const& x) {
    std::fprintf(stderr, "bench_hlr: %s\n", x.what());
    return 2;
  } catch (Standard_Failure const& x) {
    std::fprintf(stderr, "bench_hlr: Open CASCADE: %s\n", x.GetMessageString());
    return 2;
  }
}
