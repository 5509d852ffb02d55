// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_EDGE_LENGTH_GRAPH_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_EDGE_LENGTH_GRAPH_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

/// The edge graph of a mesh as a compact CSR adjacency: vertices are the
/// mesh's vertex indices, every mesh edge appears in both directions, and the
/// bundled edge property is the edge's Euclidean length.
typedef boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, double>
  Edge_length_graph;

/// Builds the `Edge_length_graph` of `tm`. Out-edges are sorted by target, so
/// the graph depends only on the indexed geometry, not on the mesh type or
/// its element order. `vim` must number the vertices `0 .. num_vertices(tm)-1`.
template <typename PolygonMesh, typename VertexPointMap, typename VertexIndexMap>
Edge_length_graph make_edge_length_graph(const PolygonMesh& tm, VertexPointMap vpm, VertexIndexMap vim)
{
  typedef typename boost::property_traits<VertexPointMap>::value_type Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel               Kernel;
  const typename Kernel::Compute_squared_distance_3 squared_distance =
    Kernel().compute_squared_distance_3_object();

  std::vector<std::tuple<std::size_t, std::size_t, double> > arcs;
  arcs.reserve(2 * static_cast<std::size_t>(num_edges(tm)));
  for(auto e : edges(tm)) {
    const auto u = source(e, tm), v = target(e, tm);
    const double length = std::sqrt(CGAL::to_double(squared_distance(get(vpm, u), get(vpm, v))));
    const std::size_t iu = static_cast<std::size_t>(get(vim, u)), iv = static_cast<std::size_t>(get(vim, v));
    arcs.emplace_back(iu, iv, length);
    arcs.emplace_back(iv, iu, length);
  }
  std::sort(arcs.begin(), arcs.end());

  std::vector<std::pair<std::size_t, std::size_t> > ends;
  std::vector<double> lengths;
  ends.reserve(arcs.size());
  lengths.reserve(arcs.size());
  for(const auto& a : arcs) {
    ends.emplace_back(std::get<0>(a), std::get<1>(a));
    lengths.push_back(std::get<2>(a));
  }
  return Edge_length_graph(boost::edges_are_sorted, ends.begin(), ends.end(), lengths.begin(),
                           static_cast<std::size_t>(num_vertices(tm)));
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_EDGE_LENGTH_GRAPH_H
