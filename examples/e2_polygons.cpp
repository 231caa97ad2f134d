// E2: a square minus a triangle that overlaps one of its sides, with exact
// areas, the tree printed and an SVG picture of the cells written next to the
// binary (e2_polygons.svg).
#include <bsp/bsp.hpp>
#include <bsp/print.hpp>
#include <geometry/e2.hpp>
#include <geometry/e2/svg.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace geometry;
using Q = rational;
using K = e2::exact_kernel;
using P = e2::point<Q>;

namespace {
/// The boundary of a counter-clockwise ring: each edge reversed, so that the
/// polygon is on the negative (right-hand) side of every piece.
std::vector<e2::sub_hyperplane<Q>> boundary_of(std::vector<P> const& ring) {
  std::vector<e2::sub_hyperplane<Q>> out;
  for (std::size_t i = 0; i < ring.size(); ++i) out.push_back(e2::segment(ring[(i + 1) % ring.size()], ring[i]));
  return out;
}
/// A node's line as the inequality that holds in its positive child.
std::string equation(e2::hyperplane<Q> const& h) {
  std::ostringstream s;
  s << h.n[0] << "x + " << h.n[1] << "y + " << h.n[2] << " > 0";
  return s.str();
}
char const* in_out(bool in) { return in ? "in" : "out"; }
} // namespace

int main(int, char** argv) {
  auto A = bsp::build_point_set<K>(boundary_of({P(0, 0), P(4, 0), P(4, 4), P(0, 4)}));
  auto B = bsp::build_point_set<K>(boundary_of({P(2, -1), P(5, 2), P(2, 5)}));
  auto D = bsp::set_difference(A, B);
  auto U = bsp::set_union(A, B);

  // By hand: |A| = 16, |B| = 6·3/2 = 9.  A ∩ B is the rectangle [2, 3] × [0, 4]
  // (area 4) and, for x in [3, 4], the strip between y = x − 3 and y = 7 − x
  // (heights 4 and 2, area 3): 7.  So |A \ B| = 16 − 7 = 9, |A ∪ B| = 16 + 9 − 7 = 18.
  auto d = bsp::measure(D, true), u = bsp::measure(U, true); // an empty optional: unbounded
  std::cout << "|A \\ B| = " << (d ? d->str() : "unbounded") << ", |A u B| = " << (u ? u->str() : "unbounded") << '\n';
  if (!d || *d != 9 || !u || *u != 18) {
    std::cerr << "e2_polygons: wrong area, expected 9 and 18\n";
    return 1;
  }

  // A's four edges come first (merging keeps A's structure), then B's where they cut A.
  std::cout << "tree of A \\ B:\n";
  bsp::print(std::cout, D, equation, in_out);

  // The picture goes to a temporary name first, so that a viewer never reads half of it.
  std::error_code ec;
  std::filesystem::path svg = std::filesystem::read_symlink("/proc/self/exe", ec); // the binary, however started
  if (ec) svg = argv[0];
  svg += ".svg";
  auto tmp = svg;
  tmp += ".tmp";
  {
    std::ofstream out(tmp);
    e2::write_svg<Q, bool>(out, D, {-2, -2, 7, 7, 450}, [](bool in) { return std::string(in ? "orange" : "white"); });
    if (!out.flush()) {
      std::cerr << "e2_polygons: cannot write " << tmp << '\n';
      return 1;
    }
  }
  std::filesystem::rename(tmp, svg);
  std::cout << "wrote " << svg.string() << '\n';
  return 0;
}
