/// @file
/// Exact homogeneous vectors as keys: a hash of their primitive integer
/// coordinates, and a welder that numbers equal vectors once each.  Two
/// homogeneous vectors are equal when one is a positive multiple of the other
/// (`hvec::operator==`), so a point, a direction or an oriented hyperplane
/// gets one number whatever construction produced it.
#pragma once

#include "filter.hpp"

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace geometry {

/// Hash of an exact homogeneous vector, from the low 64 bits of its
/// primitive integer coordinates (equal vectors, equal integers; `==` then
/// compares them whole).
struct hvec_hash {
  template <std::size_t N> std::size_t operator()(hvec<rational, N> const& v) const {
    auto const& z = v.integer_view();
    std::uint64_t h = N;
    for (std::size_t i = 0; i < N; ++i) {
      std::uint64_t low;
      if (z.mid()) {
        low = static_cast<std::uint64_t>(z.z128[i]);
      } else {
        mpz_srcptr p = z.big()[i].backend().data();
        std::uint64_t m = mpz_size(p) != 0 ? mpz_getlimbn(p, 0) : 0;
        low = mpz_sgn(p) < 0 ? ~m + 1 : m;
      }
      h = (h ^ low) * 0x9e3779b97f4a7c15ull;
      h ^= h >> 29;
    }
    return static_cast<std::size_t>(h);
  }
};

/// Homogeneous vectors numbered once each: equal vectors (equal primitive
/// integer coordinates), one number, in order of first appearance.
template <std::size_t N> struct welder {
  std::vector<hvec<rational, N>> vertex; ///< the vectors by number
  std::unordered_map<hvec<rational, N>, std::uint32_t, hvec_hash> number;
  std::uint32_t operator()(hvec<rational, N> const& v) {
    auto [it, added] = number.try_emplace(v, static_cast<std::uint32_t>(vertex.size()));
    if (added) vertex.push_back(v);
    return it->second;
  }
};

} // namespace geometry
