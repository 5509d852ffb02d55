// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_IRSA_TRANSFORM_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_IRSA_TRANSFORM_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/progress.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/voting_common.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/voting_kernel.h>

#include <CGAL/Real_timer.h>
#include <CGAL/tags.h>
#include <CGAL/boost/graph/named_params_helper.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// What one voting pair {a, b} contributed to the IRSA transform: its voted
/// boundary, the local symmetry support along it, and the pairs that voted.
/// Curve extraction (paper Sec. 3.4) ranks boundaries by the line integral of
/// `tau * mu` along them and refines `mu` with the eligible pairs.
struct Irsa_voting_pair
{
  /// the two samples (rows of the distance matrix), `a < b`
  std::size_t a = 0, b = 0;
  /// vertex index of `m`, the vertex of `boundary` minimising d(a,.) + d(b,.)
  std::size_t midpoint = 0;
  /// beta(a, b): vertex indices, increasing
  std::vector<std::size_t> boundary;
  /// mu(m') for each vertex m' of `boundary` (same order)
  std::vector<double> support;
  /// the pairs {p, q} that passed the similarity, distance, locality and
  /// axial filters (all but the test at m'), as (p on a's side, q on b's
  /// side), in increasing order of (min(p,q), max(p,q))
  std::vector<std::pair<std::size_t, std::size_t>> eligible_pairs;
};

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Result of `compute_irsa_transform()`: the voting pairs that voted, and
/// the quantities the filters used, in the mesh's length unit.
struct Irsa_voting_result
{
  /// the voting pairs with at least one eligible pair, in increasing order of (a, b)
  std::vector<Irsa_voting_pair> voting_pairs;
  std::size_t number_of_similar_pairs = 0;        ///< distinct similar pairs given
  std::size_t number_of_voting_pairs = 0;         ///< after the cap `maximum_number_of_voting_pairs`
  std::size_t number_of_disconnected_pairs = 0;   ///< a and b in different components: no vote
  std::size_t number_of_pairs_without_boundary = 0; ///< empty beta(a, b): no vote
  std::size_t number_of_pairs_without_support = 0;  ///< no pair passed the filters: no vote
  double sigma = 0.;                  ///< Gaussian width: largest finite sample-to-sample distance
  double mean_edge_length = 0.;
  double mean_sample_spacing = 0.;    ///< mean distance from a sample to its nearest sample
  double distance_tolerance_floor = 0.; ///< absolute floor of the distance tests
  double locality_radius = 0.;        ///< absolute DBSCAN radius
  std::size_t number_of_candidate_pairs = 0;      ///< pairs passing the m'-independent distance tests, summed over voting pairs
  std::size_t number_of_pairs_after_locality = 0; ///< of those, pairs passing the locality filter, summed
  std::size_t number_of_pairs_after_axial = 0;    ///< of those, pairs passing the axial-sym filter, summed
  double setup_seconds = 0.;          ///< wall time of the set-up (checks, sample matrix)
  double voting_seconds = 0.;         ///< wall time of the voting proper (with its indices)
  /// time spent in each stage of the voting, summed over the threads (wall
  /// clock inside the stage, so it counts waiting on a busy machine): beta and
  /// m, the distance filter, the locality filter, the axial-sym filter, mu
  /// along beta
  double stage_seconds[5] = {0., 0., 0., 0., 0.};
};

namespace internal {

template <class Result>
void fill_result_header(const Voting_setup& s, Result& r)
{
  r.number_of_similar_pairs = s.similar_pairs.size();
  r.number_of_voting_pairs = s.voting_pairs.size();
  r.sigma = s.settings.sigma;
  r.mean_edge_length = s.mesh.mean_edge_length;
  r.mean_sample_spacing = s.settings.mean_sample_spacing;
  r.distance_tolerance_floor = s.settings.tolerance.floor;
  r.locality_radius = s.settings.locality_radius;
}

// Runs the fast voting of every voting pair and sums tau in pair order.
// `index`: the (mesh, D) index of a previous transform on the same mesh and
// matrix, or nullptr (it is then built here). `progress`: the callback, or
// nullptr; once it asks to stop, the remaining pairs are skipped and the
// result is incomplete (the caller throws).
template <class ConcurrencyTag>
Irsa_voting_result run_fast_voting(const Voting_setup& s, std::vector<double>& tau, int number_of_threads,
                                   const Voting_index* index = nullptr, Progress* progress = nullptr)
{
  Irsa_voting_result result;
  fill_result_header(s, result);
  tau.assign(s.mesh.number_of_vertices, 0.);

  const bool parallel = std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
  const std::size_t nvote = s.voting_pairs.size();
  std::vector<Irsa_voting_pair> records(nvote);
  std::vector<unsigned char> outcome(nvote, 0);
  auto collect = [&](const Fast_voting::Scratch& sc) {
    for(int i = 0; i < 5; ++i) result.stage_seconds[i] += sc.stage_seconds[i];
    result.number_of_candidate_pairs += sc.total_candidates;
    result.number_of_pairs_after_locality += sc.total_after_locality;
    result.number_of_pairs_after_axial += sc.total_after_axial;
  };

  // Every pair is computed alone (the scratch buffers only avoid
  // allocations), in two passes: beta and m for every pair, then the filters
  // and mu with the pairs grouped by midpoint, so that each column D(., m)
  // (a cache miss per sample) is read once per midpoint, not once per pair.
  Progress no_callback{Progress::Callback(), std::string()};
  Progress& p = progress != nullptr ? *progress : no_callback;
  // advancement: the boundaries up to 0.3, the support of the pairs that have one up to 1
  Progress_counter first_count(p, 0., 0.3, nvote);
  std::unique_ptr<Progress_counter> second_count;
  auto run = [&] {
    const Fast_voting fv(s, parallel, index);
    auto first_pass = [&](std::size_t k, Fast_voting::Scratch& sc) {
      if(p.stopped()) return;
      Irsa_voting_pair& r = records[k];
      r.a = s.similar_pairs[s.voting_pairs[k]].first;
      r.b = s.similar_pairs[s.voting_pairs[k]].second;
      outcome[k] = (unsigned char)fv.boundary_and_midpoint(r.a, r.b, sc, r.midpoint, r.boundary);
      first_count.advance();
    };
    std::vector<std::size_t> by_midpoint, group_start;
    auto group = [&] {
      for(std::size_t k = 0; k < nvote; ++k)
        if(outcome[k] == Fast_voting::voted) by_midpoint.push_back(k);
      std::sort(by_midpoint.begin(), by_midpoint.end(), [&](std::size_t x, std::size_t y) {
        return records[x].midpoint < records[y].midpoint || (records[x].midpoint == records[y].midpoint && x < y);
      });
      for(std::size_t i = 0; i < by_midpoint.size(); ++i)
        if(i == 0 || records[by_midpoint[i]].midpoint != records[by_midpoint[i - 1]].midpoint)
          group_start.push_back(i);
      group_start.push_back(by_midpoint.size());
      second_count.reset(new Progress_counter(p, 0.3, 1., by_midpoint.size()));
    };
    auto second_pass = [&](std::size_t g, Fast_voting::Scratch& sc) {
      if(p.stopped()) return;
      fv.load_midpoint(records[by_midpoint[group_start[g]]].midpoint, sc);
      for(std::size_t i = group_start[g]; i < group_start[g + 1]; ++i)
      {
        const std::size_t k = by_midpoint[i];
        Irsa_voting_pair& r = records[k];
        outcome[k] = (unsigned char)fv.support(r.a, r.b, r.midpoint, r.boundary, sc, r.support, r.eligible_pairs);
        if(outcome[k] != Fast_voting::voted)
        {
          std::vector<std::size_t>().swap(r.boundary);
          std::vector<double>().swap(r.support);
        }
      }
      second_count->advance(group_start[g + 1] - group_start[g]);
    };
#ifdef CGAL_LINKED_WITH_TBB
    if(parallel)
    {
      tbb::enumerable_thread_specific<Fast_voting::Scratch> scratch([&] { return fv.make_scratch(); });
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nvote, 16),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          Fast_voting::Scratch& sc = scratch.local();
                          for(std::size_t k = range.begin(); k != range.end(); ++k)
                            first_pass(k, sc);
                        });
      group();
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, group_start.size() - 1, 1),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          Fast_voting::Scratch& sc = scratch.local();
                          for(std::size_t g = range.begin(); g != range.end(); ++g)
                            second_pass(g, sc);
                        });
      for(const auto& sc : scratch) collect(sc);
      return;
    }
#endif
    Fast_voting::Scratch sc = fv.make_scratch();
    for(std::size_t k = 0; k < nvote; ++k)
      first_pass(k, sc);
    group();
    for(std::size_t g = 0; g + 1 < group_start.size(); ++g)
      second_pass(g, sc);
    collect(sc);
  };

#ifdef CGAL_LINKED_WITH_TBB
  if(parallel && number_of_threads > 0)
  {
    tbb::task_arena arena(number_of_threads);
    arena.execute(run);
  }
  else
#endif
  {
    (void)number_of_threads;
    run();
  }
  if(p.stopped()) return result; // incomplete: the caller throws

  // deterministic reduction: pairs in canonical order, boundary in order
  for(std::size_t k = 0; k < nvote; ++k)
  {
    switch(outcome[k])
    {
      case Fast_voting::disconnected: ++result.number_of_disconnected_pairs; continue;
      case Fast_voting::no_boundary: ++result.number_of_pairs_without_boundary; continue;
      case Fast_voting::no_support: ++result.number_of_pairs_without_support; continue;
      default: break;
    }
    const Irsa_voting_pair& r = records[k];
    for(std::size_t i = 0; i < r.boundary.size(); ++i)
      tau[r.boundary[i]] += r.support[i];
    result.voting_pairs.push_back(std::move(records[k]));
  }
  return result;
}

} // namespace internal

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Computes the IRSA transform `tau` (paper Sec. 3.3, Alg. 1 and 2) by letting
/// every similar sample pair {a, b} vote for its intrinsic Voronoi boundary
/// beta(a, b), weighted at each boundary vertex m' by the local symmetry
/// support mu(m').
///
/// **Inputs.** Samples are the rows of `D` (`D.sources()[i]` is the vertex
/// of sample `i`); the distance from sample `i` to sample `j` is
/// `D(i, D.sources()[j])` (read in the row of `i`: the heat method is not
/// exactly symmetric) and from sample `i` to vertex `v` is `D(i, v)`.
/// `similar_pairs` lists the sample pairs that passed the similarity filter
/// (in any order and orientation; duplicates are ignored), for example from
/// `similar_sample_pairs()`. Every similar pair votes (unless capped, see
/// `maximum_number_of_voting_pairs`) and is also a candidate supporter
/// {p, q} of every other vote.
///
/// **What is voted.** For a voting pair {a, b}, f = d(a,.) - d(b,.).
/// - beta(a, b) is the set of vertices where f changes sign across an incident
///   edge (of the edge's two endpoints, the one with the smaller |f|, the
///   smaller index on a tie), plus the vertices where f == 0 (f in single
///   precision, like `D`). It is the whole discrete bisector: every connected
///   component of it is kept (on a torus, both loops), found by a scan of the
///   mesh edges restricted to the vertex blocks where f can change sign. Pairs
///   in different components, or with an empty beta, do not vote.
/// - m is the vertex of beta minimising d(a,.) + d(b,.) (smallest index on a tie).
/// - A similar pair {p, q} supports m' in beta when, oriented so that p is
///   strictly on a's side (d(a,p) < d(b,p)) and q strictly on b's side, it
///   passes the distance filter d(a,p) ~ d(b,q), d(a,q) ~ d(b,p),
///   d(p,m) ~ d(q,m), d(p,m') ~ d(q,m'), the locality filter and the
///   axial-sym filter. x ~ y means |x - y| <= max(eps * max(x, y), floor),
///   evaluated in single precision; infinite distances are never equal.
/// - Locality (DBSCAN, once per {a, b}): the samples of the pairs that pass
///   the three m'-independent distance tests are clustered (two samples are
///   neighbours when one is within `locality_radius` of the other, a core
///   sample has `locality_min_points` neighbours, itself included); the
///   cluster "containing beta" is the one of the clustered sample closest to
///   m; pairs with both samples in it stay. If every sample is noise, nothing stays.
/// - Axial-sym (once per {a, b}): among the pairs left, {p, q} stays when the
///   number of compared pairs {s, t} (s on a's side) with d(s,p) ~ d(t,q) and
///   d(s,q) ~ d(t,p) is at least `axial_threshold` times the number of
///   compared pairs. The compared pairs are all pairs left (the paper; {p, q}
///   counts itself), or, when more than `axial_sample_size` are left, that
///   many of them, evenly spread over the list (positions floor(i E / K)):
///   the paper's count is a statistical test, and this keeps it O(E K)
///   instead of O(E^2) for the E pairs left (standard error of the estimated
///   share about 3.5 % at 80 % with K = 128; on FAUST and the camel the
///   ridges are the same with K = 64, 128, 256 or all pairs).
/// - mu(m') = sum over the pairs left that pass d(p,m') ~ d(q,m') of
///   exp(-d(p,m')^2 / sigma^2), sigma the largest finite sample-to-sample
///   distance, summed in increasing order of (min(p,q), max(p,q));
///   tau(m') is the sum of mu(m') over all voting pairs, in the same order.
///
/// **The distance tolerance floor (measured).** With the paper's purely
/// relative test (floor 0), only 10-25 % of true mirror quadruples pass
/// d(a,p) ~ d(b,q) and d(a,q) ~ d(b,p) on the generated shapes (sample pairs
/// = a farthest-point sample and the sample nearest to its mirror vertex,
/// 1/4 as many samples as vertices, heat-method geodesics), 60-70 % with a
/// floor of one mean edge length, 97-99 % with 2 and ~100 % with 3 (with
/// 1/10 as many samples: 10 %, 30-40 %, 75-85 %, 96-99 %). What matters in
/// the end is the ridge of tau on the symmetry axis (mean tau on the axis /
/// mean tau), with the package's SDF similarity filter:
/// - real shapes, where the similarity filter passes ~0.5-1 % of the pairs:
///   FAUST humans (5K vertices, 1250 samples, 3 shapes): 1.8-4.8 with floor 0,
///   4.7-7.3 with 1, 7.4-9.6 with 2, 8.7-13 with 3; CGAL's camel (1000
///   samples): 3.2, 4.6, 4.0, 3.4 for floors 0, 1, 2, 3. With floor 0 almost
///   nothing votes (camel: 9 of 2191 voting pairs, FAUST: 25-87 of 6-8K).
/// - the generated shapes (exactly symmetric meshes whose smooth parts make
///   the similarity filter pass 5-75 % of the pairs) are the opposite case:
///   floor 0 gives the clearest ridges (ellipsoid 14, capsule 5.0, 2K vertices,
///   1/4 as many samples) and a floor of 1 or more lets so many unrelated
///   pairs through that the ridges fade (ellipsoid 1.7-2.6, capsule 1.0-1.6).
/// The default, 2 mean edge lengths, follows the real shapes; use 0 (the
/// paper's setting) when the similarity filter passes many pairs on an
/// exactly symmetric model. The benchmark `voting_benchmark --floor-study`
/// reproduces these figures.
///
/// **Cost and determinism.** Everything that does not depend on m' is
/// evaluated once per voting pair. beta comes from blocks of about 16
/// vertices: the sign of f over a block is decided by a per-block bound or by
/// one contiguous read of the block (the rows of D are copied in block order),
/// and the crossing edges are found with sign bit masks on the blocks where f
/// changes sign or that touch a block of the opposite sign. The voting pairs are processed in two
/// passes: beta and m for every pair, then the filters and mu with the pairs
/// grouped by midpoint, so that the column D(., m) (a cache miss per sample)
/// is read once per midpoint instead of once per pair. The candidate partners
/// come from one flat, branch-free scan of the similar pairs per voting pair
/// (a grid range query over (d(b,.), d(a,.)) when the pairs are more than 32
/// per sample); the axial counts visit the compared pairs least popular first
/// and stop as soon as the verdict is certain; the loop over m' only evaluates
/// d(p,m') ~ d(q,m') and the Gaussian. The total cost grows as (similar
/// pairs)^2, plus voting pairs x (vertices / 16 + E K). Voting pairs are
/// processed in parallel (`ConcurrencyTag`), each alone, and tau is summed
/// afterwards in pair order: the result is bit-identical at any thread count,
/// and equal to the literal reference implementation of Alg. 1-2 kept for the
/// tests. Memory: besides `D`, a copy of `D` with its columns in block order,
/// two sample-by-sample float matrices and a sample-by-(vertices/8) table
/// (bounds and distances per block).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
///         (the default when TBB is linked)
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam VertexTauMap a model of `WritablePropertyMap` with the vertex
///         descriptor as key and a floating-point value type
///
/// \param tm the mesh `D` was computed on (read only)
/// \param D sample-to-vertex geodesic distances (`compute_geodesic_distance_matrix()`)
/// \param similar_pairs sample pairs {i, j} (rows of `D`) that passed the similarity filter
/// \param tau receives tau at every vertex (0 where nothing was voted)
/// \param np optional named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{distance_threshold}
///     \cgalParamDescription{eps_DIS, the relative tolerance of the distance and axial-sym tests}
///     \cgalParamType{double in [0, 1)}
///     \cgalParamDefault{0.02 (the paper's value)}
///   \cgalParamNEnd
///   \cgalParamNBegin{distance_tolerance_floor}
///     \cgalParamDescription{absolute floor of the same tests, in units of the mean edge length of `tm`;
///       0 is the paper's purely relative test (see above for the measurements behind the default)}
///     \cgalParamType{double >= 0}
///     \cgalParamDefault{2.0}
///   \cgalParamNEnd
///   \cgalParamNBegin{axial_threshold}
///     \cgalParamDescription{eps_AXS, the share of compared pairs that must agree with a pair}
///     \cgalParamType{double in [0, 1]}
///     \cgalParamDefault{0.80 (the paper's value)}
///   \cgalParamNEnd
///   \cgalParamNBegin{axial_sample_size}
///     \cgalParamDescription{at most this many pairs are compared with each pair in the axial-sym
///       filter; 0 compares all of them, as the paper does}
///     \cgalParamType{std::size_t}
///     \cgalParamDefault{128}
///   \cgalParamNEnd
///   \cgalParamNBegin{locality_radius}
///     \cgalParamDescription{DBSCAN radius of the locality filter, in units of the mean sample spacing
///       (mean geodesic distance from a sample to its nearest sample)}
///     \cgalParamType{double > 0}
///     \cgalParamDefault{2.0}
///   \cgalParamNEnd
///   \cgalParamNBegin{locality_min_points}
///     \cgalParamDescription{DBSCAN minimum number of samples within the radius (itself included)
///       for a core sample}
///     \cgalParamType{std::size_t >= 1}
///     \cgalParamDefault{5}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_number_of_voting_pairs}
///     \cgalParamDescription{if smaller than the number of similar pairs, only that many voting pairs,
///       drawn at random with `random_seed`, vote (all similar pairs still support)}
///     \cgalParamType{std::size_t}
///     \cgalParamDefault{no cap}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{seed of the voting-pair draw}
///     \cgalParamType{unsigned int}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{number of threads of the voting with `Parallel_tag` (0: TBB's default);
///       does not change the result}
///     \cgalParamType{int}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called with the advancement (between 0 and 1) as the voting pairs are done,
///       never twice at once; returning `false` stops the voting}
///     \cgalParamType{a model of `std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm` (for the mean edge length)}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between
///       0 and `num_vertices(tm) - 1`: the column order of `D`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the voting pairs that voted (boundary, support, eligible pairs) and statistics
/// \throws Operation_cancelled if the callback returns `false`
/// \throws Input_error (`invalid_parameter`) if `D` does not match `tm`, a pair
///         index is out of range or pairs a sample with itself, or a parameter
///         is out of range
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename TriangleMesh, typename VertexTauMap,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
Irsa_voting_result
compute_irsa_transform(const TriangleMesh& tm, const Geodesic_distance_matrix& D,
                       const std::vector<std::pair<std::size_t, std::size_t>>& similar_pairs,
                       VertexTauMap tau, const CGAL_NP_CLASS& np = parameters::default_values())
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
#endif
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  CGAL::Real_timer timer;
  timer.start();
  const internal::Voting_setup setup = internal::make_voting_setup(tm, D, similar_pairs, np);
  const int threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), 0);
  const double setup_seconds = timer.time();

  std::vector<double> values;
  internal::Progress progress(internal::progress_callback(np), "compute_irsa_transform()");
  Irsa_voting_result result = internal::run_fast_voting<ConcurrencyTag>(setup, values, threads, nullptr, &progress);
  progress.step(1.);
  result.setup_seconds = setup_seconds;
  result.voting_seconds = timer.time() - setup_seconds;

  typedef typename boost::property_traits<VertexTauMap>::value_type Value;
  auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  for(auto v : vertices(tm))
    put(tau, v, static_cast<Value>(values[std::size_t(get(vim, v))]));
  return result;
}

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_IRSA_TRANSFORM_H
