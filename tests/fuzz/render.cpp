// libFuzzer target for drawing.  The input's bytes make a tiny scene (as for
// the map's target), a view of it (one of the five central projections, or
// a parallel view) and a camera: any direction, any up, any field of view the
// projection allows, images from 2×2 pixels.  The exact map clipped to the
// view is drawn in every style and as a hidden-line drawing, and each
// drawing is checked:
//   * every coordinate (path points, arc centres and radii, polylines) is
//     finite;
//   * its SVG is well-formed XML (expat) and holds no "nan" or "inf";
//   * cairo draws it without error (on a recording surface, as the PDF, PS,
//     EPS and PNG writers do).
// Any failed check aborts, with the reason on standard error.
#include "input.hpp"

#include <svm/build.hpp>
#include <svm/camera.hpp>
#include <svm/lines.hpp>
#include <svm/parallel.hpp>
#include <svm/render/cairo.hpp>
#include <svm/render/drawing.hpp>
#include <svm/render/lines.hpp>
#include <svm/render/svg.hpp>

#include <cairo.h>
#include <expat.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

using Q = geometry::rational;
using test::ray::ivec;
namespace render = svm::render;

[[noreturn]] void fail(std::string const& what) { fuzz::fail("fuzz_render", what); }

bool is_finite(double x) { return std::isfinite(x); }

void check_lines(std::vector<std::vector<svm::pixel>> const& lines, char const* what) {
  for (auto const& l : lines)
    for (auto const& p : l)
      if (!is_finite(p.x) || !is_finite(p.y)) fail(std::string("a point of ") + what + " that is not finite");
}

void check(render::drawing const& d, int digits, char const* what) {
  auto why = [&](char const* problem) { return std::string(problem) + " (" + what + ")"; };
  for (auto const& r : d.regions)
    for (auto const& c : r.path)
      if (!is_finite(c.x) || !is_finite(c.y) || !is_finite(c.cx) || !is_finite(c.cy) || !is_finite(c.radius) || c.radius < 0)
        fail(why("a path command whose numbers are not finite"));
  check_lines(d.polylines, what);
  check_lines(d.thin_polylines, what);
  for (auto const& l : d.layers) check_lines(l.lines, what);

  std::string svg = render::to_svg(d, digits);
  std::unique_ptr<XML_ParserStruct, void (*)(XML_Parser)> parser(XML_ParserCreate("UTF-8"), XML_ParserFree);
  if (!parser) fail("expat could not start");
  if (XML_Parse(parser.get(), svg.data(), static_cast<int>(svg.size()), 1) != XML_STATUS_OK)
    fail(why("SVG that is not well-formed XML: ") + XML_ErrorString(XML_GetErrorCode(parser.get())) + " at line " +
         std::to_string(XML_GetCurrentLineNumber(parser.get())));
  std::string lower(svg.size(), ' ');
  std::transform(svg.begin(), svg.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower.find("nan") != std::string::npos || lower.find("inf") != std::string::npos) fail(why("SVG with nan or inf in it"));

  cairo_surface_t* surface = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, nullptr);
  cairo_t* cr = cairo_create(surface);
  render::draw_cairo(cr, d);
  auto status = cairo_status(cr);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) fail(why("cairo failed: ") + cairo_status_to_string(status));
}

/// What the drawing needs of each face: its plane, centre and a colour.
std::vector<render::face_info> infos_of(std::vector<test::ray::triangle> const& tris) {
  std::vector<render::face_info> out;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    std::array<svm::vec3, 3> v;
    for (int k = 0; k < 3; ++k) v[k] = {double(tris[i].v[k][0]), double(tris[i].v[k][1]), double(tris[i].v[k][2])};
    using namespace svm::detail;
    render::face_info f;
    f.normal = unit3(cross3(sub3(v[1], v[0]), sub3(v[2], v[0])));
    f.offset = dot3(f.normal, v[0]);
    f.centre = mul3(add3(add3(v[0], v[1]), v[2]), 1.0 / 3);
    if (i % 2) f.colour = render::rgb{0.2, 0.5, 0.8};
    out.push_back(f);
  }
  return out;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(std::uint8_t const* data, std::size_t size) {
  fuzz::input in(data, size);
  auto [eye_i, tris] = fuzz::read_scene(in);
  if (tris.empty()) return 0;
  auto polys = test::ray::polygons_of(tris);
  geometry::e3::point<Q> eye{Q(eye_i[0]), Q(eye_i[1]), Q(eye_i[2])};
  auto infos = infos_of(tris);

  auto vector = [&] { return svm::vec3{double(in.in(-4, 4)), double(in.in(-4, 4)), double(in.in(-4, 4))}; };
  int kind = static_cast<int>(in.in(0, 5)); // the five central projections, then the parallel view
  svm::camera cam;
  cam.forward = vector();
  if (cam.forward == svm::vec3{0, 0, 0}) cam.forward = {1, 0, 0};
  cam.up = vector();
  if (svm::detail::norm3(svm::detail::cross3(cam.forward, cam.up)) == 0) cam.up = std::abs(cam.forward[2]) > 0 ? svm::vec3{1, 0, 0} : svm::vec3{0, 0, 1};
  cam.width = static_cast<int>(in.in(1, 255)) + 1;
  cam.height = static_cast<int>(in.in(1, 255)) + 1;
  bool simplify = in.byte() % 2;
  int digits = static_cast<int>(in.in(0, 4));
  double tolerance = in.in(1, 40) / 20.0;

  std::optional<svm::projector> pr;
  svm::visibility_map<Q> vm;
  std::vector<svm::polygon<Q>> seen = polys; // what the map is of: the scene, or its image
  geometry::e3::point<Q> from = eye;
  if (kind < 5) {
    auto p = static_cast<svm::projection>(kind);
    cam.hfov = p == svm::projection::perspective ? double(in.in(1, 178)) : double(in.in(1, 360));
    pr.emplace(cam, p);
    vm = svm::build<Q>(polys, eye, pr->window_options({.simplify = simplify}));
  } else {
    std::array<Q, 3> toward{Q(in.in(-4, 4)), Q(in.in(-4, 4)), Q(in.in(-4, 4))};
    if (toward[0] == 0 && toward[1] == 0 && toward[2] == 0) toward[0] = 1;
    svm::view_from_infinity<Q> view(polys, toward, eye);
    seen = view.image(polys);
    from = view.eye();
    auto c = svm::parallel_camera(view, cam.up, double(in.in(1, 32)) / 2, cam.width, cam.height);
    if (svm::detail::norm3(svm::detail::cross3(c.forward, c.up)) == 0) c.up = std::abs(c.forward[2]) > 0 ? svm::vec3{1, 0, 0} : svm::vec3{0, 0, 1};
    pr.emplace(c, svm::projection::perspective);
    vm = svm::build<Q>(seen, from, pr->window_options({.simplify = simplify}));
  }

  svm::vec3 eye_d{double(eye_i[0]), double(eye_i[1]), double(eye_i[2])};
  for (auto s : {render::style::shaded, render::style::flat, render::style::lines, render::style::id}) {
    render::options o;
    o.style = s;
    o.tolerance = tolerance;
    o.eye = eye_d;
    o.crease = double(in.in(0, 90));
    check(render::draw(vm, *pr, infos, o), digits, "a style");
  }
  auto lines = svm::hidden_lines(vm, from, seen, {.crease = double(in.in(0, 90))});
  render::line_drawing_options lo;
  lo.hidden = static_cast<render::hidden_style>(in.in(0, 3));
  lo.tolerance = tolerance;
  render::line_drawing_summary summary;
  check(render::draw_lines(lines, vm, from, *pr, lo, &summary), digits, "hidden lines");
  if (!is_finite(summary.travel_before) || !is_finite(summary.travel_after)) fail("pen travel that is not finite");
  return 0;
}
