// The generic tree on a geometry of the user's own (the archetype: points
// on the integer line), against genbsp::bsp alone: no Boost, no GMP.
#include "archetype.hpp"

#include <bsp/bsp.hpp>
#include <bsp/print.hpp>

#if defined(BOOST_VERSION) || defined(__GNU_MP_VERSION)
#error "include/bsp reached Boost or GMP"
#endif

int main() {
  using G = archetype::line;
  // [1, 5] ∪ [9, 13], as boundary points with outward normals, minus [3, 11].
  std::vector<G::sub_hyperplane> a{{{1, false}}, {{5, true}}, {{9, false}}, {{13, true}}};
  std::vector<G::sub_hyperplane> b{{{3, false}}, {{11, true}}};
  auto d = bsp::set_difference(bsp::build_point_set<G>(a), bsp::build_point_set<G>(b));
  bool ok = *bsp::measure(d, true) == 4 && bsp::classify(d, 2L) == true && bsp::classify(d, 4L) == false &&
            bsp::classify(d, 12L) == true;
  return ok ? 0 : 1;
}
