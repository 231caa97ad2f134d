/// @file
/// Queries on a visibility map: what is visible in a direction, and the faces
/// of the map as cycles of vertices.
#pragma once

#include "build.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <set>

namespace svm {

/// The face of T seen in direction `d` (descending the locator; a direction
/// on a node's circle goes to its positive side, so a direction on an edge
/// of T gets one of the faces it bounds).
template <geometry::number FT> index locate_face(visibility_map<FT> const& vm, geometry::s2::point<FT> const& d) {
  auto const& t = vm.locator;
  auto n = t.root();
  while (!t.is_leaf(n)) n = t.child(n, geometry::s2::side(t.splitter(n), d) == geometry::oriented_side::negative ? -1 : +1);
  return t.leaf_data(n);
}

/// The direction `(d[0], d[1], d[2])` exactly as the doubles are (finite,
/// not all zero).  A double is m·2^e with an integer m below 2^53, so after
/// one common shift the three are integers: below 2^126 they are made
/// without GMP.
template <geometry::number FT> geometry::s2::point<FT> direction_of_doubles(std::array<double, 3> const& d) {
  if constexpr (!geometry::exact_field<FT>) {
    return geometry::s2::point<FT>(std::array<FT, 3>{d[0], d[1], d[2]});
  } else {
    std::array<std::int64_t, 3> m{};
    std::array<int, 3> e{};
    int lowest = 0;
    bool any = false;
    for (std::size_t i = 0; i < 3; ++i) {
      if (d[i] == 0) continue;
      m[i] = static_cast<std::int64_t>(std::ldexp(std::frexp(d[i], &e[i]), 53));
      e[i] -= 53;
      lowest = any ? std::min(lowest, e[i]) : e[i];
      any = true;
    }
    int highest = lowest;
    for (std::size_t i = 0; i < 3; ++i)
      if (m[i] != 0) highest = std::max(highest, e[i]);
    if (any && highest - lowest <= 72) {
      using geometry::detail::int128, geometry::detail::uint128;
      std::array<int128, 3> z{};
      uint128 g = 0;
      for (std::size_t i = 0; i < 3; ++i) {
        if (m[i] == 0) continue;
        z[i] = static_cast<int128>(m[i]) * (static_cast<int128>(1) << (e[i] - lowest));
        g = geometry::detail::gcd(g, z[i] < 0 ? -static_cast<uint128>(z[i]) : static_cast<uint128>(z[i]));
      }
      // Primitive, as every exact vector is: equal directions compare equal.
      for (auto& x : z) x /= static_cast<int128>(g);
      return geometry::s2::point<FT>::from_integers(geometry::detail::integer_vector<3>(z));
    }
    return geometry::s2::point<FT>(std::array<FT, 3>{FT(d[0]), FT(d[1]), FT(d[2])});
  }
}

/// The input face visible in direction `d`, or −1.
template <geometry::number FT> std::int64_t locate(visibility_map<FT> const& vm, geometry::s2::point<FT> const& d) {
  return vm.map.faces()[locate_face(vm, d)].label;
}

/// The boundary cycles of every face: `cycles[f]` lists the cycles of face
/// `f`, each as its half-edges in order.
template <geometry::number FT> std::vector<std::vector<std::vector<index>>> face_cycles(dcel<FT> const& m) {
  std::vector<std::vector<std::vector<index>>> out(m.faces().size());
  std::vector<char> seen(m.half_edges().size(), 0);
  for (index e = 0; e < m.half_edges().size(); ++e) {
    if (seen[e]) continue;
    auto c = m.cycle(e);
    for (index x : c) seen[x] = 1;
    out[m.face_of(e)].push_back(std::move(c));
  }
  return out;
}

/// The input faces visible somewhere, in increasing order.
template <geometry::number FT> std::vector<std::int64_t> visible_polygons(dcel<FT> const& m) {
  std::set<std::int64_t> s;
  for (auto const& f : m.faces())
    if (f.label >= 0) s.insert(f.label);
  return {s.begin(), s.end()};
}

/// The faces of the map where input face `label` is visible.
template <geometry::number FT> std::vector<index> faces_of(dcel<FT> const& m, std::int64_t label) {
  std::vector<index> out;
  for (index f = 0; f < m.faces().size(); ++f)
    if (m.faces()[f].label == label) out.push_back(f);
  return out;
}

/// The faces sharing an edge with face `f`, in increasing order.
template <geometry::number FT> std::vector<index> adjacent_faces(dcel<FT> const& m, index f) {
  std::set<index> s;
  for (index e = 0; e < m.half_edges().size(); ++e)
    if (m.face_of(e) == f && m.face_of(dcel<FT>::twin(e)) != f) s.insert(m.face_of(dcel<FT>::twin(e)));
  return {s.begin(), s.end()};
}

} // namespace svm
