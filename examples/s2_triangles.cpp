// S2: two spherical triangles, their union and intersection, and an SVG of the
// union written next to the binary (s2_triangles.svg).  Vertices are exact
// directions; areas are solid angles, in double, checked to 1e-12.
#include <bsp/bsp.hpp>
#include <bsp/print.hpp>
#include <geometry/s2.hpp>
#include <geometry/s2/svg.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

using namespace geometry;
using Q = rational;
using K = s2::exact_kernel;
using D = s2::point<Q>;

namespace {
D dir(int x, int y, int z) { return D(std::array<Q, 3>{Q(x), Q(y), Q(z)}); }
/// The boundary of a triangle counter-clockwise seen from outside the sphere:
/// each edge reversed, so that the triangle is on the negative side of every arc.
std::vector<s2::sub_hyperplane<Q>> boundary_of(std::vector<D> const& v) {
  std::vector<s2::sub_hyperplane<Q>> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back(s2::arc(v[(i + 1) % v.size()], v[i]));
  return out;
}
/// A node's great circle as the open hemisphere of its positive child.
std::string equation(s2::hyperplane<Q> const& h) {
  std::ostringstream s;
  s << "(" << h.n[0] << ", " << h.n[1] << ", " << h.n[2] << ") . p > 0";
  return s.str();
}
char const* in_out(bool in) { return in ? "in" : "out"; }
} // namespace

int main(int, char** argv) {
  constexpr double pi = std::numbers::pi;
  // A: the octant x, y, z ≥ 0.  B: the same octant turned by 45° about z.
  auto A = bsp::build_point_set<K>(boundary_of({dir(1, 0, 0), dir(0, 1, 0), dir(0, 0, 1)}));
  auto B = bsp::build_point_set<K>(boundary_of({dir(1, 1, 0), dir(-1, 1, 0), dir(0, 0, 1)}));
  auto U = bsp::set_union(A, B), I = bsp::set_intersection(A, B);

  // By hand: both are lunes cut to the upper hemisphere, A from longitude 0° to
  // 90° and B from 45° to 135°.  Such a lune of angle t has area t (the whole
  // upper hemisphere: t = 2π, area 2π).  So |A ∪ B| = 135° = 3π/4, |A ∩ B| = 45° = π/4.
  double u = bsp::measure(U, true), i = bsp::measure(I, true);
  std::cout.precision(17);
  std::cout << "|A u B| = " << u << " (3 pi/4), |A n B| = " << i << " (pi/4)\n";
  if (std::abs(u - 3 * pi / 4) > 1e-12 || std::abs(i - pi / 4) > 1e-12) {
    std::cerr << "s2_triangles: wrong area, expected 3 pi/4 and pi/4\n";
    return 1;
  }

  std::cout << "tree of A u B:\n";
  bsp::print(std::cout, U, equation, in_out);

  // The picture goes to a temporary name first, so that a viewer never reads half of it.
  std::error_code ec;
  std::filesystem::path svg = std::filesystem::read_symlink("/proc/self/exe", ec); // the binary, however started
  if (ec) svg = argv[0];
  svg += ".svg";
  auto tmp = svg;
  tmp += ".tmp";
  {
    std::ofstream out(tmp);
    s2::write_svg<Q, bool>(out, U, [](bool in) { return std::string(in ? "teal" : "white"); });
    if (!out.flush()) {
      std::cerr << "s2_triangles: cannot write " << tmp << '\n';
      return 1;
    }
  }
  std::filesystem::rename(tmp, svg);
  std::cout << "wrote " << svg.string() << '\n';
  return 0;
}
