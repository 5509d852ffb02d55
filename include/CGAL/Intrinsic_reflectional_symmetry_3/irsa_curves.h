// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_IRSA_CURVES_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_IRSA_CURVES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_transform.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_extraction.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_mesh.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/progress.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

/// \file irsa_curves.h
/// IRSA curve extraction (paper Sec. 3.4): from the IRSA transform `tau` and
/// the voting record of `compute_irsa_transform()` to a few explicit
/// intrinsic reflectional symmetry axes, each with its local symmetry support
/// and the sample pairs that support it. `symmetric_map.h` turns them into
/// symmetric regions and point-to-point mirror maps.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// An intrinsic reflectional symmetry axis (IRSA) curve, as returned by
/// `extract_irsa_curves()`: ordered polylines of mesh vertices (vertex
/// indices), with the refined local symmetry support `mu` at each vertex.
struct Irsa_curve
{
  /// the voting pair whose boundary beta(a, b) the curve comes from (index
  /// into `Irsa_voting_result::voting_pairs`), and its two samples (rows of the distance matrix)
  std::size_t voting_pair = 0, a = 0, b = 0;
  /// nu = int_beta tau * mu at the time the boundary was selected (tau already
  /// suppressed near the previously selected curves), and the length of beta,
  /// in the mesh's length unit
  double nu = 0., boundary_length = 0.;
  /// the curve: ordered vertex indices along each polyline (a pruned curve
  /// may be open and in several pieces); consecutive vertices are adjacent in
  /// the mesh or share a face
  std::vector<std::vector<std::size_t>> polylines;
  /// whether each polyline is a closed loop
  std::vector<bool> closed;
  /// the refined support mu (paper Alg. 2) at each polyline vertex, same layout as `polylines`
  std::vector<std::vector<double>> support;
  /// the sample pairs (p on a's side, q on b's side) that voted the refined
  /// support: the voting pair's eligible pairs whose two samples lie in the
  /// curve's region at the end of the refinement
  std::vector<std::pair<std::size_t, std::size_t>> eligible_pairs;
  /// refinement iterations run, and whether the support was stable at the end
  std::size_t number_of_iterations = 0;
  bool converged = false;
  /// whether the curve is the axis of a part found below the paper's
  /// selection (named parameter `nested_symmetries`); the region growing
  /// scales its speed by its own largest support
  bool nested = false;

  /// all vertices of the curve, sorted, without duplicates
  std::vector<std::size_t> vertices() const
  {
    std::vector<std::size_t> v;
    for(const auto& pl : polylines) v.insert(v.end(), pl.begin(), pl.end());
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
  }
  /// the largest support along the curve
  double maximum_support() const
  {
    double m = 0.;
    for(const auto& s : support) for(double x : s) m = (std::max)(m, x);
    return m;
  }
};

namespace internal {

constexpr double default_stopping_ratio = 0.8;
constexpr std::size_t default_maximum_number_of_curves = 10;
constexpr std::size_t default_number_of_refinement_iterations = 10;
constexpr double default_pruning_threshold = 0.25;
constexpr double default_vicinity_radius = 3.0;
constexpr double default_symmetry_tolerance = 1.0;
// Of the final regions and the symmetric map (symmetric_map.h). Looser than
// the extraction's: there the test tells candidate symmetries apart; here
// it only bounds a region already found, and on a posed shape a whole limb
// sits just above 1.0 (residual 1.01-1.09 times the tolerance on FAUST's
// tr_reg_008, arm down on one side and raised on the other), in or out
// depending on the landmarks, hence on the sampling seed: 77-82 % of the
// vertices covered with 4 seeds of 5, 100 % at 1.5 (symmetry_map_benchmark
// --seed S).
constexpr double default_region_symmetry_tolerance = 1.5;
constexpr std::size_t default_number_of_landmarks = 64;

/// The settings shared by curve extraction, regions and the symmetric map:
/// the reflection test of a vertex (landmarks, candidate band, tolerance)
/// and the growth delay. `unit` is the mean sample spacing, `floor` the
/// absolute floor of the distance tolerance.
template <class NamedParameters>
void symmetry_settings(const NamedParameters& np, double unit, double floor, std::size_t& number_of_landmarks,
                       Symmetry_tolerance& tol, double& ignition,
                       double default_scale = default_symmetry_tolerance)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace inp = Intrinsic_reflectional_symmetry_3::internal_np;
  const double landmarks = double(choose_parameter(get_parameter(np, inp::number_of_landmarks),
                                                   default_number_of_landmarks));
  const double scale = choose_parameter(get_parameter(np, inp::symmetry_tolerance), default_scale);
  const double eps = choose_parameter(get_parameter(np, inp::distance_threshold), default_distance_threshold);
  check_voting_parameter(landmarks >= 1., "number_of_landmarks must be >= 1");
  check_voting_parameter(std::isfinite(scale) && scale >= 0., "symmetry_tolerance must be finite and >= 0");
  check_voting_parameter(std::isfinite(eps) && eps >= 0. && eps < 1., "distance_threshold must be in [0, 1)");
  number_of_landmarks = std::size_t(landmarks);
  tol.floor = floor;
  tol.eps = eps;
  tol.scale = scale;
  ignition = unit;
}

template <class NamedParameters>
Curve_settings curve_settings(const Irsa_voting_result& vr, const Curves_mesh& m, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace inp = Intrinsic_reflectional_symmetry_3::internal_np;
  Curve_settings st;
  st.stopping_ratio = choose_parameter(get_parameter(np, inp::stopping_ratio), default_stopping_ratio);
  const double max_curves = double(choose_parameter(get_parameter(np, inp::maximum_number_of_curves),
                                                    default_maximum_number_of_curves));
  const double iterations = double(choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations),
                                                    default_number_of_refinement_iterations));
  st.pruning_threshold = choose_parameter(get_parameter(np, inp::pruning_threshold), default_pruning_threshold);
  st.close_curves = choose_parameter(get_parameter(np, inp::close_curves), false);
  st.nested_symmetries = choose_parameter(get_parameter(np, inp::nested_symmetries), false);
  const double vicinity = choose_parameter(get_parameter(np, inp::vicinity_radius), default_vicinity_radius);
  const double eps = choose_parameter(get_parameter(np, inp::distance_threshold), default_distance_threshold);

  check_voting_parameter(std::isfinite(st.stopping_ratio) && st.stopping_ratio >= 0.,
                         "stopping_ratio must be finite and >= 0");
  check_voting_parameter(max_curves >= 1., "maximum_number_of_curves must be >= 1");
  check_voting_parameter(iterations >= 0., "number_of_iterations must be >= 0");
  check_voting_parameter(st.pruning_threshold >= 0. && st.pruning_threshold <= 1.,
                         "pruning_threshold must be in [0, 1]");
  check_voting_parameter(std::isfinite(vicinity) && vicinity >= 0., "vicinity_radius must be finite and >= 0");
  check_voting_parameter(std::isfinite(eps) && eps >= 0. && eps < 1., "distance_threshold must be in [0, 1)");
  st.maximum_number_of_curves = std::size_t(max_curves);
  st.number_of_iterations = std::size_t(iterations);
  // lengths in units of the voting's mean sample spacing (the mean edge
  // length if the spacing is unknown)
  const double unit = vr.mean_sample_spacing > 0. ? vr.mean_sample_spacing : m.mean_edge_length;
  st.vicinity = vicinity * unit;
  st.tolerance.set(eps, vr.distance_tolerance_floor);
  st.inv_sigma2 = vr.sigma > 0. ? 1. / (vr.sigma * vr.sigma) : 0.;
  symmetry_settings(np, unit, vr.distance_tolerance_floor, st.number_of_landmarks, st.symmetry, st.ignition);
  return st;
}

inline void check_voting_result(const Irsa_voting_result& vr, const Geodesic_distance_matrix& D, std::size_t nv)
{
  if(D.number_of_vertices() != nv)
    throw Input_error(Input_problem::invalid_parameter,
                      "the distance matrix has " + std::to_string(D.number_of_vertices()) +
                      " columns but the mesh has " + std::to_string(nv) + " vertices");
  const std::size_t ns = D.number_of_sources();
  for(std::size_t k = 0; k < vr.voting_pairs.size(); ++k)
  {
    const Irsa_voting_pair& p = vr.voting_pairs[k];
    bool ok = p.a < ns && p.b < ns && p.support.size() == p.boundary.size();
    for(std::size_t v : p.boundary) ok = ok && v < nv;
    for(const auto& e : p.eligible_pairs) ok = ok && e.first < ns && e.second < ns;
    if(!ok)
      throw Input_error(Input_problem::invalid_parameter,
                        "voting pair " + std::to_string(k) + " does not match the distance matrix and the mesh", k);
  }
}

inline Irsa_curve to_irsa_curve(const Working_curve& w, const Irsa_voting_result& vr)
{
  Irsa_curve c;
  c.voting_pair = w.pair;
  c.a = vr.voting_pairs[w.pair].a;
  c.b = vr.voting_pairs[w.pair].b;
  c.nu = w.nu;
  c.boundary_length = w.length;
  for(std::size_t i = 0; i < w.polylines.size(); ++i)
  {
    c.polylines.push_back(w.polylines[i].vertices);
    c.closed.push_back(w.polylines[i].closed);
    c.support.push_back(w.mu[i]);
  }
  c.eligible_pairs = w.pairs;
  c.number_of_iterations = w.iterations;
  c.converged = w.converged;
  c.nested = w.nested;
  return c;
}

} // namespace internal

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Extracts the intrinsic reflectional symmetry axis (IRSA) curves of a mesh
/// from its IRSA transform (paper Sec. 3.4).
///
/// **1. Initial curves.** Every voted boundary beta(a, b) is ranked by the
/// line integral nu(a, b) = int_beta tau * mu. The integral is taken along
/// the zero level set of d(a,.) - d(b,.), linear in each face: that level set
/// is a set of polylines through the faces where the sign changes, each
/// crossing edge carrying one vertex of beta (the voting's rule), so the
/// polylines order beta's vertices along the curve; each segment's length is
/// shared half-and-half by the beta vertices of its two crossing edges
/// (trapezoidal rule). The best boundary is taken; then tau is set to zero in
/// its *vicinity*, the vertices within `vicinity_radius` (edge-path distance)
/// of its vertices, so that boundaries voted for the same axis by neighbouring
/// pairs do not come back; and the ranking is repeated. The stopping rule is
/// the paper's, on the *average* nu of the selected boundaries, read as
/// nu / length(beta) (the mean of tau * mu along the boundary, so that long
/// boundaries do not win by length alone): with drops
/// Delta_i = avg_i - avg_{i+1}, the selection stops at the first positive drop
/// Delta_i, i >= 2, larger than `stopping_ratio` times the previous drop or
/// larger than the sum of the previous two drops, and keeps boundaries 1..i.
/// It also stops when no boundary has a positive nu left, and at
/// `maximum_number_of_curves`. The first drop has no previous drop, so the
/// rule keeps at least two boundaries when two exist; step 2 removes the
/// ones that are not the axis of another part.
///
/// **2. Where each reflection holds; dominated curves.** Each curve induces a
/// reflection, represented by landmark pairs of samples: its voting pair
/// (a, b) and its eligible pairs (up to `number_of_landmarks`, spread by
/// farthest-point subsampling, and spread further by matching samples, see
/// below). The mirror partner of a vertex x is the vertex y minimising
/// `E(x, y) = sum_k (d(x,p_k) - d(y,q_k))^2 + (d(x,q_k) - d(y,p_k))^2`; the
/// reflection *holds* at x when the residual sqrt(E / 2K) of its partner is
/// at most `symmetry_tolerance` times the voting's distance tolerance
/// (`distance_tolerance_floor` + `distance_threshold` times the mean distance
/// from x to the landmarks). The landmarks are then spread: the samples are
/// matched among themselves, and mutual matches within the tolerance become
/// landmarks too (3 rounds; the landmark set under which the reflection holds
/// at the most samples is kept, and voted pairs that disagree with it are
/// dropped). A curve's *part* is the set of vertices connected to it through
/// vertices where its reflection holds (a vertex that is its own partner
/// counts only within two mean sample spacings of the curve: genuine fixed
/// points lie on the axis, while from far away a small part's landmarks look
/// like one point). A curve whose part lies mostly (more than half) where a
/// better ranked curve's reflection holds, and which that reflection maps
/// mostly onto itself, is another symmetry of the same part or the same axis
/// voted again (e.g. the front-back "symmetry" of a human body, or the other
/// mirror planes of an ellipsoid): the PIRS regions partition the shape, so
/// it is removed. A part that the better curve's reflection maps elsewhere
/// (a leg, mapped to the other leg by the body's reflection) is a nested
/// symmetry and its curve is kept. A curve whose reflection is the identity
/// on its part (more than half of the part's vertices are their own
/// partner) is no symmetry: its reflection holds everywhere, so it would
/// dominate every other curve; it is dropped. Of two symmetries of the same part
/// the better ranked one is kept, unless its reflection flips none of the
/// first six non-constant eigenfunctions of the mesh's Laplacian (cotangent
/// weights, lumped masses) while the other's flips one: the other then takes
/// its place. A reflection R flips one when its functional map on them,
/// C_ij = <phi_i, phi_j o R>, has more than half of its squared norm on the
/// diagonal and some C_ii < -1/2. An intrinsic symmetry maps each
/// eigenfunction to plus or minus itself (Ovsjanikov, Sun and Guibas 2008),
/// so one that keeps all the coarse ones is the identity at the shape's
/// scale, and one whose map is mostly off the diagonal is no symmetry at
/// that scale. The front-back "reflection" of a posed human, which swaps the
/// front and the back of each limb in place, is such an identity, and it
/// often outvotes the left-right one (on SCAPE it ranks first on 7 of 18
/// meshes). When a kept curve is still such an identity, the boundaries
/// below the stopping rule, down to the 12th best of the ranking, are
/// searched in order for a symmetry of its part whose reflection flips one,
/// which takes its place; they are never kept otherwise. The pose can push
/// the left-right reflection below the rule (SCAPE mesh068, seed 1: the
/// third boundary, the first below the rule).
///
/// **2b. Nested symmetries** (`nested_symmetries`, not in the paper). nu
/// grows like the cube of a part's supporting pairs, so that an arm's axis
/// ranks below thousands of variants of the body's axes. With this option
/// the selection goes on below step 1 for the axes of parts that a kept
/// reflection maps *elsewhere* (a leg onto the other leg). A boundary is
/// stood for by the samples of its eligible pairs; it is dropped when more
/// than half of them lie where a kept curve's reflection holds and either
/// more than a quarter of those are mapped near the set itself or more than
/// 5 % of them are near their own mirror (a part mapped elsewhere holds no
/// fixed point). First every boundary is tested against the curves of step
/// 2; then tau gets back its values before the suppression of step 1, and the
/// boundaries are taken by nu again: one with fewer than 2 % of the samples
/// in its eligible pairs is dropped, one that the reflection of a nested
/// curve taken before dominates by the same test is dropped, and so is one
/// whose boundary itself a kept reflection maps mostly onto itself (another
/// plane through the axis of a body of revolution); any other becomes a
/// nested curve (`Irsa_curve::nested`) and suppresses tau in its vicinity.
/// At most 100 boundaries are examined, and the curves stay at most
/// `maximum_number_of_curves`. A nested curve's front grows at
/// mu / its own largest mu (step 3).
///
/// **3. Iterative refinement.** All curves grow regions at once (grass fire
/// along the mesh edges from the whole curve, so fronts move orthogonally to
/// it, at the speed mu(seed) / max mu over all curves, a seed igniting after
/// one mean sample spacing / speed; a vertex belongs to the first front that
/// reaches it, and a front only enters the vertices where its curve's
/// reflection holds). Each curve's mu is then re-voted (paper Alg. 2, same
/// tolerance and Gaussian as the voting) by the eligible pairs of its voting
/// pair whose two samples lie in its region. This repeats until no curve's set
/// of voters changes, so that mu is exactly stable, or `number_of_iterations`
/// times. Curves left without support are dropped.
///
/// **4. Pruning.** mu is scaled linearly to [0, 1] along each curve by
/// dividing by its maximum (an affine min-max scaling would always cut the
/// least supported vertex, even of an evenly supported curve); runs of
/// vertices below `pruning_threshold` are cut, so curves may become open and
/// fall into pieces. With `close_curves`, each gap between consecutive pieces
/// is bridged by the shortest edge path between the piece ends if the mean
/// scaled support along it (voted by the curve's pairs) reaches the threshold.
///
/// The result depends only on the inputs, not on `ConcurrencyTag` or the
/// number of threads.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
///         (the default when TBB is linked)
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam VertexTauMap a model of `ReadablePropertyMap` with the vertex
///         descriptor as key and a floating-point value (tau, as filled by
///         `compute_irsa_transform()`)
/// \tparam OutputIterator an output iterator accepting `Irsa_curve`
///
/// \param tm the mesh (read only)
/// \param D the sample-to-vertex distance matrix the voting used
/// \param voting the result of `compute_irsa_transform()` on `tm` and `D`
/// \param tau the IRSA transform
/// \param out receives the curves, best first
/// \param np optional named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{stopping_ratio}
///     \cgalParamDescription{r of the stopping rule: a drop of the average nu larger than r times
///       the previous drop ends the selection}
///     \cgalParamType{double >= 0}
///     \cgalParamDefault{0.8 (the paper's value)}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_number_of_curves}
///     \cgalParamDescription{the most boundaries selected in step 1}
///     \cgalParamType{std::size_t >= 1}
///     \cgalParamDefault{10}
///   \cgalParamNEnd
///   \cgalParamNBegin{vicinity_radius}
///     \cgalParamDescription{tau is set to zero within this distance of a selected boundary, in units of
///       the mean sample spacing of the voting (`Irsa_voting_result::mean_sample_spacing`)}
///     \cgalParamType{double >= 0}
///     \cgalParamDefault{3.0}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_landmarks}
///     \cgalParamDescription{the most landmark pairs representing a curve's reflection}
///     \cgalParamType{std::size_t >= 1}
///     \cgalParamDefault{64}
///   \cgalParamNEnd
///   \cgalParamNBegin{symmetry_tolerance}
///     \cgalParamDescription{the reflection holds at a vertex when the residual of its mirror partner is
///       at most this factor times the voting's distance tolerance; bounds the regions}
///     \cgalParamType{double >= 0}
///     \cgalParamDefault{1.0}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the most refinement iterations (region growing + re-vote); 0 skips the refinement}
///     \cgalParamType{std::size_t}
///     \cgalParamDefault{10}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called with the advancement (between 0 and 1) after each step; returning
///       `false` stops the extraction}
///     \cgalParamType{a model of `std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{pruning_threshold}
///     \cgalParamDescription{curve vertices whose support, divided by the curve's largest support, is
///       below this value are cut}
///     \cgalParamType{double in [0, 1]}
///     \cgalParamDefault{0.25 (the paper's value)}
///   \cgalParamNEnd
///   \cgalParamNBegin{close_curves}
///     \cgalParamDescription{whether to bridge the gaps left by pruning with shortest paths that have
///       enough support}
///     \cgalParamType{bool}
///     \cgalParamDefault{false}
///   \cgalParamNEnd
///   \cgalParamNBegin{nested_symmetries}
///     \cgalParamDescription{whether to go on below the paper's selection for the axes of smaller parts
///       (limbs, fingers, tentacles) that no selected curve's reflection maps onto themselves: the
///       paper's ranking by nu, which grows like the cube of a part's supporting pairs, leaves only
///       the shape's global symmetries on most shapes; see below. Such curves have
///       `Irsa_curve::nested` set, and their regions grow at their own speed. For segmentation.}
///     \cgalParamType{bool}
///     \cgalParamDefault{false}
///   \cgalParamNEnd
///   \cgalParamNBegin{distance_threshold}
///     \cgalParamDescription{eps_DIS, the relative distance tolerance of the re-vote's test
///       d(p,m') ~ d(q,m') and of the reflection test; pass the voting's value (the absolute floor is
///       taken from `voting`)}
///     \cgalParamType{double in [0, 1)}
///     \cgalParamDefault{0.02}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between
///       0 and `num_vertices(tm) - 1`: the column order of `D`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index between
///       0 and `num_faces(tm) - 1`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the output iterator past the last curve
/// \throws Operation_cancelled if the callback returns `false`
/// \throws Input_error (`invalid_parameter`) if `D` or `voting` do not match
///         `tm`, or a parameter is out of range; (`not_triangle_mesh`) if a
///         face is not a triangle
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename TriangleMesh, typename VertexTauMap, typename OutputIterator,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
OutputIterator extract_irsa_curves(const TriangleMesh& tm, const Geodesic_distance_matrix& D,
                                   const Irsa_voting_result& voting, const VertexTauMap& tau, OutputIterator out,
                                   const CGAL_NP_CLASS& np = parameters::default_values())
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
#endif
  const internal::Curves_mesh m = internal::make_curves_mesh(tm, np);
  internal::check_voting_result(voting, D, m.number_of_vertices);
  const internal::Curve_settings st = internal::curve_settings(voting, m, np);

  std::vector<double> t(m.number_of_vertices, 0.);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  for(auto v : vertices(tm))
  {
    const double x = double(get(tau, v));
    t[std::size_t(get(vim, v))] = std::isfinite(x) ? x : 0.;
  }

  // the callback sees the end of each step
  internal::Progress progress(internal::progress_callback(np), "extract_irsa_curves()");
  internal::Boundary_ranking ranking(m, D, voting, t, st);
  progress.step(0.1);
  std::vector<internal::Working_curve> curves = internal::select_initial_curves(ranking, st);
  progress.step(0.3);
  internal::refine_curves<ConcurrencyTag>(m, D, st, curves, &ranking);
  progress.step(0.9);
  internal::prune_curves(m, D, st, curves);
  progress.step(1.);
  for(const auto& c : curves)
    *out++ = internal::to_irsa_curve(c, voting);
  return out;
}

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_IRSA_CURVES_H
