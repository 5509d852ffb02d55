// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_COMPONENT_MESHES_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_COMPONENT_MESHES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

/// Throws `Input_error(empty_mesh)` for a mesh without vertices and
/// `Input_error(not_triangle_mesh)` naming the first non-triangular face
/// (its position in `faces(tm)`).
template <typename TriangleMesh>
void check_triangle_mesh(const TriangleMesh& tm)
{
  if(num_vertices(tm) == 0)
    throw Input_error(Input_problem::empty_mesh, "the mesh has no vertices");
  std::size_t i = 0;
  for(auto f : faces(tm)) {
    if(!CGAL::is_triangle(halfedge(f, tm), tm))
      throw Input_error(Input_problem::not_triangle_mesh,
                        "face " + std::to_string(i) + " has " +
                        std::to_string(CGAL::halfedges_around_face(halfedge(f, tm), tm).size()) +
                        " sides", i);
    ++i;
  }
}

/// Throws `Input_error(invalid_parameter)` unless `vim` maps the vertices of
/// `tm` onto `0 .. num_vertices(tm)-1` (a `Surface_mesh` with removed,
/// not yet collected elements does not).
template <typename TriangleMesh, typename VertexIndexMap>
void check_vertex_index_map(const TriangleMesh& tm, VertexIndexMap vim)
{
  const std::size_t n = static_cast<std::size_t>(num_vertices(tm));
  std::vector<bool> seen(n, false);
  for(auto v : vertices(tm)) {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    if(i >= n || seen[i])
      throw Input_error(Input_problem::invalid_parameter,
                        "the vertex index map does not number the vertices 0 .. " +
                        std::to_string(n) + "-1 (collect the garbage of a Surface_mesh first)", i);
    seen[i] = true;
  }
}

/// The connected components of a triangle mesh, each copied into its own
/// `CGAL::Surface_mesh`, with the correspondence to the input's vertex indices.
///
/// Why: the heat method's Laplacian is singular on a multi-component mesh and
/// `Surface_mesh_shortest_path` is not documented for one, so both oracles
/// solve on one component at a time.
///
/// Each component mesh is built canonically from (points, triangles) in the
/// order of the input's vertex indices, with triangles sorted: two inputs that
/// differ only in their element order and mesh type (`Surface_mesh` versus
/// `Polyhedron_3`) give identical component meshes, hence identical distances.
/// Vertices that belong to no face form components without faces (their mesh
/// is empty).
template <typename Point_3>
class Component_meshes
{
public:
  typedef CGAL::Surface_mesh<Point_3>    Mesh;
  typedef typename Mesh::Vertex_index    Mesh_vertex;

  template <typename TriangleMesh, typename VertexPointMap, typename VertexIndexMap>
  Component_meshes(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim)
  {
    check_triangle_mesh(tm);
    check_vertex_index_map(tm, vim);
    const std::size_t n = static_cast<std::size_t>(num_vertices(tm));

    std::vector<Point_3> points(n);
    for(auto v : vertices(tm))
      points[static_cast<std::size_t>(get(vim, v))] = get(vpm, v);

    // each triangle rotated to start at its smallest index (orientation kept)
    std::vector<std::array<std::size_t, 3> > triangles;
    triangles.reserve(static_cast<std::size_t>(num_faces(tm)));
    std::size_t face_position = 0;
    for(auto f : faces(tm)) {
      auto h = halfedge(f, tm);
      std::array<std::size_t, 3> t = {{ static_cast<std::size_t>(get(vim, source(h, tm))),
                                        static_cast<std::size_t>(get(vim, target(h, tm))),
                                        static_cast<std::size_t>(get(vim, target(next(h, tm), tm))) }};
      if(t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
        throw Input_error(Input_problem::degenerate_face,
                          "face " + std::to_string(face_position) + " repeats a vertex", face_position);
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      triangles.push_back(t);
      ++face_position;
    }
    std::sort(triangles.begin(), triangles.end());

    // A plain union-find: boost::disjoint_sets_with_storage does not compile
    // in a translation unit that also includes Boost 1.74's CSR graph (its
    // boost::detail::get hides the pointer property-map get).
    std::vector<std::size_t> parent(n);
    for(std::size_t v = 0; v < n; ++v) parent[v] = v;
    auto find_root = [&parent](std::size_t v) {
      while(parent[v] != v) v = parent[v] = parent[parent[v]];
      return v;
    };
    for(const auto& t : triangles)
      for(std::size_t k = 1; k < 3; ++k) {
        const std::size_t a = find_root(t[0]), b = find_root(t[k]);
        if(a != b) parent[(std::max)(a, b)] = (std::min)(a, b);
      }

    // components numbered in the order of their smallest vertex index
    const std::size_t none = (std::numeric_limits<std::size_t>::max)();
    std::vector<std::size_t> component_of_root(n, none);
    component_.assign(n, none);
    local_.assign(n, 0);
    for(std::size_t v = 0; v < n; ++v) {
      const std::size_t r = find_root(v);
      if(component_of_root[r] == none) {
        component_of_root[r] = global_.size();
        global_.emplace_back();
      }
      const std::size_t c = component_of_root[r];
      component_[v] = c;
      local_[v] = global_[c].size();
      global_[c].push_back(v);
    }

    std::vector<std::vector<std::array<std::size_t, 3> > > local_triangles(global_.size());
    for(const auto& t : triangles)
      local_triangles[component_[t[0]]].push_back({{ local_[t[0]], local_[t[1]], local_[t[2]] }});

    meshes_.reserve(global_.size());
    for(std::size_t c = 0; c < global_.size(); ++c) {
      meshes_.emplace_back(new Mesh());
      if(local_triangles[c].empty())
        continue; // an isolated vertex: no mesh needed
      if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(local_triangles[c]))
        throw Input_error(Input_problem::non_manifold_vertex,
                          "the connected component of vertex " + std::to_string(global_[c][0]) +
                          " is not a manifold surface", global_[c][0]);
      std::vector<Point_3> local_points;
      local_points.reserve(global_[c].size());
      for(std::size_t v : global_[c])
        local_points.push_back(points[v]);
      // vertex i of the soup becomes Mesh_vertex(i) of the fresh mesh
      CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(local_points, local_triangles[c],
                                                                  *meshes_.back());
      CGAL_assertion(num_vertices(*meshes_.back()) == global_[c].size());
    }
  }

  std::size_t number_of_vertices() const { return component_.size(); }
  std::size_t number_of_components() const { return meshes_.size(); }

  /// the component of the vertex of (input) index `v`
  std::size_t component(std::size_t v) const { return component_[v]; }
  /// the vertex of (input) index `v` in the mesh of its component
  Mesh_vertex local_vertex(std::size_t v) const
  { return Mesh_vertex(static_cast<typename Mesh::size_type>(local_[v])); }
  /// whether component `c` has faces (otherwise it is a single isolated vertex)
  bool has_faces(std::size_t c) const { return num_faces(*meshes_[c]) != 0; }
  /// the mesh of component `c`; its address is stable for the lifetime of `*this`
  const Mesh& mesh(std::size_t c) const { return *meshes_[c]; }
  /// input index of each vertex of component `c`, in the order of `mesh(c)`'s vertex indices
  const std::vector<std::size_t>& input_indices(std::size_t c) const { return global_[c]; }

  /// fills `out` (one entry per input vertex) with `+infinity`, except
  /// `out[source] = 0`; the caller then overwrites the source's component.
  void initialize_row(std::size_t source, float* out) const
  {
    std::fill(out, out + number_of_vertices(), std::numeric_limits<float>::infinity());
    out[source] = 0.f;
  }

private:
  std::vector<std::unique_ptr<Mesh> > meshes_;       // unique_ptr: solvers keep references to the meshes
  std::vector<std::vector<std::size_t> > global_;    // component -> input indices of its vertices
  std::vector<std::size_t> component_;              // input index -> component
  std::vector<std::size_t> local_;                  // input index -> index in its component mesh
};

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_COMPONENT_MESHES_H
