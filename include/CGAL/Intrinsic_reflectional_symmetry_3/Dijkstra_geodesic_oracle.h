// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_DIJKSTRA_GEODESIC_ORACLE_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_DIJKSTRA_GEODESIC_ORACLE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/component_meshes.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/edge_length_graph.h>

#include <CGAL/Default.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/dijkstra_shortest_paths_no_color_map.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
///
/// Geodesic distances approximated by shortest paths along the mesh edges,
/// each edge weighted by its Euclidean length (Boost Graph's Dijkstra).
///
/// The cheap baseline: no precomputation beyond a compact adjacency, exact
/// symmetry `d(a,b) = d(b,a)`, but distances overestimate the true geodesics
/// (by a few percent on a well-shaped mesh, because paths zigzag along edges).
///
/// \cgalModels `GeodesicDistanceOracle`
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         (only its edges are used, so any polygon mesh works; triangles are
///         still required for consistency with the other models)
/// \tparam VertexPointMap a model of `ReadablePropertyMap` from the vertex
///         descriptors to a CGAL kernel's `Point_3`. Default: the mesh's
///         internal `CGAL::vertex_point` map.
template <typename TriangleMesh, typename VertexPointMap = CGAL::Default>
class Dijkstra_geodesic_oracle
{
public:
  typedef TriangleMesh Triangle_mesh;
  typedef typename CGAL::Default::Get<
    VertexPointMap,
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type Vertex_point_map;

  /// builds the edge adjacency of `tm`; `tm` is not used afterwards.
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{the positions of the vertices}
  ///     \cgalParamType{`Vertex_point_map`}
  ///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_index_map}
  ///     \cgalParamDescription{the vertex indices used by `distances_from()`}
  ///     \cgalParamType{a model of `ReadablePropertyMap` from vertex descriptors to `std::size_t`,
  ///                    numbering the vertices `0 .. num_vertices(tm)-1`}
  ///     \cgalParamDefault{`CGAL::get_initialized_vertex_index_map(tm, np)`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws Input_error `empty_mesh`, `not_triangle_mesh`, or `invalid_parameter`
  ///         (vertex indices not in `0 .. n-1`)
  template <typename CGAL_NP_TEMPLATE_PARAMETERS>
  explicit Dijkstra_geodesic_oracle(const TriangleMesh& tm,
                                    const CGAL_NP_CLASS& np = parameters::default_values())
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    internal::check_triangle_mesh(tm);
    const Vertex_point_map vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                  get_const_property_map(CGAL::vertex_point, tm));
    const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
    internal::check_vertex_index_map(tm, vim);
    graph_ = internal::make_edge_length_graph(tm, vpm, vim);
  }

  /// number of vertices of the mesh
  std::size_t number_of_vertices() const { return static_cast<std::size_t>(num_vertices(graph_)); }

  /// writes the edge-path distance from vertex `source` to every vertex into
  /// `out[0 .. number_of_vertices()-1]` (`+infinity` when unreachable).
  /// Thread-safe: each call has its own work arrays.
  /// \throws Input_error (`invalid_parameter`) if `source` is not a vertex index
  void distances_from(std::size_t source, float* out) const
  {
    const std::size_t n = number_of_vertices();
    if(source >= n)
      throw Input_error(Input_problem::invalid_parameter,
                        "source vertex index " + std::to_string(source) + " >= " + std::to_string(n), source);
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> distance(n, inf);
    // with a true infinity, plain addition cannot overflow (Boost's closed_plus is not needed)
    boost::dijkstra_shortest_paths_no_color_map(
      graph_, source, boost::dummy_property_map(), distance.data(),
      get(boost::edge_bundle, graph_), get(boost::vertex_index, graph_),
      std::less<double>(), std::plus<double>(), inf, 0.0, boost::default_dijkstra_visitor());
    for(std::size_t v = 0; v < n; ++v)
      out[v] = static_cast<float>(distance[v]);
  }

private:
  internal::Edge_length_graph graph_;
};

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_DIJKSTRA_GEODESIC_ORACLE_H
