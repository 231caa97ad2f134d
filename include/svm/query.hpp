/// @file
/// Queries on a visibility map: what is visible in a direction, and the faces
/// of the map as cycles of vertices.
#pragma once

#include "build.hpp"

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
