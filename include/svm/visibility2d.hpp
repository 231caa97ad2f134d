/// @file
/// Visibility polygons in the plane (2D visibility): the construction of the
/// spherical visibility map one dimension down.  The walls (input segments)
/// go into a depth-order tree of E2 once (`wall_index`, the preprocessing);
/// for each eye the tree lists its fragments front to back, each is seen as
/// an arc of the circle of directions S1, bounded by the lines through the
/// eye and its ends, and it descends the same coverage pass as the fragments
/// of a 3D view (`detail::coverage_pass`, here over S1): what reaches free
/// directions is visible.  The result is a circular list of labelled arcs;
/// the polygon's vertices are made from it only for output.
///
/// Every wall is opaque on both sides.  A wall whose line passes through the
/// eye covers no direction and is left out.  Walls of polygon rings (the
/// inside on their left: outer rings counter-clockwise, holes clockwise)
/// also tell which way the eye looks when it lies on them: on a ring's edge,
/// into the inside; at a ring's vertex, into the inside's wedge there; on
/// the boundaries of several polygons (rooms side by side), into each.
/// Directions out of them see nothing (`behind_boundary`).  At a vertex
/// whose two neighbours coincide (the tip of a spike or of a crack) the
/// inside's wedge is taken to be empty, as at a spike: walls that the eye
/// must see both sides of are line strings.
#pragma once

#include "build.hpp"

#include <bsp/depth_order.hpp>
#include <bsp/splitter.hpp>
#include <geometry/e2.hpp>
#include <geometry/s1.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

namespace svm {

/// The walls of a plane scene: closed rings (the inside on the left of each
/// edge) and free segments.  Wall `i` is, in order, each ring's edges
/// (vertex k to vertex k+1), then the segments.
template <geometry::number FT> struct wall_scene {
  std::vector<std::vector<geometry::e2::point<FT>>> rings;
  std::vector<std::array<geometry::e2::point<FT>, 2>> segments;
  /// The polygon of each ring (an outer ring and its holes share one), for
  /// an eye on the boundary of several: it looks into each polygon whose
  /// boundary it lies on, and out of none.  Empty: every ring is a polygon.
  std::vector<std::size_t> ring_polygon;

  /// The ends of wall `i` (walks the rings: `wall_table` looks walls up
  /// in logarithmic time, and `for_each_wall` visits them all in order).
  std::array<geometry::e2::point<FT>, 2> wall(std::size_t i) const {
    for (auto const& r : rings) {
      if (i < r.size()) return {r[i], r[(i + 1) % r.size()]};
      i -= r.size();
    }
    return segments.at(i);
  }
  std::size_t wall_count() const {
    std::size_t n = segments.size();
    for (auto const& r : rings) n += r.size();
    return n;
  }
  /// Calls `f(i, a, b)` for every wall `i` from `a` to `b`, in order.
  template <class F> void for_each_wall(F&& f) const {
    std::size_t i = 0;
    for (auto const& r : rings)
      for (std::size_t k = 0; k < r.size(); ++k) f(i++, r[k], r[(k + 1) % r.size()]);
    for (auto const& s : segments) f(i++, s[0], s[1]);
  }
};

/// Wall `i` of a scene in O(log rings) (`wall_scene::wall` walks the rings):
/// the number of each ring's first wall, kept.  It refers to the scene,
/// which must outlive it unchanged.
template <geometry::number FT> class wall_table {
public:
  explicit wall_table(wall_scene<FT> const& scene) : scene_(&scene) {
    first_.reserve(scene.rings.size() + 1);
    std::size_t n = 0;
    for (auto const& r : scene.rings) {
      first_.push_back(n);
      n += r.size();
    }
    first_.push_back(n);
  }
  /// The ends of wall `i`.
  std::array<geometry::e2::point<FT>, 2> operator()(std::size_t i) const {
    if (i >= first_.back()) return scene_->segments.at(i - first_.back());
    // The last ring that starts at or before i (empty rings start where the next does).
    auto k = static_cast<std::size_t>(std::upper_bound(first_.begin(), first_.end(), i) - first_.begin()) - 1;
    auto const& r = scene_->rings[k];
    std::size_t j = i - first_[k];
    return {r[j], r[(j + 1) % r.size()]};
  }

private:
  wall_scene<FT> const* scene_;
  std::vector<std::size_t> first_; ///< of each ring, then the number of ring walls
};

/// Labels of arcs where no wall is seen.
inline constexpr std::int64_t no_wall = -1;         ///< nothing in those directions: the view is unbounded there
inline constexpr std::int64_t behind_boundary = -2; ///< the eye is on a ring and those directions leave its inside

/// A maximal arc of directions from the eye in which one wall is seen: from
/// `start_point(from)` counter-clockwise to `−start_point(to)`, each a line
/// through the eye, input-derived; or the whole circle when `whole` (then
/// `from` and `to` are zero and mean nothing).
template <geometry::number FT> struct view_arc {
  geometry::s1::hyperplane<FT> from, to;
  std::int64_t wall = no_wall;
  bool whole = false;
  geometry::s1::point<FT> start() const { return geometry::s1::start_point(from); }
  geometry::s1::point<FT> end() const { return -geometry::s1::start_point(to); }
};

struct visibility2d_statistics {
  std::size_t walls = 0;
  std::size_t discarded_edge_on = 0;  ///< fragments on a line through the eye
  std::size_t fragments = 0;          ///< of the depth-order tree (the preprocessing)
  std::size_t hidden_pieces = 0;
  std::size_t visible_pieces = 0;
  std::size_t arcs = 0;               ///< of the result, merged
  std::size_t coverage_nodes_peak = 0;
  std::size_t culled_subtrees = 0;    ///< of the depth order, left out because their box was hidden
  double seconds = 0;                 ///< the query, without the preprocessing
};

/// The view of a plane scene from a point: arcs counter-clockwise from the
/// first one at or after direction (1, 0), covering the circle once.
template <geometry::number FT> struct visibility_region {
  geometry::e2::point<FT> eye;
  std::vector<view_arc<FT>> arcs;
  visibility2d_statistics stats;

  /// Whether the view is bounded in every direction: by a wall, or by the
  /// boundary the eye lies on (`behind_boundary`).
  bool bounded() const {
    return std::none_of(arcs.begin(), arcs.end(), [](auto const& a) { return a.wall == no_wall; });
  }
};

namespace detail {

/// An arc of S1 as a fragment of the coverage pass (`coverage_pass<s1::kernel<FT>>`).
template <geometry::number FT> using arc_bound = flagged_bound<geometry::s1::hyperplane<FT>>;

/// An arc at a node whose point pair is `g[0]` (`g[1]` its opposite): split
/// when the pair cuts it, else passed on whole, and then an end of the arc at
/// one of the pair's points is in the tree already (the flag reset).
template <geometry::number FT>
bsp::routed<std::vector<arc_bound<FT>>> route(std::vector<arc_bound<FT>>& arc,
                                              std::array<geometry::s1::hyperplane<FT> const*, 2> const& g,
                                              std::vector<geometry::sign>&) {
  arc_bound<FT> hp{g[0], false}, hn{g[1], false};
  auto r = geometry::detail::split_arc(arc, hp, hn);
  if (r.negative && r.positive) return {0, std::move(r.negative), std::move(r.positive)};
  for (auto& b : arc)
    if (geometry::parallel(b.line(), g[0]->n) != geometry::sign::zero) b.flag = false;
  return {r.positive ? +1 : -1, std::nullopt, std::nullopt};
}

/// An arc's ends always have a place: any non-zero point pair bounds it.
template <geometry::number FT> bool proper_edge(std::vector<arc_bound<FT>> const& arc, std::size_t i) {
  auto const& c = arc[i].line();
  return !(c[0] == 0 && c[1] == 0);
}

/// Whether direction `u` comes before `v` counter-clockwise from (1, 0), exactly.
template <geometry::number FT> bool angle_less(geometry::s1::point<FT> const& u, geometry::s1::point<FT> const& v) {
  using geometry::sign;
  auto half = [](geometry::s1::point<FT> const& p) {
    sign y = p.sign_at(1);
    return y == sign::negative || (y == sign::zero && p.sign_at(0) == sign::negative);
  };
  bool hu = half(u), hv = half(v);
  if (hu != hv) return hv;
  return geometry::det_sign(u, v) == sign::positive;
}

/// Whether the start point of `h` comes before that of `g` counter-clockwise
/// from (1, 0), read from their normals (start(n) = (n₁, −n₀), a rotation):
/// nothing is constructed.
template <geometry::number FT> bool start_less(geometry::s1::hyperplane<FT> const& h, geometry::s1::hyperplane<FT> const& g) {
  using geometry::sign;
  auto half = [](geometry::s1::hyperplane<FT> const& x) {
    sign n0 = x.n.sign_at(0);
    return n0 == sign::positive || (n0 == sign::zero && x.n.sign_at(1) == sign::negative);
  };
  bool hh = half(h), hg = half(g);
  if (hh != hg) return hg;
  return geometry::det_sign(h.n, g.n) == sign::positive;
}

/// Whether the arc ending at `−start(to)` ends where the one starting at `start(from)` starts.
template <geometry::number FT> bool meets(geometry::s1::hyperplane<FT> const& to, geometry::s1::hyperplane<FT> const& from) {
  return geometry::parallel(to.n, from.n) == geometry::sign::negative;
}

/// Whether `u` and `v` are the same direction.
template <geometry::number FT> bool same_direction(geometry::s1::point<FT> const& u, geometry::s1::point<FT> const& v) {
  return geometry::parallel(u, v) == geometry::sign::positive;
}

/// The arcs of directions from `p` counter-clockwise to `q` (the whole circle
/// when they are the same direction), as S1 polytopes of at most a half circle each.
template <geometry::number FT>
std::vector<geometry::s1::polytope<FT>> arcs_between(geometry::s1::point<FT> const& p, geometry::s1::point<FT> const& q) {
  using geometry::sign;
  namespace s1 = geometry::s1;
  sign turn = geometry::det_sign(p, q);
  if (turn == sign::positive) return {s1::arc(p, q)};
  std::vector<s1::polytope<FT>> out{{{s1::hyperplane_at(p)}}}; // p to −p
  if (turn == sign::zero) {
    if (geometry::dot_sign(p, q) == sign::positive) out.push_back({{s1::hyperplane_at(p).opposite()}}); // −p to p
    return out;
  }
  out.push_back(s1::arc(geometry::s1::point<FT>(-p), q));
  return out;
}

} // namespace detail

/// How a view is computed.
struct visibility2d_options {
  std::uint64_t seed = 1; ///< splitter choice of the depth-order tree and the coverage tree's rebuilds
};

/// A plane scene's walls in a depth-order tree (the preprocessing), which
/// answers the visibility region of any eye (`view`).
template <geometry::number FT> class wall_index {
public:
  using kernel = geometry::e2::kernel<FT>;

  explicit wall_index(wall_scene<FT> scene, visibility2d_options const& options = {})
      : scene_(std::move(scene)), seed_(options.seed) {
    namespace e2 = geometry::e2;
    auto t0 = std::chrono::steady_clock::now();
    bsp::fragment_list<kernel, std::uint32_t> input;
    scene_.for_each_wall([&](std::size_t i, e2::point<FT> const& a, e2::point<FT> const& b) {
      if (a == b) return; // a repeated vertex: no wall
      input.push_back({e2::segment(a, b, i), static_cast<std::uint32_t>(i)});
    });
    // The rings' vertices in double, and each ring's box of them, for the
    // test of where the eye lies on the rings (`blocked`).
    for (auto const& r : scene_.rings) {
      auto& ds = ring_doubles_.emplace_back();
      double const inf = std::numeric_limits<double>::infinity();
      auto& box = ring_boxes_.emplace_back(std::array<double, 4>{inf, inf, -inf, -inf}); // an empty ring holds no eye
      for (auto const& p : r) {
        auto const& d = ds.emplace_back(std::array<double, 2>{geometry::to_double(p.x()), geometry::to_double(p.y())});
        box = {std::min(box[0], d[0]), std::min(box[1], d[1]), std::max(box[2], d[0]), std::max(box[3], d[1])};
      }
    }
    walls_ = input.size();
    tree_ = bsp::build_depth_order<kernel>(std::move(input), bsp::few_splits(no_cut{}, seed_));
    bsp::for_each_front_to_back(tree_, e2::point<FT>(), [&](auto const&) { ++fragments_; });
    // Each node's box: of the walls of the fragments in its subtree (input
    // coordinates, exact), children before parents.
    wall_table<FT> walls(scene_);
    boxes_.resize(tree_.interior_count());
    std::vector<std::pair<bsp::node_id, bool>> stack{{tree_.root(), false}};
    while (!stack.empty()) {
      auto [n, done] = stack.back();
      stack.pop_back();
      if (tree_.is_leaf(n)) continue;
      if (!done) {
        stack.push_back({n, true});
        stack.push_back({tree_.negative(n), false});
        stack.push_back({tree_.positive(n), false});
        continue;
      }
      auto& b = boxes_[n.index()];
      for (auto const& fr : tree_.node_data(n)) {
        for (auto const& p : walls(fr.id)) b.add(p);
        ++b.fragments;
      }
      for (auto c : {tree_.negative(n), tree_.positive(n)})
        if (!tree_.is_leaf(c)) b.add(boxes_[c.index()]);
    }
    for (auto& b : boxes_) b.finish();
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  wall_scene<FT> const& scene() const noexcept { return scene_; }
  std::size_t fragments() const noexcept { return fragments_; }
  double preprocessing_seconds() const noexcept { return seconds_; }

  /// The visibility region of `eye`.
  visibility_region<FT> view(geometry::e2::point<FT> const& eye) const {
    using namespace geometry;
    using fragment = std::vector<detail::arc_bound<FT>>;
    auto t0 = std::chrono::steady_clock::now();
    visibility_region<FT> out;
    out.eye = eye;
    auto& st = out.stats;
    st.walls = walls_;
    detail::coverage_pass<s1::kernel<FT>> pass(seed_);
    detail::hyperplane_store<s1::hyperplane<FT>> store;
    struct piece {
      s1::hyperplane<FT> from, to;
      std::int64_t wall;
    };
    std::vector<piece> visible;
    // A fragment of the pass on `bounds`, which go to the store.
    auto fragment_of = [&store](auto const& bounds) {
      store.clear();
      fragment f;
      for (auto const& b : bounds) f.push_back({&store.emplace_back(b), true});
      return f;
    };
    auto keep = [&](fragment&& p, std::int64_t wall) {
      // A piece is at most a half circle: two ends, or one bound [b], from
      // start(b) to −start(b), which is `to = b`.
      visible.push_back({*p.front().c, *p.back().c, wall});
    };
    // The directions out of the rings the eye lies on come first, covered.
    for (auto const& arc : blocked(eye))
      pass.insert(fragment_of(arc.bounds), [&](fragment&& p) { keep(std::move(p), behind_boundary); }, [](fragment&&) {});
    pass.rebuild_if_grown();
    auto const& o = eye.homogeneous();
    auto insert = [&](bsp::fragment<kernel, std::uint32_t> const& fr) {
      auto const& P = fr.piece.support.n;
      sign po = dot_sign(P, o);
      if (po == sign::zero) {
        ++st.discarded_edge_on;
        return;
      }
      ++st.fragments;
      // Each end of the fragment seen from the eye: the line through the eye
      // and the point P ∩ B, P(O)·B − B(O)·P, its normal as a point pair
      // whose positive side holds the fragment.
      auto ray = detail::through_eye<2>(po == sign::negative);
      std::vector<s1::hyperplane<FT>> ends;
      for (auto const& b : fr.piece.bounds) ends.emplace_back(construct<2>(ray, P, b.original.n, o));
      fragment f = fragment_of(ends);
      if (f.size() != 2) throw std::logic_error("svm::wall_index: a fragment is not a bounded segment");
      // [start, end] counter-clockwise: det(c₀, c₁) < 0.
      if (det_sign(f[0].line(), f[1].line()) == sign::positive) std::swap(f[0], f[1]);
      auto wall = static_cast<std::int64_t>(fr.id);
      st.hidden_pieces += pass.insert(std::move(f), [&](fragment&& p) { keep(std::move(p), wall); }, [](fragment&&) {});
      pass.rebuild_if_grown();
    };
    // Front to back through the depth order, leaving out the subtrees whose
    // box is hidden, and stopping once every direction is covered.
    auto enter = [&](bsp::node_id n) {
      auto cone = boxes_[n.index()].seen_from(eye);
      if (!cone || !pass.hidden(fragment_of(*cone))) return true;
      ++st.culled_subtrees;
      return false;
    };
    bsp::for_each_front_to_back(tree_, eye, enter, insert, [&] { return pass.all_covered(); });
    st.visible_pieces = visible.size();
    st.coverage_nodes_peak = pass.peak_interior_nodes();
    // Counter-clockwise from (1, 0); touching pieces of one wall join, and
    // gaps are arcs where nothing is seen.
    auto touch = [](piece const& p, piece const& q) { return detail::meets(p.to, q.from); };
    std::sort(visible.begin(), visible.end(), [&](piece const& a, piece const& b) { return detail::start_less(a.from, b.from); });
    std::vector<piece> joined;
    for (auto& p : visible) {
      if (!joined.empty() && joined.back().wall == p.wall && touch(joined.back(), p))
        joined.back().to = p.to;
      else
        joined.push_back(std::move(p));
    }
    if (joined.size() >= 2 && joined.back().wall == joined.front().wall && touch(joined.back(), joined.front())) {
      joined.front().from = joined.back().from;
      joined.pop_back();
    }
    if (joined.empty()) {
      out.arcs.push_back({{}, {}, no_wall, true});
    } else if (joined.size() == 1 && touch(joined[0], joined[0])) {
      out.arcs.push_back({joined[0].from, joined[0].to, joined[0].wall, true});
    } else {
      for (std::size_t i = 0; i < joined.size(); ++i) {
        auto const& p = joined[i];
        out.arcs.push_back({p.from, p.to, p.wall, false});
        auto const& q = joined[(i + 1) % joined.size()];
        if (!touch(p, q)) out.arcs.push_back({p.to.opposite(), q.from.opposite(), no_wall, false});
      }
    }
    // An arc across (1, 0), and the gap after it, start late: order by start.
    std::sort(out.arcs.begin(), out.arcs.end(), [](view_arc<FT> const& a, view_arc<FT> const& b) { return detail::start_less(a.from, b.from); });
    st.arcs = out.arcs.size();
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  }

private:
  /// An axis-aligned box of input points, exact.
  struct box {
    std::optional<std::array<FT, 4>> b; ///< xmin, ymin, xmax, ymax
    std::size_t fragments = 0;          ///< in the subtree
    void add(FT const& x0, FT const& y0, FT const& x1, FT const& y1) {
      if (!b) {
        b = std::array<FT, 4>{x0, y0, x1, y1};
        return;
      }
      auto& v = *b;
      if (x0 < v[0]) v[0] = x0;
      if (y0 < v[1]) v[1] = y0;
      if (x1 > v[2]) v[2] = x1;
      if (y1 > v[3]) v[3] = y1;
    }
    void add(geometry::e2::point<FT> const& p) { add(p.x(), p.y(), p.x(), p.y()); }
    void add(box const& o) {
      if (o.b) add((*o.b)[0], (*o.b)[1], (*o.b)[2], (*o.b)[3]);
      fragments += o.fragments;
    }
    /// Subtrees of fewer fragments are not worth a test: their fragments go in.
    static constexpr std::size_t least_tested = 8;
    /// Its corners as points, counter-clockwise from (xmin, ymin), once the box is final.
    void finish() {
      if (!b || fragments < least_tested) return;
      auto const& v = *b;
      corner = {geometry::e2::point<FT>(v[0], v[1]), geometry::e2::point<FT>(v[2], v[1]), geometry::e2::point<FT>(v[2], v[3]),
                geometry::e2::point<FT>(v[0], v[3])};
    }
    /// The bounds of the arc of directions from `eye` to the box (less than
    /// a half circle): the lines through the eye and the two corners where
    /// the box's outline turns, found from the eye's place among the box's
    /// sides; nothing when the eye is in the closed box.
    std::optional<std::array<geometry::s1::hyperplane<FT>, 2>> seen_from(geometry::e2::point<FT> const& eye) const {
      if (!b || fragments < least_tested) return std::nullopt;
      auto const& v = *b;
      int cx = eye.x() < v[0] ? -1 : eye.x() > v[2] ? 1 : 0, cy = eye.y() < v[1] ? -1 : eye.y() > v[3] ? 1 : 0;
      if (cx == 0 && cy == 0) return std::nullopt;
      // The corner with every other counter-clockwise of it, and the one with every other clockwise.
      static constexpr int first[3][3] = {{1, 0, 0}, {1, -1, 3}, {2, 2, 3}}, last[3][3] = {{3, 3, 2}, {0, -1, 2}, {0, 1, 1}};
      auto const& p = corner[static_cast<std::size_t>(first[cx + 1][cy + 1])];
      auto const& q = corner[static_cast<std::size_t>(last[cx + 1][cy + 1])];
      // (−(p−O)y, (p−O)x) and ((q−O)y, −(q−O)x) on homogeneous points: the
      // positive sides are counter-clockwise of p and clockwise of q.
      auto start = [](auto const& P, auto const& E) {
        return std::array<std::remove_cvref_t<decltype(P[0])>, 2>{E[1] * P[2] - P[1] * E[2], P[0] * E[2] - E[0] * P[2]};
      };
      auto end = [](auto const& P, auto const& E) {
        return std::array<std::remove_cvref_t<decltype(P[0])>, 2>{P[1] * E[2] - E[1] * P[2], E[0] * P[2] - P[0] * E[2]};
      };
      return std::array<geometry::s1::hyperplane<FT>, 2>{
          geometry::s1::hyperplane<FT>(geometry::construct<2>(start, p.homogeneous(), eye.homogeneous())),
          geometry::s1::hyperplane<FT>(geometry::construct<2>(end, q.homogeneous(), eye.homogeneous()))};
    }
    std::array<geometry::e2::point<FT>, 4> corner;
  };

  struct no_cut {
    template <class Items> std::optional<geometry::e2::hyperplane<FT>> operator()(Items const&) const { return std::nullopt; }
  };

  /// The arcs of directions that leave the polygons whose boundary the eye
  /// lies on: for each polygon, the union of what its rings' edges and
  /// vertices at the eye leave out; of several polygons, what all of them do.
  std::vector<geometry::s1::polytope<FT>> blocked(geometry::e2::point<FT> const& eye) const {
    using namespace geometry;
    std::vector<std::pair<std::size_t, std::vector<s1::polytope<FT>>>> per; // polygon, its arcs
    std::vector<s1::point<FT>> critical; // the directions of the edges at the eye
    auto dir = [&](e2::point<FT> const& p) {
      return s1::point<FT>(std::array<FT, 2>{FT(p.x() - eye.x()), FT(p.y() - eye.y())});
    };
    // The eye in double: where it is on a ring exactly, it is there in
    // double too (rounding is monotone), so the rings and edges whose boxes
    // of doubles do not hold it are passed over without exact arithmetic.
    double ex = to_double(eye.x()), ey = to_double(eye.y());
    auto holds = [ex, ey](double x0, double y0, double x1, double y1) { return x0 <= ex && ex <= x1 && y0 <= ey && ey <= y1; };
    for (std::size_t ri = 0; ri < scene_.rings.size(); ++ri) {
      auto const& box = ring_boxes_[ri];
      if (!holds(box[0], box[1], box[2], box[3])) continue;
      auto const& r = scene_.rings[ri];
      auto const& rd = ring_doubles_[ri];
      std::size_t polygon = ri < scene_.ring_polygon.size() ? scene_.ring_polygon[ri] : ri;
      auto arcs_of = [&]() -> std::vector<s1::polytope<FT>>& {
        for (auto& [q, arcs] : per)
          if (q == polygon) return arcs;
        return per.emplace_back(polygon, std::vector<s1::polytope<FT>>{}).second;
      };
      std::size_t k = r.size();
      for (std::size_t i = 0; i < k; ++i) {
        auto const &fa = rd[i], &fb = rd[(i + 1) % k];
        if (!holds(std::min(fa[0], fb[0]), std::min(fa[1], fb[1]), std::max(fa[0], fb[0]), std::max(fa[1], fb[1]))) continue;
        auto const &a = r[i], &b = r[(i + 1) % k];
        if (a == b) continue;
        if (a == eye) {
          // At a vertex: from the previous distinct vertex counter-clockwise to the next.
          std::size_t j = (i + k - 1) % k;
          while (j != i && r[j] == eye) j = (j + k - 1) % k;
          auto more = detail::arcs_between(dir(r[j]), dir(b));
          auto& arcs = arcs_of();
          arcs.insert(arcs.end(), more.begin(), more.end());
          critical.push_back(dir(r[j]));
          critical.push_back(dir(b));
          continue;
        }
        if (b == eye || e2::orientation(a, b, eye) != sign::zero) continue;
        auto da = dir(a), db = dir(b);
        if (dot_sign(da, db) != sign::negative) continue; // on the line, not between the ends
        // Inside an edge: the half circle on its right, from a − b to b − a.
        arcs_of().push_back({{s1::hyperplane_at(da)}});
        critical.push_back(da);
        critical.push_back(db);
      }
    }
    if (per.size() <= 1) return per.empty() ? std::vector<s1::polytope<FT>>{} : std::move(per[0].second);
    // Several polygons: between consecutive edge directions every polygon
    // either blocks all directions or none; a sector is blocked when each
    // polygon blocks a direction strictly inside it.
    std::sort(critical.begin(), critical.end(), [](auto const& u, auto const& v) { return detail::angle_less(u, v); });
    critical.erase(std::unique(critical.begin(), critical.end(), [](auto const& u, auto const& v) { return detail::same_direction(u, v); }),
                   critical.end());
    std::vector<s1::polytope<FT>> out;
    for (std::size_t i = 0; i < critical.size(); ++i) {
      auto const &p = critical[i], &q = critical[(i + 1) % critical.size()];
      sign turn = det_sign(p, q);
      s1::point<FT> t = turn == sign::positive                               ? s1::point<FT>(std::array<FT, 2>{FT(p[0] + q[0]), FT(p[1] + q[1])})
                        : turn == sign::negative                             ? s1::point<FT>(std::array<FT, 2>{FT(-p[0] - q[0]), FT(-p[1] - q[1])})
                        : dot_sign(p, q) == sign::negative ? s1::point<FT>(std::array<FT, 2>{FT(-p[1]), p[0]})
                                                           : s1::point<FT>(-p);
      bool all = std::all_of(per.begin(), per.end(), [&](auto const& pa) {
        return std::any_of(pa.second.begin(), pa.second.end(),
                           [&](s1::polytope<FT> const& arc) { return s1::classify(arc, t) == oriented_side::positive; });
      });
      if (all) {
        auto more = detail::arcs_between(p, q);
        out.insert(out.end(), more.begin(), more.end());
      }
    }
    return out;
  }

  wall_scene<FT> scene_;
  std::uint64_t seed_;
  std::size_t walls_ = 0, fragments_ = 0;
  double seconds_ = 0;
  bsp::depth_order_tree<kernel, std::uint32_t> tree_;
  std::vector<box> boxes_; ///< of each interior node of `tree_`
  std::vector<std::vector<std::array<double, 2>>> ring_doubles_; ///< each ring's vertices in double
  std::vector<std::array<double, 4>> ring_boxes_;                 ///< each ring's box of them: xmin, ymin, xmax, ymax
};

/// The visibility region of `eye` among `scene`'s walls (one query: the
/// preprocessing included).
template <geometry::number FT>
visibility_region<FT> visibility(wall_scene<FT> scene, geometry::e2::point<FT> const& eye, visibility2d_options const& options = {}) {
  return wall_index<FT>(std::move(scene), options).view(eye);
}

/// The arc of `region` that holds direction `d` (an arc's start belongs to it).
template <geometry::number FT>
view_arc<FT> const& locate(visibility_region<FT> const& region, geometry::s1::point<FT> const& d) {
  auto const& a = region.arcs;
  if (a.size() == 1) return a[0];
  // The last arc starting at or before d counter-clockwise from (1, 0); before the first: the last.
  auto it = std::upper_bound(a.begin(), a.end(), d, [](auto const& dir, view_arc<FT> const& arc) {
    return detail::angle_less(dir, arc.start());
  });
  return it == a.begin() ? a.back() : *std::prev(it);
}

/// Where the line through `eye` in direction `d` meets the line of `wall`
/// (they are not parallel): an output construction, exact.
template <geometry::number FT>
geometry::e2::point<FT> hit_point(geometry::e2::point<FT> const& eye, geometry::s1::point<FT> const& d,
                                  std::array<geometry::e2::point<FT>, 2> const& wall) {
  FT ex = wall[1].x() - wall[0].x(), ey = wall[1].y() - wall[0].y();
  FT den = d[0] * ey - d[1] * ex;
  if (den == 0) throw std::logic_error("svm::hit_point: the direction is parallel to the wall");
  FT t = ((wall[0].x() - eye.x()) * ey - (wall[0].y() - eye.y()) * ex) / den;
  return geometry::e2::point<FT>(FT(eye.x() + t * d[0]), FT(eye.y() + t * d[1]));
}

/// The boundary of a bounded region: for each arc counter-clockwise, the
/// points of its wall at its start and end (the eye for arcs behind the
/// boundary), repeated points once.  Nothing when the region is unbounded.
template <geometry::number FT>
std::optional<std::vector<geometry::e2::point<FT>>> boundary(visibility_region<FT> const& region, wall_scene<FT> const& scene) {
  if (!region.bounded()) return std::nullopt;
  std::vector<geometry::e2::point<FT>> out;
  auto put = [&](geometry::e2::point<FT> p) {
    if (out.empty() || !(out.back() == p)) out.push_back(std::move(p));
  };
  wall_table<FT> walls(scene);
  for (auto const& a : region.arcs) {
    if (a.wall == behind_boundary) {
      put(region.eye);
      continue;
    }
    auto w = walls(static_cast<std::size_t>(a.wall));
    if (a.whole) {
      // One wall all around: impossible for a segment, which subtends less than a half circle.
      throw std::logic_error("svm::boundary: one wall seen in every direction");
    }
    put(hit_point(region.eye, a.start(), w));
    put(hit_point(region.eye, a.end(), w));
  }
  while (out.size() >= 2 && out.front() == out.back()) out.pop_back();
  return out;
}

/// The exact area of a bounded region (the triangles from the eye to each
/// arc's piece of wall); nothing when it is unbounded.
template <geometry::number FT> std::optional<FT> area(visibility_region<FT> const& region, wall_scene<FT> const& scene) {
  if (!region.bounded()) return std::nullopt;
  FT twice(0);
  auto const& e = region.eye;
  wall_table<FT> walls(scene);
  for (auto const& a : region.arcs) {
    if (a.wall == behind_boundary) continue;
    auto w = walls(static_cast<std::size_t>(a.wall));
    auto p = hit_point(e, a.start(), w), q = hit_point(e, a.end(), w);
    twice += (p.x() - e.x()) * (q.y() - e.y()) - (p.y() - e.y()) * (q.x() - e.x());
  }
  return FT(twice / 2);
}

} // namespace svm
