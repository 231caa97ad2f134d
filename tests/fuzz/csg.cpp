// libFuzzer target for Boolean operations on solids (CSG).  The input's
// bytes make two tiny operands, each one or two convex shapes (boxes and
// tetrahedra with integer corners in [−4, 4], some turned by a rational
// rotation) combined by an operation, so shared faces, edges and corners,
// nested and touching solids are the usual case.  For each operation, on
// every input:
//   * at up to 20 points off every face plane, the result's label is the
//     operation on the operands' labels, each operand's label coming from
//     its shapes by exact orientation tests (nothing shared with the library);
//   * the volumes obey inclusion–exclusion exactly:
//     |A ∪ B| + |A ∩ B| = |A| + |B|, |A − B| = |A| − |A ∩ B| = |A ∪ B| − |B|;
//   * the mesh (`combine`, without the merged tree) has the merged tree's
//     mesh's size, and every edge run once each way, possibly by more than two
//     faces (non-manifold, as `inspect_edges` reports); its vertices are
//     distinct, its faces planar, and the volume it encloses (computed here)
//     is the tree's; read back as input, it is the same solid.
// Any failed check aborts, with the reason on standard error.
#include "input.hpp"

#include <boolean/polyhedra.hpp>
#include <geometry/io/scene.hpp>

#include <array>
#include <optional>
#include <set>
#include <vector>

namespace {

using boolean::csg_op;
using Q = geometry::rational;
using P = boolean::point3;
using V = std::array<Q, 3>;

[[noreturn]] void fail(std::string const& what) { fuzz::fail("fuzz_csg", what); }

V sub(V const& a, V const& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Q det(V const& a, V const& b, V const& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}
/// Positive when `p` is on the outer side of the face (a, b, c), counter-clockwise seen from outside.
Q orient(V const& a, V const& b, V const& c, V const& p) { return det(sub(b, a), sub(c, a), sub(p, a)); }

/// A convex shape: its corners and its faces, counter-clockwise seen from outside.
struct shape {
  std::vector<V> corners;
  std::vector<std::vector<std::uint32_t>> faces;
};

/// Whether `p` is inside `s`, or nothing when it lies on a face's plane and on no face's outer side.
std::optional<bool> inside(shape const& s, V const& p) {
  bool on = false;
  for (auto const& f : s.faces) {
    auto o = orient(s.corners[f[0]], s.corners[f[1]], s.corners[f[2]], p);
    if (o > 0) return false;
    on |= o == 0;
  }
  if (on) return std::nullopt;
  return true;
}

bool apply_op(csg_op op, bool x, bool y) {
  switch (op) {
  case csg_op::union_: return x || y;
  case csg_op::intersection: return x && y;
  case csg_op::difference: return x && !y;
  }
  fail("an unknown operation");
}

char const* name(csg_op op) {
  constexpr char const* names[] = {"union", "intersection", "difference"};
  return names[static_cast<int>(op)];
}

/// An operand: one shape, or two joined by an operation.
struct operand {
  std::vector<shape> shapes;
  csg_op op = csg_op::union_;
};

std::optional<bool> inside(operand const& o, V const& p) {
  auto x = inside(o.shapes[0], p);
  if (!x || o.shapes.size() == 1) return x;
  auto y = inside(o.shapes[1], p);
  if (!y) return std::nullopt;
  return apply_op(o.op, *x, *y);
}

shape read_shape(fuzz::input& in) {
  auto point = [&] { return V{Q(in.in(-4, 4)), Q(in.in(-4, 4)), Q(in.in(-4, 4))}; };
  shape s;
  if (in.byte() % 2 == 0) {
    V lo = point(), hi{lo[0] + in.in(1, 4), lo[1] + in.in(1, 4), lo[2] + in.in(1, 4)};
    for (int i = 0; i < 8; ++i) s.corners.push_back({i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]});
    s.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  } else {
    s.corners = {point(), point(), point(), point()};
    Q o = orient(s.corners[0], s.corners[1], s.corners[2], s.corners[3]);
    if (o == 0) return {}; // flat
    if (o < 0) std::swap(s.corners[1], s.corners[2]);
    s.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  }
  if (long a = in.in(-2, 2), b = in.in(-2, 2), c = in.in(-2, 2), d = in.in(-2, 2); a || b || c || d) {
    // The rotation of the quaternion (a, b, c, d): rational.
    Q n(a * a + b * b + c * c + d * d);
    std::array<V, 3> r{{{Q(a * a + b * b - c * c - d * d) / n, Q(2 * (b * c - a * d)) / n, Q(2 * (b * d + a * c)) / n},
                        {Q(2 * (b * c + a * d)) / n, Q(a * a - b * b + c * c - d * d) / n, Q(2 * (c * d - a * b)) / n},
                        {Q(2 * (b * d - a * c)) / n, Q(2 * (c * d + a * b)) / n, Q(a * a - b * b - c * c + d * d) / n}}};
    for (auto& p : s.corners) {
      V q = p;
      for (int i = 0; i < 3; ++i) p[i] = r[i][0] * q[0] + r[i][1] * q[1] + r[i][2] * q[2];
    }
  }
  return s;
}

geometry::io::scene scene_of(shape const& s) {
  geometry::io::scene out;
  for (auto const& c : s.corners) out.vertices.emplace_back(c[0], c[1], c[2]);
  for (auto const& f : s.faces) out.faces.push_back({f, std::nullopt, 0});
  return out;
}

boolean::solid solid_of(operand const& o) {
  auto a = boolean::from_scene(scene_of(o.shapes[0]));
  if (o.shapes.size() == 1) return a;
  return boolean::apply(o.op, a, boolean::from_scene(scene_of(o.shapes[1])));
}

V coords(P const& p) { return {p.x(), p.y(), p.z()}; }

/// The independent checks of an output mesh of exact volume `volume`.
void check_mesh(boolean::mesh const& m, Q const& volume, csg_op op) {
  auto why = [&](char const* what) { return std::string(what) + " (" + name(op) + ")"; };
  std::set<V> seen;
  for (auto const& p : m.vertices)
    if (!seen.insert(coords(p)).second) fail(why("a vertex repeated in the mesh"));
  Q six(0);
  for (auto const& f : m.faces) {
    if (f.size() < 3) fail(why("a face with fewer than 3 corners"));
    for (auto i : f)
      if (i >= m.vertices.size()) fail(why("a face refers to a missing vertex"));
    // Newell's normal; every corner on the plane through the first.
    V n{0, 0, 0};
    for (std::size_t i = 0; i < f.size(); ++i) {
      auto p = coords(m.vertices[f[i]]), q = coords(m.vertices[f[(i + 1) % f.size()]]);
      n[0] += (p[1] - q[1]) * (p[2] + q[2]);
      n[1] += (p[2] - q[2]) * (p[0] + q[0]);
      n[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    if (n == V{0, 0, 0}) fail(why("a face without area"));
    auto o = coords(m.vertices[f[0]]);
    for (auto i : f) {
      auto p = coords(m.vertices[i]);
      if (n[0] * (p[0] - o[0]) + n[1] * (p[1] - o[1]) + n[2] * (p[2] - o[2]) != 0) fail(why("a face not in one plane"));
    }
    for (std::size_t i = 1; i + 1 < f.size(); ++i) six += det(o, coords(m.vertices[f[i]]), coords(m.vertices[f[i + 1]]));
  }
  if (six != 6 * volume) fail(why("the mesh encloses another volume than the tree's"));
  auto r = boolean::inspect_edges(m);
  if (r.unmatched) fail(why("an edge of the mesh is not run once each way"));
  if (volume > 0) {
    auto back = boolean::from_scene(boolean::to_scene(m));
    if (back.volume != volume) fail(why("the mesh read back has another volume"));
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(std::uint8_t const* data, std::size_t size) {
  fuzz::input in(data, size);
  auto read_operand = [&] {
    operand o;
    for (long k = 0, n = in.in(1, 2); k < n; ++k)
      if (auto s = read_shape(in); !s.corners.empty()) o.shapes.push_back(std::move(s));
    o.op = static_cast<csg_op>(in.in(0, 2));
    return o;
  };
  operand oa = read_operand(), ob = read_operand();
  if (oa.shapes.empty() || ob.shapes.empty()) return 0;
  auto a = solid_of(oa), b = solid_of(ob);

  // Points to classify: each shape's centroid, and half-integer points from the input.
  std::vector<V> points;
  for (auto const* o : {&oa, &ob})
    for (auto const& s : o->shapes) {
      V c{0, 0, 0};
      for (auto const& p : s.corners)
        for (int i = 0; i < 3; ++i) c[i] += p[i] / static_cast<long>(s.corners.size());
      points.push_back(c);
    }
  for (int k = 0; k < 16; ++k) points.push_back({Q(in.in(-11, 11), 2), Q(in.in(-11, 11), 2), Q(in.in(-11, 11), 2)});
  auto truth = [&](V const& p) -> std::optional<std::pair<bool, bool>> {
    auto x = inside(oa, p), y = inside(ob, p);
    if (!x || !y) return std::nullopt;
    return std::pair{*x, *y};
  };
  for (auto const& p : points)
    if (auto t = truth(p); t && bsp::classify(a.tree, P(p[0], p[1], p[2])) != t->first) fail("an operand's label differs from the orientation tests");

  Q volumes[3];
  for (auto op : {csg_op::union_, csg_op::intersection, csg_op::difference}) {
    auto r = boolean::apply(op, a, b);
    volumes[static_cast<int>(op)] = r.volume;
    for (auto const& p : points)
      if (auto t = truth(p); t && bsp::classify(r.tree, P(p[0], p[1], p[2])) != apply_op(op, t->first, t->second))
        fail(std::string("the ") + name(op) + "'s label differs from the operands'");
    auto fast = boolean::combine(op, a, b), slow = boolean::to_mesh(r.tree);
    if (fast.faces.size() != slow.faces.size() || fast.vertices.size() != slow.vertices.size())
      fail(std::string("combine's mesh differs from the merged tree's (") + name(op) + ")");
    check_mesh(fast, r.volume, op);
    if (boolean::volume(slow) != r.volume) fail(std::string("the merged tree's mesh has another volume (") + name(op) + ")");
  }
  auto const &U = volumes[0], &I = volumes[1], &D = volumes[2];
  if (U + I != a.volume + b.volume) fail("|A u B| + |A n B| != |A| + |B|");
  if (D != a.volume - I) fail("|A - B| != |A| - |A n B|");
  if (D != U - b.volume) fail("|A - B| != |A u B| - |B|");
  return 0;
}
