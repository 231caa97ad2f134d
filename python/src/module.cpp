// The compiled part of the Python package `genbsp` (`genbsp._genbsp`):
// scenes, visibility maps and the Boolean operations, on the library's own
// types.  The package's Python layer (genbsp/__init__.py) turns exact
// numbers into text and back into `fractions.Fraction`s.
#include <boolean/polygons.hpp>
#include <boolean/polyhedra.hpp>
#include <boolean/spherical.hpp>
#include <geometry/io/geojson.hpp>
#include <geometry/io/wkt.hpp>
#include <svm/query.hpp>

#include "batch.hpp"
#include "commands.hpp"
#include "common.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

namespace py = pybind11;

namespace {

using geometry::rational;
using point3 = geometry::e3::point<rational>;
using genbsp_tool::scene_data;

/// Library errors as the Python exceptions the package documents: bad input
/// is a ValueError with the library's one-line message.
[[noreturn]] void rethrow_as_python() {
  try {
    throw;
  } catch (genbsp_tool::usage_error const& e) {
    throw py::value_error(e.what());
  } catch (geometry::parse_error const& e) {
    throw py::value_error(e.what());
  } catch (boolean::invalid_polygon const& e) {
    throw py::value_error(e.what());
  }
}

/// A file that cannot be opened or written as the OSError subclass of its
/// `errno` value, with the library's one-line message.
[[noreturn]] void throw_os_error(int code, char const* message) {
  PyObject* type = code == ENOENT   ? PyExc_FileNotFoundError
                   : code == EACCES || code == EPERM ? PyExc_PermissionError
                   : code == EISDIR ? PyExc_IsADirectoryError
                   : code == ENOTDIR ? PyExc_NotADirectoryError
                   : code == EEXIST ? PyExc_FileExistsError
                                    : PyExc_OSError;
  PyErr_SetString(type, message);
  throw py::error_already_set();
}

/// Runs `f`, the GIL released, with library errors as Python exceptions: a
/// file that cannot be opened or written is an OSError, bad content a
/// ValueError.
template <class F> auto guarded(F&& f) {
  try {
    py::gil_scoped_release unlocked;
    return f();
  } catch (geometry::io::read_error const& e) {
    if (e.error_code != 0) throw_os_error(e.error_code, e.what());
    throw py::value_error(e.what());
  } catch (genbsp_tool::file_error const& e) {
    throw_os_error(e.code, e.what());
  } catch (py::error_already_set const&) {
    throw;
  } catch (std::bad_alloc const&) {
    throw;
  } catch (std::logic_error const& e) {
    // invalid_argument is bad input; other logic errors are the library's own.
    if (dynamic_cast<std::invalid_argument const*>(&e)) throw py::value_error(e.what());
    throw std::runtime_error(std::string("genbsp internal error: ") + e.what());
  } catch (std::exception const&) {
    rethrow_as_python();
  }
}

rational exact(std::string const& text, std::string const& what) {
  try {
    return geometry::parse_number<rational>(text);
  } catch (geometry::parse_error const& e) {
    throw py::value_error(what + ": " + e.what());
  }
}

/// A scene: faces as read, their convex polygons, and the name commands
/// know it by.
struct scene {
  std::shared_ptr<scene_data const> data;
};

std::atomic<std::uint64_t> scenes_made{0};

scene scene_from_file(std::string const& path) {
  return {guarded([&] { return genbsp_tool::read_scene_data(path); })};
}

/// A scene from exact vertex coordinates (as text) and faces (index lists).
using face_colour = std::optional<std::array<double, 3>>;

scene scene_from_text(std::vector<std::array<std::string, 3>> const& vertices, std::vector<std::vector<std::int64_t>> const& faces,
                      std::vector<face_colour> const& colours = {}, std::optional<std::string> const& name = {}) {
  if (!colours.empty() && colours.size() != faces.size())
    throw py::value_error("colours: expected one per face (" + std::to_string(faces.size()) + "), got " + std::to_string(colours.size()));
  auto d = std::make_shared<scene_data>();
  d->path = name ? *name : "<scene " + std::to_string(++scenes_made) + ">";
  d->scene.vertices.reserve(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    d->scene.vertices.emplace_back(exact(vertices[i][0], "vertex " + std::to_string(i)), exact(vertices[i][1], "vertex " + std::to_string(i)),
                                   exact(vertices[i][2], "vertex " + std::to_string(i)));
  for (std::size_t f = 0; f < faces.size(); ++f) {
    geometry::io::scene::face face;
    if (faces[f].size() < 3) throw py::value_error("face " + std::to_string(f) + ": a face has at least 3 vertices");
    for (auto k : faces[f]) {
      if (k < 0 || static_cast<std::size_t>(k) >= vertices.size())
        throw py::value_error("face " + std::to_string(f) + ": vertex index " + std::to_string(k) + " out of range (" +
                              std::to_string(vertices.size()) + " vertices)");
      face.vertices.push_back(static_cast<std::uint32_t>(k));
    }
    if (!colours.empty() && colours[f]) {
      auto [r, g, b] = *colours[f];
      for (double c : {r, g, b})
        if (!(c >= 0 && c <= 1)) throw py::value_error("face " + std::to_string(f) + ": colour components must be in [0, 1]");
      face.colour = geometry::io::rgb{r, g, b};
    }
    d->scene.faces.push_back(std::move(face));
  }
  guarded([&] {
    d->prepared = geometry::io::convex_polygons(d->scene);
    d->has_prepared = true;
    return 0;
  });
  return {std::move(d)};
}

/// A scene from an n × 3 array of doubles, each read exactly as the double it is.
scene scene_from_doubles(py::array_t<double, py::array::c_style | py::array::forcecast> vertices,
                         std::vector<std::vector<std::int64_t>> const& faces) {
  if (vertices.ndim() != 2 || vertices.shape(1) != 3) throw py::value_error("vertices: expected an n x 3 array");
  auto v = vertices.unchecked<2>();
  std::vector<std::array<std::string, 3>> text;
  // Exact text of each double: m·2^e as a fraction, with no rounding.
  auto exact_text = [](double x, std::size_t i) {
    if (!std::isfinite(x)) throw py::value_error("vertex " + std::to_string(i) + ": coordinates must be finite");
    return genbsp_tool::exact_text(rational(x));
  };
  for (py::ssize_t i = 0; i < v.shape(0); ++i)
    text.push_back({exact_text(v(i, 0), static_cast<std::size_t>(i)), exact_text(v(i, 1), static_cast<std::size_t>(i)),
                    exact_text(v(i, 2), static_cast<std::size_t>(i))});
  return scene_from_text(text, faces);
}

/// A visibility map and what made it.
struct visibility_map {
  std::shared_ptr<scene_data const> scene;
  point3 eye;
  std::array<std::string, 3> eye_text;
  bool exact = true, cull = false, simplify = true;
  std::variant<svm::visibility_map<rational>, svm::visibility_map<double>> vm;

  template <class F> decltype(auto) visit(F&& f) const { return std::visit(std::forward<F>(f), vm); }
};

visibility_map build_map(scene const& s, std::array<std::string, 3> const& eye_text, bool exact_numbers, bool cull, bool simplify) {
  point3 eye(exact(eye_text[0], "eye"), exact(eye_text[1], "eye"), exact(eye_text[2], "eye"));
  svm::build_options o;
  o.simplify = simplify;
  o.cull_backfaces = cull;
  using any_map = std::variant<svm::visibility_map<rational>, svm::visibility_map<double>>;
  auto vm = guarded([&]() -> any_map {
    if (exact_numbers) return svm::build<rational>(genbsp_tool::polygons_in<rational>(s.data->prepared), eye, o);
    geometry::e3::point<double> e(eye.x().convert_to<double>(), eye.y().convert_to<double>(), eye.z().convert_to<double>());
    return svm::build<double>(genbsp_tool::polygons_in<double>(s.data->prepared), e, o);
  });
  return visibility_map{s.data, eye, eye_text, exact_numbers, cull, simplify, std::move(vm)};
}

py::array_t<std::int64_t> locate(visibility_map const& m, py::array_t<double, py::array::c_style | py::array::forcecast> directions) {
  if (directions.ndim() == 1 && directions.shape(0) == 3) directions = directions.reshape({1, 3});
  if (directions.ndim() != 2 || directions.shape(1) != 3) throw py::value_error("directions: expected an n x 3 array");
  auto n = directions.shape(0);
  py::array_t<std::int64_t> out(n);
  auto d = directions.unchecked<2>();
  auto r = out.mutable_unchecked<1>();
  // Each row is read once and checked as read, the GIL released: another
  // thread may write the array meanwhile, so no earlier check would hold.
  py::ssize_t bad = -1;
  bool zero = false;
  {
    py::gil_scoped_release unlocked;
    m.visit([&](auto const& vm) {
      using FT = typename std::remove_cvref_t<decltype(vm)>::number_type;
      for (py::ssize_t i = 0; i < n; ++i) {
        std::array<double, 3> x{d(i, 0), d(i, 1), d(i, 2)};
        if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]) || (x[0] == 0 && x[1] == 0 && x[2] == 0)) {
          bad = i, zero = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
          return;
        }
        r(i) = svm::locate(vm, svm::direction_of_doubles<FT>(x));
      }
    });
  }
  if (bad >= 0)
    throw py::value_error("directions[" + std::to_string(bad) + "]: " +
                          (zero ? "the zero vector is no direction" : "coordinates must be finite"));
  return out;
}

/// The map's arrays: vertices (unit vectors), half-edges (origin, twin,
/// next, prev, face) and faces (the visible polygon, or −1).
py::dict map_arrays(visibility_map const& m) {
  return m.visit([](auto const& vm) {
    auto const& g = vm.map;
    auto nv = static_cast<py::ssize_t>(g.vertices().size()), ne = static_cast<py::ssize_t>(g.half_edges().size()),
         nf = static_cast<py::ssize_t>(g.faces().size());
    py::array_t<double> vertices({nv, py::ssize_t(3)});
    auto v = vertices.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < nv; ++i) {
      auto u = svm::unit(g, static_cast<svm::index>(i));
      for (int k = 0; k < 3; ++k) v(i, k) = u[static_cast<std::size_t>(k)];
    }
    py::array_t<std::int64_t> he({ne, py::ssize_t(5)});
    auto h = he.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < ne; ++i) {
      auto e = static_cast<svm::index>(i);
      h(i, 0) = g.origin(e), h(i, 1) = g.twin(e), h(i, 2) = g.next(e), h(i, 3) = g.prev(e), h(i, 4) = g.face_of(e);
    }
    py::array_t<std::int64_t> faces(nf);
    auto f = faces.mutable_unchecked<1>();
    for (py::ssize_t i = 0; i < nf; ++i) f(i) = g.faces()[static_cast<std::size_t>(i)].label;
    py::dict out;
    out["vertices"] = vertices;
    out["half_edges"] = he;
    out["faces"] = faces;
    return out;
  });
}

/// Runs a genbsp command line on `s` (read once, shared): its exit status
/// and what it printed.
std::pair<int, std::string> run_command(std::vector<std::string> args, std::optional<scene> const& s) {
  return guarded([&] {
    std::optional<genbsp_tool::scene_scope> scope;
    if (s) scope.emplace(s->data);
    std::ostringstream captured;
    auto* previous = genbsp_tool::output_stream();
    genbsp_tool::output_stream() = &captured;
    genbsp_tool::batch_worker() = true;
    args.insert(args.begin(), "genbsp");
    try {
      int status = genbsp_tool::run(args);
      genbsp_tool::output_stream() = previous;
      genbsp_tool::batch_worker() = false;
      return std::pair<int, std::string>(status, captured.str());
    } catch (...) {
      genbsp_tool::output_stream() = previous;
      genbsp_tool::batch_worker() = false;
      throw;
    }
  });
}

/// `genbsp batch` on a scene: the per-job results and the summary, as JSON text.
std::pair<std::vector<std::string>, std::string> run_batch(scene const& s, std::string const& jobs_json, std::string const& base,
                                                           unsigned workers, std::size_t shard, std::size_t shards, bool progress) {
  return guarded([&] {
    nlohmann::ordered_json m{{"jobs", nlohmann::ordered_json::parse(jobs_json)}};
    auto plan = genbsp_tool::plan_batch(m, base, "jobs", s.data->path);
    genbsp_tool::batch_settings settings{workers, shard, shards, progress};
    std::vector<std::pair<std::size_t, std::string>> lines;
    auto summary = genbsp_tool::run_batch(plan, s.data, settings, [&](nlohmann::ordered_json const& r) {
      lines.emplace_back(r["job"].get<std::size_t>(), r.dump());
    });
    std::sort(lines.begin(), lines.end());
    std::vector<std::string> out;
    for (auto& l : lines) out.push_back(std::move(l.second));
    return std::pair(out, summary.dump());
  });
}

geometry::io::multipolygon read_operand(std::string const& text, std::string const& name) {
  auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '{') return geometry::io::read_geojson(text, name);
  return geometry::io::read_wkt(text, name);
}

boolean::set_op set_operation(std::string const& op) {
  if (op == "union") return boolean::set_op::union_;
  if (op == "intersection") return boolean::set_op::intersection;
  if (op == "difference") return boolean::set_op::difference;
  if (op == "xor" || op == "symmetric_difference") return boolean::set_op::symmetric_difference;
  throw py::value_error("op: expected union, intersection, difference or xor, got '" + op + "'");
}

/// A planar Boolean operation on WKT or GeoJSON text: the result as WKT and
/// GeoJSON, its exact area as text, and its rings as doubles.
py::dict boolean2d(std::string const& a, std::string const& b, std::string const& op, std::optional<std::string> const& fill) {
  auto o = set_operation(op);
  std::optional<boolean::fill_rule> rule;
  if (fill) {
    if (*fill == "evenodd") rule = boolean::fill_rule::evenodd;
    else if (*fill == "nonzero") rule = boolean::fill_rule::nonzero;
    else if (*fill == "positive") rule = boolean::fill_rule::positive;
    else if (*fill == "negative") rule = boolean::fill_rule::negative;
    else throw py::value_error("fill_rule: expected evenodd, nonzero, positive or negative, got '" + *fill + "'");
  }
  struct result {
    std::string wkt, geojson, area;
    std::vector<std::vector<std::vector<std::array<double, 2>>>> polygons;
  };
  auto r = guarded([&] {
    auto operand = [&](std::string const& text, std::string const& name) {
      auto m = read_operand(text, name);
      if (!rule) return boolean::operand_of(m);
      std::vector<boolean::ring> paths;
      for (auto const& p : m) {
        paths.push_back(p.outer);
        for (auto const& h : p.holes) paths.push_back(h);
      }
      return boolean::operand_of(paths, *rule);
    };
    auto A = operand(a, "a"), B = operand(b, "b");
    auto m = boolean::combine(o, A, B);
    result out{geometry::io::to_wkt(m), geometry::io::to_geojson(m), genbsp_tool::exact_text(boolean::area(m)), {}};
    for (auto const& p : m) {
      std::vector<std::vector<std::array<double, 2>>> rings;
      auto ring = [](boolean::ring const& r) {
        std::vector<std::array<double, 2>> v;
        for (auto const& q : r) v.push_back({q.x().convert_to<double>(), q.y().convert_to<double>()});
        return v;
      };
      rings.push_back(ring(p.outer));
      for (auto const& h : p.holes) rings.push_back(ring(h));
      out.polygons.push_back(std::move(rings));
    }
    return out;
  });
  py::dict d;
  d["wkt"] = r.wkt, d["geojson"] = r.geojson, d["area"] = r.area, d["polygons"] = r.polygons;
  return d;
}

/// A Boolean operation on the sphere, on longitude/latitude WKT or GeoJSON.
py::dict boolean_s2(std::string const& a, std::string const& b, std::string const& op) {
  auto o = set_operation(op);
  struct result {
    std::string wkt, geojson;
    double area = 0;
  };
  auto r = guarded([&] {
    auto A = boolean::spherical_operand_of(read_operand(a, "a")), B = boolean::spherical_operand_of(read_operand(b, "b"));
    auto polygons = boolean::combine(o, A, B);
    auto m = boolean::lonlat_polygons(polygons);
    return result{geometry::io::to_wkt(m), geometry::io::to_geojson(m), boolean::area(polygons)};
  });
  py::dict d;
  d["wkt"] = r.wkt, d["geojson"] = r.geojson, d["area"] = r.area, d["area_km2"] = r.area * boolean::earth_radius_km * boolean::earth_radius_km;
  return d;
}

/// CSG of two closed meshes: the result's vertices (exact text and doubles),
/// faces, exact volume and whether it is closed.
py::dict csg(scene const& a, scene const& b, std::string const& op) {
  boolean::csg_op o;
  if (op == "union") o = boolean::csg_op::union_;
  else if (op == "intersection") o = boolean::csg_op::intersection;
  else if (op == "difference") o = boolean::csg_op::difference;
  else throw py::value_error("op: expected union, intersection or difference, got '" + op + "'");
  struct result {
    boolean::mesh m;
    std::string volume;
    bool closed;
  };
  auto r = guarded([&] {
    auto solid = [](scene const& s) {
      try {
        return boolean::from_scene(s.data->scene);
      } catch (std::invalid_argument const& e) {
        throw genbsp_tool::usage_error(s.data->path + ": " + e.what());
      }
    };
    auto A = solid(a), B = solid(b);
    auto m = boolean::combine(o, A, B);
    auto edges = boolean::inspect_edges(m);
    auto v = genbsp_tool::exact_text(boolean::volume(m));
    return result{std::move(m), std::move(v), edges.unmatched == 0 && edges.non_manifold == 0};
  });
  auto nv = static_cast<py::ssize_t>(r.m.vertices.size());
  py::array_t<double> vertices({nv, py::ssize_t(3)});
  auto v = vertices.mutable_unchecked<2>();
  std::vector<std::array<std::string, 3>> exact_vertices;
  for (py::ssize_t i = 0; i < nv; ++i) {
    auto const& p = r.m.vertices[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k) v(i, k) = p[static_cast<std::size_t>(k)].template convert_to<double>();
    exact_vertices.push_back({genbsp_tool::exact_text(p.x()), genbsp_tool::exact_text(p.y()), genbsp_tool::exact_text(p.z())});
  }
  py::dict d;
  d["vertices"] = vertices;
  d["exact_vertices"] = exact_vertices;
  d["faces"] = r.m.faces;
  d["volume"] = r.volume;
  d["closed"] = r.closed;
  return d;
}

} // namespace

PYBIND11_MODULE(_genbsp, mod) {
  mod.doc() = "The compiled core of genbsp (use the package genbsp, not this module).";
  mod.attr("version") = genbsp_tool::version();

  py::class_<scene>(mod, "Scene")
      .def_static("from_file", &scene_from_file, py::arg("path"))
      .def_static("from_text", &scene_from_text, py::arg("vertices"), py::arg("faces"), py::arg("colours") = std::vector<face_colour>{},
                  py::arg("name") = std::nullopt)
      .def_static("from_doubles", &scene_from_doubles, py::arg("vertices"), py::arg("faces"))
      .def_property_readonly("name", [](scene const& s) { return s.data->path; })
      .def_property_readonly("faces", [](scene const& s) { return s.data->scene.faces.size(); })
      .def_property_readonly("polygons", [](scene const& s) { return s.data->prepared.polygons.size(); })
      .def("exact_vertices",
           [](scene const& s) {
             std::vector<std::array<std::string, 3>> out;
             for (auto const& p : s.data->scene.vertices)
               out.push_back({genbsp_tool::exact_text(p.x()), genbsp_tool::exact_text(p.y()), genbsp_tool::exact_text(p.z())});
             return out;
           })
      .def("face_colours",
           [](scene const& s) {
             std::vector<face_colour> out;
             for (auto const& f : s.data->scene.faces)
               out.push_back(f.colour ? face_colour(std::array<double, 3>{f.colour->r, f.colour->g, f.colour->b}) : std::nullopt);
             return out;
           })
      .def("face_indices",
           [](scene const& s) {
             std::vector<std::vector<std::uint32_t>> out;
             for (auto const& f : s.data->scene.faces) out.push_back(f.vertices);
             return out;
           })
      .def("visibility_map", &build_map, py::arg("eye"), py::arg("exact"), py::arg("cull_backfaces"), py::arg("simplify"));

  py::class_<visibility_map>(mod, "VisibilityMap")
      .def("locate", &locate, py::arg("directions"))
      .def("arrays", &map_arrays)
      .def("to_json", [](visibility_map const& m) { return m.visit([&](auto const& vm) { return genbsp_tool::map_json_text(vm, m.eye, m.scene); }); })
      .def("faces_of",
           [](visibility_map const& m, std::int64_t polygon) {
             return m.visit([&](auto const& vm) { return svm::faces_of(vm.map, polygon); });
           })
      .def("neighbours", [](visibility_map const& m, svm::index f) {
        return m.visit([&](auto const& vm) {
          if (f >= vm.map.faces().size()) throw py::index_error("face " + std::to_string(f) + " out of range");
          return svm::adjacent_faces(vm.map, f);
        });
      })
      .def("visible_polygons", [](visibility_map const& m) { return m.visit([](auto const& vm) { return svm::visible_polygons(vm.map); }); })
      .def_property_readonly("eye", [](visibility_map const& m) { return m.eye_text; })
      .def_property_readonly("exact", [](visibility_map const& m) { return m.exact; })
      .def_property_readonly("cull_backfaces", [](visibility_map const& m) { return m.cull; })
      .def_property_readonly("simplify", [](visibility_map const& m) { return m.simplify; })
      .def_property_readonly("scene_name", [](visibility_map const& m) { return m.scene->path; })
      .def("stats", [](visibility_map const& m) {
        return m.visit([](auto const& vm) {
          auto const& s = vm.stats;
          py::dict d;
          d["polygons"] = s.input_polygons, d["fragments"] = s.fragments, d["hidden_pieces"] = s.hidden_pieces;
          d["visible_pieces"] = s.visible_pieces, d["filter_fallbacks"] = s.filter_fallbacks, d["seconds"] = s.seconds;
          d["vertices"] = s.simplified.vertices, d["edges"] = s.simplified.edges, d["faces"] = s.simplified.faces;
          return d;
        });
      });

  mod.def("run", &run_command, py::arg("args"), py::arg("scene") = std::nullopt);
  mod.def("batch", &run_batch, py::arg("scene"), py::arg("jobs_json"), py::arg("base"), py::arg("workers"), py::arg("shard"), py::arg("shards"),
          py::arg("progress"));
  mod.def("boolean2d", &boolean2d, py::arg("a"), py::arg("b"), py::arg("op"), py::arg("fill_rule") = std::nullopt);
  mod.def("boolean_s2", &boolean_s2, py::arg("a"), py::arg("b"), py::arg("op"));
  mod.def("csg", &csg, py::arg("a"), py::arg("b"), py::arg("op"));
}
