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
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/voting_common.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
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

/// Step 1. Ranks the voted boundaries by nu = int_beta tau * mu (trapezoidal
/// rule on the level set, see curves_level_set.h), takes the best, sets tau
/// to zero within `vicinity` of its beta (edge-path distance), and repeats.
/// The value of the stopping rule is the average of tau * mu along the
/// boundary, nu / length(beta), recorded when the boundary is chosen; the
/// selection stops before the first boundary whose value makes a significant
/// drop (`significant_drop()`). It also stops when no boundary has a positive
/// nu left, and after `maximum_number_of_curves`.
inline std::vector<Working_curve>
select_initial_curves(const Curves_mesh& m, const Geodesic_distance_matrix& D, const Irsa_voting_result& vr,
                      const std::vector<double>& tau, const Curve_settings& st,
                      std::vector<double>* selection_values = nullptr)
{
  const std::size_t np = vr.voting_pairs.size();
  Level_set_tracer tracer(m);
  std::vector<std::vector<double>> weights(np);
  std::vector<double> length(np, 0.);
  std::vector<Level_set_polyline> pls;
  for(std::size_t k = 0; k < np; ++k)
  {
    const Irsa_voting_pair& vp = vr.voting_pairs[k];
    tracer.trace(D, vp.a, vp.b, vp.boundary, pls);
    Level_set_tracer::weights_on_boundary(pls, vp.boundary, weights[k]);
    for(double w : weights[k]) length[k] += w;
  }

  std::vector<double> t = tau;
  std::vector<char> taken(np, 0);
  std::vector<std::size_t> chosen;
  std::vector<double> values, nus;
  Edge_dijkstra dij(m);
  std::vector<std::pair<std::size_t, double>> sources;
  while(chosen.size() < st.maximum_number_of_curves)
  {
    std::size_t best = np;
    double best_nu = 0.;
    for(std::size_t k = 0; k < np; ++k)
    {
      if(taken[k] || !(length[k] > 0.)) continue;
      const Irsa_voting_pair& vp = vr.voting_pairs[k];
      double nu = 0.;
      for(std::size_t i = 0; i < vp.boundary.size(); ++i)
        nu += weights[k][i] * t[vp.boundary[i]] * vp.support[i];
      if(nu > best_nu) { best_nu = nu; best = k; }
    }
    if(best == np) break;
    taken[best] = 1;
    chosen.push_back(best);
    nus.push_back(best_nu);
    values.push_back(best_nu / length[best]);

    // the stopping rule on the drops of the average
    if(significant_drop(values, st.stopping_ratio))
    {
      chosen.pop_back();
      nus.pop_back();
      break;
    }
    // suppress tau in the vicinity of the chosen boundary
    sources.clear();
    for(std::size_t v : vr.voting_pairs[best].boundary) sources.emplace_back(v, 0.);
    dij.run(sources, st.vicinity);
    for(std::size_t v : dij.reached()) t[v] = 0.;
  }
  if(selection_values) *selection_values = values;

  std::vector<Working_curve> curves;
  for(std::size_t c = 0; c < chosen.size(); ++c)
  {
    const Irsa_voting_pair& vp = vr.voting_pairs[chosen[c]];
    Working_curve w;
    w.pair = chosen[c];
    w.a = vp.a;
    w.b = vp.b;
    w.nu = nus[c];
    w.length = length[chosen[c]];
    tracer.trace(D, vp.a, vp.b, vp.boundary, w.polylines);
    w.initial_pairs = vp.eligible_pairs;
    w.pairs = vp.eligible_pairs;
    curves.push_back(std::move(w));
  }
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

/// The vertices supporting each curve's reflection (curves_mirror.h), with
/// landmarks from its voting pair and its initial eligible pairs; with
/// `partners`, also the best mirror partner of every vertex under each.
template <class ConcurrencyTag>
std::vector<std::vector<unsigned char>> curve_masks(const Geodesic_distance_matrix& D,
                                                    const Curve_settings& st,
                                                    const std::vector<Working_curve>& curves,
                                                    std::vector<std::vector<std::size_t>>* partners = nullptr)
{
  std::vector<std::vector<unsigned char>> masks;
  if(partners) partners->assign(curves.size(), std::vector<std::size_t>());
  const std::vector<unsigned char> everywhere(D.number_of_vertices(), 1);
  for(std::size_t c = 0; c < curves.size(); ++c)
  {
    const auto landmarks = curve_landmarks<ConcurrencyTag>(D, curves[c].a, curves[c].b, curves[c].initial_pairs,
                                                           everywhere, st.number_of_landmarks, st.symmetry);
    masks.push_back(symmetry_support_mask<ConcurrencyTag>(D, curves[c].flat_vertices(), landmarks, st.symmetry,
                                                          partners ? &(*partners)[c] : nullptr));
  }
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
  return seeds;
}

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
inline void remove_dominated_curves(const Curves_mesh& m, double maximum_overlap, double axis_radius,
                                    std::vector<Working_curve>& curves,
                                    std::vector<std::vector<unsigned char>>& masks,
                                    const std::vector<std::vector<std::size_t>>& partners)
{
  if(curves.empty()) return;
  const std::size_t nv = m.number_of_vertices;
  std::vector<Working_curve> kept_curves;
  std::vector<std::vector<unsigned char>> kept_masks;
  std::vector<std::size_t> kept_index;
  for(std::size_t c = 0; c < curves.size(); ++c)
  {
    const std::vector<unsigned char> part =
      curve_part(m, curves[c].flat_vertices(), masks[c], partners[c], axis_radius);
    std::size_t size = 0;
    for(std::size_t v = 0; v < nv; ++v) size += part[v];
    bool keep = true;
    for(std::size_t k = 0; keep && k < kept_index.size(); ++k)
    {
      const std::vector<unsigned char>& mask_k = kept_masks[k];
      const std::vector<std::size_t>& partner_k = partners[kept_index[k]];
      std::size_t inside = 0, onto_itself = 0;
      for(std::size_t v = 0; v < nv; ++v)
      {
        if(!part[v] || !mask_k[v]) continue;
        ++inside;
        onto_itself += (partner_k[v] != Mirror_matcher::none && part[partner_k[v]]);
      }
      if(double(inside) > maximum_overlap * double(size) && double(onto_itself) > maximum_overlap * double(inside))
        keep = false;
    }
    if(!keep) continue;
    kept_curves.push_back(std::move(curves[c]));
    kept_masks.push_back(std::move(masks[c]));
    kept_index.push_back(c);
  }
  curves.swap(kept_curves);
  masks.swap(kept_masks);
}

/// Step 2. Region growing from all curves, then each curve's mu re-voted by
/// its initial eligible pairs whose two samples lie in its region; repeated
/// until no curve's set of voters changes (then mu is exactly stable), at
/// most `number_of_iterations` times. Curves left without voters are removed.
template <class ConcurrencyTag>
void refine_curves(const Curves_mesh& m, const Geodesic_distance_matrix& D, const Curve_settings& st,
                   std::vector<Working_curve>& curves)
{
  for(auto& c : curves) recompute_support(D, st, c);
  // the curves do not move and their landmarks come from the initial pairs:
  // the support masks are computed once
  std::vector<std::vector<std::size_t>> partners;
  std::vector<std::vector<unsigned char>> masks = curve_masks<ConcurrencyTag>(D, st, curves, &partners);
  remove_dominated_curves(m, st.maximum_overlap, 2. * st.ignition, curves, masks, partners);
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
