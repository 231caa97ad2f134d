/// @file
/// The concept `bsp::measured_space`: cells with a length, an area or a volume.
#pragma once

#include "cell_space.hpp"

#include <concepts>
#include <optional>
#include <utility>

namespace bsp {

/// A number that measures add up in: constructible from 0, closed under `+`.
template <class M>
concept measure_number = std::constructible_from<M, int> && requires(M a, M b) {
  { a + b } -> std::convertible_to<M>;
};

/// A measure that may be absent (an unbounded cell): `std::optional` of a
/// `bsp::measure_number`, or a type that behaves like one.
template <class M>
concept partial_measure = measure_number<typename M::value_type> && std::constructible_from<M, std::nullopt_t> &&
                          requires(M m) {
                            { m.has_value() } -> std::convertible_to<bool>;
                            { *m } -> std::convertible_to<typename M::value_type>;
                          };

/// What `G::measure` returns: a number, or a number that may be absent.
template <class M>
concept measure_value = measure_number<M> || partial_measure<M>;

/// A space whose convex cells have a measure, so that `bsp::measure` can
/// total the cells of a point set.
///
/// Requirements on a type `G`, in addition to `bsp::cell_space`:
/// 1. `G::measure(c)` returns a `bsp::measure_value`: the length, area or
///    volume of the cell `c`.
/// 2. Measures add over the parts of a split: the measure of `c` is the sum
///    of those of `G::split(c, h)`'s parts.
/// 3. A `bsp::partial_measure` is empty exactly for unbounded cells.
///
/// @see bsp::measure
template <class G>
concept measured_space = cell_space<G> && requires(typename G::polytope const& c) {
  { G::measure(c) } -> measure_value;
};

/// The type of `G`'s measures.
template <measured_space G>
using measure_t = decltype(G::measure(std::declval<typename G::polytope const&>()));

} // namespace bsp
