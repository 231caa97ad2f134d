// Other libraries' 2D Boolean test cases with exact expected areas, read at
// test time from the shared corpus folder (GENBSP_CORPUS_DIR/boolean2d):
// Clipper2's polygon tests (paths under a fill rule) and CGAL's
// Boolean_set_operations_2 data (polygons with holes, possibly unbounded).
// Exit status 77 (skipped) when the folder is absent.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "validity.hpp"

#include <boolean/polygons.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

using boolean::ring;
using boolean::set_op;
using geometry::rational;
using json = nlohmann::json;

namespace {

std::filesystem::path corpus() { return std::filesystem::path(GENBSP_CORPUS_DIR) / "boolean2d"; }

json load(char const* name) {
  std::ifstream in(corpus() / name);
  return json::parse(in);
}

rational number(json const& v) {
  if (v.is_string()) return geometry::parse_number<rational>(v.get<std::string>());
  if (v.is_number_integer()) return rational(v.get<long long>());
  throw std::runtime_error("corpus: a coordinate is neither an integer nor an exact string");
}

ring read_ring(json const& r) {
  ring out;
  for (auto const& p : r) out.emplace_back(number(p[0]), number(p[1]));
  return out;
}

std::vector<ring> read_group(json const& groups) {
  std::vector<ring> out;
  for (auto const& g : groups)
    for (auto const& r : g) out.push_back(read_ring(r));
  return out;
}

boolean::fill_rule rule(std::string const& s) {
  if (s == "evenodd") return boolean::fill_rule::evenodd;
  if (s == "nonzero") return boolean::fill_rule::nonzero;
  if (s == "positive") return boolean::fill_rule::positive;
  if (s == "negative") return boolean::fill_rule::negative;
  throw std::runtime_error("corpus: unknown fill rule " + s);
}

set_op operation(std::string const& s) {
  if (s == "union") return set_op::union_;
  if (s == "intersection") return set_op::intersection;
  if (s == "difference") return set_op::difference;
  if (s == "xor") return set_op::symmetric_difference;
  throw std::runtime_error("corpus: unknown operation " + s);
}

/// A CGAL operand: its outer ring's interior minus its holes, or, with no
/// outer ring, the plane minus its holes.
boolean::region2 cgal_operand(json const& p) {
  std::vector<ring> holes;
  for (auto const& h : p["holes"]) holes.push_back(read_ring(h));
  if (p["outer"].empty()) {
    boolean::multipolygon m;
    for (auto& h : holes) m.push_back({std::move(h), {}});
    return bsp::complement(boolean::region(m));
  }
  return boolean::region(boolean::multipolygon{{read_ring(p["outer"]), holes}});
}

void check_valid_output(boolean::region2 const& r) {
  if (!boolean::area(r)) return; // unbounded: no rings to write
  auto m = boolean::polygons(r);
  CHECK(test::validity_problem(m) == "");
  CHECK(boolean::area(m) == *boolean::area(r));
}

} // namespace

TEST_CASE("Clipper2's polygon tests: exact areas under every fill rule", "[boolean][corpus]") {
  auto data = load("clipper2.json");
  std::size_t cases = 0;
  for (auto const& c : data["cases"]) {
    INFO(c["id"].get<std::string>());
    auto fr = rule(c["fill_rule"]);
    auto subject = boolean::operand_of(read_group(c["subject_groups"]), fr);
    auto clip = boolean::operand_of(read_group(c["clip_groups"]), fr);
    auto result = boolean::apply(operation(c["op"]), subject.tree, clip.tree);
    auto a = boolean::area(result);
    REQUIRE(a);
    auto expected = geometry::parse_number<rational>(c["exact_area"].get<std::string>());
    CHECK(*a == expected);
    check_valid_output(result);
    // The fast path, as `genbsp bool` takes it.
    auto fast = boolean::combine(operation(c["op"]), subject, clip);
    CHECK(boolean::area(fast) == expected);
    CHECK(test::validity_problem(fast) == "");
    ++cases;
  }
  CHECK(cases == data["cases"].size());
  std::printf("clipper2.json: %zu cases\n", cases);
}

TEST_CASE("CGAL's Boolean_set_operations_2 data: exact areas of every bounded result", "[boolean][corpus]") {
  auto data = load("cgal_bso2.json");
  std::size_t checks = 0;
  for (auto const& c : data["cases"]) {
    INFO(c["id"].get<std::string>());
    auto p1 = cgal_operand(c["p1"]), p2 = cgal_operand(c["p2"]);
    for (auto const& a : c["area_checks"]) {
      INFO(a["result"].get<std::string>());
      bool first = a["subject"] == "p1";
      auto result = boolean::apply(operation(a["op"]), first ? p1 : p2, first ? p2 : p1);
      auto area = boolean::area(result);
      if (a["exact_area"] == "unbounded") {
        CHECK(!area);
      } else {
        REQUIRE(area);
        CHECK(*area == geometry::parse_number<rational>(a["exact_area"].get<std::string>()));
      }
      check_valid_output(result);
      ++checks;
    }
  }
  CHECK(checks > 0);
  std::printf("cgal_bso2.json: %zu area checks\n", checks);
}

int main(int argc, char** argv) {
  if (!std::filesystem::is_directory(corpus())) {
    std::printf("skipped: no corpus at %s\n", corpus().string().c_str());
    return 77;
  }
  return Catch::Session().run(argc, argv);
}
