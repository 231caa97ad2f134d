// The laws of set operations, checked on any geometry: measures (exact where
// rational) and membership at sample points against an independent test.
#pragma once

#include <bsp/bsp.hpp>
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <optional>
#include <type_traits>
#include <vector>

namespace laws {

/// Membership by an independent test: +1 inside, 0 on the boundary, −1 outside.
template <class P> using oracle = std::function<int(P const&)>;

template <class M> void check_same(M const& a, M const& b) {
  if constexpr (std::is_floating_point_v<M>)
    CHECK(a == Approx(b).epsilon(1e-12).margin(1e-12));
  else
    CHECK(a == b);
}

/// |X| for a bounded set (the measure of its `true` cells).
template <class G> auto size(bsp::point_set<G, bool> const& x) {
  auto m = bsp::measure(x, true);
  if constexpr (requires { m.has_value(); }) {
    REQUIRE(m.has_value());
    return *m;
  } else {
    return m;
  }
}

/// X and Y are the same set: their symmetric difference has measure zero.
template <class G> void check_equal_sets(bsp::point_set<G, bool> const& x, bsp::point_set<G, bool> const& y) {
  auto d = bsp::set_symmetric_difference(x, y);
  check_same(size<G>(d), decltype(size<G>(d))(0));
}

/// Checks the classification of `t` against `truth` at `points` (boundary points skipped).
template <class G>
void check_classify(bsp::point_set<G, bool> const& t, std::vector<typename G::point> const& points,
                    oracle<typename G::point> const& truth, int& compared) {
  for (auto const& p : points) {
    int want = truth(p);
    if (want == 0) continue;
    auto got = bsp::classify(t, p);
    REQUIRE(got.has_value());
    CHECK(*got == (want > 0));
    ++compared;
  }
}

/// All the laws for bounded sets A and B with independent membership tests.
template <class G>
void check_all(bsp::point_set<G, bool> const& A, bsp::point_set<G, bool> const& B,
               oracle<typename G::point> const& inA, oracle<typename G::point> const& inB,
               std::vector<typename G::point> const& points, int& compared) {
  using S = bsp::point_set<G, bool>;
  S empty(false);
  auto U = bsp::set_union(A, B), I = bsp::set_intersection(A, B), D = bsp::set_difference(A, B);
  auto X = bsp::set_symmetric_difference(A, B);
  auto a = size<G>(A), b = size<G>(B), u = size<G>(U), i = size<G>(I), d = size<G>(D), x = size<G>(X);
  // Inclusion–exclusion.
  check_same(decltype(u)(u + i), decltype(u)(a + b));
  check_same(decltype(d)(d + i), a);
  check_same(decltype(x)(x + i + i), decltype(x)(a + b));
  // Identities.
  check_equal_sets(bsp::complement(bsp::complement(A)), A);
  check_equal_sets(bsp::set_union(A, empty), A);
  check_equal_sets(bsp::set_intersection(A, A), A);
  check_same(size<G>(bsp::set_difference(A, A)), decltype(a)(0));
  // De Morgan (unbounded sets, compared through their bounded difference).
  check_equal_sets(bsp::complement(U), bsp::set_intersection(bsp::complement(A), bsp::complement(B)));
  check_equal_sets(bsp::complement(I), bsp::set_union(bsp::complement(A), bsp::complement(B)));
  // Rebuilding from the extracted boundary gives the same set.
  check_equal_sets(bsp::build_point_set<G>(bsp::oriented_boundary(U)), U);
  // Membership against the independent tests.
  check_classify<G>(A, points, inA, compared);
  check_classify<G>(B, points, inB, compared);
  auto both = [&](auto f) {
    return [&, f](typename G::point const& p) {
      int ra = inA(p), rb = inB(p);
      if (ra == 0 || rb == 0) return 0;
      return f(ra > 0, rb > 0) ? 1 : -1;
    };
  };
  check_classify<G>(U, points, both([](bool p, bool q) { return p || q; }), compared);
  check_classify<G>(I, points, both([](bool p, bool q) { return p && q; }), compared);
  check_classify<G>(D, points, both([](bool p, bool q) { return p && !q; }), compared);
  check_classify<G>(X, points, both([](bool p, bool q) { return p != q; }), compared);
}

} // namespace laws
