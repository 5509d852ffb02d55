// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SEGMENTATION_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SEGMENTATION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/symmetric_map.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/progress.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/segmentation_graph.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/segmentation_merge.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/segmentation_sdf.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <boost/property_map/property_map.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

/// \file segmentation.h
/// Symmetry-aware mesh segmentation (paper Sec. 4.1): the symmetric (PIRS)
/// regions of the IRSA curves as segments, and the merging of a black-box
/// over-segmentation by the regions.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Default of the `minimum_segment_area` named parameter: a connected piece
/// of less than this fraction of the mesh area is not a segment of its own.
constexpr double default_minimum_segment_area = 0.01;

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Default of the `minimum_region_coverage` named parameter: a part of the
/// over-segmentation joins a region only where the region covers at least
/// this fraction of its area (0: the paper's rule, the largest share wins).
constexpr double default_minimum_region_coverage = 0.8;

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The number of parts of the default over-segmentation (the paper's choice).
constexpr std::size_t default_number_of_over_segmentation_parts = 20;

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The range of the numbers of clusters of the graph cuts whose common
/// refinement is the default over-segmentation (`Sdf_over_segmenter`).
constexpr std::size_t default_minimum_number_of_clusters = 2;
constexpr std::size_t default_maximum_number_of_clusters = 12;

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The default model of `OverSegmenter`: \cgal's SDF segmentation
/// (`Surface_mesh_segmentation`: shape diameter function per face, soft
/// clustering of its values, graph cut regularised by dihedral angles, which
/// follows the minima rule), set up to give about `number_of_parts` connected
/// parts.
///
/// **Graph cut.** The alpha expansion always uses Boost's max-flow
/// (`CGAL::Alpha_expansion_boost_adjacency_list_tag`), whatever the user's
/// translation unit defines: in \cgal 5.5 the default Boykov-Kolmogorov
/// MaxFlow graph cut of `CGAL::segmentation_from_sdf_values()` keeps the flow
/// of the first expansion move in the later ones, so that only the first
/// move is applied (often a single segment).
///
/// **Parts.** The SDF values are computed once; the graph-cut segmentation
/// is run with every number of clusters from `minimum_number_of_clusters` to
/// `maximum_number_of_clusters`, each run cut down to that many connected
/// segments (the smallest merged into their neighbours), and the parts are
/// the connected pieces of their common refinement: two faces share a part
/// when every run puts them in the same segment. So the boundaries of the
/// parts are ones that \cgal's SDF segmentation draws at some number of
/// segments, and merging parts can give back (up to the merges below) its
/// segmentation at any number in the range.
/// Pieces of less than 0.05 % of the area (slivers between nearly equal
/// boundaries of two runs; with a single run, none), then the smallest parts, are
/// merged into the neighbour they share the longest boundary with until at
/// most `number_of_parts` remain. A mesh whose SDF is nearly uniform may give
/// fewer parts. With `minimum_number_of_clusters == maximum_number_of_clusters
/// == number_of_parts == n` this is \cgal's SDF segmentation with `n`
/// segments.
/// The runs are computed in parallel where TBB is linked. Deterministic at any
/// thread count (\cgal's clustering uses a fixed seed).
///
/// \cgalModels `OverSegmenter`
class Sdf_over_segmenter
{
public:
  /// \param number_of_parts the largest number of parts (at least 1)
  /// \param minimum_number_of_clusters the smallest number of SDF clusters run (at least 1)
  /// \param maximum_number_of_clusters the largest number of SDF clusters run (at least the smallest, at most 64)
  /// \param smoothing_lambda the graph cut's smoothness weight (\cgal's default 0.26)
  /// \param cone_angle the SDF cone angle (\cgal's default 2 pi / 3)
  /// \param number_of_rays the SDF rays per face (\cgal's default 25)
  /// \throws Input_error (`invalid_parameter`) for a value out of range
  explicit Sdf_over_segmenter(std::size_t number_of_parts = default_number_of_over_segmentation_parts,
                              std::size_t minimum_number_of_clusters = default_minimum_number_of_clusters,
                              std::size_t maximum_number_of_clusters = default_maximum_number_of_clusters,
                              double smoothing_lambda = 0.26, double cone_angle = 2. / 3. * CGAL_PI,
                              std::size_t number_of_rays = 25)
    : parts_(number_of_parts), min_clusters_(minimum_number_of_clusters), max_clusters_(maximum_number_of_clusters),
      lambda_(smoothing_lambda), cone_(cone_angle), rays_(number_of_rays)
  {
    if(parts_ < 1 || min_clusters_ < 1 || max_clusters_ < min_clusters_ || max_clusters_ > 64 ||
       !(lambda_ >= 0. && lambda_ <= 1.) || !(cone_ > 0. && cone_ <= CGAL_PI) || rays_ < 1)
      throw Input_error(Input_problem::invalid_parameter,
                        "Sdf_over_segmenter: number_of_parts must be >= 1, the numbers of clusters in [1, 64] "
                        "with the minimum not above the maximum, smoothing_lambda in [0, 1], cone_angle in (0, pi], "
                        "number_of_rays >= 1");
  }

  /// writes a part id in `[0, n)` for every face of `tm` into `part` and returns `n`.
  /// Every part is connected.
  template <typename TriangleMesh, typename VertexPointMap, typename FacePartMap>
  std::size_t operator()(const TriangleMesh& tm, VertexPointMap vpm, FacePartMap part) const
  {
    typedef typename boost::property_traits<VertexPointMap>::value_type Point;
    typedef typename CGAL::Kernel_traits<Point>::Kernel GT;
    const auto fim = CGAL::get_initialized_face_index_map(tm);
    internal::make_face_graph(tm, vpm, fim); // checks the mesh before the SDF
    return from_sdf_values(tm, vpm, internal::segmentation_sdf_values(tm, vpm, fim, GT(), cone_, rays_), part);
  }

  /// the same as `operator()`, from precomputed SDF values: \cgal's
  /// post-processed values (`CGAL::sdf_values()` with `postprocess == true`),
  /// by face index (`CGAL::get_initialized_face_index_map(tm)`).
  /// The SDF parameters of the constructor are then unused.
  template <typename TriangleMesh, typename VertexPointMap, typename FacePartMap>
  std::size_t from_sdf_values(const TriangleMesh& tm, VertexPointMap vpm, const std::vector<double>& sdf,
                              FacePartMap part) const
  {
    typedef typename boost::property_traits<VertexPointMap>::value_type Point;
    typedef typename CGAL::Kernel_traits<Point>::Kernel GT;
    typedef typename boost::property_traits<FacePartMap>::value_type Value;
    const auto fim = CGAL::get_initialized_face_index_map(tm);
    const internal::Face_graph g = internal::make_face_graph(tm, vpm, fim);
    if(sdf.size() != g.number_of_faces)
      throw Input_error(Input_problem::invalid_parameter, "one SDF value per face expected");
    const GT gt;
    // the runs are independent (each with its own seeded clustering): in
    // parallel where TBB is linked, refined in a fixed order
    const std::size_t runs = max_clusters_ - min_clusters_ + 1;
    std::vector<std::vector<std::size_t>> run_segments(runs);
    std::vector<std::size_t> run_counts(runs);
    auto run = [&](std::size_t r) {
      const std::size_t k = min_clusters_ + r;
      std::size_t n = internal::sdf_graph_cut_segmentation(tm, vpm, fim, gt, sdf, k, lambda_, run_segments[r]);
      run_counts[r] = internal::merge_small_components(g, run_segments[r], n, 0., k);
    };
#ifdef CGAL_LINKED_WITH_TBB
    tbb::parallel_for(std::size_t(0), runs, run);
#else
    for(std::size_t r = 0; r < runs; ++r) run(r);
#endif
    // the common refinement: a piece is a connected set of faces that every
    // run puts in one segment
    std::vector<std::size_t> piece(g.number_of_faces, 0);
    std::vector<std::uint64_t> both(g.number_of_faces);
    std::size_t n = 1;
    for(std::size_t r = 0; r < runs; ++r)
    {
      for(std::size_t f = 0; f < g.number_of_faces; ++f)
        both[f] = std::uint64_t(piece[f]) * run_counts[r] + run_segments[r][f];
      n = internal::label_components(g, both, piece);
    }
    const double sliver = max_clusters_ > min_clusters_ ? minimum_piece_area * g.total_area : 0.;
    n = internal::merge_small_components(g, piece, n, sliver, parts_);
    for(auto f : faces(tm)) put(part, f, static_cast<Value>(piece[std::size_t(get(fim, f))]));
    return n;
  }

  std::size_t number_of_parts() const { return parts_; }

private:
  // pieces of the refinement below this fraction of the area are slivers
  // between nearly equal boundaries of two runs
  static constexpr double minimum_piece_area = 0.0005;

  std::size_t parts_, min_clusters_, max_clusters_;
  double lambda_, cone_;
  std::size_t rays_;
};

namespace internal {

template <class NamedParameters>
double segmentation_minimum_coverage(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double c =
    choose_parameter(get_parameter(np, internal_np::minimum_region_coverage), default_minimum_region_coverage);
  if(!(c >= 0. && c <= 1.))
    throw Input_error(Input_problem::invalid_parameter, "minimum_region_coverage must be in [0, 1]");
  return c;
}

template <class TriangleMesh, class NamedParameters>
double segmentation_minimum_area(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double a = choose_parameter(get_parameter(np, internal_np::minimum_segment_area), default_minimum_segment_area);
  if(!(a >= 0. && a <= 1.))
    throw Input_error(Input_problem::invalid_parameter, "minimum_segment_area must be in [0, 1]");
  return a;
}

template <class TriangleMesh, class FaceMap, class FaceIndexMap>
std::vector<long> read_face_labels(const TriangleMesh& tm, FaceMap map, FaceIndexMap fim)
{
  std::vector<long> out(num_faces(tm), -1);
  for(auto f : faces(tm)) out[std::size_t(get(fim, f))] = static_cast<long>(get(map, f));
  return out;
}

template <class TriangleMesh, class FaceSegmentMap, class FaceIndexMap>
void write_face_segments(const TriangleMesh& tm, const std::vector<std::size_t>& seg, FaceSegmentMap out,
                         FaceIndexMap fim)
{
  typedef typename boost::property_traits<FaceSegmentMap>::value_type Value;
  for(auto f : faces(tm)) put(out, f, static_cast<Value>(seg[std::size_t(get(fim, f))]));
}

template <class TriangleMesh, class NamedParameters>
Face_graph segmentation_face_graph(const TriangleMesh& tm, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if(num_vertices(tm) == 0 || num_faces(tm) == 0)
    throw Input_error(Input_problem::empty_mesh, "the mesh has no vertices or no faces");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  return make_face_graph(tm, vpm, CGAL::get_initialized_face_index_map(tm, np));
}

} // namespace internal

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Pure symmetry segmentation (paper Sec. 4.1, the "snowmen" of Fig. 12):
/// the symmetric (PIRS) regions of the IRSA curves, grown by
/// `symmetric_regions()`, as segments. Region boundaries may cross smooth
/// surface where no concavity exists.
///
/// Every face gets a segment, and every segment is connected (across edges):
/// each connected piece of a region, and each connected piece of the faces
/// of no region, is a segment of its own, except pieces of less than
/// `minimum_segment_area` times the mesh area, which join the neighbouring
/// segment they share the longest boundary with (smallest first). With
/// `merge_uncovered_parts(true)` every piece of uncovered faces joins a
/// neighbour instead, whatever its size.
/// Segment ids are `0..n-1`, numbered in the order of their smallest face index.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (for the region growing);
///         the result does not depend on it
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam CurveRange a range of `Irsa_curve` (as from `extract_irsa_curves()`)
/// \tparam FaceSegmentMap a model of `WritablePropertyMap` with the face descriptor as key and an integral value type
///
/// \param tm the triangle mesh (read only)
/// \param D the sample-to-vertex distance matrix the curves were computed with
/// \param curves the IRSA curves
/// \param segment receives the segment of every face
/// \param np optional named parameters: those of `symmetric_regions()`, and
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{minimum_segment_area}
///     \cgalParamDescription{a connected piece smaller than this fraction of the mesh area joins a neighbour}
///     \cgalParamType{double in [0, 1]}
///     \cgalParamDefault{`default_minimum_segment_area` (0.01)}
///   \cgalParamNEnd
///   \cgalParamNBegin{merge_uncovered_parts}
///     \cgalParamDescription{if `true`, faces of no region join neighbouring segments instead of forming their own}
///     \cgalParamType{bool}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{the face indices}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of segments
/// \throws Input_error `not_triangle_mesh`, `empty_mesh`, or `invalid_parameter`
///         (`D` or a curve does not match `tm`, a parameter out of range)
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh, typename CurveRange,
          typename FaceSegmentMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::size_t symmetry_segmentation(const TriangleMesh& tm, const Geodesic_distance_matrix& D,
                                  const CurveRange& curves, FaceSegmentMap segment,
                                  const CGAL_NP_CLASS& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const internal::Face_graph g = internal::segmentation_face_graph(tm, np);
  const double minimum_area = internal::segmentation_minimum_area<TriangleMesh>(np) * g.total_area;
  const bool merge_uncovered = choose_parameter(get_parameter(np, internal_np::merge_uncovered_parts), false);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);

  std::vector<long> region(g.number_of_faces, -1);
  symmetric_regions<ConcurrencyTag>(tm, D, curves, boost::make_iterator_property_map(region.begin(), fim), np);
  std::vector<std::size_t> seg;
  const std::size_t n = internal::finish_segments(g, region, minimum_area, merge_uncovered, seg);
  internal::write_face_segments(tm, seg, segment, fim);
  return n;
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Merging of an over-segmentation by symmetric regions (paper Sec. 4.1):
/// every part goes to the region that covers the largest area of it, where
/// that region covers at least `minimum_region_coverage` of the part.
///
/// The parts are first split into connected pieces (parts must be
/// connected). A part that no region covers so much of (no region touches
/// it, or it straddles the boundary of two regions) keeps its own id (it
/// becomes a segment of its own), or, with `merge_uncovered_parts(true)`,
/// joins the neighbouring segment it shares the longest boundary with. The
/// paper gives every part to the region of largest share
/// (`minimum_region_coverage(0)`); by default a part that straddles two
/// regions stays apart, because a region's boundary where two grass fires
/// meet is seldom where a part ends (on the 76 PSB models with the default
/// over-segmentation, Rand-index error 0.207 with 0.8 and 0.295 with 0,
/// against 0.223 and 0.277 for \cgal's SDF segmentation with as many
/// segments; `segmentation_benchmark --nested`). The union of
/// the parts of a region may be disconnected: each connected piece is a
/// segment, and pieces of less than `minimum_segment_area` times the mesh
/// area join a neighbour as in `symmetry_segmentation()`. So the number of
/// segments follows the number of regions (curves), plus the uncovered
/// parts. Segment ids are `0..n-1`, in the order of their smallest face index.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam FaceRegionMap a model of `ReadablePropertyMap`, face descriptor to a signed integral region id, -1 for none
///         (as written by `symmetric_regions()`)
/// \tparam FacePartMap a model of `ReadablePropertyMap`, face descriptor to an integral part id
/// \tparam FaceSegmentMap a model of `WritablePropertyMap`, face descriptor to an integral segment id
///
/// \param tm the triangle mesh (read only)
/// \param region the region of every face, or -1
/// \param part the part of every face in the over-segmentation
/// \param segment receives the segment of every face
/// \param np optional named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{minimum_segment_area}
///     \cgalParamDescription{a connected piece smaller than this fraction of the mesh area joins a neighbour}
///     \cgalParamType{double in [0, 1]}
///     \cgalParamDefault{`default_minimum_segment_area` (0.01)}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_region_coverage}
///     \cgalParamDescription{a part joins the region of largest share only if that share is at least this
///       fraction of the part's area (0: always, as in the paper)}
///     \cgalParamType{double in [0, 1]}
///     \cgalParamDefault{`default_minimum_region_coverage` (0.8)}
///   \cgalParamNEnd
///   \cgalParamNBegin{merge_uncovered_parts}
///     \cgalParamDescription{if `true`, parts of no region join neighbouring segments instead of staying segments}
///     \cgalParamType{bool}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm` (face areas)}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{the face indices}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of segments
/// \throws Input_error `not_triangle_mesh`, `empty_mesh`, or `invalid_parameter`
template <typename TriangleMesh, typename FaceRegionMap, typename FacePartMap, typename FaceSegmentMap,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
std::size_t merge_over_segmentation(const TriangleMesh& tm, FaceRegionMap region, FacePartMap part,
                                    FaceSegmentMap segment, const CGAL_NP_CLASS& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const internal::Face_graph g = internal::segmentation_face_graph(tm, np);
  const double minimum_area = internal::segmentation_minimum_area<TriangleMesh>(np) * g.total_area;
  const double minimum_coverage = internal::segmentation_minimum_coverage(np);
  const bool merge_uncovered = choose_parameter(get_parameter(np, internal_np::merge_uncovered_parts), false);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  std::vector<long> r = internal::read_face_labels(tm, region, fim);
  for(long& x : r) if(x < 0) x = -1;
  const std::vector<long> p = internal::read_face_labels(tm, part, fim);
  std::vector<std::size_t> seg;
  const std::size_t n =
    internal::merge_parts(g, r, p, minimum_area, merge_uncovered, minimum_coverage, seg);
  internal::write_face_segments(tm, seg, segment, fim);
  return n;
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Symmetry-aware segmentation (paper Sec. 4.1, Fig. 12): the symmetric
/// regions of the curves (`symmetric_regions()`) merge the parts of an
/// over-segmentation of `tm` (`merge_over_segmentation()`). The
/// over-segmenter is `Sdf_over_segmenter` (at most 20 parts, as in the paper)
/// unless another model of `OverSegmenter` is passed as `over_segmenter`.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (for the region growing);
///         the result does not depend on it
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam CurveRange a range of `Irsa_curve`
/// \tparam FaceSegmentMap a model of `WritablePropertyMap` with the face descriptor as key and an integral value type
///
/// \param tm the triangle mesh (read only)
/// \param D the sample-to-vertex distance matrix the curves were computed with
/// \param curves the IRSA curves
/// \param segment receives the segment of every face
/// \param np optional named parameters: those of `symmetric_regions()` and
///        `merge_over_segmentation()`, and
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{over_segmenter}
///     \cgalParamDescription{the black-box over-segmentation}
///     \cgalParamType{a model of `OverSegmenter`}
///     \cgalParamDefault{`Sdf_over_segmenter()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called with the advancement (between 0 and 1) while the regions are grown
///       (up to 0.5), after the over-segmentation (0.9) and at the end; returning `false` stops the function.
///       The over-segmenter itself is not interrupted: the function stops when it returns.}
///     \cgalParamType{a model of `std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{keep_off_axis_parts}
///     \cgalParamDescription{if `true`, only the parts a curve crosses (at least 3 faces with a curve vertex)
///       merge into the curve's region, the symmetric core; the region's other parts, which come in mirror
///       pairs, stay segments of their own (subject to `minimum_segment_area`). Not in the paper: with a single
///       curve the paper's merging gives a single segment. Measured on 76 PSB models (`segmentation_benchmark
///       --nested`): Rand-index error 0.200 against 0.202 for \cgal's SDF segmentation with as many segments
///       (0.207 and 0.223 without this parameter).}
///     \cgalParamType{bool}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of segments
/// \throws Input_error `not_triangle_mesh`, `empty_mesh`, or `invalid_parameter`
/// \throws Operation_cancelled if the callback returns `false`
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh, typename CurveRange,
          typename FaceSegmentMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::size_t symmetry_aware_segmentation(const TriangleMesh& tm, const Geodesic_distance_matrix& D,
                                        const CurveRange& curves, FaceSegmentMap segment,
                                        const CGAL_NP_CLASS& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const internal::Face_graph g = internal::segmentation_face_graph(tm, np); // checks the mesh first
  const double minimum_coverage = internal::segmentation_minimum_coverage(np); // and the parameters
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  std::vector<long> region(g.number_of_faces, -1);
  internal::Progress progress(internal::progress_callback(np), "symmetry_aware_segmentation()");
  {
    // the regions report the first half of the advancement; a stop there names this function
    const internal::Progress::Callback regions_callback = [&progress](double x) {
      progress.report(0.5 * x, true);
      return !progress.stopped();
    };
    try
    {
      symmetric_regions<ConcurrencyTag>(tm, D, curves, boost::make_iterator_property_map(region.begin(), fim),
                                        np.callback(regions_callback));
    }
    catch(const Operation_cancelled&)
    {
      progress.check();
      throw;
    }
  }

  std::vector<std::size_t> part(g.number_of_faces, 0);
  const auto over = choose_parameter(get_parameter(np, internal_np::over_segmenter), Sdf_over_segmenter());
  over(tm, vpm, boost::make_iterator_property_map(part.begin(), fim));
  progress.step(0.9);

  const double minimum_area = internal::segmentation_minimum_area<TriangleMesh>(np) * g.total_area;
  const bool merge_uncovered = choose_parameter(get_parameter(np, internal_np::merge_uncovered_parts), false);
  const bool off_axis = choose_parameter(get_parameter(np, internal_np::keep_off_axis_parts), false);
  std::vector<char> axis_faces;
  if(off_axis)
  {
    // faces with a vertex on a curve
    const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
    std::vector<char> on_curve(num_vertices(tm), 0);
    for(const Irsa_curve& c : curves)
      for(const auto& pl : c.polylines)
        for(std::size_t v : pl) on_curve[v] = 1; // indices checked by symmetric_regions()
    axis_faces.assign(g.number_of_faces, 0);
    for(auto f : faces(tm))
      for(auto h : halfedges_around_face(halfedge(f, tm), tm))
        if(on_curve[std::size_t(get(vim, target(h, tm)))]) axis_faces[std::size_t(get(fim, f))] = 1;
  }
  std::vector<long> p(part.begin(), part.end());
  std::vector<std::size_t> seg;
  const std::size_t n = internal::merge_parts(g, region, p, minimum_area, merge_uncovered,
                                              minimum_coverage, seg, off_axis ? &axis_faces : nullptr);
  internal::write_face_segments(tm, seg, segment, fim);
  progress.step(1.);
  return n;
}

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SEGMENTATION_H
