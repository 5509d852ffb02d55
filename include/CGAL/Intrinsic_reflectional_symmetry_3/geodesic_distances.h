// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_GEODESIC_DISTANCES_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_GEODESIC_DISTANCES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/progress.h>
#include <CGAL/for_each.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Geodesic distances from a set of source vertices to every vertex of a mesh:
/// one row per source, one column per vertex index (in the order of the
/// mesh's vertex index map). Stored as `float`: 3000 sources on 10K vertices
/// take 120 MB. Distances to vertices of another connected component are
/// `+infinity`.
class Geodesic_distance_matrix
{
public:
  Geodesic_distance_matrix() = default;

  /// an all-infinite matrix with one row per entry of `sources`
  Geodesic_distance_matrix(std::vector<std::size_t> sources, std::size_t number_of_vertices)
    : sources_(std::move(sources)), number_of_vertices_(number_of_vertices),
      data_(sources_.size() * number_of_vertices, std::numeric_limits<float>::infinity())
  {}

  std::size_t number_of_sources() const { return sources_.size(); }
  std::size_t number_of_vertices() const { return number_of_vertices_; }
  /// vertex index of the source of row `i`
  const std::vector<std::size_t>& sources() const { return sources_; }

  float* row(std::size_t i) { return data_.data() + i * number_of_vertices_; }
  const float* row(std::size_t i) const { return data_.data() + i * number_of_vertices_; }
  /// distance from the source of row `i` to the vertex of index `v`
  float operator()(std::size_t i, std::size_t v) const { return data_[i * number_of_vertices_ + v]; }

  /// the largest finite entry (0 for an empty matrix)
  float largest_finite_distance() const
  {
    float m = 0.f;
    for(float d : data_)
      if(std::isfinite(d)) m = (std::max)(m, d);
    return m;
  }

private:
  std::vector<std::size_t> sources_;
  std::size_t number_of_vertices_ = 0;
  std::vector<float> data_;
};

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Fills a `Geodesic_distance_matrix` with the distances from `sources`
/// (vertex indices) to all vertices, one oracle query per source.
///
/// With `ConcurrencyTag = Parallel_tag` (the default when TBB is linked), the
/// sources are processed in parallel; each row depends only on its source, so
/// the result is the same at any thread count.
///
/// \tparam GeodesicOracle a model of `GeodesicDistanceOracle`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called with the advancement (between 0 and 1) as rows are done, never
///       twice at once; returning `false` stops the computation}
///     \cgalParamType{a model of `std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Input_error (`invalid_parameter`) if a source index is not a vertex index
/// \throws Operation_cancelled if the callback returns `false`
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename GeodesicOracle,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
Geodesic_distance_matrix
compute_geodesic_distance_matrix(const GeodesicOracle& oracle, const std::vector<std::size_t>& sources,
                                 const CGAL_NP_CLASS& np = parameters::default_values())
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
#endif
  const std::size_t n = oracle.number_of_vertices();
  for(std::size_t i = 0; i < sources.size(); ++i)
    if(sources[i] >= n)
      throw Input_error(Input_problem::invalid_parameter,
                        "source " + std::to_string(i) + " is vertex index " + std::to_string(sources[i]) +
                        " but the mesh has " + std::to_string(n) + " vertices", i);

  Geodesic_distance_matrix matrix(sources, n);
  std::vector<std::size_t> rows(sources.size());
  std::iota(rows.begin(), rows.end(), std::size_t(0));
  internal::Progress progress(internal::progress_callback(np), "compute_geodesic_distance_matrix()");
  internal::Progress_counter counter(progress, 0., 1., rows.size());
  CGAL::for_each<ConcurrencyTag>(rows, [&](std::size_t i) {
    if(counter.stopped()) return true; // skip the remaining rows
    oracle.distances_from(sources[i], matrix.row(i));
    counter.advance();
    return true;
  });
  progress.step(1.);
  return matrix;
}

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

// the three models of GeodesicDistanceOracle
#include <CGAL/Intrinsic_reflectional_symmetry_3/Heat_method_geodesic_oracle.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/Exact_geodesic_oracle.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/Dijkstra_geodesic_oracle.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_GEODESIC_DISTANCES_H
