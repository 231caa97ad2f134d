// 2D visibility polygons (svm::wall_index) against CGAL's Visibility_2 with
// exact constructions (Epeck), on the same inputs and query points:
//   rooms   a random star-shaped room of n/2 edges with n/8 square holes
//           (clockwise, on a jittered grid), integer coordinates;
//   maze    a K×K grid of unit cells whose inner walls are kept with
//           probability 1/2, each wall a segment between grid points, in a box.
//
// Times, each the median over the queries:
//   genbsp       wall_index built once (preprocessing, reported apart), then view(eye) per query;
//   cgal_tev     Triangular_expansion_visibility_2: its constructor (the
//                triangulation: preprocessing, reported apart), then compute_visibility per query;
//   cgal_rsv     Rotational_sweep_visibility_2: compute_visibility per query.
// The arrangement that both CGAL classes take is built once and not timed;
// CGAL's point location of the query's face is not timed either.
//
// The exact areas of the three answers are compared at every query: a
// mismatch is reported and makes the program exit with status 1.
//
//   bench_visibility2d [--sizes 100,1000,10000,100000] [--queries 10] [--repeat 1] [--json OUT.json]
//
// --repeat R runs each of genbsp's queries R times (the time is their
// median), so that a profile of the program is mostly genbsp's queries.
#include <geometry/gmp_pool.hpp>
#include "common.hpp"

#include <svm/visibility2d.hpp>

#include <CGAL/Arr_naive_point_location.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Rotational_sweep_visibility_2.h>
#include <CGAL/Triangular_expansion_visibility_2.h>
#include <CGAL/version.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Traits = CGAL::Arr_segment_traits_2<K>;
using Arrangement = CGAL::Arrangement_2<Traits>;
using Q = geometry::rational;

struct ipt {
  long x, y;
  bool operator==(ipt const&) const = default;
};

struct instance {
  std::string family;
  std::vector<std::vector<ipt>> rings; ///< the room counter-clockwise, holes clockwise
  std::vector<std::array<ipt, 2>> walls; ///< free segments (maze)
  std::vector<ipt> queries;              ///< in free space, off every wall
  std::size_t edges() const {
    std::size_t n = walls.size();
    for (auto const& r : rings) n += r.size();
    return n;
  }
};

std::vector<ipt> square(long x, long y, long s) { return {{x, y}, {x, y + s}, {x + s, y + s}, {x + s, y}}; } // clockwise

instance rooms(std::size_t n, std::mt19937_64& rng) {
  instance in{"rooms", {}, {}, {}};
  std::size_t k = std::max<std::size_t>(n / 2, 8), holes = n / 8;
  long const R = 1000000;
  std::uniform_int_distribution<long> jitter(0, 1000);
  std::vector<ipt> room;
  for (std::size_t i = 0; i < k; ++i) {
    double a = 2 * 3.141592653589793 * static_cast<double>(i) / static_cast<double>(k);
    double r = R * (0.92 + 0.08 * static_cast<double>(jitter(rng)) / 1000.0);
    room.push_back({std::lround(r * std::cos(a)), std::lround(r * std::sin(a))});
  }
  in.rings.push_back(room);
  // Holes on a grid inside the disc of radius 0.6 R, one per cell, jittered inside it.
  long g = static_cast<long>(std::ceil(std::sqrt(static_cast<double>(holes) * 4 / 3.14159))) + 1;
  long cell = (12 * R / 10) / std::max<long>(g, 1);
  std::vector<std::pair<long, long>> cells;
  for (long i = 0; i < g; ++i)
    for (long j = 0; j < g; ++j) {
      long x = -6 * R / 10 + i * cell, y = -6 * R / 10 + j * cell;
      double cx = static_cast<double>(x + cell / 2), cy = static_cast<double>(y + cell / 2);
      if (std::hypot(cx, cy) < 0.6 * R) cells.push_back({x, y});
    }
  std::shuffle(cells.begin(), cells.end(), rng);
  std::uniform_int_distribution<long> off(cell / 10, cell / 4);
  for (std::size_t h = 0; h < holes && h < cells.size(); ++h) {
    auto [x, y] = cells[h];
    in.rings.push_back(square(x + off(rng), y + off(rng), cell / 2));
  }
  // Queries: corners of cells that hold no hole (free, off every wall).
  for (std::size_t h = holes; h < cells.size() && in.queries.size() < 64; ++h) in.queries.push_back({cells[h].first + 1, cells[h].second + 3});
  for (long i = 0; in.queries.size() < 64; ++i) in.queries.push_back({-(i + 1) * 7 - 3, 9 * R / 10 - 11}); // near the room's top
  return in;
}

instance maze(std::size_t n, std::mt19937_64& rng) {
  // About 2K² inner walls kept half: n ≈ K² + 4K.
  long k = std::max<long>(2, static_cast<long>(std::sqrt(static_cast<double>(n))));
  instance in{"maze", {}, {}, {}};
  long const u = 10;
  std::bernoulli_distribution keep(0.5);
  for (long i = 0; i < k; ++i) {
    in.walls.push_back({ipt{i * u, 0}, ipt{(i + 1) * u, 0}});
    in.walls.push_back({ipt{i * u, k * u}, ipt{(i + 1) * u, k * u}});
    in.walls.push_back({ipt{0, i * u}, ipt{0, (i + 1) * u}});
    in.walls.push_back({ipt{k * u, i * u}, ipt{k * u, (i + 1) * u}});
  }
  for (long i = 1; i < k; ++i)
    for (long j = 0; j < k; ++j) {
      if (keep(rng)) in.walls.push_back({ipt{i * u, j * u}, ipt{i * u, (j + 1) * u}});
      if (keep(rng)) in.walls.push_back({ipt{j * u, i * u}, ipt{(j + 1) * u, i * u}});
    }
  std::uniform_int_distribution<long> c(0, k - 1);
  for (int q = 0; q < 64; ++q) in.queries.push_back({c(rng) * u + 3, c(rng) * u + 7});
  return in;
}

Arrangement arrangement_of(instance const& in) {
  std::vector<K::Segment_2> segs;
  auto p = [](ipt a) { return K::Point_2(a.x, a.y); };
  for (auto const& r : in.rings)
    for (std::size_t i = 0; i < r.size(); ++i) segs.emplace_back(p(r[i]), p(r[(i + 1) % r.size()]));
  for (auto const& w : in.walls) segs.emplace_back(p(w[0]), p(w[1]));
  Arrangement a;
  CGAL::insert_non_intersecting_curves(a, segs.begin(), segs.end());
  return a;
}

svm::wall_scene<Q> scene_of(instance const& in) {
  svm::wall_scene<Q> s;
  auto p = [](ipt a) { return geometry::e2::point<Q>(Q(a.x), Q(a.y)); };
  for (auto const& r : in.rings) {
    s.rings.emplace_back();
    for (auto q : r) s.rings.back().push_back(p(q));
  }
  for (auto const& w : in.walls) s.segments.push_back({p(w[0]), p(w[1])});
  return s;
}

/// The exact area of the face's outer boundary (the visibility region).
Q area_of(Arrangement::Face_handle f) {
  K::FT twice(0);
  auto e = f->outer_ccb(), e0 = e;
  do {
    auto const &a = e->source()->point(), &b = e->target()->point();
    twice += a.x() * b.y() - a.y() * b.x();
  } while (++e != e0);
  std::ostringstream s;
  s << CGAL::exact(twice);
  return Q(s.str()) / 2;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

double since(std::chrono::steady_clock::time_point t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); }

} // namespace

int main(int argc, char** argv) {
  geometry::use_gmp_pool(); // as the genbsp tool runs
  std::vector<std::size_t> sizes{100, 1000, 10000, 100000};
  std::size_t queries = 10, repeat = 1;
  std::string json_out;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--sizes" && i + 1 < argc) {
      sizes.clear();
      std::stringstream ss(argv[++i]);
      for (std::string t; std::getline(ss, t, ',');) sizes.push_back(std::stoul(t));
    } else if (a == "--queries" && i + 1 < argc) {
      queries = std::stoul(argv[++i]);
    } else if (a == "--repeat" && i + 1 < argc) {
      repeat = std::max<std::size_t>(1, std::stoul(argv[++i]));
    } else if (a == "--json" && i + 1 < argc) {
      json_out = argv[++i];
    } else {
      std::cerr << "usage: bench_visibility2d [--sizes N,N,…] [--queries Q] [--repeat R] [--json OUT.json]\n";
      return 2;
    }
  }
  std::mt19937_64 rng(20261202);
  bool mismatch = false;
  std::ostringstream rows;
  std::printf("| family | edges | genbsp pre (s) | genbsp query (ms) | TEV pre (s) | TEV query (ms) | RSV query (ms) | query ratio to the faster CGAL | areas |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---|\n");
  for (std::string family : {"rooms", "maze"})
    for (std::size_t n : sizes) {
      instance in = family == "rooms" ? rooms(n, rng) : maze(n, rng);
      std::size_t nq = std::min(queries, in.queries.size());
      auto t = std::chrono::steady_clock::now();
      svm::wall_index<Q> index(scene_of(in));
      double ours_pre = since(t);
      Arrangement env = arrangement_of(in);
      CGAL::Arr_naive_point_location<Arrangement> pl(env);
      t = std::chrono::steady_clock::now();
      CGAL::Triangular_expansion_visibility_2<Arrangement> tev(env);
      // Its triangulation is built by the first query: one off the clock's queries.
      {
        auto obj = pl.locate(K::Point_2(in.queries[0].x, in.queries[0].y));
        auto const* face = boost::get<Arrangement::Face_const_handle>(&obj);
        Arrangement out;
        if (face) tev.compute_visibility(K::Point_2(in.queries[0].x, in.queries[0].y), *face, out);
      }
      double tev_pre = since(t);
      CGAL::Rotational_sweep_visibility_2<Arrangement> rsv(env);
      std::vector<double> ours, tevq, rsvq;
      std::size_t equal = 0;
      for (std::size_t k = 0; k < nq; ++k) {
        ipt q = in.queries[k];
        K::Point_2 p(q.x, q.y);
        auto obj = pl.locate(p);
        auto const* face = boost::get<Arrangement::Face_const_handle>(&obj);
        if (!face) continue;
        geometry::e2::point<Q> eye(Q(q.x), Q(q.y));
        std::vector<double> runs;
        for (std::size_t r = 1; r < repeat; ++r) {
          t = std::chrono::steady_clock::now();
          auto again = index.view(eye);
          runs.push_back(since(t));
        }
        t = std::chrono::steady_clock::now();
        auto region = index.view(eye);
        runs.push_back(since(t));
        ours.push_back(median(runs));
        Arrangement a1, a2;
        t = std::chrono::steady_clock::now();
        auto f1 = tev.compute_visibility(p, *face, a1);
        tevq.push_back(since(t));
        t = std::chrono::steady_clock::now();
        auto f2 = rsv.compute_visibility(p, *face, a2);
        rsvq.push_back(since(t));
        auto mine = svm::area(region, index.scene());
        Q x1 = area_of(f1), x2 = area_of(f2);
        if (mine && *mine == x1 && x1 == x2) {
          ++equal;
        } else {
          mismatch = true;
          std::cerr << family << " n=" << n << " query " << q.x << "," << q.y << ": areas differ: genbsp "
                    << (mine ? mine->str() : "unbounded") << ", TEV " << x1.str() << ", RSV " << x2.str() << "\n";
        }
      }
      double o = median(ours), a = median(tevq), b = median(rsvq);
      std::printf("| %s | %zu | %.3f | %.3f | %.3f | %.3f | %.3f | %.2f | %zu/%zu equal |\n", family.c_str(), in.edges(), ours_pre,
                  o * 1e3, tev_pre, a * 1e3, b * 1e3, o / std::min(a, b), equal, ours.size());
      std::fflush(stdout);
      if (rows.tellp() > 0) rows << ",\n";
      rows << "  {\"family\": " << bench::json_string(family) << ", \"edges\": " << in.edges() << ", \"queries\": " << ours.size()
           << ", \"genbsp_preprocessing_s\": " << ours_pre << ", \"genbsp_query_s\": " << o << ", \"tev_preprocessing_s\": " << tev_pre
           << ", \"tev_query_s\": " << a << ", \"rsv_query_s\": " << b << ", \"equal_areas\": " << equal << "}";
    }
  if (!json_out.empty()) {
    std::ofstream f(json_out);
    f << "{\"compiler\": " << bench::json_string(bench::compiler()) << ", \"cgal\": " << bench::json_string(CGAL_VERSION_STR)
      << ", \"results\": [\n"
      << rows.str() << "\n]}\n";
  }
  return mismatch ? 1 : 0;
}
