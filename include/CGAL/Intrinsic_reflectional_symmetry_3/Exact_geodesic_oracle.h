// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_EXACT_GEODESIC_ORACLE_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_EXACT_GEODESIC_ORACLE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/component_meshes.h>

#include <CGAL/Default.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
///
/// Exact polyhedral geodesic distances (Mitchell-Mount-Papadimitriou, as in
/// Surazhsky et al. 2005 and Xu et al. 2009's implementation), computed by
/// CGAL's `CGAL::Surface_mesh_shortest_path` with one sequence tree per source.
///
/// The reference oracle: exact up to floating point (with an inexact kernel)
/// and symmetric, but one to two orders of magnitude slower per source than
/// `Heat_method_geodesic_oracle`. Each call builds its own shortest-path
/// object, so calls are independent and thread-safe.
///
/// Each connected component is solved on its own copy; vertices of other
/// components get `+infinity`. A vertex that CGAL reports unreachable inside
/// the source's component (which should not happen) also gets `+infinity`.
///
/// \cgalModels `GeodesicDistanceOracle`
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam VertexPointMap a model of `ReadablePropertyMap` from the vertex
///         descriptors to a CGAL kernel's `Point_3`. Default: the mesh's
///         internal `CGAL::vertex_point` map.
template <typename TriangleMesh, typename VertexPointMap = CGAL::Default>
class Exact_geodesic_oracle
{
public:
  typedef TriangleMesh Triangle_mesh;
  typedef typename CGAL::Default::Get<
    VertexPointMap,
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type Vertex_point_map;

private:
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel                 Kernel;
  typedef internal::Component_meshes<Point_3>                          Components;
  typedef typename Components::Mesh                                      Mesh;
  typedef CGAL::Surface_mesh_shortest_path_traits<Kernel, Mesh>         Shortest_path_traits;
  typedef CGAL::Surface_mesh_shortest_path<Shortest_path_traits>        Shortest_path;

public:
  /// splits `tm` into connected components and copies them; `tm` is not used afterwards.
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
  /// \throws Input_error `empty_mesh`, `not_triangle_mesh`, `degenerate_face` (a face repeats a vertex),
  ///         `non_manifold_vertex` (a component that is not a manifold surface), or
  ///         `invalid_parameter` (vertex indices not in `0 .. n-1`)
  template <typename CGAL_NP_TEMPLATE_PARAMETERS>
  explicit Exact_geodesic_oracle(const TriangleMesh& tm,
                                 const CGAL_NP_CLASS& np = parameters::default_values())
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    const Vertex_point_map vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                  get_const_property_map(CGAL::vertex_point, tm));
    components_.reset(new Components(tm, vpm, CGAL::get_initialized_vertex_index_map(tm, np)));
  }

  /// number of vertices of the mesh
  std::size_t number_of_vertices() const { return components_->number_of_vertices(); }

  /// number of connected components of the mesh (isolated vertices included)
  std::size_t number_of_components() const { return components_->number_of_components(); }

  /// writes the exact geodesic distance from vertex `source` to every vertex
  /// into `out[0 .. number_of_vertices()-1]` (`+infinity` in other components).
  /// Thread-safe.
  /// \throws Input_error (`invalid_parameter`) if `source` is not a vertex index
  void distances_from(std::size_t source, float* out) const
  {
    if(source >= number_of_vertices())
      throw Input_error(Input_problem::invalid_parameter,
                        "source vertex index " + std::to_string(source) + " >= " +
                        std::to_string(number_of_vertices()), source);
    components_->initialize_row(source, out);
    const std::size_t c = components_->component(source);
    if(!components_->has_faces(c))
      return; // an isolated vertex: 0 to itself, +infinity elsewhere

    const Mesh& mesh = components_->mesh(c);
    Shortest_path shortest_paths(mesh); // reads the mesh only: safe to build concurrently
    shortest_paths.add_source_point(components_->local_vertex(source));
    shortest_paths.build_sequence_tree();
    const std::vector<std::size_t>& input_index = components_->input_indices(c);
    for(auto v : vertices(mesh)) {
      const auto d = shortest_paths.shortest_distance_to_source_points(v).first;
      if(d >= 0) // negative means unreachable
        out[input_index[static_cast<std::size_t>(v)]] = static_cast<float>(CGAL::to_double(d));
    }
    out[source] = 0.f;
  }

private:
  std::unique_ptr<Components> components_;
};

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_EXACT_GEODESIC_ORACLE_H
