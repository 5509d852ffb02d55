// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SYMMETRY_DETECTION_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SYMMETRY_DETECTION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/Heat_method_geodesic_oracle.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/check_input.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_curves.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_transform.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/sampling.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/signatures.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/symmetric_map.h>

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// One run of the pipeline in `detect_reflectional_symmetry()`: the run of
/// one seed, or the run guided by the global reflection.
struct Symmetry_detection_run
{
  unsigned seed = 0;                   ///< seed of the samples (a guided run: of the run it follows)
  bool guided = false;                 ///< voted by the pairs that the global reflection swaps
  bool whole_shape_reflection = false; ///< its map is the whole shape's reflection (`takes_whole_shape_reflection()`)
  std::size_t similar_pairs = 0;       ///< sample pairs that passed the similarity filter (and voted)
  std::size_t number_of_curves = 0;    ///< IRSA curves
  std::size_t region_faces = 0;        ///< faces in a symmetric region
  std::size_t mapped_vertices = 0;     ///< vertices with a partner
  double fixed_share = 0.;             ///< `fixed_point_share()` of its map
  double distortion = 0.;              ///< `isometric_distortion()` of its map
  double reversing_share = 0.;         ///< `orientation_reversing_share()` of its map
  double seconds = 0.;                 ///< wall-clock time of the run (the vertex SDF, shared by all runs, excluded)

  /// `is_suspect_symmetric_map()` of its map
  bool suspect() const { return is_suspect_symmetric_map(fixed_share, distortion); }
};

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// What `detect_reflectional_symmetry()` found. The samples, distances,
/// voting and curves are those of the run whose map was kept; they can be
/// handed on to the functions of the later stages (`symmetry_aware_segmentation()`,
/// `repair_missing_parts()`, ...) so that nothing is computed twice.
struct Reflectional_symmetry
{
  std::vector<std::size_t> samples;   ///< vertex indices of the samples
  Geodesic_distance_matrix distances; ///< from the samples to every vertex
  Irsa_voting_result voting;          ///< the IRSA transform's voting record
  std::vector<Irsa_curve> curves;     ///< the IRSA curves, best first
  std::vector<Symmetry_detection_run> runs; ///< every run completed, in order
  std::size_t kept_run = 0;           ///< index in `runs` of the run whose outputs these are
  bool stopped = false;               ///< a later run was cancelled by the callback; the best completed run was kept
  std::string stop_message;           ///< then: what the cancelled stage said

  /// the run whose outputs these are
  const Symmetry_detection_run& kept() const { return runs[kept_run]; }
};

namespace internal {

// the pack `np` with one more parameter, which hides any of the same tag in `np`
template <typename Tag, typename K, typename NP>
Named_function_parameters<K, Tag, NP> with_parameter(const NP& np, const K& k)
{
  return Named_function_parameters<K, Tag, NP>(k, np);
}

// The stages of one run, as `detection_run()` reports them to its observer
enum class Detection_stage { sampling, geodesic_matrix, signatures, voting, curves, regions_and_map };

// everything one run makes, by vertex and face index (irsym writes it all
// out), beside its summary
struct Detection_run_data : Symmetry_detection_run
{
  std::size_t index = 0; // in Reflectional_symmetry::runs
  std::vector<std::size_t> samples;
  Geodesic_distance_matrix D;
  Irsa_voting_result voting;
  std::vector<double> tau;
  std::vector<Irsa_curve> curves;
  std::vector<long> region;
  std::vector<std::ptrdiff_t> partner;
  double global_reversing_share = -1.; // orientation_reversing_share() of the global reflection (guided runs)
  bool global_refined = false;         // that reflection refined over the whole mesh (refine_symmetric_map())
};

// for runs that nobody watches
struct No_stage_observer
{
  void operator()(Detection_stage, bool, const Detection_run_data&) const {}
};

// One run: samples (or those of `guided_by`), distances, signatures and
// similar pairs, voting, curves, regions and map. With `global`, only the
// similar pairs that it swaps vote, the map starts from it, and the whole
// shape's reflection replaces the regions' map where
// prefer_whole_shape_reflection() says. Every stage reads the parameters of
// `np` it documents, the regions and the map those of `map_np` (the
// benchmark's studies give them a symmetry_tolerance of their own); the seed
// is `seed`. `observe(stage, begins, run)` is called as each stage begins and
// ends (irsym logs and times them).
template <typename ConcurrencyTag, typename TriangleMesh, typename Oracle, typename NP, typename Observer,
          typename MapNP>
Detection_run_data detection_run(const TriangleMesh& tm, const Oracle& oracle, const std::vector<double>& vertex_sdf,
                                 const std::vector<double>& areas, unsigned seed, const NP& np,
                                 const Detection_run_data* guided_by, const std::vector<std::ptrdiff_t>* global,
                                 Observer&& observe, const MapNP& map_np)
{
  CGAL::Real_timer timer;
  timer.start();
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto seeded = with_parameter<CGAL::internal_np::random_seed_t>(np, seed);
  Detection_run_data r;
  r.seed = seed;
  r.guided = guided_by != nullptr && global != nullptr;
  const auto stage = [&](Detection_stage s, bool begins) { observe(s, begins, static_cast<const Detection_run_data&>(r)); };
  if(r.guided)
  {
    // the samples and distances of the run it follows
    r.samples = guided_by->samples;
    r.D = guided_by->D;
  }
  else
  {
    stage(Detection_stage::sampling, true);
    r.samples = farthest_point_samples(tm, seeded);
    stage(Detection_stage::sampling, false);
    stage(Detection_stage::geodesic_matrix, true);
    r.D = compute_geodesic_distance_matrix<ConcurrencyTag>(oracle, r.samples, np);
    stage(Detection_stage::geodesic_matrix, false);
  }

  stage(Detection_stage::signatures, true);
  const Sdf_signatures signatures = sdf_signatures<ConcurrencyTag>(vertex_sdf, areas, r.D, np);
  std::vector<std::pair<std::size_t, std::size_t>> similar;
  similar_sample_pairs(signatures, std::back_inserter(similar), seeded);
  const auto global_map = [&]() { return boost::make_iterator_property_map(global->begin(), vim); };
  if(r.guided)
  {
    std::vector<std::pair<std::size_t, std::size_t>> swapped;
    pairs_consistent_with_map(tm, r.D, global_map(), similar, std::back_inserter(swapped), np);
    similar.swap(swapped);
  }
  r.similar_pairs = similar.size();
  stage(Detection_stage::signatures, false);

  stage(Detection_stage::voting, true);
  r.tau.assign(num_vertices(tm), 0.);
  const auto tau = boost::make_iterator_property_map(r.tau.begin(), vim);
  r.voting = compute_irsa_transform<ConcurrencyTag>(tm, r.D, similar, tau, seeded);
  stage(Detection_stage::voting, false);

  stage(Detection_stage::curves, true);
  extract_irsa_curves<ConcurrencyTag>(tm, r.D, r.voting, tau, std::back_inserter(r.curves), np);
  stage(Detection_stage::curves, false);

  stage(Detection_stage::regions_and_map, true);
  r.region.assign(num_faces(tm), -1);
  r.partner.assign(num_vertices(tm), -1);
  r.region_faces = symmetric_regions<ConcurrencyTag>(tm, r.D, r.curves,
                                                     boost::make_iterator_property_map(r.region.begin(), fim), map_np);
  std::vector<long> map_region(num_vertices(tm), -1);
  const auto partner = boost::make_iterator_property_map(r.partner.begin(), vim);
  const auto with_regions = with_parameter<internal_np::vertex_region_map_t>(
    map_np, boost::make_iterator_property_map(map_region.begin(), vim));
  r.mapped_vertices =
    r.guided ? symmetric_vertex_map<ConcurrencyTag>(tm, r.D, r.curves, partner,
                                                    with_parameter<internal_np::initial_vertex_map_t>(with_regions, global_map()))
             : symmetric_vertex_map<ConcurrencyTag>(tm, r.D, r.curves, partner, with_regions);
  // a reflection fixes its axis alone and preserves distances: a map that
  // keeps parts far from the curves in place (a limb onto itself) or sends a
  // part by another symmetry is suspect
  r.fixed_share = fixed_point_share(tm, r.curves, partner, np);
  r.distortion = isometric_distortion(tm, partner, with_regions);
  if(r.guided)
  {
    // the reflection itself over the whole shape where it is the better map
    // (takes_whole_shape_reflection()), refined over the whole mesh where
    // that lowers its defect (refine_symmetric_map())
    const Whole_shape_reflection w =
      prefer_whole_shape_reflection(tm, r.curves, r.samples, *global, r.partner, r.fixed_share, r.distortion);
    r.global_refined = w.refined;
    r.global_reversing_share = w.reversing_share;
    r.whole_shape_reflection = w.taken;
    if(w.taken)
    {
      std::fill(r.region.begin(), r.region.end(), 0l); // the first curve's region: the whole shape
      r.region_faces = r.region.size();
      r.mapped_vertices =
        std::size_t(std::count_if(r.partner.begin(), r.partner.end(), [](std::ptrdiff_t p) { return p >= 0; }));
      r.reversing_share = w.reversing_share;
    }
  }
  if(!r.whole_shape_reflection) r.reversing_share = orientation_reversing_share(tm, partner, np);
  stage(Detection_stage::regions_and_map, false);
  r.number_of_curves = r.curves.size();
  r.seconds = timer.time();
  return r;
}

// the same with every stage reading `np`
template <typename ConcurrencyTag, typename TriangleMesh, typename Oracle, typename NP,
          typename Observer = No_stage_observer>
Detection_run_data detection_run(const TriangleMesh& tm, const Oracle& oracle, const std::vector<double>& vertex_sdf,
                                 const std::vector<double>& areas, unsigned seed, const NP& np,
                                 const Detection_run_data* guided_by = nullptr,
                                 const std::vector<std::ptrdiff_t>* global = nullptr, Observer&& observe = Observer())
{
  return detection_run<ConcurrencyTag>(tm, oracle, vertex_sdf, areas, seed, np, guided_by, global,
                                       std::forward<Observer>(observe), np);
}

template <typename ConcurrencyTag, typename TriangleMesh, typename VertexPartnerMap, typename Oracle, typename NP>
Reflectional_symmetry detect_reflectional_symmetry_with(const TriangleMesh& tm, VertexPartnerMap partner,
                                                        const Oracle& oracle, int tries, const NP& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;

  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const unsigned first_seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);

  // the SDF does not depend on the samples: once for all runs
  const std::vector<double> vertex_sdf = vertex_sdf_values(tm, np);
  const std::vector<double> areas = vertex_areas(tm, np);

  Reflectional_symmetry out;
  const auto record = [&out](Detection_run_data& r) {
    r.index = out.runs.size();
    out.runs.push_back(r); // its summary
  };
  Tries_outcome<Detection_run_data> outcome = best_of_tries<Detection_run_data>(
    [&](unsigned seed) {
      Detection_run_data r = detection_run<ConcurrencyTag>(tm, oracle, vertex_sdf, areas, seed, np);
      record(r);
      return r;
    },
    first_seed, tries,
    // every run's map suspect: once more on the kept run's samples, with the
    // votes of the pairs that the whole shape's global reflection swaps
    [&](const Detection_run_data& suspect_run, Detection_run_data& g) {
      std::vector<std::ptrdiff_t> global(num_vertices(tm), -1);
      if(!global_reflection_map<ConcurrencyTag>(tm, suspect_run.samples,
                                                boost::make_iterator_property_map(global.begin(), vim), np))
        return false;
      g = detection_run<ConcurrencyTag>(tm, oracle, vertex_sdf, areas, suspect_run.seed, np, &suspect_run,
                                        &global);
      record(g);
      return true;
    });

  Detection_run_data& kept = outcome.kept;
  for(auto v : vertices(tm))
    put(partner, v, static_cast<typename boost::property_traits<VertexPartnerMap>::value_type>(
                      kept.partner[std::size_t(get(vim, v))]));
  if constexpr(!is_default_parameter<NP, internal_np::irsa_transform_map_t>::value)
  {
    auto tau = get_parameter(np, internal_np::irsa_transform_map);
    for(auto v : vertices(tm)) put(tau, v, kept.tau[std::size_t(get(vim, v))]);
  }
  if constexpr(!is_default_parameter<NP, internal_np::face_region_map_t>::value)
  {
    auto region = get_parameter(np, internal_np::face_region_map);
    typedef typename boost::property_traits<decltype(region)>::value_type Region;
    for(auto f : faces(tm)) put(region, f, static_cast<Region>(kept.region[std::size_t(get(fim, f))]));
  }
  out.samples = std::move(kept.samples);
  out.distances = std::move(kept.D);
  out.voting = std::move(kept.voting);
  out.curves = std::move(kept.curves);
  out.kept_run = kept.index;
  out.stopped = outcome.stopped;
  out.stop_message = outcome.stop_message;
  return out;
}

} // namespace internal

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The whole pipeline in one call, as `irsym` runs it: farthest-point samples,
/// geodesic distances, SDF signatures and the similarity filter, the IRSA
/// transform, the IRSA curves, their symmetric regions and the symmetric map.
///
/// Where the map is suspect (`is_suspect_symmetric_map()`: it keeps parts far
/// from the curves in place, or does not preserve distances), the pipeline runs
/// again with the next seed, up to `number_of_tries` runs; the map of least
/// `symmetric_map_defect()` is kept (`internal::best_of_tries()`). Where every
/// run is suspect, one more run on the kept run's samples lets only the pairs
/// that the whole shape's global reflection (`global_reflection_map()`) swaps
/// vote, and is kept where `keeps_guided_run()` says; its map may be that
/// reflection itself over the whole shape (`takes_whole_shape_reflection()`).
/// The stages are the package's free functions, each with the parameters of
/// `np` that it reads; call them one by one to change what happens between them.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
///         (the result is the same)
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam VertexPartnerMap a model of `WritablePropertyMap` from vertices to a
///         signed integer type
///
/// \param tm a closed triangle mesh, or one with small holes, which passes
///        `check_input()` (read only)
/// \param partner receives for every vertex its mirror partner's index (in the
///        order of the vertex index map), or -1 where it has none
/// \param np optional named parameters, among them:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_samples}
///     \cgalParamDescription{samples per run}
///     \cgalParamDefault{`min(3000, ceil(V / 4))`, as `farthest_point_samples()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{seed of the first run; run `k` uses `random_seed + k`}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_tries}
///     \cgalParamDescription{the most seeds run while the map is suspect, 1 to 100}
///     \cgalParamDefault{`5`, as `irsym --tries`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geodesic_oracle}
///     \cgalParamDescription{the geodesic oracle of `tm`, a model of `GeodesicDistanceOracle`}
///     \cgalParamDefault{a `Heat_method_geodesic_oracle` built on `tm`}
///   \cgalParamNEnd
///   \cgalParamNBegin{irsa_transform_map}
///     \cgalParamDescription{receives the kept run's IRSA transform `tau`}
///     \cgalParamType{a model of `WritablePropertyMap` from vertices to `double`}
///     \cgalParamDefault{not written}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_region_map}
///     \cgalParamDescription{receives the kept run's symmetric region of each face (the index of its curve), or -1}
///     \cgalParamType{a model of `WritablePropertyMap` from faces to a signed integer type}
///     \cgalParamDefault{not written}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{asked by the long stages whether to go on; a
///       run it cancels after an earlier run completed ends the tries with the
///       best completed run (`Reflectional_symmetry::stopped`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, vertex_index_map, face_index_map}
///     \cgalParamDescription{as for the stages}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// and the parameters of the stages (`similarity_threshold`,
/// `distance_threshold`, `maximum_similar_pairs_per_sample`,
/// `maximum_number_of_voting_pairs`, `symmetry_tolerance`, `nested_symmetries`, ...).
///
/// \returns the kept run's samples, distances, voting and curves, and a summary of every run
/// \throws Input_error if `tm` fails `check_input()`, for too many samples, or
///         (`invalid_parameter`) for `number_of_tries` outside 1 to 100
/// \throws Operation_cancelled if the callback cancels the first run
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh,
          typename VertexPartnerMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Reflectional_symmetry detect_reflectional_symmetry(const TriangleMesh& tm, VertexPartnerMap partner,
                                                   const CGAL_NP_CLASS& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::get_parameter_reference;
  using CGAL::parameters::is_default_parameter;

  const long long tries = choose_parameter(get_parameter(np, internal_np::number_of_tries), 5);
  if(tries < 1 || tries > 100)
    throw Input_error(Input_problem::invalid_parameter,
                      "number_of_tries must lie in 1 .. 100, not " + std::to_string(tries));
  check_input(tm, np);
  if constexpr(is_default_parameter<CGAL_NP_CLASS, internal_np::geodesic_oracle_t>::value)
  {
    const Heat_method_geodesic_oracle<TriangleMesh> oracle(tm, np);
    return internal::detect_reflectional_symmetry_with<ConcurrencyTag>(tm, partner, oracle, int(tries), np);
  }
  else
    return internal::detect_reflectional_symmetry_with<ConcurrencyTag>(
      tm, partner, get_parameter_reference(np, internal_np::geodesic_oracle), int(tries), np);
}

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SYMMETRY_DETECTION_H
