// Drawing from the map, checked against independent truth: id-style renders
// rasterized by an outside SVG rasterizer (rsvg-convert) and by cairo (PNG,
// and PDF through pdftoppm), compared pixel by pixel with a z-buffer written
// here — a double-precision ray caster through each pixel centre, with this
// file's own inverse projection formulas (not the library's).
#include <svm/build.hpp>
#include <svm/camera.hpp>
#include <svm/parallel.hpp>
#include <svm/render/cairo.hpp>
#include <svm/render/drawing.hpp>
#include <svm/render/svg.hpp>
#include <svm/scenes.hpp>

#include <catch2/catch.hpp>
#include <cairo.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <numbers>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Q = geometry::rational;
using v3 = std::array<double, 3>;
namespace fs = std::filesystem;

v3 sub(v3 a, v3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
v3 cross(v3 a, v3 b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double dot(v3 a, v3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
v3 normalized(v3 a) {
  double l = std::sqrt(dot(a, a));
  return {a[0] / l, a[1] / l, a[2] / l};
}
v3 to_double(geometry::e3::point<Q> const& p) { return {p.x().convert_to<double>(), p.y().convert_to<double>(), p.z().convert_to<double>()}; }

struct triangle {
  v3 a, b, c;
  long face;
};

std::vector<triangle> triangles(svm::scenes::scene const& s) {
  std::vector<triangle> out;
  for (auto const& p : s.polygons)
    for (std::size_t i = 1; i + 1 < p.vertices.size(); ++i)
      out.push_back({to_double(p.vertices[0]), to_double(p.vertices[i]), to_double(p.vertices[i + 1]), static_cast<long>(p.face)});
  return out;
}

/// The nearest hit of the ray from `o` along `d` (Möller–Trumbore) beyond
/// `from` (in units of |d|) and before `to`, skipping face `skip`: its
/// triangle's index and distance, or none.  Hits within a relative 1e-9 of
/// each other are one distance, where the lower face wins.
std::optional<std::pair<std::size_t, double>> first_hit(std::vector<struct triangle> const& tris, v3 o, v3 d, double from = 0,
                                                        double to = HUGE_VAL, long skip = -1);

/// The face hit first by the ray from `o` along `d`, or −1.
long cast(std::vector<triangle> const& tris, v3 o, v3 d) {
  auto h = first_hit(tris, o, d);
  return h ? tris[h->first].face : -1;
}

std::optional<std::pair<std::size_t, double>> first_hit(std::vector<triangle> const& tris, v3 o, v3 d, double from, double to, long skip) {
  double best = to;
  std::optional<std::pair<std::size_t, double>> hit;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    auto const& t = tris[i];
    if (t.face == skip) continue;
    v3 e1 = sub(t.b, t.a), e2 = sub(t.c, t.a), p = cross(d, e2);
    double det = dot(e1, p);
    if (std::abs(det) < 1e-300) continue;
    v3 s = sub(o, t.a);
    double u = dot(s, p) / det;
    if (u < 0 || u > 1) continue;
    v3 q = cross(s, e1);
    double v = dot(d, q) / det;
    if (v < 0 || u + v > 1) continue;
    double dist = dot(e2, q) / det;
    if (dist <= from || dist >= to) continue;
    // Coplanar faces tie (to rounding): the lower input index is in front, as in the map.
    bool tie = hit && std::abs(dist - best) <= 1e-9 * best;
    if (tie ? t.face < tris[hit->first].face : dist < best) best = dist, hit = {i, dist};
  }
  return hit;
}

/// The label of the ray from `o` along `d` with shadows from `light`: the
/// face hit first, plus 0x800000 when the light does not reach the hit
/// point (it is behind the face's front, or a shadow ray to it meets
/// another face), or −1.
long cast_lit(std::vector<triangle> const& tris, v3 o, v3 d, v3 light) {
  auto h = first_hit(tris, o, d);
  if (!h) return -1;
  auto const& t = tris[h->first];
  v3 x{o[0] + h->second * d[0], o[1] + h->second * d[1], o[2] + h->second * d[2]};
  bool front = dot(cross(sub(t.b, t.a), sub(t.c, t.a)), sub(light, t.a)) > 0;
  bool blocked = front && first_hit(tris, x, sub(light, x), 1e-9, 1 - 1e-9, t.face).has_value();
  return t.face + (front && !blocked ? 0 : 0x800000);
}

enum class kind { perspective, stereographic, equidistant, equisolid, panorama };

struct view {
  kind k;
  v3 forward, up{0, 0, 1};
  double hfov;
  int w, h;
  double shift_x = 0, shift_y = 0; ///< perspective image-plane shift, in half-widths
};

svm::projection library_kind(kind k) {
  switch (k) {
  case kind::perspective: return svm::projection::perspective;
  case kind::stereographic: return svm::projection::stereographic;
  case kind::equidistant: return svm::projection::fisheye_equidistant;
  case kind::equisolid: return svm::projection::fisheye_equisolid;
  default: return svm::projection::equirectangular;
  }
}

/// The direction through image point (x, y) (y down), from the definitions:
/// the half-width maps to half the field of view; a direction at angle θ from
/// the view direction lies at radius tan θ, 2 tan(θ/2), θ, 2 sin(θ/2) in
/// perspective, stereographic, equidistant, equisolid; the panorama has
/// longitude and latitude linear.
std::optional<v3> through(view const& v, double x, double y) {
  v3 f = normalized(v.forward), r = normalized(cross(f, v.up)), u = cross(r, f);
  double half = std::numbers::pi * v.hfov / 360;
  auto at = [&](double a, double b, double c) { return v3{a * r[0] + b * u[0] + c * f[0], a * r[1] + b * u[1] + c * f[1], a * r[2] + b * u[2] + c * f[2]}; };
  double px = x - v.w / 2.0, py = v.h / 2.0 - y;
  if (v.k == kind::panorama) {
    double lon = px / (v.w / 2.0) * half, lat = py / (v.w / 2.0) * half;
    if (std::abs(lat) > std::numbers::pi / 2) return std::nullopt;
    return at(std::cos(lat) * std::sin(lon), std::sin(lat), std::cos(lat) * std::cos(lon));
  }
  double edge = v.k == kind::perspective     ? std::tan(half)
                : v.k == kind::stereographic ? 2 * std::tan(half / 2)
                : v.k == kind::equidistant   ? half
                                             : 2 * std::sin(half / 2);
  double a = px / (v.w / 2.0) * edge, b = py / (v.w / 2.0) * edge, rho = std::hypot(a, b);
  if (v.k == kind::perspective) return normalized(at(a + v.shift_x * edge, b + v.shift_y * edge, 1));
  double theta = v.k == kind::stereographic ? 2 * std::atan(rho / 2) : v.k == kind::equidistant ? rho : rho <= 2 ? 2 * std::asin(rho / 2) : 99;
  if (theta > std::numbers::pi) return std::nullopt;
  if (rho == 0) return f;
  double s = std::sin(theta);
  return at(s * a / rho, s * b / rho, std::cos(theta));
}

/// Labels per pixel: the face, −1 for none, −2 for a pixel the image leaves
/// out (outside an azimuthal disc or the panorama).
using raster = std::vector<long>;



svm::projector projector_of(view const& v) {
  svm::camera c;
  c.forward = v.forward;
  c.up = v.up;
  c.hfov = v.hfov;
  c.width = v.w;
  c.height = v.h;
  c.shift_x = v.shift_x;
  c.shift_y = v.shift_y;
  return {c, library_kind(v.k)};
}

svm::render::drawing id_drawing(svm::scenes::scene const& s, view const& v) {
  auto pr = projector_of(v);
  auto vm = svm::build<Q>(s.polygons, s.eye, pr.window_options());
  svm::render::options o;
  o.style = svm::render::style::id;
  return svm::render::draw(vm, pr, {}, o);
}

/// The id drawing of `s` with shadows from `light`.
svm::render::drawing shadow_id_drawing(svm::scenes::scene const& s, geometry::e3::point<Q> const& light, view const& v) {
  auto pr = projector_of(v);
  auto sh = svm::compute_shadows<Q>(s.polygons, {light});
  auto scene = svm::label_regions(sh, s.polygons);
  auto vm = svm::build<Q>(scene.pieces, s.eye, pr.window_options());
  svm::render::options o;
  o.style = svm::render::style::id;
  o.regions = &scene.regions;
  return svm::render::draw(vm, pr, {}, o);
}

/// A scratch folder, removed at the end.
struct scratch {
  fs::path dir;
  scratch() {
    dir = fs::temp_directory_path() / ("genbsp-render-" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  ~scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  fs::path operator/(std::string const& name) const { return dir / name; }
};

bool have(char const* tool) { return std::system((std::string("command -v ") + tool + " >/dev/null 2>&1").c_str()) == 0; }

/// Labels of a decoded PNG: colour − 1 where opaque, −1 where transparent,
/// −3 where partly covered (antialiasing: never expected).
raster labels_of_png(fs::path const& png, int w, int h) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(png.c_str());
  REQUIRE(cairo_surface_status(s) == CAIRO_STATUS_SUCCESS);
  REQUIRE(cairo_image_surface_get_width(s) == w);
  REQUIRE(cairo_image_surface_get_height(s) == h);
  cairo_surface_flush(s);
  auto const* data = cairo_image_surface_get_data(s);
  int stride = cairo_image_surface_get_stride(s);
  bool alpha = cairo_image_surface_get_format(s) == CAIRO_FORMAT_ARGB32;
  raster out(static_cast<std::size_t>(w * h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint32_t p;
      std::memcpy(&p, data + y * stride + 4 * x, 4);
      std::uint32_t a = alpha ? p >> 24 : 255, rgb = p & 0xffffff;
      out[static_cast<std::size_t>(y * w + x)] = a == 255 ? static_cast<long>(rgb) - 1 : a == 0 ? -1 : -3;
    }
  cairo_surface_destroy(s);
  return out;
}

/// White-background rasters (pdftoppm): white is "none".
raster labels_of_opaque_png(fs::path const& png, int w, int h) {
  auto r = labels_of_png(png, w, h);
  for (auto& l : r)
    if (l == 0xffffff - 1) l = -1;
  return r;
}

struct agreement {
  long pixels = 0, agree = 0, near_edge = 0, far = 0;
  std::string first_far;
};

/// The true label at any image point (continuous coordinates), −2 outside the image's disc.
using sampler = std::function<long(double, double)>;

sampler sample(svm::scenes::scene const& s, view const& v) {
  return [tris = triangles(s), eye = to_double(s.eye), v](double x, double y) {
    auto d = through(v, x, y);
    return d ? cast(tris, eye, *d) : -2L;
  };
}

/// The z-buffer: the true label at each pixel centre.
raster truth(sampler const& at, int w, int h) {
  raster out(static_cast<std::size_t>(w * h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) out[static_cast<std::size_t>(y * w + x)] = at(x + 0.5, y + 0.5);
  return out;
}

/// Compares a raster with the truth over the pixels the image shows.  A
/// pixel that disagrees must be within one pixel of an edge: the truth,
/// sampled every eighth of a pixel within one pixel of the pixel's centre, shows
/// both its true label and the drawn one.
agreement compare(raster const& got, raster const& want, int w, int h, sampler const& at) {
  agreement a;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      long t = want[static_cast<std::size_t>(y * w + x)], g = got[static_cast<std::size_t>(y * w + x)];
      if (t == -2) continue; // outside the image's disc: not drawn, not compared
      ++a.pixels;
      if (g == t) {
        ++a.agree;
        continue;
      }
      bool seen = false;
      for (int i = -8; i <= 8 && !seen; ++i)
        for (int j = -8; j <= 8 && !seen; ++j)
          if (i * i + j * j <= 64 && at(x + 0.5 + i / 8.0, y + 0.5 + j / 8.0) == g) seen = true;
      if (seen) ++a.near_edge;
      else {
        if (a.far == 0) {
          std::ostringstream where;
          where << '(' << x << ',' << y << ") drawn " << g << ", true " << t;
          a.first_far = where.str();
        }
        ++a.far;
      }
    }
  return a;
}

void expect_agreement(agreement const& a, std::string const& what) {
  INFO(what << ": " << a.agree << "/" << a.pixels << " agree, " << a.near_edge << " near an edge, " << a.far << " elsewhere " << a.first_far);
  CHECK(a.pixels > 0);
  CHECK(a.far == 0);
  CHECK(static_cast<double>(a.agree) >= 0.995 * static_cast<double>(a.pixels));
}

/// With GENBSP_RENDER_KEEP=DIR, a drawing that fails is kept there for a look.
void keep(fs::path const& file, std::string name) {
  char const* dir = std::getenv("GENBSP_RENDER_KEEP");
  if (!dir) return;
  std::replace(name.begin(), name.end(), ' ', '-');
  std::error_code ec;
  fs::create_directories(dir, ec);
  fs::copy_file(file, fs::path(dir) / name, fs::copy_options::overwrite_existing, ec);
}

int run(std::string const& command) { return std::system((command + " >/dev/null 2>&1").c_str()); }

struct named_scene {
  std::string name;
  svm::scenes::scene s;
};

std::vector<named_scene> scenes() {
  std::vector<named_scene> out{{"bricks", svm::scenes::bricks(8)},
                               {"hidden-bricks", svm::scenes::hidden_bricks(8)},
                               {"platforms", svm::scenes::platforms(6)},
                               {"random", svm::scenes::random_cubes(12, 3)}};
  for (std::uint64_t seed = 11; seed < 14; ++seed) out.push_back({"random seed " + std::to_string(seed), svm::scenes::random_cubes(8, seed)});
  // Degenerate: the eye in the planes of faces (the cube's face planes z = 0
  // and y = 0 pass through it), and cubes sharing faces and edges.
  svm::scenes::scene grid;
  using P = geometry::e3::point<Q>;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) svm::scenes::add_box(grid, P(Q(2 * i + 3), Q(j), Q(0)), P(Q(2 * i + 5), Q(j + 1), Q(1 + i)));
  grid.eye = P(Q(0), Q(0), Q(0));
  out.push_back({"touching boxes, eye on face planes", grid});
  return out;
}

v3 centre_direction(svm::scenes::scene const& s) {
  v3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (auto const& p : s.polygons)
    for (auto const& q : p.vertices) {
      auto v = to_double(q);
      for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
    }
  return sub({(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2}, to_double(s.eye));
}

} // namespace

TEST_CASE("id renders rasterized by rsvg-convert agree with a z-buffer in every projection", "[render]") {
  if (!have("rsvg-convert")) {
    WARN("rsvg-convert is not installed (Debian: librsvg2-bin): comparison skipped");
    return;
  }
  scratch tmp;
  long total = 0, agreeing = 0, views = 0;
  for (auto const& [name, s] : scenes()) {
    v3 f = centre_direction(s);
    std::vector<view> vs{{kind::perspective, f, {0, 0, 1}, 70, 160, 120},
                         {kind::perspective, f, {0, 0, 1}, 50, 160, 120, 0.3, -0.4},
                         {kind::stereographic, f, {0, 0, 1}, 220, 160, 120},
                         {kind::equidistant, f, {0, 0, 1}, 180, 160, 120},
                         {kind::equidistant, f, {0, 0, 1}, 360, 160, 160},
                         {kind::equisolid, f, {0, 0, 1}, 300, 160, 120},
                         {kind::panorama, f, {0, 0, 1}, 360, 240, 120},
                         {kind::panorama, {0, 0, 1}, {0, 1, 0}, 360, 240, 120}};
    for (std::size_t i = 0; i < vs.size(); ++i) {
      auto const& v = vs[i];
      std::string what = name + ", view " + std::to_string(i) + " (" + svm::name(library_kind(v.k)) + ")";
      auto d = id_drawing(s, v);
      std::string svg = svm::render::to_svg(d, 3);
      auto svg_path = tmp / "view.svg", png_path = tmp / "view.png";
      std::ofstream(svg_path) << svg;
      REQUIRE(run("rsvg-convert -o '" + png_path.string() + "' '" + svg_path.string() + "'") == 0);
      auto got = labels_of_png(png_path, v.w, v.h);
      auto at = sample(s, v);
      auto want = truth(at, v.w, v.h);
      auto a = compare(got, want, v.w, v.h, at);
      if (a.far > 0) keep(svg_path, name + "-" + std::to_string(i) + ".svg");
      expect_agreement(a, what);
      total += a.pixels, agreeing += a.agree, ++views;
    }
  }
  std::cout << "render: " << views << " id views, " << agreeing << " of " << total << " pixels agree with the z-buffer ("
            << 100.0 * static_cast<double>(agreeing) / static_cast<double>(total) << " %)\n";
  CHECK(views >= 60);
}

TEST_CASE("id renders with shadows agree with a ray caster with shadow rays", "[render][shadow]") {
  if (!have("rsvg-convert")) {
    WARN("rsvg-convert is not installed (Debian: librsvg2-bin): comparison skipped");
    return;
  }
  using P = geometry::e3::point<Q>;
  struct lit_scene {
    std::string name;
    svm::scenes::scene s;
    P light;
  };
  std::vector<lit_scene> cases;
  {
    cases.push_back({"room with a lamp", svm::scenes::room(), P(Q(301), Q(249), Q(255))});
  }
  cases.push_back({"bricks, light off-axis", svm::scenes::bricks(8), P(Q(7, 3), Q(-5, 2), Q(-3))});
  {
    auto s = svm::scenes::sphere(6);
    s.polygons.push_back({{P(Q(-400000), Q(-400000), Q(-150000)), P(Q(400000), Q(-400000), Q(-150000)),
                           P(Q(400000), Q(400000), Q(-150000)), P(Q(-400000), Q(400000), Q(-150000))},
                          static_cast<std::uint32_t>(s.polygons.size())});
    cases.push_back({"sphere over a floor", s, P(Q(-120000), Q(-70001), Q(350000))});
  }
  {
    // Touching boxes on a floor, a face coplanar with the floor, and a
    // square overlapping the floor in its plane.
    svm::scenes::scene s;
    svm::scenes::add_box(s, P(Q(0), Q(0), Q(0)), P(Q(4), Q(4), Q(4)));
    svm::scenes::add_box(s, P(Q(4), Q(0), Q(0)), P(Q(8), Q(4), Q(2)));
    svm::scenes::add_box(s, P(Q(2), Q(6), Q(0)), P(Q(6), Q(10), Q(3)));
    auto n = [&] { return static_cast<std::uint32_t>(s.polygons.size()); };
    s.polygons.push_back({{P(Q(-20), Q(-20), Q(0)), P(Q(30), Q(-20), Q(0)), P(Q(30), Q(30), Q(0)), P(Q(-20), Q(30), Q(0))}, n()});
    s.polygons.push_back({{P(Q(-10), Q(-10), Q(0)), P(Q(0), Q(-10), Q(0)), P(Q(0), Q(20), Q(0)), P(Q(-10), Q(20), Q(0))}, n()});
    s.eye = P(Q(-12) + Q(1, 3), Q(-15) + Q(1, 7), Q(14));
    cases.push_back({"touching and coplanar", s, P(Q(9), Q(3), Q(12))});
  }
  {
    // A light inside a closed box: outside, nothing is lit; the eye looks
    // at the box and the floor from outside.
    svm::scenes::scene s;
    svm::scenes::add_box(s, P(Q(0), Q(0), Q(0)), P(Q(10), Q(10), Q(10)));
    auto n = static_cast<std::uint32_t>(s.polygons.size());
    s.polygons.push_back({{P(Q(-50), Q(-50), Q(-1)), P(Q(60), Q(-50), Q(-1)), P(Q(60), Q(60), Q(-1)), P(Q(-50), Q(60), Q(-1))}, n});
    s.eye = P(Q(-30) + Q(1, 3), Q(-25) + Q(1, 7), Q(20));
    cases.push_back({"light inside a closed box", s, P(Q(5), Q(5), Q(7))});
  }
  scratch tmp;
  long total = 0, agreeing = 0, shadowed = 0;
  for (auto const& [name, s, light] : cases) {
    v3 f = centre_direction(s);
    for (auto const& v : {view{kind::perspective, f, {0, 0, 1}, 75, 160, 120}, view{kind::equidistant, f, {0, 0, 1}, 200, 160, 120}}) {
      std::string what = name + " (" + svm::name(library_kind(v.k)) + ")";
      auto d = shadow_id_drawing(s, light, v);
      auto svg_path = tmp / "shadow.svg", png_path = tmp / "shadow.png";
      std::ofstream(svg_path) << svm::render::to_svg(d, 3);
      REQUIRE(run("rsvg-convert -o '" + png_path.string() + "' '" + svg_path.string() + "'") == 0);
      auto got = labels_of_png(png_path, v.w, v.h);
      sampler at = [tris = triangles(s), eye = to_double(s.eye), l = to_double(light), v](double x, double y) {
        auto dir = through(v, x, y);
        return dir ? cast_lit(tris, eye, *dir, l) : -2L;
      };
      auto want = truth(at, v.w, v.h);
      auto a = compare(got, want, v.w, v.h, at);
      if (a.far > 0) keep(svg_path, name + ".svg");
      expect_agreement(a, what);
      total += a.pixels, agreeing += a.agree;
      for (long l : want) shadowed += l >= 0x800000 ? 1 : 0;
      if (name == "light inside a closed box")
        for (long l : want) CHECK((l < 0 || l >= 0x800000));
    }
  }
  std::cout << "render: shadows, " << agreeing << " of " << total << " pixels agree with the ray caster\n";
  CHECK(shadowed > total / 10);
}

TEST_CASE("orthographic id renders agree with a parallel ray caster", "[render][parallel]") {
  if (!have("rsvg-convert")) {
    WARN("rsvg-convert is not installed (Debian: librsvg2-bin): comparison skipped");
    return;
  }
  using P = geometry::e3::point<Q>;
  auto all = scenes();
  all.push_back({"sphere (closed mesh)", svm::scenes::sphere(6)});
  std::vector<std::array<Q, 3>> dirs{{Q(1, 3), Q(1, 5), Q(1)}, {Q(-2), Q(1), Q(-1, 2)}, {Q(0), Q(0), Q(1)}, {Q(1), Q(0), Q(0)}};
  scratch tmp;
  long total = 0, agreeing = 0, views = 0;
  int const w = 160, h = 120;
  for (auto const& [name, s] : all) {
    // The centre of the bounding box, exactly, and its diagonal.
    std::array<Q, 3> lo, hi;
    bool first = true;
    for (auto const& p : s.polygons)
      for (auto const& q : p.vertices) {
        for (std::size_t k = 0; k < 3; ++k) {
          if (first || q[k] < lo[k]) lo[k] = q[k];
          if (first || q[k] > hi[k]) hi[k] = q[k];
        }
        first = false;
      }
    P centre((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
    double diagonal = std::sqrt(dot(sub(to_double(P(hi[0], hi[1], hi[2])), to_double(P(lo[0], lo[1], lo[2]))),
                                    sub(to_double(P(hi[0], hi[1], hi[2])), to_double(P(lo[0], lo[1], lo[2])))));
    for (auto const& d : dirs) {
      v3 f = normalized({d[0].convert_to<double>(), d[1].convert_to<double>(), d[2].convert_to<double>()});
      v3 up = std::abs(f[2]) > 0.99 ? v3{0, 1, 0} : v3{0, 0, 1};
      double extent = 0.8 * diagonal;
      svm::view_from_infinity<Q> view(s.polygons, {-d[0], -d[1], -d[2]}, centre);
      svm::projector pr(svm::parallel_camera(view, up, extent, w, h), svm::projection::perspective);
      auto vm = svm::build<Q>(view.image(s.polygons), view.eye(), pr.window_options());
      svm::render::options o;
      o.style = svm::render::style::id;
      auto drawing = svm::render::draw(vm, pr, {}, o);
      auto svg_path = tmp / "ortho.svg", png_path = tmp / "ortho.png";
      std::ofstream(svg_path) << svm::render::to_svg(drawing, 3);
      REQUIRE(run("rsvg-convert -o '" + png_path.string() + "' '" + svg_path.string() + "'") == 0);
      auto got = labels_of_png(png_path, w, h);
      // The truth: a ray along f through the point of the plane through the
      // centre that the pixel shows, from far behind.
      v3 r = normalized(cross(f, up)), u = cross(r, f), c = to_double(centre);
      sampler at = [tris = triangles(s), f, r, u, c, extent, diagonal](double x, double y) {
        double a = (x - w / 2.0) / (w / 2.0) * extent / 2, b = (h / 2.0 - y) / (w / 2.0) * extent / 2;
        v3 p{c[0] + a * r[0] + b * u[0] - 4 * diagonal * f[0], c[1] + a * r[1] + b * u[1] - 4 * diagonal * f[1],
             c[2] + a * r[2] + b * u[2] - 4 * diagonal * f[2]};
        return cast(tris, p, f);
      };
      auto want = truth(at, w, h);
      CHECK(std::count_if(want.begin(), want.end(), [](long l) { return l >= 0; }) > w * h / 50); // the scene is in view
      auto a = compare(got, want, w, h, at);
      std::string what = name + ", along (" + d[0].str() + ", " + d[1].str() + ", " + d[2].str() + ")";
      if (a.far > 0) keep(svg_path, name + "-ortho.svg");
      expect_agreement(a, what);
      total += a.pixels, agreeing += a.agree, ++views;
    }
  }
  std::cout << "render: " << views << " orthographic views, " << agreeing << " of " << total << " pixels agree with the parallel ray caster\n";
  CHECK(views >= 36);
}

TEST_CASE("PNG and PDF outputs through cairo match the SVG's id raster", "[render]") {
  if (!have("rsvg-convert") || !have("pdftoppm") || !have("pdftocairo")) {
    WARN("rsvg-convert or pdftoppm is not installed (Debian: librsvg2-bin, poppler-utils): comparison skipped");
    return;
  }
  scratch tmp;
  auto s = svm::scenes::random_cubes(10, 5);
  for (auto k : {kind::perspective, kind::stereographic, kind::panorama}) {
    view v{k, centre_direction(s), {0, 0, 1}, k == kind::panorama ? 360.0 : 90.0, k == kind::panorama ? 240 : 160, 120};
    auto d = id_drawing(s, v);
    std::ofstream(tmp / "a.svg") << svm::render::to_svg(d, 3);
    REQUIRE(run("rsvg-convert -o '" + (tmp / "a.png").string() + "' '" + (tmp / "a.svg").string() + "'") == 0);
    auto svg_raster = labels_of_png(tmp / "a.png", v.w, v.h);
    auto at = sample(s, v);
    auto want = truth(at, v.w, v.h);

    svm::render::write_cairo(d, (tmp / "b.png").string(), svm::render::cairo_format::png);
    auto png = labels_of_png(tmp / "b.png", v.w, v.h);
    expect_agreement(compare(png, want, v.w, v.h, at), "cairo PNG");
    expect_agreement(compare(png, svg_raster, v.w, v.h, at), "cairo PNG against the SVG raster");

    svm::render::write_cairo(d, (tmp / "c.pdf").string(), svm::render::cairo_format::pdf);
    // Poppler's cairo back end samples pixel centres like the others.
    REQUIRE(run("pdftocairo -r 72 -antialias none -png -singlefile '" + (tmp / "c.pdf").string() + "' '" + (tmp / "c").string() + "'") == 0);
    auto pdf = labels_of_opaque_png(tmp / "c.png", v.w, v.h);
    expect_agreement(compare(pdf, want, v.w, v.h, at), "PDF through pdftocairo");
    expect_agreement(compare(pdf, svg_raster, v.w, v.h, at), "PDF against the SVG raster");
    // Poppler's own rasterizer widens thin fills to whole pixels: it must
    // render the page, and agree but for a band along the edges.
    REQUIRE(run("pdftoppm -r 72 -aa no -aaVector no -png -singlefile '" + (tmp / "c.pdf").string() + "' '" + (tmp / "e").string() + "'") == 0);
    auto splash = labels_of_opaque_png(tmp / "e.png", v.w, v.h);
    auto a = compare(splash, svg_raster, v.w, v.h, at);
    INFO("pdftoppm: " << a.agree << "/" << a.pixels << " agree with the SVG raster");
    CHECK(static_cast<double>(a.agree) >= 0.98 * static_cast<double>(a.pixels));

    svm::render::write_cairo(d, (tmp / "d.eps").string(), svm::render::cairo_format::eps);
    std::ifstream eps(tmp / "d.eps");
    std::string first;
    std::getline(eps, first);
    CHECK(first.rfind("%!PS-Adobe", 0) == 0);
  }
}

TEST_CASE("nothing hidden in the SVG: Hidden Bricks shows only the hiding box", "[render]") {
  auto s = svm::scenes::hidden_bricks(16);
  view v{kind::perspective, {0, 0, 1}, {0, 1, 0}, 90, 400, 300};
  auto pr = projector_of(v);
  auto vm = svm::build<Q>(s.polygons, s.eye, pr.window_options());
  svm::render::options o;
  o.style = svm::render::style::flat;
  auto d = svm::render::draw(vm, pr, {}, o);
  std::string svg = svm::render::to_svg(d);
  std::regex face_attr("data-face=\"(-?[0-9]+)\"");
  std::set<long> faces;
  long paths = 0;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), face_attr); it != std::sregex_iterator(); ++it) {
    faces.insert(std::stol((*it)[1]));
    ++paths;
  }
  std::size_t visible = 0;
  for (auto const& f : vm.map.faces())
    if (f.label >= 0) ++visible;
  INFO(svg.size() << " bytes");
  CHECK(paths == static_cast<long>(visible));
  CHECK(paths == static_cast<long>(d.regions.size()));
  REQUIRE(!faces.empty());
  CHECK(*faces.rbegin() < 6); // faces 0..5 are the hiding box
  // Seen from the eye, the 90° view shows only the box's near face.
  CHECK(faces == std::set<long>{*faces.begin()});
  CHECK(svg.find("<path") != std::string::npos);
  CHECK(svg.find("fill-rule=\"evenodd\"") != std::string::npos);
}

TEST_CASE("lines style: visible edges between different planes only", "[render]") {
  using P = geometry::e3::point<Q>;
  SECTION("a cube seen from near a corner draws 9 edges") {
    svm::scenes::scene s;
    svm::scenes::add_box(s, P(Q(-1), Q(-1), Q(-1)), P(Q(1), Q(1), Q(1)));
    s.eye = P(Q(3), Q(4), Q(5));
    view v{kind::perspective, {-3, -4, -5}, {0, 0, 1}, 60, 400, 300};
    auto pr = projector_of(v);
    auto vm = svm::build<Q>(s.polygons, s.eye, pr.window_options());
    std::vector<svm::render::face_info> info(6);
    for (auto const& p : s.polygons) {
      auto a = to_double(p.vertices[0]), b = to_double(p.vertices[1]), c = to_double(p.vertices[2]);
      info[p.face].normal = normalized(cross(sub(b, a), sub(c, a)));
      info[p.face].offset = dot(info[p.face].normal, a);
    }
    svm::render::options o;
    o.style = svm::render::style::lines;
    auto d = svm::render::draw(vm, pr, info, o);
    CHECK(d.edges == 9);
    // Three silhouette-and-inner polylines meet at the near corner; every edge is drawn once.
    std::size_t segments = 0;
    for (auto const& l : d.polylines) segments += l.size() - 1;
    CHECK(segments == 9);
  }
  SECTION("a flat square split into coplanar triangles draws only its outline") {
    svm::scenes::scene s;
    int n = 6;
    auto at = [&](int i, int j) { return P(Q(i), Q(j), Q(10)); };
    std::uint32_t face = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        s.polygons.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1)}, face++});
        s.polygons.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1)}, face++});
      }
    s.eye = P(Q(3, 2), Q(5, 2), Q(0));
    view v{kind::perspective, {0, 0, 1}, {0, 1, 0}, 90, 400, 400};
    auto pr = projector_of(v);
    auto vm = svm::build<Q>(s.polygons, s.eye, pr.window_options());
    std::vector<svm::render::face_info> info(face);
    for (auto& fi : info) fi.normal = {0, 0, 1}, fi.offset = 10;
    svm::render::options o;
    o.style = svm::render::style::lines;
    auto d = svm::render::draw(vm, pr, info, o);
    CHECK(d.edges == 4);
    REQUIRE(d.polylines.size() == 1); // the outline, joined into one closed polyline
    CHECK(d.polylines[0].size() == 5);
    // With no planes known, every boundary between triangles is drawn.
    auto all = svm::render::draw(vm, pr, {}, o);
    CHECK(all.edges > 4 + 3 * static_cast<std::size_t>(n * n));
  }
}

TEST_CASE("the SVG writer: one path per region, id colours, precision", "[render]") {
  auto s = svm::scenes::random_cubes(6, 2);
  view v{kind::stereographic, centre_direction(s), {0, 0, 1}, 120, 300, 200};
  auto d = id_drawing(s, v);
  REQUIRE(!d.regions.empty());
  auto svg = svm::render::to_svg(d, 1);
  CHECK(svg.find("shape-rendering=\"crispEdges\"") != std::string::npos);
  CHECK(svg.find("stroke=") == std::string::npos);
  std::size_t n = 0;
  for (auto at = svg.find("<path"); at != std::string::npos; at = svg.find("<path", at + 1)) ++n;
  CHECK(n == d.regions.size());
  // Polygon p is filled with p + 1 as #RRGGBB.
  char hex[8];
  auto p = d.regions.front().polygon;
  std::snprintf(hex, sizeof hex, "#%06lx", static_cast<unsigned long>(p + 1));
  CHECK(svg.find(std::string("data-face=\"") + std::to_string(p) + "\"") != std::string::npos);
  CHECK(svg.find(hex) != std::string::npos);
  // Stereographic views draw circular arcs, and one decimal means one decimal.
  CHECK(svg.find(" A") != std::string::npos);
  CHECK(!std::regex_search(svg, std::regex("[0-9]\\.[0-9]{2}")));
}
