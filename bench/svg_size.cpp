// Size of the SVG genbsp writes for a large mesh, against the same view
// exported as every triangle (what a painter's-algorithm exporter writes:
// each triangle in the view, projected and filled, back to front).
//
// Usage: bench_svg_size [--scene terrain|sphere] [--n N] [--json FILE]
#include <geometry/gmp_pool.hpp>
#include <svm/build.hpp>
#include <svm/camera.hpp>
#include <svm/render/drawing.hpp>
#include <svm/render/svg.hpp>
#include <svm/scenes.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

using Q = geometry::rational;
using svm::vec3;

vec3 to_double(geometry::e3::point<Q> const& p) { return {p.x().convert_to<double>(), p.y().convert_to<double>(), p.z().convert_to<double>()}; }

int usage(char const* why) {
  std::fprintf(stderr, "bench_svg_size: %s\nusage: bench_svg_size [--scene terrain|sphere] [--n N] [--json FILE]\n", why);
  return 2;
}

} // namespace

int main(int argc, char** argv) {
  geometry::use_gmp_pool(); // as the genbsp tool runs
  std::string scene_name = "terrain", json_path;
  std::size_t n = 0;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--scene" && i + 1 < argc) scene_name = argv[++i];
    else if (a == "--n" && i + 1 < argc) n = std::strtoul(argv[++i], nullptr, 10);
    else if (a == "--json" && i + 1 < argc) json_path = argv[++i];
    else if (a == "-h" || a == "--help") {
      std::puts("usage: bench_svg_size [--scene terrain|sphere] [--n N] [--json FILE]\n"
                "  terrain: 2n^2 triangles (default n 158: 49,928); sphere: 4n(n-1) (default n 113: 50,624)");
      return 0;
    } else return usage(("unknown argument " + a).c_str());
  }
  if (scene_name != "terrain" && scene_name != "sphere") return usage("--scene: terrain or sphere");
  if (n == 0) n = scene_name == "terrain" ? 158 : 113;
  auto s = scene_name == "terrain" ? svm::scenes::terrain(n) : svm::scenes::sphere(n);
  vec3 eye = to_double(s.eye);
  vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (auto const& p : s.polygons)
    for (auto const& q : p.vertices) {
      auto v = to_double(q);
      for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
    }
  svm::camera cam;
  cam.forward = svm::detail::sub3({(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2}, eye);
  cam.hfov = 60;
  cam.width = 1200;
  cam.height = 800;
  svm::projector pr(cam, svm::projection::perspective);

  // Per-face colour and plane, shared by both exports.
  std::vector<svm::render::face_info> info(s.polygons.size());
  for (auto const& p : s.polygons) {
    auto a = to_double(p.vertices[0]), b = to_double(p.vertices[1]), c = to_double(p.vertices[2]);
    using namespace svm::detail;
    auto& fi = info[p.face];
    fi.normal = unit3(cross3(sub3(b, a), sub3(c, a)));
    fi.offset = dot3(fi.normal, a);
    fi.centre = mul3(add3(add3(a, b), c), 1.0 / 3);
  }
  svm::render::options o;
  o.eye = eye;

  auto t0 = std::chrono::steady_clock::now();
  auto vm = svm::build<Q>(s.polygons, s.eye, pr.window_options());
  auto d = svm::render::draw(vm, pr, info, o);
  std::string ours = svm::render::to_svg(d);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // Every triangle in front of the eye whose image meets the picture, back to front.
  struct tri {
    double depth;
    std::size_t index;
  };
  std::vector<tri> order;
  for (std::size_t i = 0; i < s.polygons.size(); ++i) {
    bool front = true;
    double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
    for (auto const& q : s.polygons[i].vertices) {
      auto l = pr.local(svm::detail::sub3(to_double(q), eye));
      if (l[2] <= 0) front = false;
      else {
        auto px = pr.project(svm::detail::unit3(svm::detail::sub3(to_double(q), eye)));
        x0 = std::min(x0, px.x), x1 = std::max(x1, px.x), y0 = std::min(y0, px.y), y1 = std::max(y1, px.y);
      }
    }
    if (!front || x1 < 0 || y1 < 0 || x0 > cam.width || y0 > cam.height) continue;
    order.push_back({svm::detail::norm3(svm::detail::sub3(info[s.polygons[i].face].centre, eye)), i});
  }
  std::sort(order.begin(), order.end(), [](tri const& a, tri const& b) { return a.depth > b.depth; });
  svm::render::drawing all;
  all.width = cam.width;
  all.height = cam.height;
  all.style = svm::render::style::shaded;
  all.background = o.background;
  for (auto const& t : order) {
    auto const& p = s.polygons[t.index];
    svm::render::region r;
    r.polygon = p.face;
    for (std::size_t k = 0; k < p.vertices.size(); ++k) {
      auto px = pr.project(svm::detail::unit3(svm::detail::sub3(to_double(p.vertices[k]), eye)));
      r.path.push_back({k == 0 ? svm::render::command::move : svm::render::command::line, px.x, px.y});
    }
    r.path.push_back({svm::render::command::close});
    auto const& fi = info[p.face];
    double light = std::abs(svm::detail::dot3(svm::detail::unit3(svm::detail::sub3(eye, fi.centre)), fi.normal));
    auto c = svm::render::palette(p.face);
    r.fill = {c.r * (0.2 + 0.8 * light), c.g * (0.2 + 0.8 * light), c.b * (0.2 + 0.8 * light)};
    all.regions.push_back(std::move(r));
  }
  std::string painter = svm::render::to_svg(all);

  std::printf("%s n=%zu: %zu triangles; genbsp SVG %zu bytes in %zu paths (map and drawing %.2f s); "
              "all-triangles SVG %zu bytes in %zu paths; ratio %.1fx\n",
              scene_name.c_str(), n, s.polygons.size(), ours.size(), d.regions.size(), seconds, painter.size(), all.regions.size(),
              static_cast<double>(painter.size()) / static_cast<double>(ours.size()));
  if (!json_path.empty()) {
    std::ofstream(json_path) << "{\"scene\":\"" << scene_name << "\",\"n\":" << n << ",\"triangles\":" << s.polygons.size()
                             << ",\"genbsp_bytes\":" << ours.size() << ",\"genbsp_paths\":" << d.regions.size()
                             << ",\"seconds\":" << seconds << ",\"all_triangles_bytes\":" << painter.size()
                             << ",\"all_triangles_paths\":" << all.regions.size() << "}\n";
  }
  return 0;
}
