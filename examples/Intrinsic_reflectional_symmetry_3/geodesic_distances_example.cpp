// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers
//
// Geodesic distances from a few farthest-point samples to every vertex, with
// the package's default oracle (heat method on the intrinsic Delaunay
// triangulation).
//
// usage: geodesic_distances_example [mesh]
// Without an argument: CGAL's meshes/elephant.off (found through CGAL_DATA_DIR),
// or a generated sphere when that file is not available.

#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/sampling.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/config.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;

int main(int argc, char** argv)
{
  Mesh mesh;
  const std::string file = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/elephant.off");
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || is_empty(mesh)) {
    if(argc > 1) {
      std::cerr << "cannot read " << file << "\n";
      return EXIT_FAILURE;
    }
    // no data files installed: a unit sphere of 2562 vertices
    std::cout << "cannot read " << file << ", using a generated sphere\n";
    mesh.clear();
    CGAL::make_icosahedron(mesh, K::Point_3(0, 0, 0), 1.);
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(4));
    for(auto v : vertices(mesh))
      mesh.point(v) = CGAL::ORIGIN + (mesh.point(v) - CGAL::ORIGIN) / std::sqrt((mesh.point(v) - CGAL::ORIGIN).squared_length());
  }
  if(!CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "the mesh is not a triangle mesh\n";
    return EXIT_FAILURE;
  }

  try {
    // 10 well-spread source vertices (deterministic for the seed)
    const std::vector<std::size_t> sources =
      IRS::farthest_point_samples(mesh, IRS::parameters::number_of_samples(10).random_seed(0u));

    // one factorisation up front, then one cheap solve per source (in parallel with TBB)
    IRS::Heat_method_geodesic_oracle<Mesh> oracle(mesh);
    const IRS::Geodesic_distance_matrix distances = IRS::compute_geodesic_distance_matrix(oracle, sources);

    std::cout << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces, "
              << oracle.number_of_components() << " connected component(s)\n"
              << "distance matrix: " << distances.number_of_sources() << " sources x "
              << distances.number_of_vertices() << " vertices\n"
              << "largest finite distance: " << distances.largest_finite_distance() << "\n";
    for(std::size_t i = 0; i < distances.number_of_sources(); ++i) {
      const float* row = distances.row(i);
      std::size_t farthest = sources[i];
      double sum = 0;
      std::size_t reachable = 0;
      for(std::size_t v = 0; v < distances.number_of_vertices(); ++v)
        if(std::isfinite(row[v])) {
          sum += row[v];
          ++reachable;
          if(row[v] > row[farthest]) farthest = v;
        }
      std::cout << "  source vertex " << sources[i] << ": mean distance " << sum / double(reachable)
                << ", farthest vertex " << farthest << " at " << row[farthest]
                << ", " << distances.number_of_vertices() - reachable << " unreachable\n";
    }
  } catch(const IRS::Input_error& e) {
    std::cerr << "bad input: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
