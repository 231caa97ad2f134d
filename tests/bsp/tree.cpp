// The tree itself: arenas, statistics, copies, the text printer and the SVG pictures.
#include "../support.hpp"

#include <bsp/bsp.hpp>
#include <bsp/print.hpp>
#include <catch2/catch.hpp>
#include <geometry/e2/svg.hpp>
#include <geometry/geometry.hpp>
#include <geometry/s2/svg.hpp>

#include <sstream>

using namespace geometry;
using test::Q;

namespace bsp_tree_tests {

namespace {
using K = e2::exact_kernel;
using P = e2::point<Q>;

std::vector<e2::sub_hyperplane<Q>> ring(std::vector<P> const& r) {
  std::vector<e2::sub_hyperplane<Q>> b;
  for (std::size_t i = 0; i < r.size(); ++i) b.push_back(e2::segment(r[(i + 1) % r.size()], r[i]));
  return b;
}

std::size_t count(std::string const& text, std::string const& what) {
  std::size_t n = 0;
  for (auto i = text.find(what); i != std::string::npos; i = text.find(what, i + 1)) ++n;
  return n;
}
} // namespace

TEST_CASE("a square's tree: statistics, copies, printing", "[bsp][tree]") {
  auto square = bsp::build_point_set<K>(ring({P(0, 0), P(1, 0), P(1, 1), P(0, 1)}));
  auto s = square.statistics();
  CHECK(s.interior_nodes == 4); // one node per edge, in input order
  CHECK(s.leaves == 5);
  CHECK(s.depth == 4);
  CHECK(s.bytes > 0);
  // A copy is independent of the original.
  auto copy = square;
  copy.leaf_data(copy.negative(copy.root())) = true;
  CHECK(square.leaf_data(square.negative(square.root())) != copy.leaf_data(copy.negative(copy.root())));
  auto moved = std::move(copy);
  CHECK(moved.statistics().leaves == 5);
  std::ostringstream out;
  bsp::print(out, square, [](auto const& h) { return h.n[0].str() + "x+" + h.n[1].str() + "y+" + h.n[2].str(); },
             [](bool in) { return in ? "in" : "out"; });
  auto text = out.str();
  CHECK(count(text, "\n") == 9);
  CHECK(count(text, "leaf in") == 1);
  CHECK(count(text, "leaf out") == 4);
  CHECK(text.rfind("  node 0x+-1y+0", 0) == 0); // the root: the first edge, outward normal −y
  // Reducing a tree whose labels are all equal leaves one leaf.
  auto everything = bsp::relabel(square, [](bool) { return true; });
  CHECK(everything.statistics().leaves == 1);
}

TEST_CASE("SVG pictures of E2 and S2 trees", "[bsp][svg]") {
  auto a = bsp::build_point_set<K>(ring({P(-5, -5), P(5, -5), P(5, 5), P(0, 0), P(-5, 5)}));
  auto b = bsp::build_point_set<K>(ring({P(-2, -8), P(8, -2), P(3, 3)}));
  auto u = bsp::set_union(a, b);
  std::ostringstream out;
  e2::write_svg<Q, bool>(out, u, {}, [](bool in) { return in ? std::string("orange") : std::string("white"); });
  auto svg = out.str();
  auto st = u.statistics();
  // Every cell meets the window [-10, 10]², so each is one polygon; every splitting line is drawn.
  CHECK(count(svg, "<polygon") == st.leaves);
  CHECK(count(svg, "<line") == st.interior_nodes);
  auto cells = bsp::cells(u);
  auto inside = static_cast<std::size_t>(std::count_if(cells.begin(), cells.end(), [&](auto const& c) { return u.leaf_data(c.leaf); }));
  CHECK(count(svg, "fill=\"orange\"") == inside);
  CHECK(count(svg, "fill=\"white\"") == cells.size() - inside);
  CHECK(svg.find("</svg>") != std::string::npos);

  using KS = s2::exact_kernel;
  using SP = s2::point<Q>;
  auto d = [](int x, int y, int z) { return SP(std::array<Q, 3>{Q(x), Q(y), Q(z)}); };
  std::vector<SP> tri{d(1, 0, 0), d(0, 1, 0), d(0, 0, 1)};
  std::vector<s2::sub_hyperplane<Q>> bs;
  for (std::size_t i = 0; i < 3; ++i) bs.push_back(s2::arc(tri[(i + 1) % 3], tri[i]));
  auto octant = bsp::build_point_set<KS>(bs);
  std::ostringstream sout;
  s2::write_svg<Q, bool>(sout, octant, [](bool in) { return in ? std::string("teal") : std::string("white"); });
  // The octant lies in the upper hemisphere only: one teal polygon.
  CHECK(count(sout.str(), "fill=\"teal\"") == 1);
  CHECK(count(sout.str(), "<circle") == 2);
}

} // namespace bsp_tree_tests
