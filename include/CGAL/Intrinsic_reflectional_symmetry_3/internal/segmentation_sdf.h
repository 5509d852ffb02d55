// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SEGMENTATION_SDF_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SEGMENTATION_SDF_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/segmentation_graph.h>

#include <CGAL/boost/graph/alpha_expansion_graphcut.h>
#include <CGAL/Surface_mesh_segmentation/internal/Surface_mesh_segmentation.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

// CGAL's SDF segmentation (Shapira et al. 2008: SDF per face, GMM soft
// clustering, graph cut) called through its building blocks with an
// explicitly chosen graph cut.
//
// Why not CGAL::segmentation_from_sdf_values(): in CGAL 5.5.1 its default
// graph cut, unless the translation unit defines
// CGAL_DO_NOT_USE_BOYKOV_KOLMOGOROV_MAXFLOW_SOFTWARE before the first CGAL
// segmentation header, is the bundled Boykov-Kolmogorov MaxFlow, whose
// Graph::clear() (CGAL/Surface_mesh_segmentation/internal/auxiliary/graph.h)
// does not reset the flow counter: max_flow() of every later alpha-expansion
// move returns the accumulated flow, never below the first move's, so only
// the first move is applied (a single segment on a third of the PSB models).
// The algorithm class takes the graph cut as a template argument; passing
// Boost's max-flow here makes the package immune to what the user defines
// or includes first.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

/// the graph cut the package uses (Boost's Boykov-Kolmogorov max-flow on an adjacency list)
typedef CGAL::Alpha_expansion_boost_adjacency_list_tag Segmentation_graph_cut_tag;

template <class TriangleMesh, class VertexPointMap, class GeomTraits>
using Sdf_segmentation_algorithm =
  CGAL::internal::Surface_mesh_segmentation<TriangleMesh, GeomTraits, VertexPointMap, true /* fast bbox */,
                                             Segmentation_graph_cut_tag>;

// CGAL's post-processed SDF (filled, bilateral-smoothed, normalised to [0, 1]), by face index
template <class TriangleMesh, class VertexPointMap, class FaceIndexMap, class GeomTraits>
std::vector<double> segmentation_sdf_values(const TriangleMesh& tm, VertexPointMap vpm, FaceIndexMap fim,
                                            const GeomTraits& gt, double cone_angle, std::size_t number_of_rays)
{
  std::vector<double> sdf(num_faces(tm), 0.);
  Sdf_segmentation_algorithm<TriangleMesh, VertexPointMap, GeomTraits> algorithm(tm, gt, vpm);
  algorithm.calculate_sdf_values(cone_angle, number_of_rays, boost::make_iterator_property_map(sdf.begin(), fim),
                                 true);
  return sdf;
}

// The graph-cut segmentation of CGAL::segmentation_from_sdf_values() with
// `number_of_clusters` clusters, with the package's graph cut. `segment`
// receives connected segment ids 0..n-1 by face index; returns n.
template <class TriangleMesh, class VertexPointMap, class FaceIndexMap, class GeomTraits>
std::size_t sdf_graph_cut_segmentation(const TriangleMesh& tm, VertexPointMap vpm, FaceIndexMap fim,
                                       const GeomTraits& gt, const std::vector<double>& sdf,
                                       std::size_t number_of_clusters, double smoothing_lambda,
                                       std::vector<std::size_t>& segment)
{
  if(number_of_clusters < 1)
    throw Input_error(Input_problem::invalid_parameter, "the number of SDF clusters must be at least 1");
  segment.assign(num_faces(tm), 0);
  // CGAL's k-means++ seeding reads out of bounds when there are fewer
  // distinct values than clusters (e.g. the constant SDF of a sphere)
  std::vector<double> distinct(sdf);
  std::sort(distinct.begin(), distinct.end());
  number_of_clusters = (std::min)(number_of_clusters,
                                  std::size_t(std::unique(distinct.begin(), distinct.end()) - distinct.begin()));
  if(number_of_clusters <= 1) // one cluster: a segment per connected component
  {
    if(segment.empty()) return 0;
    const std::vector<int> same(segment.size(), 0);
    return label_components(make_face_graph(tm, vpm, fim), same, segment);
  }
  Sdf_segmentation_algorithm<TriangleMesh, VertexPointMap, GeomTraits> algorithm(tm, gt, vpm);
  return algorithm.partition(number_of_clusters, smoothing_lambda,
                             boost::make_iterator_property_map(sdf.begin(), fim),
                             boost::make_iterator_property_map(segment.begin(), fim), true);
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SEGMENTATION_SDF_H
