/// @file
/// Splitter selection: which of the sub-hyperplanes left in a cell supplies
/// the next node's hyperplane.  Policies are small function objects called as
/// `policy.template choose<G>(items, piece)` with a vector of items and a
/// function giving each item's sub-hyperplane; they return an index
/// (`bsp::choosing_policy`).  A policy that may prefer a free hyperplane
/// answers `decide` instead (`bsp::cutting_policy`).
#pragma once

#include "concepts/geometry.hpp"
#include "concepts/policy.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <utility>
#include <vector>

namespace bsp {

/// The first piece: the input order decides (deterministic, and the tree
/// mirrors the input; a sorted input can give a deep tree).
struct input_order {
  template <geometry G, class Item, class Piece> std::size_t choose(std::vector<Item> const&, Piece&&) { return 0; }
};

/// A uniformly random piece (expected O(n log n) nodes for segments in the
/// plane, Paterson and Yao), reproducible from the seed.
struct random_order {
  explicit random_order(std::uint64_t seed = 1) : rng(seed) {}
  template <geometry G, class Item, class Piece> std::size_t choose(std::vector<Item> const& items, Piece&&) {
    return std::uniform_int_distribution<std::size_t>(0, items.size() - 1)(rng);
  }
  std::mt19937_64 rng;
};

/// Of `samples` random candidates, the one whose hyperplane cuts the fewest
/// other pieces in two (ties: the first sampled).
struct least_splits {
  explicit least_splits(std::size_t samples_ = 8, std::uint64_t seed = 1) : samples(samples_), rng(seed) {}
  template <geometry G, class Item, class Piece> std::size_t choose(std::vector<Item> const& items, Piece&& piece) {
    std::size_t best = 0, best_cuts = std::numeric_limits<std::size_t>::max();
    std::size_t n = items.size();
    std::size_t tries = n <= samples ? n : samples;
    for (std::size_t t = 0; t < tries; ++t) {
      std::size_t c = n <= samples ? t : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
      auto const& h = G::supporting(piece(items[c]));
      std::size_t cuts = 0;
      for (std::size_t i = 0; i < n && cuts < best_cuts; ++i) {
        auto r = G::split(piece(items[i]), h);
        cuts += r.negative && r.positive;
      }
      if (cuts < best_cuts) best = c, best_cuts = cuts;
    }
    return best;
  }
  std::size_t samples;
  std::mt19937_64 rng;
};

/// Autopartition that stays shallow on convex input.  Every piece of a convex
/// surface has all the others on one side of its hyperplane, so an
/// autopartition of it is a chain, n deep, and costs n²/2 splits to build.
/// Above `threshold` pieces, this policy samples `samples` candidates on a
/// random subset of at most `probe` pieces; when even the best leaves fewer
/// than one piece in `min_share` on its smaller side, it asks `cutter(pieces)`
/// for a free hyperplane (for instance an axis-aligned plane through a median
/// input vertex: input-derived, so the degree bound holds) that balances the
/// cell.  At or below the threshold it is `random_order`.
template <class Cutter> struct balanced {
  explicit balanced(Cutter c, std::uint64_t seed = 1, std::size_t threshold_ = 64)
      : cutter(std::move(c)), threshold(threshold_), rng(seed) {}

  template <geometry G, class Item, class Piece>
  split_decision<typename G::hyperplane> decide(std::vector<Item> const& items, Piece&& piece) {
    std::size_t n = items.size();
    std::uniform_int_distribution<std::size_t> pick(0, n - 1);
    if (n <= threshold) return {pick(rng), std::nullopt};
    std::size_t best_share = 0, best = 0;
    for (std::size_t t = 0; t < samples; ++t) {
      std::size_t c = pick(rng);
      auto const& h = G::supporting(piece(items[c]));
      std::size_t neg = 0, pos = 0;
      for (std::size_t i = 0; i < probe; ++i) {
        auto r = G::split(piece(items[pick(rng)]), h);
        neg += r.negative.has_value();
        pos += r.positive.has_value();
      }
      std::size_t share = neg < pos ? neg : pos;
      if (share > best_share || t == 0) best_share = share, best = c;
    }
    if (best_share * min_share >= probe) return {best, std::nullopt};
    return {best, cutter(items)};
  }

  Cutter cutter;
  std::size_t threshold;
  std::size_t samples = 4, probe = 32, min_share = 8;
  std::mt19937_64 rng;
};

} // namespace bsp
