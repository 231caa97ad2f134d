// WKT and GeoJSON polygons: exact coordinates, every accepted form, errors
// naming the line, and writers that read back to the same doubles.
#include "../support.hpp"

#include <geometry/io/geojson.hpp>
#include <geometry/io/wkt.hpp>

#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>

using namespace geometry;
using test::Q;

namespace io_planar_tests {

namespace {

std::string error_of(auto&& f) {
  try {
    f();
  } catch (io::read_error const& e) {
    return e.what();
  }
  return "no error";
}

} // namespace

TEST_CASE("WKT: polygons, multipolygons and collections, exact", "[io][wkt]") {
  auto m = io::read_wkt("polygon ((0 0, 0.1 0, 0.1 1e-1, 0 0.1, 0 0), (0.02 0.02, 0.02 0.04, 0.04 0.04, 0.02 0.02))", "a.wkt");
  REQUIRE(m.size() == 1);
  CHECK(m[0].outer.size() == 4); // the closing position is dropped
  CHECK(m[0].outer[1].x() == Q(1, 10));
  CHECK(m[0].outer[2].y() == Q(1, 10));
  REQUIRE(m[0].holes.size() == 1);
  CHECK(m[0].holes[0][1].y() == Q(1, 25));
  auto c = io::read_wkt("GEOMETRYCOLLECTION (MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), EMPTY, ((5 5, 6 5, 6 6, 5 5))),\n"
                        "  POLYGON EMPTY, POLYGON ((-1 -1, -2 -1, -2 -2, -1 -1)))",
                        "c.wkt");
  CHECK(c.size() == 3);
  CHECK(io::read_wkt("MULTIPOLYGON EMPTY", "e.wkt").empty());
}

TEST_CASE("WKT: errors name the file and line", "[io][wkt]") {
  CHECK(error_of([] { io::read_wkt("POLYGON ((0 0, 1 0,\n1 1, 0 0)", "x.wkt"); }) == "x.wkt:2: expected ',' or ')', found the end");
  CHECK(error_of([] { io::read_wkt("POLYGON ((0 0, 1 0, 1 1, 0 1))", "x.wkt"); }).find("x.wkt:1: a ring is not closed") == 0);
  CHECK(error_of([] { io::read_wkt("\n\nPOLYGON ((0 0, 1 0, 0 0))", "x.wkt"); }).find("x.wkt:3: a ring needs at least 4") == 0);
  CHECK(error_of([] { io::read_wkt("POLYGON Z ((0 0 0, 1 0 0, 1 1 0, 0 0 0))", "x.wkt"); }).find("only planar geometries") != std::string::npos);
  CHECK(error_of([] { io::read_wkt("LINESTRING (0 0, 1 1)", "x.wkt"); }).find("expected POLYGON") != std::string::npos);
  CHECK(error_of([] { io::read_wkt("POLYGON ((0 0 1, 1 0 1, 1 1 1, 0 0 1))", "x.wkt"); }).find("more than two coordinates") != std::string::npos);
}

TEST_CASE("GeoJSON: every object kind, exact numbers, altitudes ignored", "[io][geojson]") {
  std::string text = R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"name": "a \"quoted\" name"}, "geometry":
      {"type": "Polygon", "coordinates": [[[0, 0], [0.1, 0, 7], [0.1, 0.1], [0, 0]]]}},
    {"type": "Feature", "properties": null, "geometry": null},
    {"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [1, 2]}},
    {"type": "Feature", "properties": {}, "geometry": {"type": "GeometryCollection", "geometries": [
      {"type": "MultiPolygon", "coordinates": [[[[5, 5], [6, 5], [6, 6], [5, 5]]], [[[7, 7], [8, 7], [8, 8], [7, 7]],
                                               [[7.1, 7.05], [7.2, 7.1], [7.9, 7.8], [7.1, 7.05]]]]}]}}]})";
  auto m = io::read_geojson(text, "f.geojson");
  REQUIRE(m.size() == 3);
  CHECK(m[0].outer[1].x() == Q(1, 10));
  CHECK(m[2].holes.size() == 1);
  CHECK(m[2].holes[0][0].y() == Q(141, 20));
}

TEST_CASE("GeoJSON: errors name the file and line", "[io][geojson]") {
  CHECK(error_of([] { io::read_geojson("{\"type\": \"Polygon\",\n \"coordinates\": [[[0, 0], [1, 0], [0, 0]]]}", "g.json"); })
            .find("g.json:2: a ring needs at least 4") == 0);
  CHECK(error_of([] { io::read_geojson("{\"type\": \"Polygon\",\n\n \"coordinates\": [[[0, 0], [1, 0], [1, x], [0, 0]]]}", "g.json"); })
            .find("g.json:3:") == 0);
  CHECK(error_of([] { io::read_geojson("{\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1, 0], [1, 1], [0, 0]]]", "g.json"); })
            .find("expected '}'") != std::string::npos);
  CHECK(error_of([] { io::read_geojson("{\"type\": \"LineString\", \"coordinates\": [[0, 0], [1, 1]]}", "g.json"); })
            .find("expected a Polygon") != std::string::npos);
  CHECK(error_of([] { io::read_geojson("{\"coordinates\": []}", "g.json"); }).find("no \"type\"") != std::string::npos);
}

TEST_CASE("Planar writers: WKT and GeoJSON read back to the nearest doubles", "[io][wkt][geojson]") {
  io::multipolygon m{{{io::point2(Q(0), Q(0)), io::point2(Q(1, 3), Q(0)), io::point2(Q(1, 3), Q(1, 10))},
                      {{io::point2(Q(1, 100), Q(1, 100)), io::point2(Q(1, 50), Q(1, 25)), io::point2(Q(1, 50), Q(1, 100))}}}};
  for (auto const& back : {io::read_wkt(io::to_wkt(m), "w"), io::read_geojson(io::to_geojson(m), "g")}) {
    REQUIRE(back.size() == 1);
    REQUIRE(back[0].outer.size() == 3);
    CHECK(back[0].outer[1].x().convert_to<double>() == Q(1, 3).convert_to<double>());
    CHECK(back[0].outer[2].y() == Q(1, 10)); // 0.1 prints as "0.1", read exactly
    CHECK(back[0].holes.size() == 1);
  }
  CHECK(io::to_wkt({}) == "MULTIPOLYGON EMPTY\n");
  CHECK(io::to_svg(m).find("<path") != std::string::npos);
}

TEST_CASE("Walls: polygons and line strings from WKT and GeoJSON files", "[io][wkt][geojson]") {
  auto dir = std::filesystem::temp_directory_path() / ("genbsp-walls-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto write = [&](char const* name, char const* text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  };
  auto w = io::read_walls(write("a.wkt", "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 0)),\n"
                                         "MULTILINESTRING ((1 1, 2 2, 3 1.5), EMPTY), LINESTRING (0 5, 0.1 5))"));
  REQUIRE(w.polygons.size() == 1);
  REQUIRE(w.lines.size() == 2);
  CHECK(w.lines[0].size() == 3);
  CHECK(w.lines[0][2].y() == Q(3, 2));
  CHECK(w.lines[1][1].x() == Q(1, 10));
  auto g = io::read_walls(write("b.geojson", "{\"type\": \"FeatureCollection\", \"features\": [\n"
                                             "{\"type\": \"Feature\", \"geometry\": {\"type\": \"LineString\", \"coordinates\": [[0, 0], [1, 1]]}},\n"
                                             "{\"type\": \"Feature\", \"geometry\": {\"type\": \"MultiLineString\", \"coordinates\": [[[2, 0], [2, 1], [3, 1]]]}},\n"
                                             "{\"type\": \"Feature\", \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}}]}"));
  CHECK(g.polygons.size() == 1);
  REQUIRE(g.lines.size() == 2);
  CHECK(g.lines[1].size() == 3);
  CHECK(error_of([&] { io::read_walls(write("c.wkt", "LINESTRING (0 0)")); }).find("c.wkt:1: a line string needs at least 2 positions") !=
        std::string::npos);
  CHECK(error_of([&] { io::read_walls(write("d.wkt", "POINT (0 0)")); }).find("expected POLYGON, MULTIPOLYGON, LINESTRING") !=
        std::string::npos);
  std::filesystem::remove_all(dir);
}

} // namespace io_planar_tests
