// Exact CSG (boolean::from_scene, combine) against CGAL on the same input:
// Polygon_mesh_processing's corefinement (exact predicates, inexact
// constructions: Epick) and Nef_polyhedron_3 (exact: Epeck).
//
// Input: two icospheres of level L (20·4^L triangles each), radius 1, the
// second moved by (5/16, 3/16, 1/8) of the radius.  Every vertex is rounded
// to a multiple of 2^-20, so that the doubles CGAL reads and the rationals
// genbsp reads are the same numbers.
//
// Each library's time is the whole job, from the two triangle lists to the
// result's mesh (the checks of the output after it are not timed):
//   genbsp      from_scene(A), from_scene(B) (which check each input:
//               closed, not self-intersecting, exact volume), then
//               combine (the boundaries classified against both trees, the
//               faces merged per plane, no T-junction);
//   corefine    two Surface_mesh built from the lists, then
//               corefine_and_compute_union / _intersection / _difference;
//   nef         two Surface_mesh<Epeck>, each made a Nef_polyhedron_3, the
//               operation, and the result converted back to a polygon mesh.
// Each library runs each case in a child process stopped after the limit;
// a case that does not finish is reported as such.  The median of the runs
// is reported, with the output's faces, vertices and volume (as a double).
#include <geometry/gmp_pool.hpp>
#include "common.hpp"

#include <boolean/polyhedra.hpp>
#include <geometry/io/scene.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/convert_nef_polyhedron_to_polygon_mesh.h>
#include <CGAL/version.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using clock_type = std::chrono::steady_clock;
double since(clock_type::time_point t0) { return std::chrono::duration<double>(clock_type::now() - t0).count(); }
using Q = geometry::rational;
namespace PMP = CGAL::Polygon_mesh_processing;

/// A triangle mesh in doubles that are exact multiples of 2^-20.
struct tri_mesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<std::uint32_t, 3>> faces;
};

/// An icosphere of `level` subdivisions, radius 1, centred at `c`.
tri_mesh icosphere(int level, std::array<double, 3> c) {
  double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3>> v{{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                       {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::uint32_t, 3>> f{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9},  {5, 11, 4},
                                              {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6},  {3, 6, 8},
                                              {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  auto unit = [](std::array<double, 3> p) {
    double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    return std::array<double, 3>{p[0] / n, p[1] / n, p[2] / n};
  };
  for (auto& p : v) p = unit(p);
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      auto [it, added] = mid.try_emplace(std::minmax(a, b), static_cast<std::uint32_t>(v.size()));
      if (added) v.push_back(unit({v[a][0] + v[b][0], v[a][1] + v[b][1], v[a][2] + v[b][2]}));
      return it->second;
    };
    std::vector<std::array<std::uint32_t, 3>> g;
    for (auto [a, b, d] : f) {
      auto ab = midpoint(a, b), bd = midpoint(b, d), da = midpoint(d, a);
      g.push_back({a, ab, da});
      g.push_back({b, bd, ab});
      g.push_back({d, da, bd});
      g.push_back({ab, bd, da});
    }
    f = std::move(g);
  }
  tri_mesh m;
  for (auto const& p : v) {
    std::array<double, 3> q;
    for (int k = 0; k < 3; ++k) q[k] = std::ldexp(std::round(std::ldexp(p[k] + c[k], 20)), -20);
    m.vertices.push_back(q);
  }
  m.faces = std::move(f);
  return m;
}

geometry::io::scene scene_of(tri_mesh const& m) {
  geometry::io::scene s;
  for (auto const& p : m.vertices) s.vertices.emplace_back(Q(p[0]), Q(p[1]), Q(p[2]));
  for (auto const& f : m.faces) s.faces.push_back({{f[0], f[1], f[2]}, std::nullopt, 0});
  return s;
}

template <class Mesh> Mesh surface_mesh_of(tri_mesh const& m) {
  using P = typename Mesh::Point;
  Mesh out;
  std::vector<typename Mesh::Vertex_index> idx;
  idx.reserve(m.vertices.size());
  for (auto const& p : m.vertices) idx.push_back(out.add_vertex(P(p[0], p[1], p[2])));
  for (auto const& f : m.faces) out.add_face(idx[f[0]], idx[f[1]], idx[f[2]]);
  return out;
}

enum class op_kind { union_, intersection, difference };
char const* name(op_kind o) { return o == op_kind::union_ ? "union" : o == op_kind::intersection ? "intersection" : "difference"; }

/// What one run of a library gives.
struct outcome {
  std::size_t faces = 0, vertices = 0;
  double volume = 0;
  bool closed = false;
};

outcome run_genbsp(op_kind o, tri_mesh const& a, tri_mesh const& b, double& seconds) {
  auto t0 = clock_type::now();
  auto A = boolean::from_scene(scene_of(a));
  auto B = boolean::from_scene(scene_of(b));
  auto op = o == op_kind::union_ ? boolean::csg_op::union_ : o == op_kind::intersection ? boolean::csg_op::intersection : boolean::csg_op::difference;
  auto m = boolean::combine(op, A, B);
  seconds = since(t0);
  return {m.faces.size(), m.vertices.size(), boolean::volume(m).convert_to<double>(), boolean::closed(m)};
}

outcome run_corefine(op_kind o, tri_mesh const& a, tri_mesh const& b, double& seconds) {
  using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
  auto t0 = clock_type::now();
  auto A = surface_mesh_of<Mesh>(a), B = surface_mesh_of<Mesh>(b);
  Mesh out;
  bool ok = o == op_kind::union_ ? PMP::corefine_and_compute_union(A, B, out)
            : o == op_kind::intersection ? PMP::corefine_and_compute_intersection(A, B, out)
                                         : PMP::corefine_and_compute_difference(A, B, out);
  seconds = since(t0);
  if (!ok) throw std::runtime_error("corefinement: the output is not a valid mesh");
  return {out.number_of_faces(), out.number_of_vertices(), CGAL::to_double(PMP::volume(out)), CGAL::is_closed(out)};
}

outcome run_nef(op_kind o, tri_mesh const& a, tri_mesh const& b, double& seconds) {
  using K = CGAL::Exact_predicates_exact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  using Nef = CGAL::Nef_polyhedron_3<K>;
  auto t0 = clock_type::now();
  auto A = surface_mesh_of<Mesh>(a), B = surface_mesh_of<Mesh>(b);
  Nef na(A), nb(B);
  Nef r = o == op_kind::union_ ? na + nb : o == op_kind::intersection ? na * nb : na - nb;
  Mesh out;
  CGAL::convert_nef_polyhedron_to_polygon_mesh(r, out);
  seconds = since(t0);
  outcome result{out.number_of_faces(), out.number_of_vertices(), 0, CGAL::is_closed(out)};
  PMP::triangulate_faces(out); // the volume wants triangles (not timed)
  result.volume = CGAL::to_double(PMP::volume(out));
  return result;
}

struct options {
  std::vector<int> levels{2, 3, 4, 5};
  std::vector<std::string> libraries{"genbsp", "corefine", "nef"};
  std::vector<op_kind> ops{op_kind::union_, op_kind::difference};
  double limit = 60;       ///< seconds a child may stay silent
  int min_runs = 3;        ///< runs per case at least (one when a run is long)
  double min_total = 0.5;  ///< short cases are repeated until their runs add up to this
  int max_runs = 15;
  std::string json_path;
};

struct measurement {
  std::string status = "not run";
  std::vector<double> runs;
  outcome out;
  double median() const {
    auto t = runs;
    std::sort(t.begin(), t.end());
    return t.empty() ? NAN : t[t.size() / 2];
  }
};

/// Runs `f` in a child process as often as the options ask, each run's time
/// and outcome sent back; stops the child when it stays silent longer than
/// the limit.
template <class F> measurement measure_in_child(options const& o, F f) {
  measurement m;
  auto end = bench::run_in_child(
      o.limit,
      [&](int fd) {
        double total = 0;
        for (int r = 0; r < o.max_runs; ++r) {
          double s = 0;
          outcome out = f(s);
          total += s;
          char line[200];
          std::snprintf(line, sizeof line, "run %.9g %zu %zu %.17g %d\n", s, out.faces, out.vertices, out.volume, out.closed ? 1 : 0);
          bench::write_all(fd, line);
          if (r + 1 >= o.min_runs && total >= o.min_total) break;
          if (s > o.limit / 4) break; // a long case: fewer runs
        }
      },
      [&](std::string const& kind, std::istringstream& in) {
        if (kind != "run") return;
        double s = 0;
        int closed = 0;
        in >> s >> m.out.faces >> m.out.vertices >> m.out.volume >> closed;
        m.out.closed = closed != 0;
        m.runs.push_back(s);
        std::fprintf(stderr, " %.3gs", s);
      });
  m.status = end.timed_out && !m.runs.empty() ? "ok" : end.status;
  return m;
}

std::vector<std::string> split_list(std::string const& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

[[noreturn]] void usage(int status) {
  std::fprintf(status ? stderr : stdout,
               "Usage: bench_csg [--levels L,...] [--libraries genbsp,corefine,nef] [--ops union,intersection,difference]\n"
               "                 [--limit SECONDS] [--json FILE]\n"
               "Exact CSG (genbsp) against CGAL's corefinement (Epick) and Nef_polyhedron_3 (Epeck) on\n"
               "pairs of icospheres of level L (20*4^L triangles each, the second moved by 5/16, 3/16, 1/8\n"
               "of the radius, vertices on a 2^-20 grid).  Each library's time is the whole job from two\n"
               "triangle lists to the result's mesh; median of at least 3 runs (or 0.5 s), one run for\n"
               "long cases; a case silent for longer than the limit (default 60 s) is not finished.\n"
               "  --levels LIST     icosphere levels (default 2,3,4,5)\n"
               "  --libraries LIST  which to run (default genbsp,corefine,nef)\n"
               "  --ops LIST        operations (default union,difference)\n"
               "  --json FILE       also write the results as JSON\n");
  std::exit(status);
}

options parse(int argc, char** argv) {
  options o;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "-h" || a == "--help") usage(0);
    if (i + 1 >= argc) usage(2);
    std::string v = argv[++i];
    try {
      if (a == "--levels") {
        o.levels.clear();
        for (auto const& x : split_list(v)) o.levels.push_back(std::stoi(x));
      } else if (a == "--libraries") {
        o.libraries = split_list(v);
        for (auto const& l : o.libraries)
          if (l != "genbsp" && l != "corefine" && l != "nef") usage(2);
      } else if (a == "--ops") {
        o.ops.clear();
        for (auto const& x : split_list(v)) {
          if (x == "union") o.ops.push_back(op_kind::union_);
          else if (x == "intersection") o.ops.push_back(op_kind::intersection);
          else if (x == "difference") o.ops.push_back(op_kind::difference);
          else usage(2);
        }
      } else if (a == "--limit") {
        o.limit = std::stod(v);
      } else if (a == "--json") {
        o.json_path = v;
      } else {
        usage(2);
      }
    } catch (std::logic_error const&) {
      usage(2);
    }
  }
  return o;
}

} // namespace

int main(int argc, char** argv) {
  geometry::use_gmp_pool(); // as the genbsp tool runs
  auto o = parse(argc, argv);
  std::string json = "{\"compiler\": " + bench::json_string(bench::compiler()) + ", \"optimised\": " + (bench::optimised() ? "true" : "false") +
                     ", \"cgal\": " + bench::json_string(CGAL_VERSION_STR) + ", \"cases\": [";
  std::printf("| Level | Faces (both) | Operation | Library | Median s | Runs | Output faces | Output vertices | Volume | Closed |\n");
  std::printf("|---:|---:|---|---|---:|---:|---:|---:|---:|---|\n");
  bool first = true;
  for (int level : o.levels) {
    auto a = icosphere(level, {0, 0, 0}), b = icosphere(level, {5.0 / 16, 3.0 / 16, 1.0 / 8});
    for (auto op : o.ops)
      for (auto const& lib : o.libraries) {
        std::fprintf(stderr, "level %d %s %s:", level, name(op), lib.c_str());
        auto m = measure_in_child(o, [&](double& s) {
          return lib == "genbsp" ? run_genbsp(op, a, b, s) : lib == "corefine" ? run_corefine(op, a, b, s) : run_nef(op, a, b, s);
        });
        std::fprintf(stderr, " %s\n", m.status.c_str());
        std::size_t faces = a.faces.size() + b.faces.size();
        if (m.runs.empty())
          std::printf("| %d | %zu | %s | %s | %s | 0 | | | | |\n", level, faces, name(op), lib.c_str(), m.status == "not finished" ? "> limit" : m.status.c_str());
        else
          std::printf("| %d | %zu | %s | %s | %.4g | %zu | %zu | %zu | %.12g | %s |\n", level, faces, name(op), lib.c_str(), m.median(), m.runs.size(),
                      m.out.faces, m.out.vertices, m.out.volume, m.out.closed ? "yes" : "no");
        std::fflush(stdout);
        char buf[400];
        std::snprintf(buf, sizeof buf,
                      "%s\n  {\"level\": %d, \"input_faces\": %zu, \"op\": \"%s\", \"library\": \"%s\", \"status\": %s, \"seconds\": %.9g, \"runs\": %zu, "
                      "\"faces\": %zu, \"vertices\": %zu, \"volume\": %.17g, \"closed\": %s}",
                      first ? "" : ",", level, faces, name(op), lib.c_str(), bench::json_string(m.status).c_str(), m.runs.empty() ? -1.0 : m.median(),
                      m.runs.size(), m.out.faces, m.out.vertices, m.out.volume, m.out.closed ? "true" : "false");
        json += buf;
        first = false;
      }
  }
  json += "\n]}\n";
  if (!o.json_path.empty()) {
    FILE* f = std::fopen(o.json_path.c_str(), "w");
    if (!f) {
      std::fprintf(stderr, "bench_csg: cannot write %s\n", o.json_path.c_str());
      return 2;
    }
    std::fputs(json.c_str(), f);
    std::fclose(f);
  }
  return 0;
}
