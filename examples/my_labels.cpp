// My own labels: a colour per cell instead of bool.  Two rectangles of E2 are
// painted red and blue, combined with bsp::merge and a paint-over operation,
// and the law A ∪ ∅ = A checked for it: merging with the empty (uncoloured)
// picture, on either side, keeps every sample point's colour and every colour's area.
#include <bsp/bsp.hpp>
#include <geometry/e2.hpp>

#include <iostream>
#include <optional>
#include <string>
#include <vector>

using namespace geometry;
using Q = rational;
using K = e2::exact_kernel;
using P = e2::point<Q>;

enum class colour { none, red, blue };
template <> inline constexpr bool bsp::enable_label<colour> = true;
static_assert(bsp::label<colour>);

namespace {
/// The boundary of the rectangle [x0, x1] × [y0, y1], the rectangle on the negative side of each edge.
std::vector<e2::sub_hyperplane<Q>> rectangle(int x0, int y0, int x1, int y1) {
  return {e2::segment(P(x1, y0), P(x0, y0)), e2::segment(P(x1, y1), P(x1, y0)), e2::segment(P(x0, y1), P(x1, y1)),
          e2::segment(P(x0, y0), P(x0, y1))};
}
/// Paint over: `top` where it has a colour, `below` elsewhere; `colour::none` is its identity on both sides.
colour paint(colour below, colour top) { return top == colour::none ? below : top; }
/// An area as text (an empty optional: unbounded).
std::string text(std::optional<Q> const& area) { return area ? area->str() : "unbounded"; }
} // namespace

int main() {
  auto red = bsp::build_point_set<K>(rectangle(0, 0, 4, 3), colour::red, colour::none);
  auto blue = bsp::build_point_set<K>(rectangle(2, 1, 6, 5), colour::blue, colour::none);
  auto picture = bsp::merge(red, blue, paint); // by hand: red 12 − 4 = 8, blue 16
  bsp::point_set<K, colour> empty(colour::none);
  auto right = bsp::merge(picture, empty, paint), left = bsp::merge(empty, picture, paint);
  auto area = [](bsp::point_set<K, colour> const& t, colour c) { return bsp::measure(t, c); };
  bool ok = area(picture, colour::red) == Q(8) && area(picture, colour::blue) == Q(16);
  for (colour c : {colour::none, colour::red, colour::blue})
    ok = ok && area(right, c) == area(picture, c) && area(left, c) == area(picture, c);
  for (int i = -2; i <= 14; ++i) // on a half-unit grid over [-1, 7]², boundaries included
    for (int j = -2; j <= 14; ++j) {
      P p(Q(i, 2), Q(j, 2));
      auto c = bsp::classify(picture, p);
      ok = ok && bsp::classify(right, p) == c && bsp::classify(left, p) == c;
    }
  std::cout << "red " << text(area(picture, colour::red)) << ", blue " << text(area(picture, colour::blue))
            << ", uncoloured " << text(area(picture, colour::none)) << "; merged with the empty picture: red "
            << text(area(right, colour::red)) << ", blue " << text(area(right, colour::blue)) << '\n';
  if (!ok) {
    std::cerr << "my_labels: a colour or an area differs from the hand check or after merging with the empty picture\n";
    return 1;
  }
  return 0;
}
