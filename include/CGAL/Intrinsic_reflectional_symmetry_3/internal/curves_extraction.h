// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_EXTRACTION_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_EXTRACTION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_transform.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_level_set.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_mesh.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_mirror.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_regions.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_support.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/symmetric_map_spectral.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/voting_common.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

// The steps of IRSA curve extraction (paper Sec. 3.4) on the flat mesh:
// initial selection by nu, removal of dominated curves, iterative refinement
// (region growing + re-vote), pruning and optional closing. irsa_curves.h
// wraps them and documents them for users.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

/// rounds of `spread_landmarks()`
constexpr std::size_t landmark_rounds = 3;

struct Curve_settings
{
  double stopping_ratio = 0.8;
  std::size_t maximum_number_of_curves = 10;
  std::size_t number_of_iterations = 10;
  double pruning_threshold = 0.25;
  bool close_curves = false;
  double vicinity = 0.;        // absolute
  double ignition = 0.;        // absolute: region growing delay of a seed of speed 1
  double maximum_overlap = 0.5;
  bool nested_symmetries = false;
  double minimum_part = 0.02;           // of the samples, in a nested curve's eligible pairs
  std::size_t nested_candidates = 100;  // boundaries examined for nested curves
  double nested_onto_itself = 0.25;     // a nested part is mapped elsewhere: at most this share onto itself,
  double nested_fixed_points = 0.05;    // and at most this share near its own mirror
  std::size_t number_of_landmarks = 64;
  Symmetry_tolerance symmetry;
  Distance_tolerance tolerance;
  double inv_sigma2 = 0.;
};

/// A curve while it is being extracted.
struct Working_curve
{
  std::size_t pair = 0;                      // index into the voting pairs
  std::size_t a = 0, b = 0;                  // its samples
  double nu = 0., length = 0.;
  std::vector<Level_set_polyline> polylines; // ordered beta vertices
  std::vector<std::vector<double>> mu;       // support along each polyline
  std::vector<std::pair<std::size_t, std::size_t>> initial_pairs, pairs;
  std::size_t iterations = 0;
  bool converged = false;
  bool nested = false;                       // found by add_nested_curves()

  std::vector<std::size_t> flat_vertices() const
  {
    std::vector<std::size_t> out;
    for(const auto& pl : polylines) out.insert(out.end(), pl.vertices.begin(), pl.vertices.end());
    return out;
  }
  double max_support() const
  {
    double m = 0.;
    for(const auto& l : mu) for(double x : l) m = (std::max)(m, x);
    return m;
  }
};

inline void recompute_support(const Geodesic_distance_matrix& D, const Curve_settings& st, Working_curve& c)
{
  c.mu.resize(c.polylines.size());
  for(std::size_t i = 0; i < c.polylines.size(); ++i)
    support_at(D, st.tolerance, st.inv_sigma2, c.pairs, c.polylines[i].vertices, c.mu[i]);
}

/// The paper's stopping test on the averages `v` of the boundaries selected
/// so far (the last one being the candidate): the latest drop
/// d = v[n-2] - v[n-1] is significant when it is positive and larger than
/// `ratio` times the previous drop, or larger than the sum of the two
/// previous drops. The first drop has no previous drop and is never
/// significant.
inline bool significant_drop(const std::vector<double>& v, double ratio)
{
  const std::size_t n = v.size();
  if(n < 3) return false;
  const double d = v[n - 2] - v[n - 1];
  const double d1 = v[n - 3] - v[n - 2];
  if(!(d > 0.)) return false;
  if(d > ratio * d1) return true;
  return n >= 4 && d > d1 + (v[n - 4] - v[n - 3]);
}

/// The voted boundaries ranked by nu = int_beta tau * mu (trapezoidal rule
/// on the level set, see curves_level_set.h) under a tau that is set to zero
/// within `vicinity` (edge-path distance) of every boundary taken.
class Boundary_ranking
{
public:
  Boundary_ranking(const Curves_mesh& m, const Geodesic_distance_matrix& D, const Irsa_voting_result& vr,
                   const std::vector<double>& tau, const Curve_settings& st)
    : D_(D), vr_(vr), st_(st), tracer_(m), tau_(tau), t_(tau), taken_(vr.voting_pairs.size(), 0),
      weights_(vr.voting_pairs.size()), length_(vr.voting_pairs.size(), 0.), dij_(m)
  {
    std::vector<Level_set_polyline> pls;
    for(std::size_t k = 0; k < vr.voting_pairs.size(); ++k)
    {
      const Irsa_voting_pair& vp = vr.voting_pairs[k];
      tracer_.trace(D, vp.a, vp.b, vp.boundary, pls);
      Level_set_tracer::weights_on_boundary(pls, vp.boundary, weights_[k]);
      for(double w : weights_[k]) length_[k] += w;
    }
  }

  static constexpr std::size_t none = std::size_t(-1);

  /// the untaken boundary of largest positive nu (`none` if there is none), and its nu
  std::size_t best(double& best_nu) const
  {
    std::size_t best = none;
    best_nu = 0.;
    for(std::size_t k = 0; k < taken_.size(); ++k)
    {
      if(taken_[k] || !(length_[k] > 0.)) continue;
      const Irsa_voting_pair& vp = vr_.voting_pairs[k];
      double nu = 0.;
      for(std::size_t i = 0; i < vp.boundary.size(); ++i)
        nu += weights_[k][i] * t_[vp.boundary[i]] * vp.support[i];
      if(nu > best_nu) { best_nu = nu; best = k; }
    }
    return best;
  }

  /// marks boundary k as taken, and sets tau to zero in its vicinity
  void take(std::size_t k)
  {
    taken_[k] = 1;
    sources_.clear();
    for(std::size_t v : vr_.voting_pairs[k].boundary) sources_.emplace_back(v, 0.);
    dij_.run(sources_, st_.vicinity);
    for(std::size_t v : dij_.reached()) t_[v] = 0.;
  }

  /// tau as given to the constructor again (the taken boundaries stay taken)
  void restore_tau() { t_ = tau_; }

  /// marks boundary k as taken without touching tau
  void discard(std::size_t k) { taken_[k] = 1; }

  double length(std::size_t k) const { return length_[k]; }

  /// the curve of boundary k, before refinement
  Working_curve curve(std::size_t k, double nu)
  {
    const Irsa_voting_pair& vp = vr_.voting_pairs[k];
    Working_curve w;
    w.pair = k;
    w.a = vp.a;
    w.b = vp.b;
    w.nu = nu;
    w.length = length_[k];
    tracer_.trace(D_, vp.a, vp.b, vp.boundary, w.polylines);
    w.initial_pairs = vp.eligible_pairs;
    w.pairs = vp.eligible_pairs;
    return w;
  }

  const Irsa_voting_result& voting() const { return vr_; }

private:
  const Geodesic_distance_matrix& D_;
  const Irsa_voting_result& vr_;
  const Curve_settings& st_;
  Level_set_tracer tracer_;
  std::vector<double> tau_, t_;
  std::vector<char> taken_;
  std::vector<std::vector<double>> weights_;
  std::vector<double> length_;
  Edge_dijkstra dij_;
  std::vector<std::pair<std::size_t, double>> sources_;
};

/// Step 1. Takes the best ranked boundary (`Boundary_ranking`) and repeats.
/// The value of the stopping rule is the average of tau * mu along the
/// boundary, nu / length(beta), recorded when the boundary is chosen; the
/// selection stops before the first boundary whose value makes a significant
/// drop (`significant_drop()`). It also stops when no boundary has a positive
/// nu left, and after `maximum_number_of_curves`.
inline std::vector<Working_curve> select_initial_curves(Boundary_ranking& ranking, const Curve_settings& st)
{
  std::vector<std::size_t> chosen;
  std::vector<double> values, nus;
  while(chosen.size() < st.maximum_number_of_curves)
  {
    double best_nu = 0.;
    const std::size_t best = ranking.best(best_nu);
    if(best == Boundary_ranking::none) break;
    values.push_back(best_nu / ranking.length(best));
    // the stopping rule on the drops of the average
    if(significant_drop(values, st.stopping_ratio))
      break;
    chosen.push_back(best);
    nus.push_back(best_nu);
    ranking.take(best);
  }

  std::vector<Working_curve> curves;
  for(std::size_t c = 0; c < chosen.size(); ++c)
    curves.push_back(ranking.curve(chosen[c], nus[c]));
  return curves;
}

/// The landmarks of a curve's reflection: its voting pair and its
/// (eligible) pairs, then spread over where the reflection holds
/// (curves_mirror.h).
template <class ConcurrencyTag>
std::vector<std::pair<std::size_t, std::size_t>>
curve_landmarks(const Geodesic_distance_matrix& D, std::size_t a, std::size_t b,
                const std::vector<std::pair<std::size_t, std::size_t>>& pairs,
                const std::vector<unsigned char>& allowed, std::size_t K, const Symmetry_tolerance& tol)
{
  return spread_landmarks<ConcurrencyTag>(D, choose_landmarks(D, a, b, pairs, K), allowed, tol, K, landmark_rounds);
}

/// The vertices supporting a curve's reflection (curves_mirror.h), with
/// landmarks from its voting pair and its initial eligible pairs; with
/// `partner`, also the best mirror partner of every vertex under it.
template <class ConcurrencyTag>
std::vector<unsigned char> curve_mask(const Geodesic_distance_matrix& D, const Curve_settings& st,
                                      const Working_curve& curve, std::vector<std::size_t>* partner = nullptr)
{
  const std::vector<unsigned char> everywhere(D.number_of_vertices(), 1);
  const auto landmarks = curve_landmarks<ConcurrencyTag>(D, curve.a, curve.b, curve.initial_pairs, everywhere,
                                                         st.number_of_landmarks, st.symmetry);
  return symmetry_support_mask<ConcurrencyTag>(D, curve.flat_vertices(), landmarks, st.symmetry, partner);
}

/// `curve_mask()` of each curve
template <class ConcurrencyTag>
std::vector<std::vector<unsigned char>> curve_masks(const Geodesic_distance_matrix& D,
                                                    const Curve_settings& st,
                                                    const std::vector<Working_curve>& curves,
                                                    std::vector<std::vector<std::size_t>>* partners = nullptr)
{
  std::vector<std::vector<unsigned char>> masks;
  if(partners) partners->assign(curves.size(), std::vector<std::size_t>());
  for(std::size_t c = 0; c < curves.size(); ++c)
    masks.push_back(curve_mask<ConcurrencyTag>(D, st, curves[c], partners ? &(*partners)[c] : nullptr));
  return masks;
}

/// The part of the shape a curve is the axis of: the vertices connected to
/// the curve through vertices where its reflection holds, a vertex that is
/// its own best partner counting only within `axis_radius` of the curve.
/// Why: seen from far away, the landmarks of a small part (a leg) shrink to a
/// point, so every distant vertex is "its own mirror" within the relative
/// tolerance; genuine fixed points of a reflection lie on its axis.
inline std::vector<unsigned char> curve_part(const Curves_mesh& m, const std::vector<std::size_t>& curve_vertices,
                                             const std::vector<unsigned char>& mask,
                                             const std::vector<std::size_t>& partner, double axis_radius)
{
  const std::size_t nv = m.number_of_vertices;
  Edge_dijkstra dij(m);
  std::vector<std::pair<std::size_t, double>> sources;
  for(std::size_t v : curve_vertices) sources.emplace_back(v, 0.);
  dij.run(sources, axis_radius);
  std::vector<unsigned char> near_axis(nv, 0);
  for(std::size_t v : dij.reached()) near_axis[v] = 1;

  std::vector<unsigned char> part(nv, 0);
  std::vector<std::size_t> stack;
  for(std::size_t v : curve_vertices)
    if(!part[v]) { part[v] = 1; stack.push_back(v); }
  while(!stack.empty())
  {
    const std::size_t v = stack.back();
    stack.pop_back();
    for(std::size_t k = m.adjacency_offsets[v]; k < m.adjacency_offsets[v + 1]; ++k)
    {
      const std::size_t w = m.adjacency[k];
      if(part[w] || !mask[w] || (partner[w] == w && !near_axis[w])) continue;
      part[w] = 1;
      stack.push_back(w);
    }
  }
  return part;
}

inline std::vector<Region_seed_curve> region_seeds(const std::vector<Working_curve>& curves,
                                                   const std::vector<std::vector<unsigned char>>& masks)
{
  std::vector<Region_seed_curve> seeds(curves.size());
  for(std::size_t c = 0; c < curves.size(); ++c)
  {
    for(std::size_t i = 0; i < curves[c].polylines.size(); ++i)
    {
      seeds[c].vertices.insert(seeds[c].vertices.end(), curves[c].polylines[i].vertices.begin(),
                               curves[c].polylines[i].vertices.end());
      seeds[c].support.insert(seeds[c].support.end(), curves[c].mu[i].begin(), curves[c].mu[i].end());
    }
    seeds[c].mask = masks[c];
  }
  std::vector<bool> nested(curves.size());
  for(std::size_t c = 0; c < curves.size(); ++c) nested[c] = curves[c].nested;
  scale_seed_support(seeds, nested);
  return seeds;
}

/// Whether a better curve (its support mask and mirror partners) dominates
/// the part `part` of `size` vertices (step 1b).
inline bool is_dominated(const std::vector<unsigned char>& part, std::size_t size, double maximum_overlap,
                         const std::vector<unsigned char>& better_mask, const std::vector<std::size_t>& better_partner)
{
  std::size_t inside = 0, onto_itself = 0;
  for(std::size_t v = 0; v < part.size(); ++v)
  {
    if(!part[v] || !better_mask[v]) continue;
    ++inside;
    onto_itself += (better_partner[v] != Mirror_matcher::none && part[better_partner[v]]);
  }
  return double(inside) > maximum_overlap * double(size) && double(onto_itself) > maximum_overlap * double(inside);
}

inline std::size_t count_set(const std::vector<unsigned char>& x)
{
  std::size_t n = 0;
  for(unsigned char c : x) n += (c != 0);
  return n;
}

/// Whether a reflection is the identity on the part it is the axis of
/// (`curve_part()`): more than half of the part's vertices are their own
/// best partner. A reflection fixes its axis alone (a genuine one fixes a
/// few percent of its part: 1.3-7 % on SCAPE mesh016). Why: a curve whose
/// landmark pairs nearly coincide induces the identity, which holds
/// everywhere, so it is not dominated and dominates every other curve (SCAPE
/// mesh016, seed 1: a small curve kept after the body's, under whose
/// reflection 99 % of the mesh and 81 % of its part are their own partner,
/// barred the left-right reflection from replacing the front-back one).
inline bool is_identity_on(const std::vector<unsigned char>& part, const std::vector<std::size_t>& partner)
{
  std::size_t size = 0, fixed = 0;
  for(std::size_t v = 0; v < part.size(); ++v)
    if(part[v])
    {
      ++size;
      fixed += (partner[v] == v);
    }
  return 2 * fixed > size;
}

/// the first non-constant Laplace eigenfunctions that
/// `coarse_functional_map()` looks at
constexpr std::size_t coarse_eigenfunctions = 6;

/// The functional map of a reflection (the mirror partner of every vertex)
/// on the first `coarse_eigenfunctions` non-constant eigenfunctions phi_i
/// of `spectrum` (the whole mesh's): C_ij = <phi_i, phi_j o partner>_M. The
/// partners are those of every vertex (where the reflection holds or not); a
/// partner outside the spectrum's rows counts as 0.
inline Eigen::MatrixXd coarse_functional_map(const Region_spectrum& spectrum, const std::vector<std::size_t>& partner,
                                             std::size_t number_of_vertices)
{
  const Eigen::Index k = (std::min)(Eigen::Index(coarse_eigenfunctions + 1), spectrum.basis.cols()) - 1;
  if(k < 1) return Eigen::MatrixXd();
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> row(number_of_vertices, none);
  for(std::size_t r = 0; r < spectrum.rows.size(); ++r) row[spectrum.rows[r]] = r;
  const Eigen::Index n = Eigen::Index(spectrum.rows.size());
  Eigen::MatrixXd mapped = Eigen::MatrixXd::Zero(n, k); // phi_j o partner
  for(Eigen::Index r = 0; r < n; ++r)
  {
    const std::size_t p = partner[spectrum.rows[std::size_t(r)]];
    if(p != Mirror_matcher::none && row[p] != none) mapped.row(r) = spectrum.basis.block(Eigen::Index(row[p]), 1, 1, k);
  }
  return spectrum.basis.middleCols(1, k).transpose() * spectrum.mass.asDiagonal() * mapped;
}

/// Whether a functional map on the coarse eigenfunctions
/// (`coarse_functional_map()`) is that of a symmetry, at the shape's scale,
/// that changes the sign of one of them. An intrinsic symmetry maps each
/// (simple) eigenfunction to +-itself (Ovsjanikov, Sun, Guibas 2008): C is
/// diagonal with entries +-1. So: more than half of C's squared norm on its
/// diagonal, and some C_ii < -1/2. A reflection that keeps all the coarse
/// ones is, at the shape's scale, the identity: it swaps only the two sides
/// of each limb in place; one whose C is mostly off the diagonal is no
/// symmetry at that scale (SCAPE mesh056, seed 1: C_11 = -0.52 with 64 % of
/// the norm off the diagonal; its symmetric map got none of the benchmark's
/// checks right).
inline bool is_coarse_flip(const Eigen::MatrixXd& C)
{
  return C.size() > 0 && C.diagonal().squaredNorm() > 0.5 * C.squaredNorm() && C.diagonal().minCoeff() < -0.5;
}

/// `is_coarse_flip()` of a reflection's `coarse_functional_map()`
inline bool flips_coarse_eigenfunction(const Region_spectrum& spectrum, const std::vector<std::size_t>& partner,
                                       std::size_t number_of_vertices)
{
  return is_coarse_flip(coarse_functional_map(spectrum, partner, number_of_vertices));
}

/// The number of best ranked boundaries, those above the stopping rule
/// included, among which `remove_dominated_curves()` looks for a symmetry to
/// replace a kept curve whose reflection is a coarse identity.
constexpr std::size_t coarse_identity_horizon = 12;

/// No boundary below the stopping rule (the default of
/// `remove_dominated_curves()`).
struct No_more_candidates
{
  bool operator()(Working_curve&, std::vector<unsigned char>&, std::vector<std::size_t>&) const { return false; }
};

/// Step 1b. Keeps the curves that are the axes of different parts. A curve
/// whose part (`curve_part()`) lies mostly (more than `maximum_overlap`)
/// where the reflection of a better ranked kept curve holds is either
///  - another symmetry of that curve's part, or the same axis voted again
///    (the front-back "symmetry" of a human body, the other mirror planes of
///    an ellipsoid): the better curve's reflection maps the part mostly onto
///    itself; it is removed, since the PIRS regions partition the shape;
///  - or the axis of a sub-part that the better curve's reflection maps to
///    another sub-part (a leg, mapped to the other leg by the body's
///    reflection): a nested symmetry, kept (paper Fig. 12).
/// A curve whose reflection is the identity on its part (`is_identity_on()`)
/// is no symmetry, and is dropped.
/// Of two symmetries of the same part, the better ranked one is kept, unless
/// it keeps the mesh's coarse eigenfunctions (`flips_coarse_eigenfunction()`)
/// and the other does not: the other then takes its place. Why: on a posed
/// human body (SCAPE) the front-back "reflection", which swaps the front and
/// the back of each limb in place, often gets more votes than the left-right
/// one, whose support the pose breaks; at the body's scale it is the
/// identity, and the left-right reflection flips the eigenfunction that tells
/// the left limbs from the right ones. The whole mesh's eigenfunctions, not
/// the part's: on SCAPE mesh036 the part leaves out limbs, and on its own
/// spectrum the left-right reflection flips none (on the mesh's, phi_3: -0.96).
/// When a kept curve is still such an identity after the curves above the
/// stopping rule, the boundaries below it (`more_candidates` gives the next
/// one with its support mask and partners, or returns false) are searched for
/// the same replacement, down to the `coarse_identity_horizon`-th boundary of
/// the ranking; they are never kept otherwise. Why: the pose can push the
/// left-right reflection below the rule (SCAPE mesh068, seed 1: the third
/// boundary, the first below the rule).
template <class MoreCandidates = No_more_candidates>
void remove_dominated_curves(const Curves_mesh& m, double maximum_overlap, double axis_radius,
                             std::vector<Working_curve>& curves, std::vector<std::vector<unsigned char>>& masks,
                             std::vector<std::vector<std::size_t>>& partners,
                             MoreCandidates more_candidates = MoreCandidates())
{
  if(curves.empty()) return;
  std::vector<Working_curve> kept_curves;
  std::vector<std::vector<unsigned char>> kept_masks;
  std::vector<std::vector<std::size_t>> kept_partners;
  // the coarse eigenfunctions of the whole mesh, computed when first needed,
  // and whether each kept curve's reflection flips one (-1: not known yet)
  Region_spectrum spectrum;
  int spectrum_state = 0; // 0: not yet, 1: computed, -1: failed
  std::vector<int> kept_flips;
  auto flips = [&](const std::vector<std::size_t>& partner) {
    if(spectrum_state == 0)
      spectrum_state = region_spectrum(m, std::vector<unsigned char>(m.number_of_vertices, 1),
                                       coarse_eigenfunctions + 1, spectrum) ? 1 : -1;
    return spectrum_state > 0 && flips_coarse_eigenfunction(spectrum, partner, m.number_of_vertices);
  };
  auto kept_flip = [&](std::size_t k) {
    if(kept_flips[k] < 0) kept_flips[k] = flips(kept_partners[k]);
    return kept_flips[k] == 1;
  };
  // a candidate dominated by no kept curve is kept when `may_keep`; one
  // dominated by a single kept curve only may replace it
  auto offer = [&](Working_curve& curve, std::vector<unsigned char>& mask, std::vector<std::size_t>& partner,
                   bool may_keep) {
    const std::vector<unsigned char> part = curve_part(m, curve.flat_vertices(), mask, partner, axis_radius);
    if(is_identity_on(part, partner)) return; // no symmetry: neither kept nor a replacement
    const std::size_t size = count_set(part);
    std::size_t dominating = 0, number_dominating = 0;
    for(std::size_t k = 0; k < kept_curves.size(); ++k)
      if(is_dominated(part, size, maximum_overlap, kept_masks[k], kept_partners[k]) && number_dominating++ == 0)
        dominating = k;
    if(number_dominating == 0 && may_keep)
    {
      kept_curves.push_back(std::move(curve));
      kept_masks.push_back(std::move(mask));
      kept_partners.push_back(std::move(partner));
      kept_flips.push_back(-1);
    }
    if(number_dominating != 1) return;
    const std::size_t k = dominating;
    if(!kept_flip(k) && flips(partner))
    {
      kept_curves[k] = std::move(curve);
      kept_masks[k] = std::move(mask);
      kept_partners[k] = std::move(partner);
      kept_flips[k] = 1;
    }
  };
  const std::size_t above_stopping_rule = curves.size();
  for(std::size_t c = 0; c < above_stopping_rule; ++c)
    offer(curves[c], masks[c], partners[c], true);
  auto some_identity_is_kept = [&] {
    if(std::is_same<MoreCandidates, No_more_candidates>::value) return false; // no spectrum needed
    for(std::size_t k = 0; k < kept_curves.size(); ++k)
      if(!kept_flip(k)) return true;
    return false;
  };
  Working_curve curve;
  std::vector<unsigned char> mask;
  std::vector<std::size_t> partner;
  for(std::size_t rank = above_stopping_rule; rank < coarse_identity_horizon && some_identity_is_kept(); ++rank)
  {
    if(!more_candidates(curve, mask, partner)) break;
    offer(curve, mask, partner, false);
  }
  curves.swap(kept_curves);
  masks.swap(kept_masks);
  partners.swap(kept_partners);
}

/// `is_dominated()` on the samples alone, as a cheap test of many
/// boundaries, made stricter for nested parts. The part is stood for by the
/// samples of the voting pair's eligible pairs. A better curve dominates it
/// when more than `maximum_overlap` of them lie where its reflection holds and
/// either more than `maximum_onto_itself` of those have their partner's
/// nearest sample within `radius` of one of them, or more than
/// `maximum_fixed` of them are within `radius` of their own partner: a part
/// that the better reflection maps elsewhere (a limb onto the other limb)
/// cannot contain its fixed points.
class Sample_domination_test
{
public:
  Sample_domination_test(const Geodesic_distance_matrix& D, double radius, double maximum_overlap,
                         double maximum_onto_itself, double maximum_fixed)
    : D_(D), radius_(radius), overlap_(maximum_overlap), onto_(maximum_onto_itself), fixed_(maximum_fixed),
      nearest_(D.number_of_vertices(), 0), neighbors_(D.number_of_sources()),
      in_set_(D.number_of_sources(), 0), near_set_(D.number_of_sources(), 0)
  {
    const std::size_t n = D.number_of_sources(), nv = D.number_of_vertices();
    std::vector<float> best(nv, std::numeric_limits<float>::infinity());
    for(std::size_t x = 0; x < n; ++x)
    {
      const float* row = D.row(x);
      for(std::size_t v = 0; v < nv; ++v)
        if(row[v] < best[v]) { best[v] = row[v]; nearest_[v] = x; }
      for(std::size_t y = 0; y < n; ++y)
        if(D(x, D.sources()[y]) <= radius) neighbors_[x].push_back(y);
    }
  }

  bool dominated(const std::vector<std::pair<std::size_t, std::size_t>>& pairs,
                 const std::vector<unsigned char>& better_mask, const std::vector<std::size_t>& better_partner)
  {
    set_.clear();
    for(const auto& pq : pairs)
      for(std::size_t x : {pq.first, pq.second})
        if(!in_set_[x]) { in_set_[x] = 1; set_.push_back(x); }
    for(std::size_t x : set_)
      for(std::size_t y : neighbors_[x]) near_set_[y] = 1;
    std::size_t inside = 0, onto_itself = 0, fixed = 0;
    for(std::size_t x : set_)
    {
      const std::size_t v = D_.sources()[x];
      if(!better_mask[v]) continue;
      ++inside;
      const std::size_t w = better_partner[v];
      if(w == Mirror_matcher::none) continue;
      onto_itself += near_set_[nearest_[w]];
      fixed += (D_(x, w) <= radius_);
    }
    for(std::size_t x : set_)
    {
      in_set_[x] = 0;
      for(std::size_t y : neighbors_[x]) near_set_[y] = 0;
    }
    return double(inside) > overlap_ * double(set_.size()) &&
           (double(onto_itself) > onto_ * double(inside) || double(fixed) > fixed_ * double(inside));
  }

private:
  const Geodesic_distance_matrix& D_;
  double radius_, overlap_, onto_, fixed_;
  std::vector<std::size_t> nearest_;                // nearest sample of each vertex
  std::vector<std::vector<std::size_t>> neighbors_; // samples within the radius of each sample
  std::vector<unsigned char> in_set_, near_set_;
  std::vector<std::size_t> set_;
};

/// Step 1c (`nested_symmetries`). The paper's ranking by nu favours large
/// symmetric parts overwhelmingly (nu grows like the cube of the number of
/// supporting pairs: on a human body the axis of an arm has about 1e-4 of the
/// body axis' nu), so that after the stopping rule only the global
/// symmetries are left, and thousands of their variants rank above the axis
/// of a limb. This step
///  - drops the boundaries that a curve kept so far dominates, by the test on
///    their samples (`Sample_domination_test`), without touching tau (the
///    vicinity of the body's boundaries covers the limbs), then gives tau
///    back its values before step 1's suppression;
///  - goes on down the ranking: a boundary whose eligible pairs have fewer
///    than `minimum_part` of the samples, or that a nested curve kept so far
///    dominates (same test), or whose boundary a kept reflection maps mostly
///    onto itself, is dropped; any other is kept as a nested curve and
///    suppresses tau in its vicinity, as in step 1.
/// At most `nested_candidates` boundaries are examined, and the curves stay
/// at most `maximum_number_of_curves`. A nested curve's part is not tested by
/// `curve_part()`: seen from the rest of the shape, the few landmarks of a
/// small part make its reflection hold almost everywhere.
template <class ConcurrencyTag>
void add_nested_curves(const Curves_mesh& m, const Geodesic_distance_matrix& D,
                       const Curve_settings& st, Boundary_ranking& ranking, std::vector<Working_curve>& curves,
                       std::vector<std::vector<unsigned char>>& masks,
                       std::vector<std::vector<std::size_t>>& partners)
{
  const Irsa_voting_result& vr = ranking.voting();
  const std::vector<unsigned char> everywhere(m.number_of_vertices, 1);
  Sample_domination_test quick(D, 1.5 * st.ignition, st.maximum_overlap, st.nested_onto_itself,
                               st.nested_fixed_points);
  for(std::size_t k = 0; k < vr.voting_pairs.size(); ++k)
    for(std::size_t c = 0; c < curves.size(); ++c)
      if(quick.dominated(vr.voting_pairs[k].eligible_pairs, masks[c], partners[c]))
      {
        ranking.discard(k);
        break;
      }
  ranking.restore_tau();
  const std::size_t first_nested = curves.size();
  Edge_dijkstra dij(m);
  std::vector<std::pair<std::size_t, double>> sources;
  std::vector<unsigned char> near_beta(m.number_of_vertices, 0);
  const double minimum_samples = st.minimum_part * double(D.number_of_sources());
  for(std::size_t examined = 0;
      examined < st.nested_candidates && curves.size() < st.maximum_number_of_curves; ++examined)
  {
    double nu = 0.;
    const std::size_t k = ranking.best(nu);
    if(k == Boundary_ranking::none) break;
    ranking.discard(k);
    const auto& pairs = vr.voting_pairs[k].eligible_pairs;
    if(double(2 * pairs.size()) < minimum_samples) continue;
    bool dominated = false;
    for(std::size_t c = first_nested; !dominated && c < curves.size(); ++c)
      dominated = quick.dominated(pairs, masks[c], partners[c]);
    if(dominated) continue;
    Working_curve w = ranking.curve(k, nu);
    // the boundary itself: mapped onto itself by a kept reflection, it is
    // another symmetry of that curve's part (a plane through the axis of a
    // body of revolution), whatever its eligible pairs
    const std::vector<std::size_t> beta = w.flat_vertices();
    sources.clear();
    for(std::size_t v : beta) sources.emplace_back(v, 0.);
    dij.run(sources, 1.5 * st.ignition);
    std::fill(near_beta.begin(), near_beta.end(), 0);
    for(std::size_t v : dij.reached()) near_beta[v] = 1;
    for(std::size_t c = 0; !dominated && c < curves.size(); ++c)
    {
      std::size_t inside = 0, onto_itself = 0;
      for(std::size_t v : beta)
      {
        if(!masks[c][v]) continue;
        ++inside;
        onto_itself += (partners[c][v] != Mirror_matcher::none && near_beta[partners[c][v]]);
      }
      dominated = double(inside) > st.maximum_overlap * double(beta.size()) &&
                  double(onto_itself) > st.maximum_overlap * double(inside);
    }
    if(dominated) continue;
    ranking.take(k);
    w.nested = true;
    recompute_support(D, st, w);
    std::vector<std::size_t> partner;
    const auto landmarks = curve_landmarks<ConcurrencyTag>(D, w.a, w.b, w.initial_pairs, everywhere,
                                                           st.number_of_landmarks, st.symmetry);
    masks.push_back(symmetry_support_mask<ConcurrencyTag>(D, w.flat_vertices(), landmarks, st.symmetry, &partner));
    partners.push_back(std::move(partner));
    curves.push_back(std::move(w));
  }
}

/// Step 2. Region growing from all curves, then each curve's mu re-voted by
/// its initial eligible pairs whose two samples lie in its region; repeated
/// until no curve's set of voters changes (then mu is exactly stable), at
/// most `number_of_iterations` times. Curves left without voters are removed.
template <class ConcurrencyTag>
void refine_curves(const Curves_mesh& m, const Geodesic_distance_matrix& D, const Curve_settings& st,
                   std::vector<Working_curve>& curves, Boundary_ranking* ranking = nullptr)
{
  for(auto& c : curves) recompute_support(D, st, c);
  // the curves do not move and their landmarks come from the initial pairs:
  // the support masks are computed once
  std::vector<std::vector<std::size_t>> partners;
  std::vector<std::vector<unsigned char>> masks = curve_masks<ConcurrencyTag>(D, st, curves, &partners);
  // the next boundaries below the stopping rule, taken as step 1 takes them
  auto below_stopping_rule = [&](Working_curve& w, std::vector<unsigned char>& mask,
                                 std::vector<std::size_t>& partner) {
    double nu = 0.;
    const std::size_t k = ranking ? ranking->best(nu) : Boundary_ranking::none;
    if(k == Boundary_ranking::none) return false;
    ranking->take(k);
    w = ranking->curve(k, nu);
    recompute_support(D, st, w);
    mask = curve_mask<ConcurrencyTag>(D, st, w, &partner);
    return true;
  };
  remove_dominated_curves(m, st.maximum_overlap, 2. * st.ignition, curves, masks, partners, below_stopping_rule);
  if(ranking != nullptr && st.nested_symmetries)
    add_nested_curves<ConcurrencyTag>(m, D, st, *ranking, curves, masks, partners);
  for(std::size_t it = 0; it < st.number_of_iterations && !curves.empty(); ++it)
  {
    const Region_growing_result rg = grow_regions(m, region_seeds(curves, masks), st.ignition);
    bool changed = false;
    for(std::size_t c = 0; c < curves.size(); ++c)
    {
      std::vector<std::pair<std::size_t, std::size_t>> kept;
      for(const auto& pq : curves[c].initial_pairs)
        if(rg.label[D.sources()[pq.first]] == int(c) && rg.label[D.sources()[pq.second]] == int(c))
          kept.push_back(pq);
      ++curves[c].iterations;
      if(kept != curves[c].pairs)
      {
        changed = true;
        curves[c].pairs.swap(kept);
        recompute_support(D, st, curves[c]);
      }
    }
    if(!changed)
    {
      for(auto& c : curves) c.converged = true;
      break;
    }
  }
  curves.erase(std::remove_if(curves.begin(), curves.end(),
                              [](const Working_curve& c) { return !(c.max_support() > 0.); }),
               curves.end());
}

/// Step 3. mu scaled linearly by its maximum along the curve (mu / max, in
/// [0, 1]); runs of vertices below `pruning_threshold` are cut. With
/// `close_curves`, each gap between two consecutive kept pieces of a polyline
/// is bridged by the shortest edge path between their ends when the mean
/// scaled support along that path (voted by the curve's pairs) reaches the
/// threshold too.
inline void prune_curves(const Curves_mesh& m, const Geodesic_distance_matrix& D, const Curve_settings& st,
                         std::vector<Working_curve>& curves)
{
  Edge_dijkstra dij(m);
  for(auto& c : curves)
  {
    const double mu_max = c.max_support();
    std::vector<Level_set_polyline> out_pl;
    std::vector<std::vector<double>> out_mu;
    for(std::size_t i = 0; i < c.polylines.size(); ++i)
    {
      const Level_set_polyline& pl = c.polylines[i];
      const std::vector<double>& mu = c.mu[i];
      const std::size_t n = pl.vertices.size();
      std::vector<char> keep(n, 0);
      std::size_t nkeep = 0;
      for(std::size_t k = 0; k < n; ++k)
        if(mu[k] >= st.pruning_threshold * mu_max) { keep[k] = 1; ++nkeep; }
      if(nkeep == 0) continue;
      if(nkeep == n)
      {
        out_pl.push_back(pl);
        out_mu.push_back(mu);
        continue;
      }
      // pieces: maximal runs of kept vertices, in order; for a loop start
      // right after a cut vertex so that no piece wraps around
      std::size_t start = 0;
      if(pl.closed)
        while(keep[start]) ++start; // exists since nkeep < n
      std::vector<std::pair<Level_set_polyline, std::vector<double>>> pieces;
      bool in_piece = false;
      for(std::size_t s = 0; s < n; ++s)
      {
        const std::size_t k = (start + s) % n;
        if(!keep[k]) { in_piece = false; continue; }
        if(!in_piece) { pieces.emplace_back(); in_piece = true; }
        pieces.back().first.vertices.push_back(pl.vertices[k]);
        pieces.back().first.weights.push_back(pl.weights[k]);
        pieces.back().second.push_back(mu[k]);
      }
      if(st.close_curves && pieces.size() >= 1)
      {
        // bridge gap g between piece g and piece g+1 (cyclically for a loop)
        const std::size_t gaps = pl.closed ? pieces.size() : pieces.size() - 1;
        std::vector<char> bridged(gaps, 0);
        std::vector<std::vector<std::size_t>> paths(gaps);
        std::vector<std::vector<double>> path_mu(gaps);
        for(std::size_t g = 0; g < gaps; ++g)
        {
          const std::size_t from = pieces[g].first.vertices.back();
          const std::size_t to = pieces[(g + 1) % pieces.size()].first.vertices.front();
          if(from == to) continue;
          std::vector<std::pair<std::size_t, double>> src(1, std::make_pair(from, 0.));
          dij.run(src);
          if(!std::isfinite(dij.distance(to))) continue;
          std::vector<std::size_t> path; // interior vertices, from -> to
          for(std::size_t v = dij.parent(to); v != Curves_mesh::none && v != from; v = dij.parent(v))
            path.push_back(v);
          std::reverse(path.begin(), path.end());
          std::vector<double> pm;
          support_at(D, st.tolerance, st.inv_sigma2, c.pairs, path, pm);
          double mean = 0.;
          for(double x : pm) mean += x;
          mean = path.empty() ? mu_max : mean / double(path.size());
          if(mean >= st.pruning_threshold * mu_max)
          {
            bridged[g] = 1;
            paths[g] = path;
            path_mu[g] = pm;
          }
        }
        // concatenate bridged pieces
        std::vector<std::pair<Level_set_polyline, std::vector<double>>> joined;
        std::size_t first_unbridged = gaps; // a piece after which the chain is cut
        for(std::size_t g = 0; g < gaps; ++g)
          if(!bridged[g]) { first_unbridged = g; break; }
        bool all_bridged = (first_unbridged == gaps);
        const std::size_t np_ = pieces.size();
        // start after an unbridged gap (or at 0 for an open polyline / full loop)
        const std::size_t s0 = (pl.closed && !all_bridged) ? (first_unbridged + 1) % np_ : 0;
        for(std::size_t s = 0; s < np_; ++s)
        {
          const std::size_t p = (s0 + s) % np_;
          const std::size_t prev_gap = (p + np_ - 1) % np_; // gap between p-1 and p
          const bool continues = s > 0 && (pl.closed || p > 0) && prev_gap < gaps && bridged[prev_gap];
          if(!continues) joined.emplace_back();
          auto& j = joined.back();
          if(continues)
          {
            for(std::size_t k = 0; k < paths[prev_gap].size(); ++k)
            {
              j.first.vertices.push_back(paths[prev_gap][k]);
              j.first.weights.push_back(0.);
              j.second.push_back(path_mu[prev_gap][k]);
            }
          }
          j.first.vertices.insert(j.first.vertices.end(), pieces[p].first.vertices.begin(), pieces[p].first.vertices.end());
          j.first.weights.insert(j.first.weights.end(), pieces[p].first.weights.begin(), pieces[p].first.weights.end());
          j.second.insert(j.second.end(), pieces[p].second.begin(), pieces[p].second.end());
        }
        if(pl.closed && all_bridged && !joined.empty())
        {
          // the last gap closes the loop again
          auto& j = joined.back();
          const std::size_t g = gaps - 1;
          for(std::size_t k = 0; k < paths[g].size(); ++k)
          {
            j.first.vertices.push_back(paths[g][k]);
            j.first.weights.push_back(0.);
            j.second.push_back(path_mu[g][k]);
          }
          j.first.closed = true;
        }
        pieces.swap(joined);
      }
      for(auto& p : pieces)
      {
        out_pl.push_back(std::move(p.first));
        out_mu.push_back(std::move(p.second));
      }
    }
    c.polylines.swap(out_pl);
    c.mu.swap(out_mu);
  }
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_EXTRACTION_H
