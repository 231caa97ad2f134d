// The subcommands of genbsp as functions, for the program's entry, for
// `genbsp batch` and for the Python module: one argument vector in, what
// the command prints on `out()` (common.hpp), its files written.
#pragma once

#include <geometry/io/polygons.hpp>
#include <geometry/io/scene.hpp>
#include <svm/build.hpp>
#include <svm/parallel.hpp>
#include <svm/render/drawing.hpp>

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace genbsp_tool {

/// A scene file read once: its faces as written, and (when asked) its
/// convex polygons, as every map subcommand starts from them.
struct scene_data {
  std::string path;               ///< the name subcommands know it by
  geometry::io::scene scene;      ///< as read
  geometry::io::prepared prepared; ///< its convex polygons, when `has_prepared`
  bool has_prepared = false;
};

/// Reads `path` (a `geometry::io::read_error` for bad input), and prepares
/// its convex polygons when `prepare`.
std::shared_ptr<scene_data const> read_scene_data(std::string const& path, bool prepare = true);

/// While alive, subcommands run on this thread that name `data->path` use
/// `data` instead of reading the file again (scopes nest).
class scene_scope {
public:
  explicit scene_scope(std::shared_ptr<scene_data const> data);
  ~scene_scope();
  scene_scope(scene_scope const&) = delete;
  scene_scope& operator=(scene_scope const&) = delete;

private:
  std::shared_ptr<scene_data const> data_;
  scene_data const* previous_;
};

/// The scene `path`: the one of this thread's innermost `scene_scope`
/// when it names `path`, else read from the file.
std::shared_ptr<scene_data const> scene_data_of(std::string const& path, bool prepare = true);

/// The scene's convex polygons in the number type `FT` (rounded to doubles
/// for `double`), labelled by their input faces.
template <class FT> std::vector<svm::polygon<FT>> polygons_in(geometry::io::prepared const& p) {
  std::vector<svm::polygon<FT>> out;
  out.reserve(p.polygons.size());
  for (auto const& q : p.polygons) {
    if constexpr (std::is_same_v<FT, geometry::rational>) out.push_back({q.vertices, q.face});
    else {
      std::vector<geometry::e3::point<FT>> v;
      for (auto const& x : q.vertices) v.emplace_back(x.x().convert_to<double>(), x.y().convert_to<double>(), x.z().convert_to<double>());
      out.push_back({std::move(v), q.face});
    }
  }
  return out;
}

/// MAP.json of a map of `scene` from `eye` (docs/map-format.md), as
/// `genbsp map` writes it.
std::string map_json_text(svm::visibility_map<geometry::rational> const& vm, geometry::e3::point<geometry::rational> const& eye,
                          std::shared_ptr<scene_data const> const& scene);
std::string map_json_text(svm::visibility_map<double> const& vm, geometry::e3::point<geometry::rational> const& eye,
                          std::shared_ptr<scene_data const> const& scene);

/// The parallel view of `scene` along `direction` ("DX,DY,DZ", exact) about
/// the centre of its bounding box, as `genbsp map --view-dir` makes it.
svm::view_from_infinity<geometry::rational> parallel_view_of(std::shared_ptr<scene_data const> const& scene,
                                                             std::vector<svm::polygon<geometry::rational>> const& polygons,
                                                             std::string const& direction);
/// MAP.json of a parallel view (`vm` the map of `view`'s image from its
/// eye), as `genbsp map --view-dir` writes it; `up` as its `--up`.
std::string parallel_map_json_text(svm::visibility_map<geometry::rational> const& vm, svm::view_from_infinity<geometry::rational> const& view,
                                   std::string const& up, std::shared_ptr<scene_data const> const& scene);

/// The bounding box of `scene`'s polygons, exactly: their lowest and highest
/// coordinates, and whether there is a vertex at all.
std::tuple<std::array<geometry::rational, 3>, std::array<geometry::rational, 3>, bool> exact_box(geometry::io::prepared const& scene);

/// A point's coordinates rounded to doubles, for drawing.
svm::vec3 vec_of(geometry::e3::point<geometry::rational> const& p);

/// The perspective camera at `view.eye()` that draws the parallel view,
/// `width`×`height` pixels, up along `up`: as `genbsp render --projection
/// orthographic` draws it without `--extent`, the box [lo, hi] (the scene's)
/// fitted with a margin.
svm::camera parallel_fit(svm::view_from_infinity<geometry::rational> const& view, std::array<geometry::rational, 3> const& lo,
                         std::array<geometry::rational, 3> const& hi, svm::vec3 const& up, int width, int height);

/// What a drawing knows of each input face of `scene` (its prepared
/// polygons read): its colour from the file, and its plane.
std::vector<svm::render::face_info> face_infos(scene_data const& scene);

/// `path` with `-what` before its extension: where `genbsp render` writes a
/// cube map's face ("out-front.svg") or one layer ("out-visible-outline.svg").
std::string suffixed(std::string const& path, std::string_view what);

/// The faces of a cube map, in the order `genbsp render` draws them.
inline constexpr std::array<std::string_view, 6> cube_faces{"front", "right", "back", "left", "up", "down"};

/// Every file `genbsp render -o OUT` may write: first the views it always
/// writes (OUT, or a cube map's six faces); then, with `--split-layers`, each
/// of those with each layer a line drawing can have (only the layers with
/// lines are written).
std::vector<std::string> render_files(std::string const& out, bool cube, bool split_layers);

/// Runs the command line `argv` (`argv[0]` the program's name): its exit
/// status; bad input throws `usage_error` or `geometry::io::read_error`.
int run(int argc, char** argv);
int run(std::vector<std::string> const& args);

/// `run`, with errors reported on standard error as one line: status 2 for
/// bad input, 1 for an internal error.
int run_main(int argc, char** argv);

} // namespace genbsp_tool
