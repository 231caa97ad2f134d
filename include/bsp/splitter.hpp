/// @file
/// Splitter selection: which of the sub-hyperplanes left in a cell supplies
/// the next node's hyperplane.  Policies are small function objects called as
/// `policy.template choose<G>(items, piece)` with a vector of items and a
/// function giving each item's sub-hyperplane; they return an index.
#pragma once

#include "concepts/geometry.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
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

} // namespace bsp
