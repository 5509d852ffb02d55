// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SAMPLING_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SAMPLING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/component_meshes.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/edge_length_graph.h>

#include <CGAL/Random.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/range/iterator_range.hpp>

#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
///
/// Geodesic farthest-point sampling of the vertices of a mesh (paper §3.5):
/// the first sample is a vertex drawn with `random_seed`; each further sample
/// is the vertex farthest from all samples chosen so far, distances being
/// shortest paths along the edges weighted by their Euclidean length. Ties are
/// broken by the smallest vertex index, so the result depends only on the
/// mesh and the seed.
///
/// The distance to the sample set is maintained incrementally: a new sample
/// only relaxes the vertices that it brings closer, so 3000 samples on a 17K
/// vertex mesh take a fraction of a second.
///
/// Connected components: a vertex of a component without samples is at
/// infinite distance, so each component receives a sample before any
/// component receives a second one (as long as samples remain).
///
/// \tparam PolygonMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         (only the edges are used; the faces need not be triangles)
///
/// \param tm the mesh
/// \param np an optional sequence of named parameters among the ones below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_samples}
///     \cgalParamDescription{how many vertices to select}
///     \cgalParamType{`int` (or `std::size_t`), between 1 and `num_vertices(tm)`}
///     \cgalParamDefault{`min(3000, ceil(num_vertices(tm) / 4))`: the paper used 2K-5K samples on 10K-15K vertices}
///     \cgalParamExtra{the package's `IRS::parameters::number_of_samples()`; CGAL's
///                     `CGAL::parameters::number_of_samples()` is read too when the former is absent}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{seed of the random choice of the first sample}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices}
///     \cgalParamType{a model of `ReadablePropertyMap` from vertex descriptors to a CGAL kernel's `Point_3`}
///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{the vertex indices returned}
///     \cgalParamType{a model of `ReadablePropertyMap` from vertex descriptors to `std::size_t`,
///                    numbering the vertices `0 .. num_vertices(tm)-1`}
///     \cgalParamDefault{`CGAL::get_initialized_vertex_index_map(tm, np)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the vertex indices of the samples, in the order of their selection
///          (all distinct)
///
/// \throws Input_error `empty_mesh` (no vertices), `too_many_samples` (more
///         samples than vertices), or `invalid_parameter` (fewer than one sample,
///         vertex indices not in `0 .. n-1`)
template <typename PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::vector<std::size_t>
farthest_point_samples(const PolygonMesh& tm, const CGAL_NP_CLASS& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  const std::size_t n = static_cast<std::size_t>(num_vertices(tm));
  if(n == 0)
    throw Input_error(Input_problem::empty_mesh, "the mesh has no vertices");

  const long long default_samples = static_cast<long long>((std::min)((n + 3) / 4, std::size_t(3000)));
  const long long requested = static_cast<long long>(
    choose_parameter(get_parameter(np, internal_np::number_of_samples),
                     choose_parameter(get_parameter(np, CGAL::internal_np::number_of_samples),
                                      default_samples)));
  if(requested < 1)
    throw Input_error(Input_problem::invalid_parameter,
                      "number_of_samples must be at least 1, not " + std::to_string(requested));
  if(static_cast<unsigned long long>(requested) > n)
    throw Input_error(Input_problem::too_many_samples,
                      std::to_string(requested) + " samples requested but the mesh has only " +
                      std::to_string(n) + " vertices");
  const std::size_t number_of_samples = static_cast<std::size_t>(requested);
  const unsigned int seed =
    static_cast<unsigned int>(choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u));

  typedef typename CGAL::GetVertexPointMap<PolygonMesh, CGAL_NP_CLASS>::const_type Vertex_point_map;
  const Vertex_point_map vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  internal::check_vertex_index_map(tm, vim);
  const internal::Edge_length_graph graph = internal::make_edge_length_graph(tm, vpm, vim);

  // Hand-written Dijkstra: Boost's re-initialises every vertex on each call, while
  // an incremental update must only visit the vertices that the new sample brings closer.
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> distance(n, inf); // to the nearest sample so far
  std::vector<bool> selected(n, false);
  typedef std::pair<double, std::size_t> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;

  std::vector<std::size_t> samples;
  samples.reserve(number_of_samples);
  CGAL::Random random(seed);
  std::size_t next = static_cast<std::size_t>(random.get_int(0, static_cast<int>(n)));
  for(;;) {
    samples.push_back(next);
    selected[next] = true;
    if(samples.size() == number_of_samples)
      break;

    distance[next] = 0.;
    queue.push(Entry(0., next));
    while(!queue.empty()) {
      const Entry top = queue.top();
      queue.pop();
      if(top.first > distance[top.second])
        continue; // stale entry
      for(auto e : boost::make_iterator_range(out_edges(top.second, graph))) {
        const std::size_t w = static_cast<std::size_t>(target(e, graph));
        const double d = top.first + graph[e];
        if(d < distance[w]) {
          distance[w] = d;
          queue.push(Entry(d, w));
        }
      }
    }

    // the farthest unselected vertex; strict comparison keeps the smallest index on ties
    next = n;
    for(std::size_t v = 0; v < n; ++v)
      if(!selected[v] && (next == n || distance[v] > distance[next]))
        next = v;
  }
  return samples;
}

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SAMPLING_H
