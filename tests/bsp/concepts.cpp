// The concepts, checked on every model and against types that must not model them.
#include "archetype.hpp"

#include <bsp/bsp.hpp>
#include <catch2/catch.hpp>
#include <geometry/geometry.hpp>

#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace {

// Every geometry, in both number types.
template <class FT> constexpr bool all_models() {
  return bsp::geometry<geometry::e1::kernel<FT>> && bsp::geometry<geometry::e2::kernel<FT>> &&
         bsp::geometry<geometry::e3::kernel<FT>> && bsp::geometry<geometry::s1::kernel<FT>> &&
         bsp::geometry<geometry::s2::kernel<FT>>;
}
static_assert(all_models<double>());
static_assert(all_models<geometry::rational>());
static_assert(bsp::geometry<archetype::line>);
static_assert(bsp::cell_space<archetype::line> && bsp::oriented_space<archetype::line>);

// The extension points: every geometry measures its cells; E2, E3 and S2
// also tell cheaply that a piece lies wholly on one side.
template <class FT> constexpr bool all_extensions() {
  using namespace geometry;
  return bsp::measured_space<e1::kernel<FT>> && bsp::measured_space<e2::kernel<FT>> &&
         bsp::measured_space<e3::kernel<FT>> && bsp::measured_space<s1::kernel<FT>> &&
         bsp::measured_space<s2::kernel<FT>> && bsp::whole_side_geometry<e2::kernel<FT>> &&
         bsp::whole_side_geometry<e3::kernel<FT>> && bsp::whole_side_geometry<s2::kernel<FT>> &&
         !bsp::whole_side_geometry<e1::kernel<FT>> && !bsp::whole_side_geometry<s1::kernel<FT>>;
}
static_assert(all_extensions<double>());
static_assert(all_extensions<geometry::rational>());
static_assert(bsp::measured_space<archetype::line> && !bsp::whole_side_geometry<archetype::line>);
static_assert(bsp::partial_measure<std::optional<long>> && !bsp::partial_measure<double>);
static_assert(bsp::measure_value<double> && !bsp::measure_value<std::string>);

// Splitting policies: the three that choose a piece, and `balanced`, which
// decides (a piece or a free cut) and does not choose.
using E3 = geometry::e3::exact_kernel;
using median_cut = bsp::balanced<geometry::e3::axis_median_cut<geometry::rational>>;
static_assert(bsp::choosing_policy<bsp::input_order, E3> && bsp::choosing_policy<bsp::random_order, E3> &&
              bsp::choosing_policy<bsp::least_splits, E3> && bsp::choosing_policy<bsp::random_order, archetype::line>);
static_assert(bsp::cutting_policy<median_cut, E3> && !bsp::choosing_policy<median_cut, E3>);
static_assert(bsp::splitting_policy<median_cut, E3> && bsp::splitting_policy<bsp::least_splits, E3> &&
              bsp::splitting_policy<median_cut, E3, bsp::fragment<E3>>);
static_assert(!bsp::cutting_policy<bsp::input_order, E3>);
namespace {
struct chooses_nothing { // `choose` of the wrong shape
  template <class G, class Item, class Piece> void choose(std::vector<Item> const&, Piece&&) {}
};
struct decides_optional { // `decide` returning a bare hyperplane, not a decision
  template <class G, class Item, class Piece> std::optional<typename G::hyperplane> decide(std::vector<Item> const&, Piece&&) {
    return std::nullopt;
  }
};
} // namespace
static_assert(!bsp::splitting_policy<chooses_nothing, E3> && !bsp::splitting_policy<decides_optional, E3>);
static_assert(!bsp::splitting_policy<int, E3>);
static_assert(std::is_same_v<bsp::measure_t<geometry::e2::exact_kernel>, std::optional<geometry::rational>>);

// Payloads: semiregular types only.
struct no_default {
  explicit no_default(int) {}
};
static_assert(bsp::tree_payload<bsp::none> && bsp::tree_payload<bool> &&
              bsp::tree_payload<bsp::fragment_list<archetype::line, int>>);
static_assert(!bsp::tree_payload<std::unique_ptr<int>> && !bsp::tree_payload<no_default>);

// A look-alike that has every member but did not opt in.
struct look_alike : archetype::line {};
static_assert(!bsp::geometry<look_alike>);
static_assert(bsp::cell_space<look_alike>); // the structural parts hold …

// … and types missing a part.
struct no_split {
  using point = long;
  using hyperplane = archetype::line::hyperplane;
  static int side(hyperplane const&, point) { return 1; }
  static hyperplane opposite(hyperplane const& h) { return h; }
};
static_assert(bsp::oriented_space<no_split>);
static_assert(!bsp::cell_space<no_split>);
static_assert(!bsp::measured_space<no_split>);
struct no_side {
  using point = long;
  using hyperplane = int;
};
static_assert(!bsp::oriented_space<no_side>);

// Labels: bool and integers are labels; other types opt in; non-regular types never are.
struct colour {
  int rgb;
  friend bool operator==(colour, colour) = default;
};
struct unopted {
  int v;
  friend bool operator==(unopted, unopted) = default;
};
struct not_comparable {};
static_assert(bsp::label<bool> && bsp::label<int> && bsp::label<std::size_t>);
static_assert(!bsp::label<unopted> && !bsp::label<std::string>);
static_assert(!bsp::label<not_comparable>);
static_assert(bsp::depth_order_payload<bsp::fragment_list<geometry::e3::exact_kernel>>);
static_assert(!bsp::depth_order_payload<std::vector<int>>);

} // namespace

template <> inline constexpr bool bsp::enable_label<colour> = true;
static_assert(bsp::label<colour>);

// A whole-side test of the wrong shape (it returns nothing) is not taken for one.
namespace {
struct void_whole_side : archetype::line {
  static void whole_side(sub_hyperplane const&, hyperplane const&) {}
};
} // namespace
template <> inline constexpr bool bsp::enable_geometry<void_whole_side> = true;
static_assert(bsp::geometry<void_whole_side> && !bsp::whole_side_geometry<void_whole_side>);

TEST_CASE("the archetype runs the whole generic tree", "[bsp][concepts]") {
  using G = archetype::line;
  // [1, 5] ∪ [9, 13] as boundary points with outward normals (odd positions).
  std::vector<G::sub_hyperplane> a{{{1, false}}, {{5, true}}, {{9, false}}, {{13, true}}};
  std::vector<G::sub_hyperplane> b{{{3, false}}, {{11, true}}};
  auto A = bsp::build_point_set<G>(a), B = bsp::build_point_set<G>(b);
  CHECK(*bsp::measure(A, true) == 8);
  CHECK(*bsp::measure(B, true) == 8);
  CHECK(*bsp::measure(bsp::set_union(A, B), true) == 12);
  CHECK(*bsp::measure(bsp::set_intersection(A, B), true) == 4);
  CHECK(*bsp::measure(bsp::set_difference(A, B), true) == 4);
  CHECK(bsp::classify(A, 2L) == true);
  CHECK(bsp::classify(A, 6L) == false);
  CHECK(bsp::boundary(bsp::set_union(A, B)).size() == 2);
  // Labels of another type, merged.
  auto colours = bsp::merge(A, B, [](bool x, bool y) { return colour{(x ? 1 : 0) + (y ? 2 : 0)}; });
  CHECK(bsp::classify(colours, 4L) == colour{3});
  CHECK(bsp::classify(colours, 12L) == colour{1});
  // Depth order: the points, nearest first from 0.
  bsp::fragment_list<G, int> f{{{{5, true}}, 5}, {{{1, true}}, 1}, {{{3, true}}, 3}};
  auto T = bsp::build_depth_order<G>(f);
  std::vector<int> order;
  bsp::for_each_front_to_back(T, 0L, [&](auto const& fr) { order.push_back(fr.id); });
  CHECK(order == std::vector<int>{1, 3, 5});
}
