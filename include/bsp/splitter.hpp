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
#include "concepts/whole_side.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <utility>
#include <vector>

namespace bsp {

namespace detail {

/// −1 or +1 when the sub-hyperplane `s` lies wholly on that side of `h` (as
/// `split` would put it), found cheaply by a geometry that offers
/// `whole_side`; 0 when `split` must decide.
template <geometry G> int whole_side(typename G::sub_hyperplane const& s, typename G::hyperplane const& h) {
  if constexpr (whole_side_geometry<G>)
    return static_cast<int>(G::whole_side(s, h));
  else
    return 0;
}

} // namespace detail

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

/// Autopartition that splits as little as it can while staying shallow.
/// Of `samples` random candidates, scored on a random subset of `probe`
/// pieces, it takes the one with the least `split_weight` × splits +
/// imbalance among those leaving at least one piece in `min_share` on each
/// side.  It also asks `cutter` for a free hyperplane for the sampled pieces
/// and takes it when that is as balanced and costs less (a grid line through
/// a terrain, or a convex surface, whose autopartition is a chain n deep);
/// failing both, the candidate with the fewest splits.  At or below `threshold` pieces, of
/// `small_samples` candidates scored on every piece, the one with the fewest
/// splits (ties: the more even), and no free cut.  A depth-order tree built
/// with it has few fragments per input polygon on scenes of boxes and slabs,
/// through which `balanced`'s free cuts go.
template <class Cutter> struct few_splits {
  explicit few_splits(Cutter c, std::uint64_t seed = 1) : cutter(std::move(c)), rng(seed) {}

  template <geometry G, class Item, class Piece>
  split_decision<typename G::hyperplane> decide(std::vector<Item> const& items, Piece&& piece) {
    std::size_t n = items.size();
    if (n == 1) return {0, std::nullopt};
    std::uniform_int_distribution<std::size_t> pick(0, n - 1);
    bool small = n <= threshold;
    std::size_t m = small ? n : probe;
    sample.resize(m);
    for (std::size_t i = 0; i < m; ++i) sample[i] = small ? i : pick(rng);
    struct score {
      std::size_t splits, neg, pos;
      std::size_t least() const { return neg < pos ? neg : pos; }
      std::size_t imbalance() const { return neg > pos ? neg - pos : pos - neg; }
    };
    auto count = [&](typename G::hyperplane const& h) {
      score s{0, 0, 0};
      for (std::size_t i : sample) {
        auto const& p = piece(items[i]);
        if (int w = detail::whole_side<G>(p, h)) {
          ++(w < 0 ? s.neg : s.pos);
          continue;
        }
        auto r = G::split(p, h);
        s.splits += r.negative && r.positive;
        s.neg += r.negative.has_value();
        s.pos += r.positive.has_value();
      }
      return s;
    };
    std::size_t k = small ? small_samples : samples;
    std::size_t tries = n <= k ? n : k;
    if (small) {
      std::size_t best = 0;
      std::optional<score> best_score;
      for (std::size_t t = 0; t < tries; ++t) {
        std::size_t c = n <= k ? t : pick(rng);
        score s = count(G::supporting(piece(items[c])));
        if (!best_score || s.splits < best_score->splits ||
            (s.splits == best_score->splits && s.imbalance() < best_score->imbalance()))
          best = c, best_score = s;
      }
      return {best, std::nullopt};
    }
    auto balanced = [&](score const& s) { return s.least() * min_share >= m; };
    auto cost = [&](score const& s) { return s.splits * split_weight + s.imbalance(); };
    std::size_t best = 0, fewest = 0;
    std::optional<score> best_score, fewest_score;
    for (std::size_t t = 0; t < tries; ++t) {
      std::size_t c = pick(rng);
      score s = count(G::supporting(piece(items[c])));
      if (!fewest_score || s.splits < fewest_score->splits) fewest = c, fewest_score = s;
      if (balanced(s) && (!best_score || cost(s) < cost(*best_score))) best = c, best_score = s;
    }
    // The cutter sees the sampled pieces only: a median of a sample is near
    // enough, and the cut is scored on the sample anyway.  It is taken when
    // it is balanced and costs less than the best balanced input plane.
    std::vector<Item> subset;
    subset.reserve(m);
    for (std::size_t i : sample) subset.push_back(items[i]);
    if (auto cut = cutter(subset)) {
      score s = count(*cut);
      if (balanced(s) && (!best_score || cost(s) < cost(*best_score))) return {best_score ? best : fewest, std::move(cut)};
    }
    if (best_score) return {best, std::nullopt};
    return {fewest, std::nullopt};
  }

  Cutter cutter;
  std::size_t samples = 8, small_samples = 3, threshold = 64, probe = 64, min_share = 8, split_weight = 4;
  std::mt19937_64 rng;
  std::vector<std::size_t> sample;
};

} // namespace bsp
