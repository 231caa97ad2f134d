// Hidden-surface removal against the tools people use instead, on the same
// scene and view in one run:
//   * genbsp's exact visibility map of the view (the build clipped to the
//     camera's frustum, as `genbsp render` builds it), and of all directions;
//   * a software z-buffer of the same perspective view (this file's own few
//     dozen lines: near-plane clipping, edge functions, 1/z depth), timed on
//     transformation and rasterisation only;
//   * gl2ps's BSP export to SVG (GL2PS_BSP_SORT | GL2PS_BEST_ROOT) of the
//     same view through an off-screen OSMesa context, when built with it
//     (GENBSP_BENCH_GL2PS), timed from gl2psBeginPage to gl2psEndPage.
// The camera is `genbsp render`'s default: looking at the centre of the
// scene's bounding box, z up, 60° horizontal field of view, a square image.
// Prints one JSON object.
#include <geometry/gmp_pool.hpp>
#include "common.hpp"

#include <geometry/io/polygons.hpp>
#include <svm/build.hpp>
#include <svm/camera.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#ifdef GENBSP_BENCH_GL2PS
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gl2ps.h>
#endif

namespace {

using vec3 = std::array<double, 3>;
vec3 sub(vec3 a, vec3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(vec3 a, vec3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
vec3 cross(vec3 a, vec3 b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
vec3 unit(vec3 a) {
  double n = std::sqrt(dot(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}

/// The view: an orthonormal frame at the eye, and the image.
struct view {
  vec3 eye, right, up, forward;
  int size;
  double focal; ///< pixels
  double near;
};

using poly = std::vector<vec3>;

/// A software z-buffer: every polygon clipped to the near plane, fanned into
/// triangles, rasterised a span a row (where the edge functions at pixel
/// centres are all at least 0), 1/z stepped along the span (it is linear in
/// the image).  Returns the covered pixels; `tested` counts the depth tests
/// (pixels of every triangle in view: their mean over the image is the
/// scene's depth complexity).
std::size_t zbuffer(std::vector<poly> const& scene, view const& v, std::vector<float>& depth, std::vector<std::uint32_t>& id,
                    std::size_t& tested) {
  int n = v.size;
  tested = 0;
  std::fill(depth.begin(), depth.end(), 0.0f);
  std::fill(id.begin(), id.end(), 0u);
  std::vector<vec3> cam, clipped;
  for (std::size_t f = 0; f < scene.size(); ++f) {
    cam.clear();
    for (auto const& p : scene[f]) {
      vec3 d = sub(p, v.eye);
      cam.push_back({dot(d, v.right), dot(d, v.up), dot(d, v.forward)});
    }
    // Near plane z = near (Sutherland–Hodgman).
    clipped.clear();
    for (std::size_t i = 0; i < cam.size(); ++i) {
      vec3 a = cam[i], b = cam[(i + 1) % cam.size()];
      bool ain = a[2] >= v.near, bin = b[2] >= v.near;
      if (ain) clipped.push_back(a);
      if (ain != bin) {
        double t = (v.near - a[2]) / (b[2] - a[2]);
        clipped.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), v.near});
      }
    }
    if (clipped.size() < 3) continue;
    // Image coordinates and 1/z.
    std::vector<std::array<double, 3>> s(clipped.size());
    for (std::size_t i = 0; i < clipped.size(); ++i) {
      double iz = 1 / clipped[i][2];
      s[i] = {n / 2.0 + v.focal * clipped[i][0] * iz, n / 2.0 - v.focal * clipped[i][1] * iz, iz};
    }
    for (std::size_t k = 1; k + 1 < s.size(); ++k) {
      auto const &a = s[0], &b = s[k], &c = s[k + 1];
      double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      if (area == 0) continue;
      int x0 = std::max(0, static_cast<int>(std::floor(std::min({a[0], b[0], c[0]}))));
      int x1 = std::min(n - 1, static_cast<int>(std::ceil(std::max({a[0], b[0], c[0]}))));
      int y0 = std::max(0, static_cast<int>(std::floor(std::min({a[1], b[1], c[1]}))));
      int y1 = std::min(n - 1, static_cast<int>(std::ceil(std::max({a[1], b[1], c[1]}))));
      // The barycentric weights and 1/z are linear in the pixel centre
      // (px, py): c[0]·px + c[1]·py + c[2].  Each row is one span: where the
      // three weights are at least 0.
      double inv = 1 / area;
      using linear = std::array<double, 3>;
      auto weight = [inv](auto const& p, auto const& q) { // of the vertex opposite the edge p → q
        return linear{(p[1] - q[1]) * inv, (q[0] - p[0]) * inv, (p[0] * q[1] - p[1] * q[0]) * inv};
      };
      linear w0 = weight(b, c), w1 = weight(c, a);
      linear w2{-w0[0] - w1[0], -w0[1] - w1[1], 1 - w0[2] - w1[2]};
      linear z;
      for (int i = 0; i < 3; ++i) z[i] = w0[i] * a[2] + w1[i] * b[2] + w2[i] * c[2];
      for (int y = y0; y <= y1; ++y) {
        double py = y + 0.5, lo = x0 + 0.5, hi = x1 + 0.5;
        bool empty = false;
        for (auto const* w : {&w0, &w1, &w2}) {
          double slope = (*w)[0], at = (*w)[1] * py + (*w)[2];
          if (slope > 0)
            lo = std::max(lo, -at / slope);
          else if (slope < 0)
            hi = std::min(hi, -at / slope);
          else if (at < 0)
            empty = true;
        }
        if (empty || lo > hi) continue;
        int xs = std::max(x0, static_cast<int>(std::ceil(lo - 0.5))), xe = std::min(x1, static_cast<int>(std::floor(hi - 0.5)));
        if (xs > xe) continue;
        tested += static_cast<std::size_t>(xe - xs + 1);
        double zx = z[0] * (xs + 0.5) + z[1] * py + z[2];
        std::size_t row = static_cast<std::size_t>(y) * static_cast<std::size_t>(n);
        for (int x = xs; x <= xe; ++x, zx += z[0]) {
          float zf = static_cast<float>(zx);
          std::size_t at = row + static_cast<std::size_t>(x);
          if (zf > depth[at]) depth[at] = zf, id[at] = static_cast<std::uint32_t>(f + 1);
        }
      }
    }
  }
  return static_cast<std::size_t>(std::count_if(id.begin(), id.end(), [](std::uint32_t x) { return x != 0; }));
}

#ifdef GENBSP_BENCH_GL2PS
/// gl2ps's BSP-sorted SVG of the view; returns the bytes written, or 0.
long gl2ps_svg(std::vector<poly> const& scene, view const& v, double far, std::string const& path) {
  int n = v.size;
  glViewport(0, 0, n, n);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  double h = v.near * (n / 2.0) / v.focal;
  glFrustum(-h, h, -h, h, v.near, far);
  glMatrixMode(GL_MODELVIEW);
  // The camera frame as a look-at matrix (column-major).
  double m[16] = {v.right[0], v.up[0], -v.forward[0], 0, v.right[1], v.up[1], -v.forward[1], 0,
                  v.right[2], v.up[2], -v.forward[2], 0, -dot(v.right, v.eye), -dot(v.up, v.eye), dot(v.forward, v.eye), 1};
  glLoadMatrixd(m);
  glEnable(GL_DEPTH_TEST);
  FILE* out = std::fopen(path.c_str(), "wb");
  if (!out) return 0;
  GLint viewport[4] = {0, 0, n, n};
  GLint buffer = 1 << 22, state = GL2PS_OVERFLOW;
  while (state == GL2PS_OVERFLOW) {
    std::rewind(out);
    gl2psBeginPage("genbsp bench", "bench_hsr", viewport, GL2PS_SVG, GL2PS_BSP_SORT,
                   GL2PS_BEST_ROOT | GL2PS_SILENT, GL_RGBA, 0, nullptr, 0, 0, 0, buffer, out, path.c_str());
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (std::size_t f = 0; f < scene.size(); ++f) {
      glColor3ub(static_cast<GLubyte>(f * 37), static_cast<GLubyte>(f * 91), static_cast<GLubyte>(f * 53));
      glBegin(GL_POLYGON);
      for (auto const& p : scene[f]) glVertex3d(p[0], p[1], p[2]);
      glEnd();
    }
    state = gl2psEndPage();
    buffer *= 2;
  }
  long bytes = std::ftell(out);
  std::fclose(out);
  return state == GL2PS_SUCCESS ? bytes : 0;
}
#endif

} // namespace

int main(int argc, char** argv) {
  geometry::use_gmp_pool(); // as the genbsp tool runs
  CLI::App app{"Hidden-surface removal of one scene and view: genbsp's exact map, a software z-buffer and (when built with it) "
               "gl2ps's BSP export; prints one JSON object"};
  std::string path, eye_text, svg = "/tmp/bench_hsr_gl2ps.svg";
  int size = 1024, runs = 3;
  bool skip_map = false;
  app.add_option("SCENE", path, "scene file: OFF, OBJ or STL")->required();
  app.add_option("--eye", eye_text, "the observer, X,Y,Z")->required();
  app.add_option("--size", size, "image width and height in pixels (default 1024)")->check(CLI::Range(16, 16384));
  app.add_option("--runs", runs, "runs of each method; the median is reported (default 3)")->check(CLI::Range(1, 100));
  app.add_option("--gl2ps-svg", svg, "where gl2ps writes its SVG");
  app.add_flag("--no-map", skip_map, "leave genbsp's map out");
  CLI11_PARSE(app, argc, argv);
  try {
    auto s = geometry::io::read_scene(path);
    auto prepared = geometry::io::convex_polygons(s);
    auto eye = bench::parse_point(eye_text, "--eye");
    std::vector<poly> scene;
    vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (auto const& p : prepared.polygons) {
      poly q;
      for (auto const& v : p.vertices) {
        vec3 d{v.x().convert_to<double>(), v.y().convert_to<double>(), v.z().convert_to<double>()};
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], d[k]), hi[k] = std::max(hi[k], d[k]);
        q.push_back(d);
      }
      scene.push_back(std::move(q));
    }
    vec3 e{eye[0].convert_to<double>(), eye[1].convert_to<double>(), eye[2].convert_to<double>()};
    vec3 centre{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
    view v;
    v.eye = e;
    v.forward = unit(sub(centre, e));
    vec3 z{0, 0, 1};
    if (std::abs(v.forward[2]) > 1 - 1e-9) z = {0, 1, 0};
    v.right = unit(cross(v.forward, z));
    v.up = cross(v.right, v.forward);
    v.size = size;
    v.focal = (size / 2.0) / std::tan(30.0 * std::acos(-1.0) / 180);
    double diameter = std::sqrt(dot(sub(hi, lo), sub(hi, lo)));
    v.near = diameter * 1e-4;
    double far = std::sqrt(dot(sub(centre, e), sub(centre, e))) + diameter;

    std::printf("{\"scene\": %s, \"polygons\": %zu, \"size\": %d, \"runs\": %d, \"compiler\": %s, \"optimised\": %s",
                bench::json_string(path).c_str(), scene.size(), size, runs, bench::json_string(bench::compiler()).c_str(),
                bench::optimised() ? "true" : "false");
    if (!skip_map) {
      std::vector<svm::polygon<geometry::rational>> polys;
      for (auto const& p : prepared.polygons) polys.push_back({p.vertices, p.face});
      geometry::e3::point<geometry::rational> eye_q(eye[0], eye[1], eye[2]);
      svm::camera cam;
      cam.forward = v.forward;
      cam.up = z;
      cam.hfov = 60;
      cam.width = cam.height = size;
      auto in_view = svm::projector(cam, svm::projection::perspective).window_options();
      std::size_t faces = 0, all_faces = 0;
      svm::build_statistics view_stats;
      double t = bench::median_seconds(runs, [&] {
        view_stats = svm::build<geometry::rational>(polys, eye_q, in_view).stats;
        faces = view_stats.simplified.faces;
      });
      double t_all = bench::median_seconds(runs, [&] { all_faces = svm::build<geometry::rational>(polys, eye_q).stats.simplified.faces; });
      std::printf(", \"map_seconds\": %.6g, \"map_faces\": %zu, \"sphere_map_seconds\": %.6g, \"sphere_map_faces\": %zu", t, faces,
                  t_all, all_faces);
      // Where the view's build goes (its last run).
      auto const& w = view_stats;
      std::printf(", \"view\": {\"outside_window\": %zu, \"fragments\": %zu, \"hidden_pieces\": %zu, \"map_pieces\": %zu, "
                  "\"depth_order_seconds\": %.6g, \"visible_seconds\": %.6g, \"map_seconds\": %.6g, \"simplify_seconds\": %.6g, "
                  "\"seconds\": %.6g}",
                  w.discarded_outside_window, w.fragments, w.hidden_pieces, w.map_pieces, w.depth_order_seconds, w.visible_seconds,
                  w.map_seconds, w.simplify_seconds, w.seconds);
    }
    std::vector<float> depth(static_cast<std::size_t>(size) * static_cast<std::size_t>(size));
    std::vector<std::uint32_t> id(depth.size());
    std::size_t covered = 0;
    std::size_t tested = 0;
    double tz = bench::median_seconds(runs, [&] { covered = zbuffer(scene, v, depth, id, tested); });
    std::printf(", \"zbuffer_seconds\": %.6g, \"zbuffer_pixels\": %zu, \"zbuffer_depth_tests\": %zu", tz, covered, tested);
#ifdef GENBSP_BENCH_GL2PS
    // The off-screen context, made once, outside the timing.
    std::vector<unsigned char> pixels(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * 4, 0);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!ctx || !OSMesaMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, size, size)) throw std::runtime_error("no OSMesa context");
    long bytes = 0;
    double tg = bench::median_seconds(runs, [&] { bytes = gl2ps_svg(scene, v, far, svg); });
    if (bytes > 0) std::printf(", \"gl2ps_seconds\": %.6g, \"gl2ps_bytes\": %ld", tg, bytes);
    else std::printf(", \"gl2ps_error\": \"no output\"");
    OSMesaDestroyContext(ctx);
#else
    (void)far;
#endif
    std::printf("}\n");
  } catch (std::exception const& x) {
    std::fprintf(stderr, "bench_hsr: %s\n", x.what());
    return 2;
  }
}
