/// @file
/// The concepts `bsp::choosing_policy`, `bsp::cutting_policy` and
/// `bsp::splitting_policy`: how a tree build asks which hyperplane comes next.
#pragma once

#include "geometry.hpp"

#include <concepts>
#include <cstddef>
#include <optional>
#include <vector>

namespace bsp {

/// What a policy decides for a cell: the index of the piece whose supporting
/// hyperplane splits the cell, or a free hyperplane `cut` (derived from the
/// input, so that predicate degrees stay bounded) to use instead.  `piece` is
/// valid in both cases: a build that declines the cut (the point-set build
/// does when the cut would leave one side empty) takes the piece.
template <class Hyperplane> struct split_decision {
  std::size_t piece = 0;
  std::optional<Hyperplane> cut;
};

/// A function giving an item's sub-hyperplane, as builds pass it to policies.
template <class G, class Item> using piece_function = typename G::sub_hyperplane const& (*)(Item const&);

/// A policy that picks one of the pieces.
///
/// Requirements on a type `P`, for a `bsp::geometry` `G` and items `Item`:
/// 1. `p.template choose<G>(items, piece)`, for a non-empty
///    `std::vector<Item>` and a `bsp::piece_function`, returns an index
///    below `items.size()`.
/// 2. It may change `p` (a random state) but keeps no state about `items`
///    for a later call.
template <class P, class G, class Item = typename G::sub_hyperplane>
concept choosing_policy = geometry<G> && requires(P& p, std::vector<Item> const& items, piece_function<G, Item> piece) {
  { p.template choose<G>(items, piece) } -> std::convertible_to<std::size_t>;
};

/// A policy that may answer with a free cut.
///
/// Requirements on a type `P`, as for `bsp::choosing_policy` but with
/// `p.template decide<G>(items, piece)` returning a
/// `bsp::split_decision<typename G::hyperplane>` whose `piece` is below
/// `items.size()`.
template <class P, class G, class Item = typename G::sub_hyperplane>
concept cutting_policy = geometry<G> && requires(P& p, std::vector<Item> const& items, piece_function<G, Item> piece) {
  { p.template decide<G>(items, piece) } -> std::same_as<split_decision<typename G::hyperplane>>;
};

/// A policy that a tree build accepts: one that chooses or one that decides.
template <class P, class G, class Item = typename G::sub_hyperplane>
concept splitting_policy = choosing_policy<P, G, Item> || cutting_policy<P, G, Item>;

/// The decision of `policy` for `items`: its own when it is a
/// `bsp::cutting_policy`, else the piece it chooses and no cut.
template <geometry G, class Item, class Piece, splitting_policy<G, Item> P>
split_decision<typename G::hyperplane> decide(P& policy, std::vector<Item> const& items, Piece&& piece) {
  if constexpr (cutting_policy<P, G, Item>)
    return policy.template decide<G>(items, piece);
  else
    return {static_cast<std::size_t>(policy.template choose<G>(items, piece)), std::nullopt};
}

} // namespace bsp
