/// @file
/// The map as Boost.Graph graphs, so that BGL algorithms run on it directly:
/// the primal graph (vertices and edges of the map) and the dual graph of face
/// adjacency (faces, and one edge per half-edge, from its face to its twin's).
/// Both are thin views; `boost::graph_traits` are specialised for them
/// (IncidenceGraph, VertexListGraph, EdgeListGraph; undirected, since every
/// edge is listed from both ends).  This is an opt-in
/// header: it brings in Boost.Graph.
#pragma once

#include "dcel.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/iterator/counting_iterator.hpp>

#include <map>
#include <set>
#include <utility>
#include <vector>

namespace svm {

/// The primal graph of a map: its vertices, and its half-edges as directed
/// edges (both directions of every edge), from origin to target.
template <geometry::number FT> class primal_graph {
public:
  explicit primal_graph(dcel<FT> const& m) : m_(&m), out_(m.vertices().size()) {
    for (index e = 0; e < m.half_edges().size(); ++e) out_[m.origin(e)].push_back(e);
  }
  dcel<FT> const& map() const noexcept { return *m_; }
  std::vector<index> const& out(index v) const { return out_[v]; }

private:
  dcel<FT> const* m_;
  std::vector<std::vector<index>> out_;
};

/// The dual graph of a map: its faces, and its half-edges as directed edges
/// from the face on their left to the face on their right.
template <geometry::number FT> class dual_graph {
public:
  explicit dual_graph(dcel<FT> const& m) : m_(&m), out_(m.faces().size()) {
    for (index e = 0; e < m.half_edges().size(); ++e) out_[m.face_of(e)].push_back(e);
  }
  dcel<FT> const& map() const noexcept { return *m_; }
  std::vector<index> const& out(index f) const { return out_[f]; }

private:
  dcel<FT> const* m_;
  std::vector<std::vector<index>> out_;
};

namespace detail {
/// The traits both views share: vertices are indices, edges half-edge indices.
struct graph_traits_base {
  using vertex_descriptor = index;
  using edge_descriptor = index;
  // Every edge appears as both its half-edges, one from each end: undirected.
  using directed_category = boost::undirected_tag;
  using edge_parallel_category = boost::allow_parallel_edge_tag;
  struct traversal_category : boost::incidence_graph_tag, boost::vertex_list_graph_tag, boost::edge_list_graph_tag {};
  using vertex_iterator = boost::counting_iterator<index>;
  using edge_iterator = boost::counting_iterator<index>;
  using out_edge_iterator = std::vector<index>::const_iterator;
  using degree_size_type = std::size_t;
  using vertices_size_type = std::size_t;
  using edges_size_type = std::size_t;
  using in_edge_iterator = void;
  using adjacency_iterator = void;
  static vertex_descriptor null_vertex() { return none; }
};
} // namespace detail

/// @name Boost.Graph functions of the primal graph
/// @{
template <class FT> index source(index e, primal_graph<FT> const& g) { return g.map().origin(e); }
template <class FT> index target(index e, primal_graph<FT> const& g) { return g.map().target(e); }
template <class FT>
std::pair<std::vector<index>::const_iterator, std::vector<index>::const_iterator> out_edges(index v, primal_graph<FT> const& g) {
  return {g.out(v).begin(), g.out(v).end()};
}
template <class FT> std::size_t out_degree(index v, primal_graph<FT> const& g) { return g.out(v).size(); }
template <class FT> auto vertices(primal_graph<FT> const& g) {
  return std::pair{boost::counting_iterator<index>(0), boost::counting_iterator<index>(static_cast<index>(g.map().vertices().size()))};
}
template <class FT> std::size_t num_vertices(primal_graph<FT> const& g) { return g.map().vertices().size(); }
template <class FT> auto edges(primal_graph<FT> const& g) {
  return std::pair{boost::counting_iterator<index>(0), boost::counting_iterator<index>(static_cast<index>(g.map().half_edges().size()))};
}
template <class FT> std::size_t num_edges(primal_graph<FT> const& g) { return g.map().half_edges().size(); }
/// @}

/// @name Boost.Graph functions of the dual graph
/// @{
template <class FT> index source(index e, dual_graph<FT> const& g) { return g.map().face_of(e); }
template <class FT> index target(index e, dual_graph<FT> const& g) { return g.map().face_of(dcel<FT>::twin(e)); }
template <class FT>
std::pair<std::vector<index>::const_iterator, std::vector<index>::const_iterator> out_edges(index f, dual_graph<FT> const& g) {
  return {g.out(f).begin(), g.out(f).end()};
}
template <class FT> std::size_t out_degree(index f, dual_graph<FT> const& g) { return g.out(f).size(); }
template <class FT> auto vertices(dual_graph<FT> const& g) {
  return std::pair{boost::counting_iterator<index>(0), boost::counting_iterator<index>(static_cast<index>(g.map().faces().size()))};
}
template <class FT> std::size_t num_vertices(dual_graph<FT> const& g) { return g.map().faces().size(); }
template <class FT> auto edges(dual_graph<FT> const& g) {
  return std::pair{boost::counting_iterator<index>(0), boost::counting_iterator<index>(static_cast<index>(g.map().half_edges().size()))};
}
template <class FT> std::size_t num_edges(dual_graph<FT> const& g) { return g.map().half_edges().size(); }
/// @}

/// The connected components of the map's edges (BGL's connected_components
/// on the primal graph): the C of Euler's formula V − E + F = 1 + C.
template <geometry::number FT> std::size_t edge_components(dcel<FT> const& m) {
  primal_graph<FT> g(m);
  std::vector<int> component(m.vertices().size());
  std::vector<boost::default_color_type> colour(m.vertices().size());
  boost::typed_identity_property_map<index> id;
  return static_cast<std::size_t>(boost::connected_components(g, boost::make_iterator_property_map(component.begin(), id),
                                                               boost::color_map(boost::make_iterator_property_map(colour.begin(), id))));
}

/// The connected visible regions of each input polygon: BGL's
/// connected_components on the dual graph with the edges between faces of
/// different labels left out.  `regions[label]` counts them (label −1, the
/// background, is left out); on a simplified map each region is one face.
template <geometry::number FT> std::map<std::int64_t, std::size_t> visible_regions(dcel<FT> const& m) {
  // The same-label subgraph, as its own small BGL graph of faces.
  using G = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
  G same(m.faces().size());
  dual_graph<FT> d(m);
  for (auto [e, end] = edges(d); e != end; ++e) {
    index a = source(*e, d), b = target(*e, d);
    if (a < b && m.faces()[a].label == m.faces()[b].label) boost::add_edge(a, b, same);
  }
  std::vector<int> component(m.faces().size());
  boost::connected_components(same, component.data());
  std::map<std::int64_t, std::set<int>> per_label;
  for (index f = 0; f < m.faces().size(); ++f)
    if (m.faces()[f].label >= 0) per_label[m.faces()[f].label].insert(component[f]);
  std::map<std::int64_t, std::size_t> out;
  for (auto const& [label, comps] : per_label) out[label] = comps.size();
  return out;
}

} // namespace svm

namespace boost {
template <class FT> struct graph_traits<svm::primal_graph<FT>> : svm::detail::graph_traits_base {};
template <class FT> struct graph_traits<svm::dual_graph<FT>> : svm::detail::graph_traits_base {};
} // namespace boost
