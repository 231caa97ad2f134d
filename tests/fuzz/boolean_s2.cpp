// libFuzzer target for Boolean operations on the sphere.  The input's bytes
// make two tiny operands, each one to three spherical triangles combined by
// set operations.  Their vertices are integer directions in [−4, 4]³, so
// shared vertices and great circles, touching and nested triangles are the
// usual case, and a triangle whose loop runs clockwise stands for the large
// region around it.  For each of the four operations, on every input:
//   * at up to 24 directions off every input circle, the result's label is
//     the operation on the operands' labels, each operand's label coming
//     from the triangles by exact integer orientation tests (nothing shared
//     with the library);
//   * the results obey the set identities exactly, A ∪ B = (A △ B) ∪ (A ∩ B)
//     and A − B = A − (A ∩ B), and inclusion–exclusion on areas
//     (|A ∪ B| + |A ∩ B| = |A| + |B|, to 1e-9: areas are doubles);
//   * the output loops read back into exactly the same region, every edge a
//     minor arc; the whole sphere, which no loop bounds, is refused;
//   * `combine` (no merged tree) gives loops that read back into the same
//     region, with the same area.
// Any failed check aborts, with the reason on standard error.
#include "input.hpp"

#include <boolean/spherical.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using boolean::set_op;
using ivec = std::array<long, 3>;

[[noreturn]] void fail(std::string const& what) { fuzz::fail("fuzz_boolean_s2", what); }

long det(ivec a, ivec b, ivec c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/// A loop of three directions, not on one great circle.
struct triangle {
  std::array<ivec, 3> v;
};

/// An operand: triangles folded left to right by operations.
struct operand {
  std::vector<triangle> triangles;
  std::vector<set_op> ops; // ops[k] joins triangle k + 1
};

bool apply_op(set_op op, bool x, bool y) {
  switch (op) {
  case set_op::union_: return x || y;
  case set_op::intersection: return x && y;
  case set_op::difference: return x && !y;
  case set_op::symmetric_difference: return x != y;
  }
  fail("an unknown operation");
}

/// Whether `d` is inside triangle `t`'s region (on the left of its loop),
/// or nothing when `d` lies on one of its great circles.
std::optional<bool> inside(triangle const& t, ivec d) {
  int positive = 0;
  for (int k = 0; k < 3; ++k) {
    long s = det(t.v[k], t.v[(k + 1) % 3], d);
    if (s == 0) return std::nullopt;
    positive += s > 0;
  }
  bool small = det(t.v[0], t.v[1], t.v[2]) > 0; // counter-clockwise: the small triangle
  return small ? positive == 3 : positive > 0;
}

std::optional<bool> inside(operand const& o, ivec d) {
  std::optional<bool> r = inside(o.triangles[0], d);
  for (std::size_t k = 1; r && k < o.triangles.size(); ++k) {
    auto x = inside(o.triangles[k], d);
    if (!x) return std::nullopt;
    r = apply_op(o.ops[k - 1], *r, *x);
  }
  return r;
}

boolean::direction direction_of(ivec d) {
  return boolean::direction(std::array<geometry::rational, 3>{geometry::rational(d[0]), geometry::rational(d[1]), geometry::rational(d[2])});
}

boolean::region_s2 region(operand const& o) {
  auto loop_of = [](triangle const& t) {
    return boolean::spherical_region(std::vector<boolean::loop>{{direction_of(t.v[0]), direction_of(t.v[1]), direction_of(t.v[2])}});
  };
  auto r = loop_of(o.triangles[0]);
  for (std::size_t k = 1; k < o.triangles.size(); ++k) r = boolean::apply(o.ops[k - 1], r, loop_of(o.triangles[k]));
  return r;
}

bool empty(boolean::region_s2 const& r) {
  for (auto const& c : bsp::cells(r))
    if (r.leaf_data(c.leaf)) return false;
  return true;
}

bool same(boolean::region_s2 const& a, boolean::region_s2 const& b) { return empty(boolean::apply(set_op::symmetric_difference, a, b)); }

char const* name(set_op op) {
  constexpr char const* names[] = {"union", "intersection", "difference", "symmetric difference"};
  return names[static_cast<int>(op)];
}

/// The output loops of `r`, read back, must be `r` exactly.
void check_output(boolean::region_s2 const& r, set_op op) {
  if (empty(boolean::apply(set_op::difference, boolean::region_s2(true), r))) {
    try {
      boolean::spherical_polygons(r);
    } catch (std::invalid_argument const&) {
      return;
    }
    fail(std::string("the whole sphere (") + name(op) + ") was given loops");
  }
  boolean::region_s2 back(false);
  for (auto const& p : boolean::spherical_polygons(r)) {
    std::vector<boolean::loop> loops{p.outer};
    loops.insert(loops.end(), p.holes.begin(), p.holes.end());
    for (auto const& l : loops)
      for (std::size_t i = 0; i < l.size(); ++i)
        if (geometry::parallel(l[i], l[(i + 1) % l.size()]) != geometry::sign::zero)
          fail(std::string("an output edge with no minor arc (") + name(op) + ")");
    back = boolean::apply(set_op::union_, back, boolean::spherical_region(loops));
  }
  if (!same(back, r)) fail(std::string("the output loops do not bound the result (") + name(op) + ")");
}

/// `combine` on the operands (their boundaries read off their trees) must
/// give polygons that read back into `r` exactly, with `r`'s area, or
/// refuse the whole sphere.
void check_combine(boolean::spherical_operand const& a, boolean::spherical_operand const& b, boolean::region_s2 const& r, set_op op) {
  bool whole = empty(boolean::apply(set_op::difference, boolean::region_s2(true), r));
  std::vector<boolean::spherical_polygon> polygons;
  try {
    polygons = boolean::combine(op, a, b);
  } catch (std::invalid_argument const&) {
    if (whole) return;
    fail(std::string("combine refused a result that is not the whole sphere (") + name(op) + ")");
  }
  if (whole) fail(std::string("combine gave loops for the whole sphere (") + name(op) + ")");
  boolean::region_s2 back(false);
  for (auto const& p : polygons) {
    std::vector<boolean::loop> loops{p.outer};
    loops.insert(loops.end(), p.holes.begin(), p.holes.end());
    back = boolean::apply(set_op::union_, back, boolean::spherical_region(loops));
  }
  if (!same(back, r)) fail(std::string("combine's loops do not bound the result (") + name(op) + ")");
  if (std::abs(boolean::area(polygons) - boolean::area(r)) > 1e-9 * 4 * std::numbers::pi)
    fail(std::string("combine's area differs from the result's (") + name(op) + ")");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(std::uint8_t const* data, std::size_t size) {
  fuzz::input in(data, size);
  auto dir = [&] { return ivec{in.in(-4, 4), in.in(-4, 4), in.in(-4, 4)}; };
  auto read_operand = [&] {
    operand o;
    for (long k = 0, n = in.in(1, 3); k < n; ++k) {
      triangle t{{dir(), dir(), dir()}};
      if (det(t.v[0], t.v[1], t.v[2]) == 0) continue; // on one great circle (or a zero direction)
      if (!o.triangles.empty()) o.ops.push_back(static_cast<set_op>(in.in(0, 3)));
      o.triangles.push_back(t);
    }
    return o;
  };
  operand oa = read_operand(), ob = read_operand();
  if (oa.triangles.empty() || ob.triangles.empty()) return 0;
  auto a = region(oa), b = region(ob);

  // Directions to classify: each triangle's vertex sum, and some from the input.
  std::vector<ivec> directions;
  for (auto const* o : {&oa, &ob})
    for (auto const& t : o->triangles) directions.push_back({t.v[0][0] + t.v[1][0] + t.v[2][0], t.v[0][1] + t.v[1][1] + t.v[2][1], t.v[0][2] + t.v[1][2] + t.v[2][2]});
  for (int k = 0; k < 16; ++k) directions.push_back({in.in(-9, 9), in.in(-9, 9), in.in(-9, 9)});

  for (auto const& d : directions) {
    auto x = inside(oa, d), y = inside(ob, d);
    if (d == ivec{0, 0, 0} || !x || !y) continue;
    if (bsp::classify(a, direction_of(d)) != *x) fail("an operand's label differs from the orientation tests");
  }

  boolean::spherical_operand oa_set{{a, bsp::oriented_boundary(a)}, {}}, ob_set{{b, bsp::oriented_boundary(b)}, {}};
  double A = boolean::area(a), B = boolean::area(b), areas[4];
  boolean::region_s2 results[4] = {boolean::region_s2(false), boolean::region_s2(false), boolean::region_s2(false), boolean::region_s2(false)};
  for (auto op : {set_op::union_, set_op::intersection, set_op::difference, set_op::symmetric_difference}) {
    auto const& r = results[static_cast<int>(op)] = boolean::apply(op, a, b);
    areas[static_cast<int>(op)] = boolean::area(r);
    for (auto const& d : directions) {
      auto x = inside(oa, d), y = inside(ob, d);
      if (d == ivec{0, 0, 0} || !x || !y) continue;
      if (bsp::classify(r, direction_of(d)) != apply_op(op, *x, *y))
        fail(std::string("the ") + name(op) + "'s label differs from the operands' at (" + std::to_string(d[0]) + ", " + std::to_string(d[1]) + ", " +
             std::to_string(d[2]) + ")");
    }
    check_output(r, op);
    check_combine(oa_set, ob_set, r, op);
  }
  auto const &U = results[0], &I = results[1], &D = results[2], &X = results[3];
  if (!same(U, boolean::apply(set_op::union_, X, I))) fail("A u B != (A xor B) u (A n B)");
  if (!same(D, boolean::apply(set_op::difference, a, I))) fail("A - B != A - (A n B)");
  double tol = 1e-9 * 4 * std::numbers::pi;
  if (std::abs(areas[0] + areas[1] - A - B) > tol) fail("|A u B| + |A n B| != |A| + |B|");
  if (std::abs(areas[2] - (A - areas[1])) > tol) fail("|A - B| != |A| - |A n B|");
  if (std::abs(areas[3] - (areas[0] - areas[1])) > tol) fail("|A xor B| != |A u B| - |A n B|");
  return 0;
}
