// The visibility pass (svm::detail::coverage_pass), one property test for
// both of its targets: the sphere S2 (central and parallel 3D views) and the
// circle S1 (2D visibility).  Convex fragments on small integer directions
// (shared corners, common circles, nested and equal fragments) go in front
// to back; in every sampled direction the visible piece that holds it must
// belong to the first fragment that holds it, and none when none does.
#include "support.hpp"

#include <catch2/catch.hpp>
#include <svm/visibility2d.hpp>

#include <optional>
#include <vector>

namespace svm_coverage_pass_tests {

namespace {

using geometry::rational;
using geometry::sign;

/// Random convex fragments and directions of one target geometry.
struct sphere_target {
  using kernel = geometry::s2::kernel<rational>;
  using vec = geometry::hvec<rational, 3>;
  static vec direction(long bound) {
    for (;;) {
      vec v(std::array<rational, 3>{test::random_integer(bound), test::random_integer(bound), test::random_integer(bound)});
      if (!(v[0] == 0 && v[1] == 0 && v[2] == 0)) return v;
    }
  }
  /// A spherical triangle's circles, counter-clockwise, its inside on their positive sides.
  static std::optional<std::vector<vec>> fragment() {
    auto a = direction(3), b = direction(3), c = direction(3);
    sign d = geometry::det_sign(a, b, c);
    if (d == sign::zero) return std::nullopt;
    if (d == sign::negative) std::swap(b, c);
    return std::vector<vec>{geometry::cross(a, b), geometry::cross(b, c), geometry::cross(c, a)};
  }
};

struct circle_target {
  using kernel = geometry::s1::kernel<rational>;
  using vec = geometry::hvec<rational, 2>;
  static vec direction(long bound) {
    for (;;) {
      vec v(std::array<rational, 2>{test::random_integer(bound), test::random_integer(bound)});
      if (!(v[0] == 0 && v[1] == 0)) return v;
    }
  }
  /// An arc of less than a half circle: its two bounds.
  static std::optional<std::vector<vec>> fragment() {
    auto a = direction(3), b = direction(3);
    if (geometry::det_sign(a, b) != sign::positive) return std::nullopt;
    auto arc = geometry::s1::arc(a, b);
    return std::vector<vec>{arc.bounds[0].n, arc.bounds[1].n};
  }
};

/// Whether `d` is strictly inside the region of `bounds` (nullopt: on its boundary).
template <class V> std::optional<bool> inside(std::vector<V> const& bounds, V const& d) {
  bool in = true;
  for (auto const& b : bounds) {
    sign s = geometry::dot_sign(b, d);
    if (s == sign::zero) return std::nullopt;
    in = in && s == sign::positive;
  }
  return in;
}

template <class T> void check_pass(std::size_t scenes, std::size_t fragments, std::size_t samples) {
  using K = typename T::kernel;
  using H = typename K::hyperplane;
  using V = typename T::vec;
  using pass_type = svm::detail::coverage_pass<K>;
  std::size_t checked = 0, wrong = 0, visible_total = 0, hidden_total = 0;
  for (std::size_t s = 0; s < scenes; ++s) {
    pass_type pass(s + 1);
    std::vector<std::vector<V>> input;
    struct piece {
      std::vector<V> bounds;
      std::size_t id;
    };
    std::vector<piece> visible;
    svm::detail::hyperplane_store<H> store;
    while (input.size() < fragments) {
      auto f = T::fragment();
      if (!f) continue;
      std::size_t id = input.size();
      input.push_back(*f);
      store.clear();
      typename pass_type::fragment frag;
      for (auto const& n : *f) frag.push_back({&store.emplace_back(n), true});
      hidden_total += pass.insert(
          std::move(frag),
          [&](typename pass_type::fragment&& p) {
            piece q{{}, id};
            for (auto const& b : p) q.bounds.push_back(b.c->n);
            visible.push_back(std::move(q));
          },
          [](typename pass_type::fragment&&) {});
      pass.rebuild_if_grown();
    }
    visible_total += visible.size();
    for (std::size_t k = 0; k < samples; ++k) {
      V d = T::direction(1000);
      // The first fragment holding d, or none; skip d on any fragment's boundary.
      std::optional<std::size_t> first;
      bool on_boundary = false;
      for (std::size_t i = 0; i < input.size() && !on_boundary; ++i) {
        auto in = inside(input[i], d);
        if (!in) on_boundary = true;
        else if (*in && !first) first = i;
      }
      if (on_boundary) continue;
      std::optional<std::size_t> seen;
      std::size_t holders = 0;
      for (auto const& p : visible) {
        auto in = inside(p.bounds, d);
        if (!in) {
          on_boundary = true; // on a cut made by the pass: d is on no input boundary, so this cannot be a fragment's edge
          break;
        }
        if (*in) seen = p.id, ++holders;
      }
      if (on_boundary) continue;
      ++checked;
      if (seen != first || holders > 1) ++wrong;
    }
  }
  INFO(checked << " directions, " << visible_total << " visible pieces, " << hidden_total << " hidden");
  CHECK(checked >= scenes * samples / 2);
  CHECK(hidden_total > 0);
  CHECK(wrong == 0);
}

} // namespace

TEST_CASE("The visibility pass on the sphere: each direction sees the first fragment that holds it", "[coverage_pass]") {
  check_pass<sphere_target>(30, 60, 400);
}

TEST_CASE("The visibility pass on the circle: each direction sees the first fragment that holds it", "[coverage_pass]") {
  check_pass<circle_target>(60, 40, 400);
}

} // namespace svm_coverage_pass_tests
