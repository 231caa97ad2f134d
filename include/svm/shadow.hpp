/// @file
/// Shadows from point lights and lights at infinity: the visibility map's
/// construction seen from each light.  The scene's depth-order tree is traversed front to back from
/// the light and each fragment descends a coverage tree (the visibility pass
/// of `build.hpp`); a part that reaches free space is what the light sees,
/// a part that reaches covered space is in shadow.  Each part, a spherical
/// polygon about the light, is lifted back to its polygon's plane: a circle
/// about the light is the trace of a plane through the light, and the part is
/// the fragment cut by those planes.  The planes are input-derived (through
/// the light and a line where two input-derived planes meet), so a piece's
/// vertices, and every predicate on them, keep the degree bound that
/// DESIGN.md requires.  With several lights, each polygon's partitions are
/// overlaid, and a piece carries the set of lights that reach it.  A light
/// at infinity is a finite light in the scene's image under a projective
/// map (`view_from_infinity`, parallel.hpp).
///
/// The pieces are ordinary convex inputs of `svm::build` (`convex_piece`),
/// labelled by region (`label_regions`): the eye's map then draws shadow
/// boundaries as exact edges.
#pragma once

#include "build.hpp"
#include "parallel.hpp"

#include <map>

namespace svm {

/// A piece of an input polygon and the lights that reach it.
template <geometry::number FT> struct shadow_piece {
  geometry::e3::sub_hyperplane<FT> shape; ///< in the polygon's plane, oriented as the polygon
  std::uint32_t polygon = 0;              ///< index in the input
  std::uint64_t lights = 0;               ///< bit k set: light k lights it
};

struct shadow_options {
  std::uint64_t seed = 1; ///< splitter choice of the depth-order trees
  /// With one light, whether the pieces in shadow are made too.  Without
  /// them a polygon's pieces cover only its lit part, and `shadows::dark`
  /// says which polygons have a part in shadow: all that `label_regions`
  /// (and so the eye's map) needs, and most of the work saved where shadows
  /// are intricate.  Several lights always make them (the overlay needs them).
  bool shadowed_pieces = true;
  /// Called with the fraction of the work done (0 to 1), per light, when set.
  std::function<void(double)> progress{};
};

struct shadow_statistics {
  std::size_t input_polygons = 0;
  std::size_t lights = 0;
  std::size_t fragments = 0;       ///< of the lights' depth-order trees, all lights
  std::size_t lit_parts = 0;       ///< parts found lit (and made), all lights
  std::size_t shadowed_parts = 0;  ///< parts found in shadow (made when asked), all lights
  std::size_t pieces = 0;          ///< after the overlay of all lights
  std::uint64_t filter_fallbacks = 0;
  double seconds = 0;
};

/// Every input polygon split into pieces by the lights that reach them,
/// polygon by polygon.
template <geometry::number FT> struct shadows {
  std::vector<shadow_piece<FT>> pieces;
  /// By polygon: whether some part of it is reached by no light.
  std::vector<char> dark;
  shadow_statistics stats;
};

/// The most lights one computation takes (the bits of `shadow_piece::lights`).
inline constexpr std::size_t max_lights = 64;

namespace detail {

/// The plane through `light` whose trace on the sphere of directions about
/// it is the circle `c`, positive where `c` is: (w·n, −n·l) for the light
/// (l, w) and the circle's normal n.
template <geometry::number FT>
geometry::e3::hyperplane<FT> lift(geometry::s2::hyperplane<FT> const& c, geometry::e3::point<FT> const& light) {
  auto plane = [](auto const& n, auto const& l) {
    std::array<std::remove_cvref_t<decltype(n[0] * l[0])>, 4> h;
    for (std::size_t i = 0; i < 3; ++i) h[i] = l[3] * n[i];
    h[3] = -(n[0] * l[0] + n[1] * l[1] + n[2] * l[2]);
    return h;
  };
  return geometry::e3::hyperplane<FT>(geometry::construct<4>(plane, c.n, light.homogeneous()), c.tag);
}

/// `a ∩ b` for two convex pieces of one plane: `a` cut by each bound of `b`.
template <geometry::number FT>
std::optional<geometry::e3::sub_hyperplane<FT>> intersect(geometry::e3::sub_hyperplane<FT> a, geometry::e3::sub_hyperplane<FT> const& b) {
  for (auto const& bound : b.bounds) {
    auto r = geometry::e3::split(a, bound.original);
    if (!r.positive) return std::nullopt;
    a = std::move(*r.positive);
  }
  return a;
}

/// A piece of a polygon seen from one light: lit or not, and whether it is
/// the polygon whole.
template <geometry::number FT> struct light_part {
  geometry::e3::sub_hyperplane<FT> shape;
  bool lit = false;
  bool whole = false;
};

/// Each polygon's pieces seen from one light.
template <geometry::number FT> using light_split = std::vector<std::vector<light_part<FT>>>;

/// The visibility pass from `light` over `shapes`: each polygon split into
/// what the light sees of its front side (lit) and the rest.  A polygon
/// whose plane holds the light is lit on neither side and hides nothing; a
/// polygon that turns its back to the light hides what is behind it and is
/// in shadow whole.
template <geometry::number FT>
light_split<FT> light_pass(std::vector<geometry::e3::sub_hyperplane<FT>> const& shapes, geometry::e3::point<FT> const& light,
                           shadow_options const& options, bool make_dark, std::vector<char>& dark, shadow_statistics& st) {
  using namespace geometry;
  using K3 = e3::kernel<FT>;
  using fragment = std::vector<sphere_bound<FT>>;
  std::size_t const n = shapes.size();
  light_split<FT> out(n);
  std::vector<char> front(n, 0);
  bsp::fragment_list<K3, std::uint32_t> input;
  for (std::uint32_t i = 0; i < n; ++i) {
    auto side = e3::side(shapes[i].support, light);
    if (side == oriented_side::on) {
      if (make_dark) out[i].push_back({shapes[i], false, true});
      dark[i] = 1;
      continue;
    }
    front[i] = side == oriented_side::positive;
    input.push_back({shapes[i], i});
  }
  auto tree = bsp::build_depth_order<K3>(std::move(input), bsp::few_splits(e3::axis_median_cut<FT>{}, options.seed));
  build_options bo;
  bo.seed = options.seed;
  auto pass = make_sphere_pass<FT>(bo);
  circle_store<FT> scratch;
  std::vector<std::uint32_t> fragments_of(n, 0), lit_whole(n, 0), dark_whole(n, 0);
  std::vector<fragment> lit, unlit;
  // The fragment cut by the lifted circles of a part other than its own.
  auto lifted = [&](e3::sub_hyperplane<FT> const& whole, fragment const& own, fragment const& part) {
    std::optional<e3::sub_hyperplane<FT>> s = whole;
    for (auto const& b : part) {
      if (std::any_of(own.begin(), own.end(), [&](auto const& o) { return o.c == b.c; })) continue;
      s = e3::split(*s, lift(*b.c, light)).positive;
      if (!s) break;
    }
    return s;
  };
  bsp::for_each_front_to_back(tree, light, [&](auto const& fr) {
    ++st.fragments;
    scratch.clear();
    lit.clear();
    unlit.clear();
    fragment projected = project(fr.piece, light, scratch);
    bool const lights = front[fr.id] != 0;
    std::size_t seen = 0, parts = 0;
    // In maximal parts wholly lit or wholly in shadow (not the tree's cells).
    pass.insert_merged(projected, [&](fragment&& p, bool visible) {
      ++parts;
      seen += visible ? 1 : 0;
      if (lights) (visible ? lit : unlit).push_back(std::move(p));
    });
    std::size_t hidden = parts - seen;
    ++fragments_of[fr.id];
    if (!lights || hidden > 0) dark[fr.id] = 1;
    if (!lights || hidden == 0 || seen == 0) {
      bool is_lit = lights && hidden == 0;
      ++(is_lit ? lit_whole : dark_whole)[fr.id];
      if (is_lit || make_dark) out[fr.id].push_back({fr.piece, is_lit, false});
      ++(is_lit ? st.lit_parts : st.shadowed_parts);
    } else {
      for (auto const* group : {&lit, &unlit}) {
        bool is_lit = group == &lit;
        if (!is_lit && !make_dark) {
          st.shadowed_parts += unlit.size();
          continue;
        }
        for (auto const& p : *group)
          if (auto s = lifted(fr.piece, projected, p)) {
            out[fr.id].push_back({std::move(*s), is_lit, false});
            ++(is_lit ? st.lit_parts : st.shadowed_parts);
          }
      }
    }
    pass.rebuild_if_grown();
  });
  // A polygon all of whose fragments were lit whole, or dark whole, is one
  // piece: the polygon itself.
  for (std::uint32_t i = 0; i < n; ++i)
    if (fragments_of[i] >= 1 && (lit_whole[i] == fragments_of[i] || dark_whole[i] == fragments_of[i])) {
      bool is_lit = lit_whole[i] == fragments_of[i];
      out[i].clear();
      if (is_lit || make_dark) out[i].push_back({shapes[i], is_lit, true});
    }
  return out;
}

/// The pass from a light at infinity, in direction `d` (towards it): the
/// pass from a finite light in the scene's image under the projective map of
/// `view_from_infinity` (parallel.hpp), the pieces carried back.
template <geometry::number FT>
light_split<FT> sun_pass(std::vector<polygon<FT>> const& polygons, std::vector<geometry::e3::sub_hyperplane<FT>> const& shapes,
                         std::array<FT, 3> const& d, shadow_options const& options, bool make_dark, std::vector<char>& dark,
                         shadow_statistics& st) {
  view_from_infinity<FT> view(polygons, d);
  std::vector<geometry::e3::sub_hyperplane<FT>> image;
  image.reserve(polygons.size());
  for (auto const& p : view.image(polygons)) image.push_back(scene_polygon(p));
  auto split = light_pass(image, view.eye(), options, make_dark, dark, st);
  for (std::size_t i = 0; i < split.size(); ++i)
    for (auto& part : split[i]) part.shape = part.whole ? shapes[i] : view.carry(part.shape, false);
  return split;
}

} // namespace detail

/// A light: a point, or a light at infinity (the sun), given by the
/// direction towards it.
template <geometry::number FT> struct light_source {
  std::optional<geometry::e3::point<FT>> point; ///< none: at infinity
  std::array<FT, 3> direction{};                ///< towards the light at infinity
  static light_source at(geometry::e3::point<FT> p) { return {std::move(p), {}}; }
  static light_source sun(std::array<FT, 3> d) { return {std::nullopt, std::move(d)}; }
};

/// The pieces of `polygons` lit by each of `lights` (points or suns): see
/// the overload for points.  Throws `std::invalid_argument` for a sun's zero
/// direction.
template <geometry::number FT>
shadows<FT> compute_shadows(std::vector<polygon<FT>> const& polygons, std::vector<light_source<FT>> const& lights,
                            shadow_options const& options = {});

/// The pieces of `polygons` (as `svm::build` takes them) lit by each of
/// `lights` (at most `max_lights`; none lies on a polygon's plane on its
/// lit side, since a light on a plane lights neither side).  Throws
/// `std::invalid_argument` for too many lights.
template <geometry::number FT>
shadows<FT> compute_shadows(std::vector<polygon<FT>> const& polygons, std::vector<geometry::e3::point<FT>> const& lights,
                            shadow_options const& options = {}) {
  std::vector<light_source<FT>> sources;
  for (auto const& l : lights) sources.push_back(light_source<FT>::at(l));
  return compute_shadows(polygons, sources, options);
}

template <geometry::number FT>
shadows<FT> compute_shadows(std::vector<polygon<FT>> const& polygons, std::vector<light_source<FT>> const& lights,
                            shadow_options const& options) {
  using namespace geometry;
  if (lights.size() > max_lights) throw std::invalid_argument("svm::compute_shadows: at most 64 lights");
  for (auto const& l : lights)
    if (!l.point && l.direction[0] == 0 && l.direction[1] == 0 && l.direction[2] == 0)
      throw std::invalid_argument("svm::compute_shadows: a sun's direction is zero");
  auto pass = [&](light_source<FT> const& l, bool make_dark, std::vector<char>& dark, shadow_statistics& st,
                  std::vector<e3::sub_hyperplane<FT>> const& shapes) {
    return l.point ? detail::light_pass(shapes, *l.point, options, make_dark, dark, st)
                   : detail::sun_pass(polygons, shapes, l.direction, options, make_dark, dark, st);
  };
  auto t0 = std::chrono::steady_clock::now();
  auto fallbacks0 = filter_stats().fallbacks;
  shadows<FT> out;
  auto& st = out.stats;
  st.input_polygons = polygons.size();
  st.lights = lights.size();
  std::vector<e3::sub_hyperplane<FT>> shapes;
  shapes.reserve(polygons.size());
  for (auto const& p : polygons) shapes.push_back(detail::scene_polygon(p));
  bool const make_dark = options.shadowed_pieces || lights.size() != 1;
  out.dark.assign(polygons.size(), lights.empty() ? 1 : 0);
  if (!make_dark) {
    // One light, lit pieces only.
    if (options.progress) options.progress(0.0);
    auto split = pass(lights[0], false, out.dark, st, shapes);
    for (std::uint32_t i = 0; i < split.size(); ++i)
      for (auto& part : split[i]) out.pieces.push_back({std::move(part.shape), i, 1});
    st.pieces = out.pieces.size();
    if (options.progress) options.progress(1.0);
    st.filter_fallbacks = filter_stats().fallbacks - fallbacks0;
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  }
  // Per polygon, its pieces so far and the lights that reach each.
  std::vector<std::vector<std::pair<e3::sub_hyperplane<FT>, std::uint64_t>>> current(polygons.size());
  for (std::size_t i = 0; i < shapes.size(); ++i) current[i].push_back({shapes[i], 0});
  std::vector<char> ignored(polygons.size(), 0);
  for (std::size_t k = 0; k < lights.size(); ++k) {
    if (options.progress) options.progress(static_cast<double>(k) / static_cast<double>(lights.size()));
    auto split = pass(lights[k], true, ignored, st, shapes);
    std::uint64_t const bit = std::uint64_t{1} << k;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      auto& cur = current[i];
      auto const& by = split[i];
      if (by.size() == 1 && by[0].whole) {
        // The polygon whole, lit or not.
        if (by[0].lit)
          for (auto& c : cur) c.second |= bit;
        continue;
      }
      std::vector<std::pair<e3::sub_hyperplane<FT>, std::uint64_t>> next;
      if (cur.size() == 1) {
        // The polygon whole so far: its pieces are this light's.
        for (auto const& part : by) next.push_back({part.shape, cur[0].second | (part.lit ? bit : 0)});
      } else {
        for (auto const& [c, mask] : cur)
          for (auto const& part : by)
            if (auto r = detail::intersect(c, part.shape)) next.push_back({std::move(*r), mask | (part.lit ? bit : 0)});
      }
      cur = std::move(next);
    }
  }
  for (std::uint32_t i = 0; i < current.size(); ++i)
    for (auto& [s, mask] : current[i]) {
      if (mask == 0) out.dark[i] = 1;
      out.pieces.push_back({std::move(s), i, mask});
    }
  st.pieces = out.pieces.size();
  if (options.progress) options.progress(1.0);
  st.filter_fallbacks = filter_stats().fallbacks - fallbacks0;
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

/// A region of a shadowed scene: an input face and the lights that reach it.
struct lit_region {
  std::uint32_t face = 0;
  std::uint64_t lights = 0;
  friend bool operator==(lit_region const&, lit_region const&) = default;
};

/// The pieces as inputs of `svm::build`, labelled by region: one label per
/// distinct (face, lights), so that the map joins the pieces of one face
/// that the same lights reach and keeps the shadow boundaries between others.
template <geometry::number FT> struct shadowed_scene {
  std::vector<convex_piece<FT>> pieces;
  std::vector<lit_region> regions; ///< by label
};

/// The shadowed scene for the eye's map.  Each polygon goes in as the
/// pieces that some light reaches and then, when some part of it is in
/// shadow, itself whole, labelled as reached by no light: coplanar and
/// later in the input, it is behind its own lit pieces (the depth order's
/// tie), so the map shows it where they are not.  That is far fewer inputs
/// than every shadowed piece: the shadow of a polygon needs no convex
/// pieces of its own.
template <geometry::number FT> shadowed_scene<FT> label_regions(shadows<FT> const& sh, std::vector<polygon<FT>> const& polygons) {
  shadowed_scene<FT> out;
  std::map<std::pair<std::uint32_t, std::uint64_t>, std::int64_t> ids;
  auto label = [&](std::uint32_t face, std::uint64_t lights) {
    auto [it, added] = ids.try_emplace({face, lights}, static_cast<std::int64_t>(out.regions.size()));
    if (added) out.regions.push_back({face, lights});
    return it->second;
  };
  // The pieces come polygon by polygon (`compute_shadows`).
  std::size_t at = 0;
  for (std::uint32_t i = 0; i < polygons.size(); ++i) {
    std::uint32_t face = polygons[i].face;
    for (; at < sh.pieces.size() && sh.pieces[at].polygon == i; ++at)
      if (sh.pieces[at].lights != 0) out.pieces.push_back({sh.pieces[at].shape, label(face, sh.pieces[at].lights)});
    if (sh.dark[i]) out.pieces.push_back({detail::scene_polygon(polygons[i]), label(face, 0)});
  }
  return out;
}

} // namespace svm
