// libFuzzer target for Boolean operations in the plane.  The input's bytes
// make two tiny operands, each a few closed paths (integer vertices in
// [−4, 4]: self-crossing, overlapping and touching rings are the usual case)
// under a fill rule.  For each of the four operations, on every input:
//   * the output polygons (from the merged tree, and from `combine`, which
//     classifies boundaries without merging) are valid by the tests'
//     independent checker, and have the merged tree's exact area;
//   * the exact areas obey inclusion–exclusion: |A ∪ B| + |A ∩ B| = |A| + |B|,
//     |A − B| = |A| − |A ∩ B|, |A △ B| = |A ∪ B| − |A ∩ B|.
// Any failed check aborts, with the reason on standard error.
#include "../boolean/validity.hpp"

#include <boolean/polygons.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

[[noreturn]] void fail(char const* what, std::string const& detail = {}) {
  std::fprintf(stderr, "fuzz_boolean2d: %s %s\n", what, detail.c_str());
  std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(std::uint8_t const* data, std::size_t size) {
  using boolean::set_op;
  std::size_t at = 0;
  auto byte = [&]() -> long { return at < size ? data[at++] : 0; };
  auto operand = [&] {
    auto rule = static_cast<boolean::fill_rule>(byte() % 4);
    std::vector<boolean::ring> paths;
    for (long p = 0, n = 1 + byte() % 3; p < n; ++p) {
      boolean::ring r;
      for (long k = 0, m = 3 + byte() % 5; k < m; ++k) r.emplace_back(geometry::rational(byte() % 9 - 4), geometry::rational(byte() % 9 - 4));
      paths.push_back(std::move(r));
    }
    return boolean::operand_of(paths, rule);
  };
  auto a = operand(), b = operand();
  auto area = [](boolean::region2 const& r) {
    auto s = boolean::area(r);
    if (!s) fail("an unbounded result");
    return *s;
  };
  geometry::rational A = area(a.tree), B = area(b.tree), areas[4];
  for (auto op : {set_op::union_, set_op::intersection, set_op::difference, set_op::symmetric_difference}) {
    auto r = boolean::apply(op, a.tree, b.tree);
    geometry::rational s = area(r);
    areas[static_cast<int>(op)] = s;
    auto m = boolean::polygons(r);
    if (auto p = test::validity_problem(m); !p.empty()) fail("invalid output polygons:", p);
    if (boolean::area(m) != s) fail("the output polygons' area is not the tree's");
    auto c = boolean::combine(op, a, b);
    if (auto p = test::validity_problem(c); !p.empty()) fail("invalid polygons from combine:", p);
    if (boolean::area(c) != s) fail("combine's area is not the merged tree's");
  }
  auto const &U = areas[0], &I = areas[1], &D = areas[2], &X = areas[3];
  if (U + I != A + B) fail("|A u B| + |A n B| != |A| + |B|");
  if (D != A - I) fail("|A - B| != |A| - |A n B|");
  if (X != U - I) fail("|A xor B| != |A u B| - |A n B|");
  return 0;
}
