/// @file
/// Construction of the spherical visibility map (the paper's section 3): a
/// depth-order BSP tree of the scene, traversed front to back from the eye;
/// each fragment, described on the sphere by the circles through the eye and
/// its edges' lines, descends an S2 coverage tree (`bsp::coverage_tree`,
/// covered or free, rebuilt from its covered boundary when it has grown fourfold);
/// what reaches a free leaf is visible and is kept, and its flagged edges
/// bound the cell it covers.  The visible pieces, which do not overlap, then
/// go in random order into a tree whose leaves are the faces of the map T,
/// cut with `split_edge` and `split_face` as in the paper; a point-set tree
/// built from T's edges locates directions.  (`keep_construction_tree`, and
/// builds over double: the paper's one pass, its tree V as the locator.)
#pragma once

#include "dcel.hpp"

#include <bsp/coverage.hpp>
#include <bsp/depth_order.hpp>
#include <bsp/point_set.hpp>
#include <bsp/splitter.hpp>
#include <bsp/tree.hpp>
#include <boost/pending/disjoint_sets.hpp>
#include <geometry/e3.hpp>
#include <geometry/hash.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <deque>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <span>
#include <stdexcept>
#include <type_traits>

namespace svm {

/// An input polygon: convex, planar, vertices counter-clockwise seen from its
/// front; `face` is the index reported for it (its face in the input file).
template <geometry::number FT> struct polygon {
  std::vector<geometry::e3::point<FT>> vertices;
  std::uint32_t face;
};

/// A great circle given by its normal, in doubles: it is read exactly (a
/// double is a rational of bounded size), so predicates on it keep their
/// degree bound.  Its positive side is where `normal · d > 0`.
using circle_normal = std::array<double, 3>;

/// How a map is built.
struct build_options {
  bool simplify = true;        ///< join adjacent faces with equal labels
  bool cull_backfaces = false; ///< drop polygons whose front faces away from the eye
  /// Drop the polygons facing away from the eye that are proven hidden: those
  /// of closed convex solids the eye is outside of (see
  /// `detail::on_convex_solids_seen_from_outside`).  The map is the same;
  /// only polygons given one by one (`build` of `polygon`s), over exact
  /// numbers.
  bool cull_convex_solids = true;
  std::uint64_t seed = 1;      ///< splitter choice of the depth-order tree
  /// A convex spherical polygon (its circles, the inside on their positive
  /// sides): only directions inside it are mapped; the rest is one face
  /// labelled `clipped`, and no scene polygon is projected there.  This is
  /// the exact clipping of a view frustum.
  std::vector<circle_normal> window{};
  /// A convex spherical polygon left out of the map in the same way (its
  /// inside labelled `clipped`): for projections that cannot show a small
  /// neighbourhood of one direction.
  std::vector<circle_normal> exclude{};
  /// Great circles cut through the whole map first and kept by
  /// simplification (a panorama's seam and poles).
  std::vector<circle_normal> cuts{};
  /// Keep the paper's tree V (every cell ever split, covered or not) and
  /// locate directions with it, instead of a coverage tree whose covered
  /// siblings collapse and a locator built from the final map.  Same map,
  /// slower: for comparison and tests.  Builds over `double` always do.
  bool keep_construction_tree = false;
  /// Called with the fraction of the scene's fragments inserted so far (0 to
  /// 1), about every percent, when set: for progress on long builds.
  std::function<void(double)> progress{};
};

/// Sizes of a map.
struct map_size {
  std::size_t vertices = 0, edges = 0, faces = 0;
};

struct build_statistics {
  std::size_t input_polygons = 0;
  std::size_t discarded_edge_on = 0;  ///< plane through the eye: no area on the sphere
  std::size_t discarded_backfacing = 0; ///< by `cull_backfaces` or `cull_convex_solids`
  std::size_t convex_solids = 0;        ///< closed convex solids the eye is outside of
  std::size_t discarded_outside_window = 0; ///< wholly outside `build_options::window`
  std::size_t fragments = 0;          ///< of the depth-order tree
  std::size_t hidden_pieces = 0;      ///< fragment pieces that reached a covered leaf (or a clipped one)
  std::size_t v_nodes = 0;            ///< interior nodes of the coverage tree at the end of the build
  std::size_t v_nodes_peak = 0;       ///< the most it ever had
  std::size_t locator_nodes = 0;      ///< interior nodes of the tree that locates directions
  double locator_seconds = 0;         ///< building it
  double depth_order_seconds = 0;     ///< building the depth-order tree
  double visible_seconds = 0;         ///< finding the visible pieces (the coverage pass; the one pass of the paper's build)
  double map_seconds = 0;             ///< making the map of the visible pieces
  double simplify_seconds = 0;        ///< simplification, the locator included
  std::size_t rebuilds = 0;           ///< of the coverage tree from its covered boundary
  std::size_t visible_pieces = 0;     ///< fragment pieces found visible
  /// What the map is made of: a polygon whose fragments were all wholly
  /// visible counts once, a fragment wholly visible once, else its visible pieces.
  std::size_t map_pieces = 0;
  std::size_t overlapping_pieces = 0; ///< visible pieces that met another's cell in the map: always 0
  std::size_t map_tree_nodes = 0;     ///< interior nodes of the tree that cut the map
  map_size unsimplified, simplified;
  std::uint64_t filter_fallbacks = 0;
  double seconds = 0;
};

/// The spherical visibility map: the half-edge map T (faces labelled with
/// the visible polygon's `face`, or −1) and a point-set tree on the sphere
/// whose leaves are T's faces, to locate directions.
template <geometry::number FT> struct visibility_map {
  using number_type = FT;
  using locator_tree = bsp::point_set<geometry::s2::kernel<FT>, index>;
  dcel<FT> map;
  /// Built from T's edges (`build_locator`), or the construction's own tree
  /// with `build_options::keep_construction_tree`.
  locator_tree locator;
  bool locator_is_construction_tree = false;
  std::uint64_t seed = 1; ///< the build's seed, which the locator's splitter order also uses
  /// For each input, whether it was left out facing away from the eye on a
  /// closed convex solid (`build_options::cull_convex_solids`): hidden
  /// wherever it lies.  Empty when no input was.
  std::vector<char> hidden_backfaces;
  /// The build's `window` circles, and whether it left directions out by
  /// `exclude` too: where the map shows the scene.
  std::vector<circle_normal> window;
  bool excluded = false;
  build_statistics stats;
};

namespace detail {

/// The tag of an edge plane of polygon i (the high bit marks scene edges).
inline constexpr geometry::hyperplane_tag edge_tag_bit = 0x80000000u;

/// The hyperplanes of one build (circles on S2, point pairs on S1), each
/// stored once where it stays put (a deque never moves its elements):
/// fragments and their pieces refer to them.
template <class Hyperplane> using hyperplane_store = std::deque<Hyperplane>;
template <geometry::number FT> using circle_store = hyperplane_store<geometry::s2::hyperplane<FT>>;

/// A bound of a fragment in the target geometry: its hyperplane, in a
/// `hyperplane_store`, and the paper's flag — true while the edge may still
/// add a node to V.  Splitting a fragment copies these, never a number.
template <class Hyperplane> struct flagged_bound {
  Hyperplane const* c;
  bool flag = true;
  auto const& line() const noexcept { return c->n; }
};
template <geometry::number FT> using sphere_bound = flagged_bound<geometry::s2::hyperplane<FT>>;

/// The hyperplane through the eye O and the meeting of hyperplanes P and B
/// (the line P ∩ B in E3, the point P ∩ B in E2), P(O)·B − B(O)·P, as the
/// first `M` coordinates of its normal: a circle of directions (M = 3) or a
/// point pair (M = 2), turned round when `flip`.  One formula for every
/// view: degree deg P + deg B + 1 in the input.
template <std::size_t M> auto through_eye(bool flip) {
  return [flip](auto const& P, auto const& B, auto const& O) {
    auto po = geometry::dot(P, O), bo = geometry::dot(B, O);
    std::array<std::remove_cvref_t<decltype(P[0])>, M> n;
    for (std::size_t i = 0; i < M; ++i) {
      auto q = po * B[i] - bo * P[i];
      n[i] = flip ? -q : q;
    }
    return n;
  };
}

/// The fragment of an E3 polygon as seen from the eye: each bound B of the
/// polygon (in the plane P) becomes the circle of the plane through the eye
/// and the line P ∩ B: `P(O)·B − B(O)·P`, whose normal has degree
/// deg P + deg B + 1 in the input — bounded, whatever the depth of the trees.
/// The circles go to `store`.
template <geometry::number FT>
std::vector<sphere_bound<FT>> project(geometry::e3::sub_hyperplane<FT> const& f, geometry::e3::point<FT> const& eye,
                                      circle_store<FT>& store) {
  auto const& P = f.support.n;
  auto const& o = eye.homogeneous();
  auto circle = through_eye<3>(geometry::dot_sign(P, o) == geometry::sign::negative);
  std::vector<sphere_bound<FT>> out;
  out.reserve(f.bounds.size());
  for (auto const& b : f.bounds)
    out.push_back({&store.emplace_back(geometry::construct<3>(circle, P, b.original.n, o), b.original.tag), true});
  // Counter-clockwise seen from outside the sphere: det(c₀, c₁, c₂) > 0.
  if (out.size() >= 3 && det_sign(out[0].c->n, out[1].c->n, out[2].c->n) == geometry::sign::negative)
    std::reverse(out.begin(), out.end());
  return out;
}

template <geometry::number FT> provenance provenance_of(geometry::s2::hyperplane<FT> const& c) {
  return (c.tag != geometry::no_tag && (c.tag & edge_tag_bit) != 0) ? provenance::scene_edge : provenance::depth_split;
}

/// Input polygon `p` as the build takes it: its plane cut by its edge planes,
/// each tagged as a scene edge of its face.
template <geometry::number FT> geometry::e3::sub_hyperplane<FT> scene_polygon(polygon<FT> const& p) {
  auto s = geometry::e3::convex_polygon<FT>(p.vertices, p.face);
  for (auto& b : s.bounds) b.original.tag = edge_tag_bit | p.face;
  return s;
}

/// Whether circle `c` cuts the interior of face `f` of `m` (a face without edges is the whole sphere).
template <geometry::number FT> bool cuts(dcel<FT> const& m, index f, geometry::s2::hyperplane<FT> const& c) {
  index e0 = m.faces()[f].edge;
  if (e0 == none) return true;
  bool pos = false, neg = false;
  index e = e0;
  do {
    auto s = m.side(m.origin(e), c);
    pos = pos || s == geometry::sign::positive;
    neg = neg || s == geometry::sign::negative;
    e = m.next(e);
  } while (e != e0 && !(pos && neg));
  return pos && neg;
}

/// The tree that decides what is hidden during a build: its free leaves are
/// the map's faces that nothing is visible in yet.
template <geometry::number FT> using coverage = bsp::coverage_tree<geometry::s2::kernel<FT>, index>;

/// Cuts circle `c` through every face of the map it crosses (the map and the
/// coverage tree still one face per leaf), each cut adding a node to the tree.
template <geometry::number FT> void cut_everywhere(dcel<FT>& m, coverage<FT>& v, geometry::s2::hyperplane<FT> const& c) {
  std::vector<std::pair<bsp::node_id, typename coverage<FT>::place>> leaves;
  v.for_each_leaf([&](bsp::node_id n, auto at) { leaves.emplace_back(n, at); });
  index ci = none;
  for (auto const& [n, at] : leaves) {
    index f = v.as_tree().leaf_data(n);
    if (!cuts(m, f, c)) continue;
    if (ci == none) ci = m.add_circle(c, provenance::cut);
    index g = m.faces()[f].edge == none ? m.make_first_circle(ci) : m.split_face(f, ci);
    v.split(at, c, g, f);
  }
}

/// The hyperplanes of a tree's nodes, each with its opposite, stored once
/// where they stay put; `of[i]` for interior node i.  Fragments split at a
/// node take their new bounds from here.
template <class Hyperplane> struct node_hyperplanes {
  hyperplane_store<Hyperplane> store;
  std::vector<std::array<Hyperplane const*, 2>> of;
  void keep(bsp::node_id node, Hyperplane const& c) {
    if (of.size() <= node.index()) of.resize(node.index() + 1);
    auto const* pos = &store.emplace_back(c);
    of[node.index()] = {pos, &store.emplace_back(c.opposite())};
  }
  /// Every interior node of `t` (after a new tree replaced the old one); the
  /// old nodes' circles go, so nothing may still point to them.
  template <class Tree> void refresh(Tree const& t) {
    of.clear();
    store.clear();
    for (std::uint32_t i = 0; i < t.interior_count(); ++i) keep(bsp::node_id::interior(i), t.splitter(bsp::node_id::interior(i)));
  }
};

template <geometry::number FT> using node_circles = node_hyperplanes<geometry::s2::hyperplane<FT>>;

/// A fragment at a node whose circle is `g[0]` (`g[1]` its opposite): split
/// when the circle crosses it, else passed on whole, and then an edge lying
/// in the circle is in the tree already (the paper's flag reset).
template <geometry::number FT>
bsp::routed<std::vector<sphere_bound<FT>>> route(std::vector<sphere_bound<FT>>& frag,
                                                  std::array<geometry::s2::hyperplane<FT> const*, 2> const& g,
                                                  std::vector<geometry::sign>& signs) {
  using geometry::sign;
  int where = geometry::detail::polygon_side(frag, g[0]->n, signs);
  if (where == 0) {
    sphere_bound<FT> hp{g[0], false}, hn{g[1], false};
    auto r = geometry::detail::split_polygon_across(frag, hp, hn, signs);
    return {0, std::move(r.negative), std::move(r.positive)};
  }
  std::size_t k = frag.size();
  if (k <= 2) {
    // A lune's vertices lie on every circle through them, and a hemisphere
    // has none: an edge lies in g when its circle is g.
    for (auto& b : frag)
      if (geometry::parallel(b.line(), g[0]->n) != sign::zero) b.flag = false;
  } else if (signs.size() == k) {
    for (std::size_t i = 0; i < k; ++i)
      if (signs[i] == sign::zero && signs[(i + k - 1) % k] == sign::zero) frag[i].flag = false;
  }
  return {where, std::nullopt, std::nullopt};
}

/// Whether edge `i` of the spherical polygon `frag` has positive length: its
/// circle is not concurrent with its neighbours' (for three bounds or more;
/// a hemisphere's circle and a lune's half circles always are), and not zero.
template <geometry::number FT> bool proper_edge(std::vector<sphere_bound<FT>> const& frag, std::size_t i) {
  std::size_t k = frag.size();
  auto const& c = frag[i].line();
  if (k <= 2) return !(c[0] == 0 && c[1] == 0 && c[2] == 0);
  return det_sign(frag[(i + k - 1) % k].line(), c, frag[(i + 1) % k].line()) != geometry::sign::zero;
}

/// Whether face `f` (a cell not crossed by `c`) lies on the positive side of `c`.
template <geometry::number FT> bool on_positive_side(dcel<FT> const& m, index f, geometry::s2::hyperplane<FT> const& c) {
  index e0 = m.faces()[f].edge, e = e0;
  if (e0 == none) return true;
  do {
    auto s = m.side(m.origin(e), c);
    if (s != geometry::sign::zero) return s == geometry::sign::positive;
    e = m.next(e);
  } while (e != e0);
  return true;
}

/// Cuts the window's, the excluded polygon's and the free cuts' circles
/// through the map and labels the faces outside the window or inside the
/// excluded polygon `clipped`.
template <geometry::number FT> void prepare(dcel<FT>& m, coverage<FT>& v, build_options const& o) {
  using circle = geometry::s2::hyperplane<FT>;
  auto exact = [](std::vector<circle_normal> const& cs) {
    std::vector<circle> out;
    for (auto const& n : cs) {
      if (!(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2])) || (n[0] == 0 && n[1] == 0 && n[2] == 0))
        throw std::invalid_argument("svm::build: a window, exclusion or cut circle has a zero or non-finite normal");
      out.emplace_back(geometry::hvec<FT, 3>(std::array<FT, 3>{FT(n[0]), FT(n[1]), FT(n[2])}));
    }
    return out;
  };
  auto window = exact(o.window), excluded = exact(o.exclude), free_cuts = exact(o.cuts);
  for (auto const* group : {&window, &excluded, &free_cuts})
    for (auto const& c : *group) cut_everywhere(m, v, c);
  for (index f = 0; f < m.faces().size(); ++f) {
    bool out = false;
    for (auto const& c : window) out = out || !on_positive_side(m, f, c);
    if (!excluded.empty()) {
      bool in = true;
      for (auto const& c : excluded) in = in && on_positive_side(m, f, c);
      out = out || in;
    }
    if (out) m.face_at(f).label = clipped;
  }
  // What is clipped is covered: nothing is ever visible there.
  std::vector<std::pair<bsp::node_id, typename coverage<FT>::place>> leaves;
  v.for_each_leaf([&](bsp::node_id n, auto at) { leaves.emplace_back(n, at); });
  for (auto const& [n, at] : leaves)
    if (m.faces()[v.as_tree().leaf_data(n)].label != -1 && !v.is_covered(n)) v.cover(at, n);
}

/// The visibility pass of a build (pass 1): fragments, front to back, into a
/// coverage tree that knows only covered and free.  What reaches free space
/// is visible: its flagged edges of positive length bound the cell it covers.
/// When the tree has grown fourfold (and past 256 nodes) it is rebuilt from
/// the boundary of the covered region, so that what was cut through the free
/// space and through the covered region goes: a rebuild costs a few times
/// what an insertion pays per node, and on scenes whose covered boundary
/// stays complex it shrinks the tree little.  After a rebuild that more than
/// halved it (free space cut up by earlier pieces, as on Platforms), it is
/// rebuilt when it has doubled.
///
/// The pass is written once for every target geometry `K` of a view: the
/// sphere S2 (central views, and parallel views through
/// `svm::view_from_infinity`) and the circle S1 (2D visibility).  A
/// fragment is a list of `flagged_bound`s; `route(fragment, node's
/// hyperplanes, signs)` and `proper_edge(fragment, i)`, found by
/// argument-dependent lookup, are the target's own.
template <class K> class coverage_pass {
public:
  using hyperplane = typename K::hyperplane;
  using fragment = std::vector<flagged_bound<hyperplane>>;
  using tree_type = bsp::coverage_tree<K, index>;

  /// A tree with one free leaf; `init(tree)` may cut it and cover cells
  /// first (a window, say) before any fragment comes.
  template <class Init = void (*)(tree_type&)>
  explicit coverage_pass(std::uint64_t seed, Init&& init = [](tree_type&) {}) : seed_(seed) {
    init(cover_);
    circles_.refresh(cover_.as_tree());
    limit_ = std::max(least_rebuild, growth_ * cover_.interior_nodes());
  }

  /// Inserts `frag`, which lies behind every fragment inserted before it:
  /// `visible(piece)` for each part that reaches free space (the cell it
  /// covers is then covered), `hidden(piece)` for each part that reaches
  /// covered space.  Pieces' circles are `frag`'s and the tree's, which last
  /// until the next `rebuild_if_grown`.  Returns the number of hidden parts.
  template <class Visible, class Hidden> std::size_t insert(fragment frag, Visible&& visible, Hidden&& hidden) {
    auto visit = [&](fragment&& piece, bsp::node_id leaf, typename tree_type::place at) {
      cover_cell(piece, leaf, at);
      visible(std::move(piece));
    };
    return cover_.insert(std::move(frag), [&](fragment& p, bsp::node_id n) { return route(p, circles_.of[n.index()], signs_); },
                         visit, hidden);
  }

  /// Inserts `frag` as `insert` does, and calls `part(piece, visible)` for
  /// each maximal part of it that the tree's cells leave wholly visible or
  /// wholly hidden (`bsp::coverage_tree::insert_merged`).  Returns the number
  /// of hidden cells.
  template <class Part> std::size_t insert_merged(fragment frag, Part&& part) {
    return cover_.insert_merged(
        std::move(frag), [&](fragment& p, bsp::node_id n) { return route(p, circles_.of[n.index()], signs_); },
        [&](fragment&& piece, bsp::node_id leaf, typename tree_type::place at) { cover_cell(std::move(piece), leaf, at); }, part);
  }

  /// Whether every part of `frag` would reach covered space (nothing of it
  /// is visible); the tree is left as it is.
  bool hidden(fragment frag) {
    std::vector<std::pair<bsp::node_id, fragment>> stack;
    stack.emplace_back(cover_.root(), std::move(frag));
    auto const& t = cover_.as_tree();
    while (!stack.empty()) {
      auto [n, p] = std::move(stack.back());
      stack.pop_back();
      if (t.is_leaf(n)) {
        if (!cover_.is_covered(n)) return false;
        continue;
      }
      auto r = route(p, circles_.of[n.index()], signs_);
      if (r.side != 0) {
        stack.emplace_back(t.child(n, r.side), std::move(p));
        continue;
      }
      if (r.negative) stack.emplace_back(t.negative(n), std::move(*r.negative));
      if (r.positive) stack.emplace_back(t.positive(n), std::move(*r.positive));
    }
    return true;
  }

  /// Whether the whole target is covered: nothing more can be visible.
  bool all_covered() const {
    auto r = cover_.root();
    return cover_.as_tree().is_leaf(r) && cover_.is_covered(r);
  }

  /// Rebuilds the tree when it has grown past its limit; whether it did.
  /// A rebuild that at least halved the tree (the covered region is simpler
  /// than its history: boxes on a floor) sets the next at twice the new
  /// size; one that did not (many separate visible regions: random cubes)
  /// sets it at eight times, since recomputing the boundary then costs more
  /// than the smaller tree saves.
  bool rebuild_if_grown() {
    if (cover_.interior_nodes() <= limit_) return false;
    std::size_t before = cover_.interior_nodes();
    cover_.rebuild(bsp::random_order(seed_ + rebuilds_));
    circles_.refresh(cover_.as_tree());
    ++rebuilds_;
    growth_ = 2 * cover_.interior_nodes() < before ? 2 : 8;
    limit_ = std::max(least_rebuild, growth_ * cover_.interior_nodes());
    return true;
  }

  std::size_t interior_nodes() const noexcept { return cover_.interior_nodes(); }
  std::size_t peak_interior_nodes() const noexcept { return cover_.peak_interior_nodes(); }
  std::size_t rebuilds() const noexcept { return rebuilds_; }

private:
  /// The visible `piece` in the free leaf `leaf` hanging at `at`: its
  /// flagged edges of positive length (not lying in a circle of the path:
  /// `proper_edge`) cut the cell, and the cell inside is covered.
  void cover_cell(fragment const& piece, bsp::node_id leaf, typename tree_type::place at) {
    for (std::size_t i = 0; i < piece.size(); ++i) {
      auto const& b = piece[i];
      if (!b.flag || !proper_edge(piece, i)) continue;
      bsp::node_id node = cover_.split(at, *b.c, index{0}, index{0});
      circles_.keep(node, *b.c);
      at = {node, +1};
      leaf = cover_.as_tree().positive(node);
    }
    cover_.cover(at, leaf);
  }

  static constexpr std::size_t least_rebuild = 256;
  tree_type cover_{index{0}, true};
  node_hyperplanes<hyperplane> circles_;
  std::vector<geometry::sign> signs_;
  std::uint64_t seed_;
  std::size_t growth_ = 4, limit_ = 0, rebuilds_ = 0;
};

/// The visibility pass of a central view on the sphere, with the window,
/// exclusion and free cuts of `o` in its tree from the start.
template <geometry::number FT> using sphere_pass = coverage_pass<geometry::s2::kernel<FT>>;
template <geometry::number FT> sphere_pass<FT> make_sphere_pass(build_options const& o) {
  return sphere_pass<FT>(o.seed, [&o](coverage<FT>& tree) {
    dcel<FT> scratch;
    prepare(scratch, tree, o);
  });
}

/// The arc of the map's half-edge `e` (even: it runs about its table
/// circle), bounded by circles through its endpoints taken from the
/// endpoints' own pairs: input-derived, so its predicates keep their degree.
template <geometry::number FT> geometry::s2::sub_hyperplane<FT> edge_arc(dcel<FT> const& m, index e) {
  using geometry::sign;
  auto const& C = m.circles();
  auto const& support = C[m.half_edges()[e].circle];
  // A circle through u, other than the support, oriented with w on its positive side.
  auto bound_at = [&](index u, index w) {
    auto const& V = m.vertices()[u];
    auto const* b = &C[V.a];
    if (geometry::parallel(b->n, support.n) != sign::zero) b = &C[V.b];
    auto s = m.side(w, *b);
    if (s == sign::zero) throw std::logic_error("svm: a map edge is not a minor arc");
    return s == sign::positive ? *b : b->opposite();
  };
  index u = m.origin(e), w = m.target(e);
  auto half = geometry::s2::split(geometry::s2::whole_circle(support), bound_at(u, w));
  if (!half.positive) throw std::logic_error("svm: a map edge has an empty arc");
  auto arc = geometry::s2::split(*half.positive, bound_at(w, u));
  if (!arc.positive) throw std::logic_error("svm: a map edge has an empty arc");
  return std::move(*arc.positive);
}

/// A point-set tree whose leaves are the faces of `m`: an autopartition of
/// its edges in random order (expected O(n log n) nodes for n edges).
template <geometry::number FT> typename visibility_map<FT>::locator_tree build_locator(dcel<FT> const& m, std::uint64_t seed) {
  using K = geometry::s2::kernel<FT>;
  std::vector<bsp::boundary_piece<K, index>> pieces;
  auto const& he = m.half_edges();
  pieces.reserve(he.size() / 2);
  for (index e = 0; e < he.size(); e += 2) pieces.push_back({edge_arc(m, e), he[e + 1].face, he[e].face});
  return bsp::build_partition<K, index>(std::move(pieces), index{0}, bsp::random_order(seed));
}

/// Builds `vm.locator` from the map, with its statistics.
template <geometry::number FT> void rebuild_locator(visibility_map<FT>& vm, std::uint64_t seed = 1) {
  auto t0 = std::chrono::steady_clock::now();
  vm.locator = build_locator(vm.map, seed);
  vm.locator_is_construction_tree = false;
  vm.stats.locator_nodes = vm.locator.statistics().interior_nodes;
  vm.stats.locator_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace detail

/// Simplifies `vm` in place: removes every edge between faces with equal
/// labels, so that each connected visible region is one face (its holes are
/// further boundary cycles); the locator is rebuilt (or, for the
/// construction tree, its leaves follow their faces).
template <geometry::number FT> void simplify(visibility_map<FT>& vm);

namespace detail {

/// The build over `count` convex inputs: `shape_of(i)` is input i as an
/// `e3::sub_hyperplane` (bounded, its bounds tagged), `corners_of(i)` its
/// homogeneous vertices (for the window's discard), `label_of(i)` what the
/// map reports where it is visible; `hidden_if_back(i)` tells that input i
/// is hidden when it faces away from the eye.
template <geometry::number FT, class Shape, class Corners, class Label, class HiddenIfBack>
visibility_map<FT> build_map(std::size_t count, Shape&& shape_of, Corners&& corners_of, Label&& label_of,
                             HiddenIfBack&& hidden_if_back, geometry::e3::point<FT> const& eye,
                             build_options const& options) {
  using namespace geometry;
  using K3 = e3::kernel<FT>;
  auto t0 = std::chrono::steady_clock::now();
  auto fallbacks0 = filter_stats().fallbacks;
  visibility_map<FT> vm;
  vm.seed = options.seed;
  vm.window = options.window;
  vm.excluded = !options.exclude.empty();
  auto& st = vm.stats;
  st.input_polygons = count;

  // 1. The polygons, their edge planes tagged as scene edges; discards.
  // A polygon whose every vertex lies on the negative side of one of the
  // window's circles, or on it, shows nothing inside the window: the cone of
  // its directions is in that closed half-space.  (Exact: the circles' doubles
  // are rationals.)
  for (auto const* group : {&options.window, &options.exclude, &options.cuts})
    for (auto const& n : *group)
      if (!(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2])) || (n[0] == 0 && n[1] == 0 && n[2] == 0))
        throw std::invalid_argument("svm::build: a window, exclusion or cut circle has a zero or non-finite normal");
  std::vector<hvec<FT, 4>> window;
  for (auto const& n : options.window) window.emplace_back(std::array<FT, 4>{FT(n[0]), FT(n[1]), FT(n[2]), FT(0)});
  auto outside_window = [&](std::uint32_t i) {
    auto toward = [](auto const& q, auto const& o, auto const& w) {
      return (w[0] * q[0] + w[1] * q[1] + w[2] * q[2]) * o[3] - (w[0] * o[0] + w[1] * o[1] + w[2] * o[2]) * q[3];
    };
    auto const corners = corners_of(i);
    for (auto const& w : window) {
      bool all = true;
      for (auto const& q : corners)
        if (filtered_sign(toward, q, eye.homogeneous(), w) == sign::positive) {
          all = false;
          break;
        }
      if (all) return true;
    }
    return false;
  };
  // Fragments carry the index of their input.
  bsp::fragment_list<K3, std::uint32_t> input;
  for (std::uint32_t i = 0; i < count; ++i) {
    if (!window.empty() && outside_window(i)) {
      ++st.discarded_outside_window;
      continue;
    }
    auto s = shape_of(i);
    auto side = e3::side(s.support, eye);
    if (side == oriented_side::on) {
      ++st.discarded_edge_on;
      continue;
    }
    if (side == oriented_side::negative && (options.cull_backfaces || hidden_if_back(i))) {
      ++st.discarded_backfacing;
      if (!options.cull_backfaces) {
        vm.hidden_backfaces.resize(count, 0);
        vm.hidden_backfaces[i] = 1;
      }
      continue;
    }
    input.push_back({std::move(s), i});
  }

  // 2. The depth-order tree.
  auto t_depth = std::chrono::steady_clock::now();
  auto tree = bsp::build_depth_order<K3>(std::move(input), bsp::few_splits(geometry::e3::axis_median_cut<FT>{}, options.seed));
  st.depth_order_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_depth).count();

  // 3. Front to back: each fragment into a coverage tree.
  using fragment = std::vector<sphere_bound<FT>>;
  using place = typename coverage<FT>::place;
  auto& m = vm.map;
  std::vector<sign> signs;
  std::size_t total = 0, next_report = 0;
  if (options.progress) {
    bsp::for_each_front_to_back(tree, eye, [&](auto const&) { ++total; });
    options.progress(0.0);
  }
  auto report = [&] {
    if (options.progress && st.fragments >= next_report) {
      options.progress(static_cast<double>(st.fragments - 1) / static_cast<double>(total));
      next_report = st.fragments + total / 100 + 1;
    }
  };
  // Visible where it reaches a free leaf of `v`, whose payload is a face of
  // the map: the flagged edges cut the face, each adding a node, and the cell
  // inside is covered and labelled `label`.
  auto into_map = [&](coverage<FT>& v, node_circles<FT>& nc, fragment frag, std::int64_t label) {
    auto visit = [&](fragment&& piece, bsp::node_id leaf, place at) {
      index f = v.as_tree().leaf_data(leaf);
      for (auto const& b : piece) {
        if (!b.flag || !cuts(m, f, *b.c)) continue;
        index c = m.add_circle(*b.c, provenance_of(*b.c));
        index g = m.faces()[f].edge == none ? m.make_first_circle(c) : m.split_face(f, c);
        bsp::node_id node = v.split(at, *b.c, g, f);
        nc.keep(node, *b.c);
        at = {node, +1};
        leaf = v.as_tree().positive(node);
      }
      m.face_at(f).label = label;
      v.cover(at, leaf);
    };
    return v.insert(std::move(frag), [&](fragment& p, bsp::node_id n) { return route(p, nc.of[n.index()], signs); }, visit);
  };
  // Over double, and when asked, one pass as the paper's: the coverage tree's
  // leaves are the map's faces, and it stays the locator.  (Over double,
  // cutting the map's arcs out of their circles would round constructed bounds.)
  bool const keep_tree = options.keep_construction_tree || std::is_same_v<FT, double>;
  if (keep_tree) {
    coverage<FT> v(index{0}, false);
    prepare(m, v, options);
    node_circles<FT> nc;
    nc.refresh(v.as_tree());
    circle_store<FT> fragment_circles;
    auto t_visible = std::chrono::steady_clock::now();
    bsp::for_each_front_to_back(tree, eye, [&](auto const& fr) {
      ++st.fragments;
      report();
      fragment_circles.clear();
      st.hidden_pieces += into_map(v, nc, project(fr.piece, eye, fragment_circles), label_of(fr.id));
    });
    st.visible_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_visible).count();
    st.v_nodes = st.v_nodes_peak = st.map_tree_nodes = v.interior_nodes();
    vm.locator = std::move(v).release();
    vm.locator_is_construction_tree = true;
    st.locator_nodes = st.v_nodes;
  } else {
    // Pass 1: what is visible (`coverage_pass`).
    auto pass = make_sphere_pass<FT>(options);
    // The circles of visible pieces, for both passes; a fragment's circles
    // are made in `scratch` and moved here only when some piece of it is
    // visible, so that hidden fragments leave nothing behind.
    circle_store<FT> circles, scratch;
    struct visible_piece {
      fragment bounds;
      std::uint32_t polygon;
    };
    std::vector<visible_piece> visible;
    // Per input: its fragments, and how many of them were wholly visible.
    std::vector<std::uint32_t> fragments_of(count, 0), whole_of(count, 0);
    auto t_visible = std::chrono::steady_clock::now();
    bsp::for_each_front_to_back(tree, eye, [&](auto const& fr) {
      ++st.fragments;
      report();
      std::size_t first = visible.size();
      scratch.clear();
      fragment projected = project(fr.piece, eye, scratch);
      std::size_t hidden = pass.insert(
          projected, [&](fragment&& piece) { visible.push_back({std::move(piece), fr.id}); }, [](fragment&&) {});
      st.hidden_pieces += hidden;
      st.visible_pieces += visible.size() - first;
      ++fragments_of[fr.id];
      // Wholly visible: its pieces partition it, so the map takes it whole.
      if (hidden == 0 && visible.size() > first) {
        ++whole_of[fr.id];
        visible.resize(first);
        visible.push_back({std::move(projected), fr.id});
      }
      // The visible pieces' circles (the fragment's own and the nodes' that
      // split it) are copied to the store: the scratch is cleared for the
      // next fragment, and the nodes' circles go with a rebuild.
      if (visible.size() > first) {
        std::vector<std::pair<geometry::s2::hyperplane<FT> const*, geometry::s2::hyperplane<FT> const*>> moved;
        for (std::size_t i = first; i < visible.size(); ++i)
          for (auto& b : visible[i].bounds) {
            auto it = std::find_if(moved.begin(), moved.end(), [&](auto const& m) { return m.first == b.c; });
            if (it == moved.end()) it = moved.insert(moved.end(), {b.c, &circles.emplace_back(*b.c)});
            b.c = it->second;
          }
      }
      pass.rebuild_if_grown();
    });
    st.rebuilds = pass.rebuilds();
    st.v_nodes = pass.interior_nodes();
    st.v_nodes_peak = pass.peak_interior_nodes();
    // Neither the depth order nor the coverage tree is needed any more.
    tree = decltype(tree){};
    pass = make_sphere_pass<FT>(build_options{});
    // A polygon all of whose fragments were wholly visible is visible whole:
    // the map takes its own projection, without the depth order's cuts.
    {
      std::erase_if(visible, [&](visible_piece const& p) { return fragments_of[p.polygon] >= 2 && whole_of[p.polygon] == fragments_of[p.polygon]; });
      for (std::uint32_t i = 0; i < count; ++i)
        if (fragments_of[i] >= 2 && whole_of[i] == fragments_of[i])
          visible.push_back({project(shape_of(i), eye, circles), i});
    }
    st.map_pieces = visible.size();
    st.visible_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_visible).count();
    // Pass 2: the map from the visible pieces, which do not overlap, in
    // random order (the tree's cuts then stay few), every edge flagged again.
    auto t_map = std::chrono::steady_clock::now();
    std::mt19937_64 rng(options.seed);
    std::shuffle(visible.begin(), visible.end(), rng);
    coverage<FT> v(index{0}, true);
    prepare(m, v, options);
    node_circles<FT> mc;
    mc.refresh(v.as_tree());
    for (auto& p : visible) {
      for (auto& b : p.bounds) b.flag = true;
      st.overlapping_pieces += into_map(v, mc, std::move(p.bounds), label_of(p.polygon));
    }
    st.map_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_map).count();
    st.map_tree_nodes = v.peak_interior_nodes();
  }
  st.unsimplified = {m.vertices().size(), m.half_edges().size() / 2, m.faces().size()};
  st.simplified = st.unsimplified;
  if (options.progress) options.progress(1.0);
  auto t_simplify = std::chrono::steady_clock::now();
  if (options.simplify)
    simplify(vm);
  else if (!keep_tree)
    rebuild_locator(vm, options.seed);
  st.simplify_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_simplify).count();
  st.filter_fallbacks = filter_stats().fallbacks - fallbacks0;
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return vm;
}

/// The side tests a build spends proving solids convex: at least a million,
/// and 64 a polygon in larger scenes.
inline std::size_t convex_solid_budget(std::size_t polygons) { return std::max<std::size_t>(1u << 20, 64 * polygons); }

/// For each polygon, whether it is a face of a closed convex solid that
/// `eye` lies outside of: facing away from the eye, such a polygon is hidden
/// by the solid's own faces.  Exact; polygons found in no such solid are
/// `false`.
///
/// A solid is a set of polygons joined by shared sides, closed: every side
/// a → b (vertices welded by exact coordinates) is one polygon's, and b → a
/// exactly one other's, so the faces turn one way around it.  It is convex,
/// its faces facing out, when every vertex of it lies on or behind every face's
/// plane, one strictly.  Then each face lies in a supporting plane of the
/// convex hull P of the vertices, facing out, and a closed surface of such
/// faces covers the boundary of P.  An eye in front of some face's plane is
/// outside P; a ray from it to a point of a face it sees the back of enters
/// P before (near a point inside a face, P is the half-space behind it), where
/// a front face covers the boundary.  Sides with a vertex in their middle
/// (T-junctions) or met by more than two polygons leave their polygons
/// unproven.  The test costs faces × vertices side tests a solid; solids
/// past `budget` side tests in all are left unproven too.
template <geometry::number FT>
std::vector<char> on_convex_solids_seen_from_outside(std::vector<polygon<FT>> const& polygons,
                                                     geometry::e3::point<FT> const& eye, std::size_t budget,
                                                     std::size_t* solids = nullptr) {
  std::size_t n = polygons.size();
  std::vector<char> out(n, 0);
  if constexpr (geometry::exact_field<FT>) {
    using geometry::oriented_side;
    if (n < 4) return out;
    // Vertices welded by exact coordinates; polygon i's are ids[first[i] .. first[i + 1]).
    std::vector<std::uint32_t> ids, first{0};
    std::vector<geometry::e3::point<FT> const*> point_of;
    {
      geometry::welder<4> weld;
      for (auto const& p : polygons) {
        for (auto const& v : p.vertices) {
          auto id = weld(v.homogeneous());
          if (id == point_of.size()) point_of.push_back(&v);
          ids.push_back(id);
        }
        first.push_back(static_cast<std::uint32_t>(ids.size()));
      }
    }
    // Sides a → b (one word each) with their polygon, sorted.
    auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; };
    std::vector<std::pair<std::uint64_t, std::uint32_t>> sides;
    sides.reserve(ids.size());
    std::vector<char> open(n, 0);
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t k = first[i], e = first[i + 1]; k < e; ++k) {
        auto a = ids[k], b = ids[k + 1 < e ? k + 1 : first[i]];
        if (a == b) open[i] = 1;
        sides.emplace_back(key(a, b), i);
      }
    std::sort(sides.begin(), sides.end());
    // A side met twice the same way opens both polygons; one never met the
    // other way opens its polygon; the others join their two polygons.
    std::vector<std::uint32_t> rank(n, 0), parent(n);
    for (std::uint32_t i = 0; i < n; ++i) parent[i] = i;
    boost::disjoint_sets<std::uint32_t*, std::uint32_t*> sets(rank.data(), parent.data());
    auto once = [&](std::size_t j) {
      return (j == 0 || sides[j - 1].first != sides[j].first) && (j + 1 == sides.size() || sides[j + 1].first != sides[j].first);
    };
    for (std::size_t j = 0; j < sides.size(); ++j) {
      auto [ab, i] = sides[j];
      auto ba = (ab << 32) | (ab >> 32);
      auto it = std::lower_bound(sides.begin(), sides.end(), std::pair<std::uint64_t, std::uint32_t>{ba, 0});
      if (!once(j) || it == sides.end() || it->first != ba || !once(static_cast<std::size_t>(it - sides.begin()))) {
        open[i] = 1;
        continue;
      }
      sets.union_set(i, it->second);
    }
    decltype(sides)().swap(sides);
    // Solids: polygons sorted by set, a set named by its first polygon.
    std::vector<std::uint32_t> least(n, std::numeric_limits<std::uint32_t>::max()), set_of(n), order(n);
    for (std::uint32_t i = 0; i < n; ++i) {
      auto& l = least[sets.find_set(i)];
      l = std::min(l, i);
    }
    for (std::uint32_t i = 0; i < n; ++i) set_of[i] = least[sets.find_set(i)], order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return set_of[a] < set_of[b]; });
    std::vector<std::uint32_t> vertices;
    std::vector<char> seen(point_of.size(), 0);
    for (std::size_t lo = 0, hi; lo < n; lo = hi) {
      hi = lo;
      bool whole = true;
      for (; hi < n && set_of[order[hi]] == set_of[order[lo]]; ++hi)
        if (open[order[hi]]) whole = false;
      std::span<std::uint32_t const> faces(order.data() + lo, hi - lo);
      if (!whole || faces.size() < 4) continue;
      vertices.clear();
      for (auto f : faces)
        for (std::uint32_t k = first[f]; k < first[f + 1]; ++k)
          if (!seen[ids[k]]) seen[ids[k]] = 1, vertices.push_back(ids[k]);
      for (auto v : vertices) seen[v] = 0;
      if (faces.size() * vertices.size() > budget) continue;
      budget -= faces.size() * vertices.size();
      bool convex = true, strict = false, outside = false;
      for (auto f : faces) {
        auto const& p = polygons[f].vertices;
        auto plane = geometry::e3::plane_through(p[0], p[1], p[2]);
        if (plane.n.is_zero()) {
          convex = false;
          break;
        }
        if (geometry::e3::side(plane, eye) == oriented_side::positive) outside = true;
        for (auto v : vertices) {
          auto side = geometry::e3::side(plane, *point_of[v]);
          if (side == oriented_side::positive) {
            convex = false;
            break;
          }
          if (side == oriented_side::negative) strict = true;
        }
        if (!convex) break;
      }
      if (!(convex && strict && outside)) continue;
      for (auto f : faces) out[f] = 1;
      if (solids) ++*solids;
    }
  }
  return out;
}

} // namespace detail

/// Builds the visibility map of `polygons` seen from `eye`.
template <geometry::number FT>
visibility_map<FT> build(std::vector<polygon<FT>> const& polygons, geometry::e3::point<FT> const& eye,
                         build_options const& options = {}) {
  auto shape = [&](std::uint32_t i) { return detail::scene_polygon(polygons[i]); };
  auto corners = [&](std::uint32_t i) {
    std::vector<geometry::hvec<FT, 4>> out;
    for (auto const& q : polygons[i].vertices) out.push_back(q.homogeneous());
    return out;
  };
  auto label = [&](std::uint32_t i) { return static_cast<std::int64_t>(polygons[i].face); };
  std::size_t solids = 0;
  std::vector<char> hidden;
  if (options.cull_convex_solids && !options.cull_backfaces)
    hidden = detail::on_convex_solids_seen_from_outside(polygons, eye, detail::convex_solid_budget(polygons.size()), &solids);
  auto hidden_if_back = [&](std::uint32_t i) { return !hidden.empty() && hidden[i] != 0; };
  auto vm = detail::build_map<FT>(polygons.size(), shape, corners, label, hidden_if_back, eye, options);
  vm.stats.convex_solids = solids;
  return vm;
}

/// An input polygon given by planes: its plane and bounding planes (a
/// bounded `e3::sub_hyperplane`, counter-clockwise seen from its plane's
/// positive side), and the label the map reports where it is visible.  The
/// planes must be input-derived (as those of `e3::convex_polygon`, or planes
/// through a point and such a polygon's edges, as shadows make them), so
/// that every predicate keeps its degree bound.
template <geometry::number FT> struct convex_piece {
  geometry::e3::sub_hyperplane<FT> shape;
  std::int64_t label = 0;
};

/// Builds the visibility map of convex `pieces` seen from `eye`.
template <geometry::number FT>
visibility_map<FT> build(std::vector<convex_piece<FT>> const& pieces, geometry::e3::point<FT> const& eye,
                         build_options const& options = {}) {
  auto shape = [&](std::uint32_t i) { return pieces[i].shape; };
  auto corners = [&](std::uint32_t i) { return geometry::e3::homogeneous_vertices(pieces[i].shape); };
  auto label = [&](std::uint32_t i) { return pieces[i].label; };
  return detail::build_map<FT>(pieces.size(), shape, corners, label, [](std::uint32_t) { return false; }, eye, options);
}

namespace detail {

/// Removes every vertex where exactly two edges meet on one great circle,
/// joining them, as long as the joined edge stays a minor arc; compacts the tables.
template <geometry::number FT>
void merge_collinear(std::vector<typename dcel<FT>::vertex>& vertices, std::vector<typename dcel<FT>::half_edge>& edges,
                     std::vector<typename dcel<FT>::face>& faces, dcel<FT> const& table) {
  using geometry::sign;
  auto const& C = table.circles();
  auto point = [&](index v) { return cross(C[vertices[v].a].n, C[vertices[v].b].n); };
  auto normal_sign = [](index e) { return (e & 1u) ? sign::negative : sign::positive; };
  std::vector<index> out(vertices.size(), none);
  for (index e = 0; e < edges.size(); ++e) out[edges[e].origin] = e;
  std::vector<char> dead_edge(edges.size(), 0), dead_vertex(vertices.size(), 0);
  for (index v = 0; v < vertices.size(); ++v) {
    index out1 = out[v];
    if (out1 == none) continue;
    index out2 = edges[out1 ^ 1u].next;
    if (out2 == out1 || edges[out2 ^ 1u].next != out1) continue; // degree other than 2
    index e1 = out1 ^ 1u, e2 = out2; // u → v → w along one face
    auto par = geometry::parallel(C[edges[e1].circle].n, C[edges[e2].circle].n) * normal_sign(e1) * normal_sign(e2);
    if (par != sign::positive) continue;
    index u = edges[out1 ^ 1u].origin, w = edges[e2 ^ 1u].origin;
    if (u == w) continue;
    auto n1 = C[edges[e1].circle].n;
    if (normal_sign(e1) == sign::negative) n1 = -n1;
    if (det_sign(n1, point(u), point(w)) != sign::positive) continue; // the joined arc would not be minor
    // e1 now runs u → w and its twin w → u; e2 and its twin go.
    index t2 = e2 ^ 1u;
    edges[e1].next = edges[e2].next;
    edges[edges[e2].next].prev = e1;
    edges[out1].origin = w;
    edges[out1].prev = edges[t2].prev;
    edges[edges[t2].prev].next = out1;
    if (faces[edges[e2].face].edge == e2) faces[edges[e2].face].edge = e1;
    if (faces[edges[t2].face].edge == t2) faces[edges[t2].face].edge = out1;
    if (out[w] == t2) out[w] = out1;
    dead_edge[e2] = dead_edge[t2] = 1;
    dead_vertex[v] = 1;
    out[v] = none;
  }
  // Compact, keeping twins in even/odd pairs.
  std::vector<index> ne(edges.size(), none), nv(vertices.size(), none);
  std::vector<typename dcel<FT>::vertex> v2;
  for (index v = 0; v < vertices.size(); ++v)
    if (!dead_vertex[v]) nv[v] = static_cast<index>(v2.size()), v2.push_back(vertices[v]);
  index k = 0;
  for (index e = 0; e < edges.size(); ++e)
    if (!dead_edge[e]) ne[e] = k++;
  std::vector<typename dcel<FT>::half_edge> e2s;
  for (index e = 0; e < edges.size(); ++e) {
    if (dead_edge[e]) continue;
    auto h = edges[e];
    h.origin = nv[h.origin];
    h.next = ne[h.next];
    h.prev = ne[h.prev];
    e2s.push_back(h);
  }
  for (auto& f : faces)
    if (f.edge != none) f.edge = ne[f.edge];
  vertices = std::move(v2);
  edges = std::move(e2s);
}

} // namespace detail

template <geometry::number FT> void simplify(visibility_map<FT>& vm) {
  auto& m = vm.map;
  auto const& he = m.half_edges();
  auto const& faces = m.faces();
  std::size_t ne = he.size();
  // Faces joined across removed edges.
  boost::disjoint_sets_with_storage<> joined(faces.size());
  auto find = [&](index x) { return static_cast<index>(joined.find_set(x)); };
  std::vector<char> keep(ne, 0);
  for (index e = 0; e < ne; e += 2) {
    index a = he[e].face, b = he[e + 1].face;
    bool kept_cut = m.circle_provenance()[he[e].circle] == provenance::cut && faces[a].label != clipped;
    if (faces[a].label != faces[b].label || kept_cut) {
      keep[e] = keep[e + 1] = 1;
    } else {
      joined.union_set(a, b);
    }
  }
  // New indices: kept edges in pairs (keeping parity), vertices with a kept edge, face classes.
  std::vector<index> new_edge(ne, none), new_vertex(m.vertices().size(), none), new_face(faces.size(), none);
  std::vector<typename dcel<FT>::vertex> vertices;
  std::vector<typename dcel<FT>::half_edge> edges;
  std::vector<typename dcel<FT>::face> out_faces;
  for (index f = 0; f < faces.size(); ++f)
    if (find(f) == f) {
      new_face[f] = static_cast<index>(out_faces.size());
      out_faces.push_back({faces[f].label, none});
    }
  for (index f = 0; f < faces.size(); ++f) new_face[f] = new_face[find(f)];
  for (index e = 0; e < ne; ++e) {
    if (!keep[e]) continue;
    index o = he[e].origin;
    if (new_vertex[o] == none) {
      new_vertex[o] = static_cast<index>(vertices.size());
      vertices.push_back(m.vertices()[o]);
    }
    new_edge[e] = static_cast<index>(edges.size());
    edges.push_back({new_vertex[o], none, none, new_face[he[e].face], he[e].circle});
  }
  // Around each vertex the kept edges keep their old rotation, o → next(twin(o)):
  // the next kept half-edge after twin(o) is the first kept one in that rotation.
  for (index e = 0; e < ne; ++e) {
    if (!keep[e]) continue;
    index t = dcel<FT>::twin(e); // ends where e starts
    index o = he[t].next;
    while (!keep[o]) o = he[dcel<FT>::twin(o)].next;
    edges[new_edge[t]].next = new_edge[o];
    edges[new_edge[o]].prev = new_edge[t];
  }
  for (auto& f : out_faces) f.edge = none;
  for (index e = 0; e < edges.size(); ++e)
    if (out_faces[edges[e].face].edge == none) out_faces[edges[e].face].edge = e;
  detail::merge_collinear<FT>(vertices, edges, out_faces, m);
  m.assign(std::move(vertices), std::move(edges), std::move(out_faces));
  vm.stats.simplified = {m.vertices().size(), m.half_edges().size() / 2, m.faces().size()};
  if (vm.locator_is_construction_tree) {
    // The construction tree's leaves follow their faces.
    for_each_node(vm.locator, vm.locator.root(), [&](bsp::node_id n, std::size_t) {
      if (vm.locator.is_leaf(n)) vm.locator.leaf_data(n) = new_face[vm.locator.leaf_data(n)];
    });
  } else {
    detail::rebuild_locator(vm, vm.seed);
  }
}

} // namespace svm
