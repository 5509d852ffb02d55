// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SYMMETRIC_MAP_DENSE_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SYMMETRIC_MAP_DENSE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_curves.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_mesh.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_mirror.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_extraction.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_regions.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/progress.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/symmetric_map_spectral.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

// The symmetric regions of a set of final IRSA curves and the dense mirror
// map of each region (paper Sec. 3.4 and 4.2).

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

/// Mean geodesic distance from a sample to its nearest other sample (the
/// voting's `mean_sample_spacing`), from the sample rows of `D`.
inline double mean_sample_spacing(const Geodesic_distance_matrix& D)
{
  const std::size_t n = D.number_of_sources();
  double sum = 0.;
  std::size_t count = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    float nearest = std::numeric_limits<float>::infinity();
    for(std::size_t j = 0; j < n; ++j)
      if(j != i) nearest = (std::min)(nearest, D(i, D.sources()[j]));
    if(std::isfinite(nearest)) { sum += nearest; ++count; }
  }
  return count > 0 ? sum / double(count) : 0.;
}

struct Region_settings
{
  std::size_t number_of_landmarks = 32;
  std::size_t local_rounds = 3; // of the dense map (dense_region_map())
  std::size_t eigenfunctions = 150; // of its spectral refinement (0: none)
  double side_margin = 0.1; // of the spectral refinement's side test, in d(a,b) (mirror_sides())
  double side_violations = 0.05; // the side test applies if the map breaks it at most at this share
  Symmetry_tolerance symmetry;
  double ignition = 0.;
  double sample_spacing = 0.; // mean_sample_spacing()
  // a sample mapped to itself is a landmark of the local rounds only within
  // this many sample spacings of the curve (dense_region_map())
  double fixed_point_radius = 2.;
  // initial_vertex_map (by vertex index, Mirror_matcher::none where unset):
  // where given, the partner the spectral refinement starts from
  std::vector<std::size_t> initial_map;
};

/// What the region growing needs of the final curves: each curve with its
/// final support, and its support mask computed with landmarks from its
/// final eligible pairs.
template <class ConcurrencyTag>
std::vector<Region_seed_curve> final_curve_seeds(const Geodesic_distance_matrix& D,
                                                 const std::vector<const Irsa_curve*>& curves,
                                                 const Region_settings& st)
{
  std::vector<Region_seed_curve> seeds(curves.size());
  const std::vector<unsigned char> everywhere(D.number_of_vertices(), 1);
  for(std::size_t c = 0; c < curves.size(); ++c)
  {
    const Irsa_curve& k = *curves[c];
    for(std::size_t i = 0; i < k.polylines.size(); ++i)
    {
      seeds[c].vertices.insert(seeds[c].vertices.end(), k.polylines[i].begin(), k.polylines[i].end());
      seeds[c].support.insert(seeds[c].support.end(), k.support[i].begin(), k.support[i].end());
    }
    const auto landmarks = curve_landmarks<ConcurrencyTag>(D, k.a, k.b, k.eligible_pairs, everywhere,
                                                           st.number_of_landmarks, st.symmetry);
    seeds[c].mask = symmetry_support_mask<ConcurrencyTag>(D, seeds[c].vertices, landmarks, st.symmetry);
  }
  std::vector<bool> nested(curves.size());
  for(std::size_t c = 0; c < curves.size(); ++c) nested[c] = curves[c]->nested;
  scale_seed_support(seeds, nested);
  return seeds;
}

/// Vertex labels of the grass-fire regions of the final curves: the growth
/// of the refinement, all curves at once (a partition).
template <class ConcurrencyTag>
Region_growing_result curve_regions(const Curves_mesh& m, const Geodesic_distance_matrix& D,
                                    const std::vector<const Irsa_curve*>& curves, const Region_settings& st)
{
  return grow_regions(m, final_curve_seeds<ConcurrencyTag>(D, curves, st), st.ignition);
}

/// Vertex labels by prominence, for the symmetric map: the curves in order
/// (best first), each growing alone into the vertices its reflection holds at
/// and no better curve took. Why not the partition: a nested symmetry (a leg's
/// own axis) claims its part in the partition, but at a vertex of that part
/// the reflection of the whole (the body's, mapping the leg to the other leg)
/// is the more prominent symmetry, the one a symmetric map should follow.
/// With a single curve both labellings are the same.
template <class ConcurrencyTag>
Region_growing_result prominence_regions(const Curves_mesh& m, const Geodesic_distance_matrix& D,
                                         const std::vector<const Irsa_curve*>& curves, const Region_settings& st)
{
  std::vector<Region_seed_curve> seeds = final_curve_seeds<ConcurrencyTag>(D, curves, st);
  Region_growing_result r;
  r.label.assign(m.number_of_vertices, -1);
  r.time.assign(m.number_of_vertices, std::numeric_limits<double>::infinity());
  for(std::size_t c = 0; c < seeds.size(); ++c)
  {
    std::vector<Region_seed_curve> one(1);
    one[0].mask = seeds[c].mask;
    for(std::size_t v = 0; v < m.number_of_vertices; ++v)
      if(r.label[v] >= 0) one[0].mask[v] = 0;
    for(std::size_t i = 0; i < seeds[c].vertices.size(); ++i)
      if(r.label[seeds[c].vertices[i]] < 0)
      {
        one[0].vertices.push_back(seeds[c].vertices[i]);
        one[0].support.push_back(seeds[c].support[i]);
      }
    const Region_growing_result g = grow_regions(m, one, st.ignition);
    for(std::size_t v = 0; v < m.number_of_vertices; ++v)
      if(g.label[v] == 0) { r.label[v] = int(c); r.time[v] = g.time[v]; }
  }
  return r;
}

/// Face labels from vertex labels: the label shared by at least two of the
/// face's vertices; if the three labels differ, the label of the vertex
/// reached first; -1 if at least two vertices are unlabelled.
inline std::vector<int> face_labels(const Curves_mesh& m, const Region_growing_result& rg)
{
  std::vector<int> out(m.faces.size(), -1);
  for(std::size_t f = 0; f < m.faces.size(); ++f)
  {
    const auto& v = m.faces[f];
    const int l0 = rg.label[v[0]], l1 = rg.label[v[1]], l2 = rg.label[v[2]];
    if(l0 >= 0 && (l0 == l1 || l0 == l2)) out[f] = l0;
    else if(l1 >= 0 && l1 == l2) out[f] = l1;
    else if(int(l0 >= 0) + int(l1 >= 0) + int(l2 >= 0) == 3)
    {
      std::size_t first = 0;
      for(std::size_t k = 1; k < 3; ++k)
        if(rg.time[v[k]] < rg.time[v[first]]) first = k;
      out[f] = rg.label[v[first]];
    }
  }
  return out;
}

/// The side of each vertex relative to the bisector of the curve's voting
/// pair (a, b): +1 where d(a,x) - d(b,x) exceeds `margin` times d(a,b), -1
/// below minus that, 0 in the band between. A reflection swaps a and b, so
/// it maps each side onto the other. The band stays free: it holds the axis,
/// and on a posed shape the bisector strays from the axis (FAUST, a band of
/// 0.05 d(a,b) instead of 0.1: tr_reg_008 99.6 -> 99.4 % CR; none at all:
/// 76 %).
inline std::vector<signed char> mirror_sides(const Geodesic_distance_matrix& D, std::size_t a, std::size_t b,
                                             double margin)
{
  const float* ra = D.row(a);
  const float* rb = D.row(b);
  const double width = margin * double(ra[D.sources()[b]]);
  std::vector<signed char> side(D.number_of_vertices(), 0);
  if(!(width > 0.) || !std::isfinite(width)) return side;
  for(std::size_t v = 0; v < side.size(); ++v)
  {
    const double f = double(ra[v]) - double(rb[v]);
    side[v] = f > width ? 1 : (f < -width ? -1 : 0);
  }
  return side;
}

/// The mutual sample pairs of a vertex map `best` (of the vertices whose
/// `slot` is set): each sample goes to the sample nearest to its image, and
/// pairs of samples going to each other are kept, once each. A sample going
/// to itself is kept only within `fixed_point_radius` of `curve_vertices`: a
/// reflection fixes its axis alone (see dense_region_map()).
inline std::vector<std::pair<std::size_t, std::size_t>>
mutual_sample_pairs(const Geodesic_distance_matrix& D, const std::vector<std::size_t>& slot,
                    const std::vector<std::size_t>& best, const std::vector<std::size_t>& curve_vertices,
                    double fixed_point_radius)
{
  const std::size_t ns = D.number_of_sources();
  std::vector<std::size_t> image(ns, Mirror_matcher::none);
  for(std::size_t s = 0; s < ns; ++s)
  {
    const std::size_t i = slot[D.sources()[s]];
    if(i == Mirror_matcher::none || best[i] == Mirror_matcher::none) continue;
    float nearest = std::numeric_limits<float>::infinity();
    for(std::size_t t = 0; t < ns; ++t)
      if(D(t, best[i]) < nearest) { nearest = D(t, best[i]); image[s] = t; }
  }
  auto near_curve = [&](std::size_t s) {
    float d = std::numeric_limits<float>::infinity();
    for(std::size_t u : curve_vertices) d = (std::min)(d, D(s, u));
    return double(d) <= fixed_point_radius;
  };
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for(std::size_t s = 0; s < ns; ++s)
    if(image[s] != Mirror_matcher::none && image[s] >= s && image[image[s]] == s && (image[s] != s || near_curve(s)))
      pairs.emplace_back(s, image[s]);
  return pairs;
}

/// The distortion of `isometric_distortion()`: over L farthest-point
/// landmarks among `candidates` (along the mesh edges, from the first
/// candidate), the mean over landmark pairs (x, l) of the same `label` of
/// |d(x, l) - d(p(x), p(l))| / sqrt(area). The landmarks and their distances
/// are computed once, so that maps of the same vertices compare at the cost
/// of their partners' distances alone.
class Map_distortion
{
public:
  Map_distortion(const Curves_mesh& m, const std::vector<std::size_t>& candidates, const std::vector<long long>& label,
                 std::size_t number_of_landmarks = 150)
    : m_(m), dijkstra_(m)
  {
    if(candidates.empty()) return;
    // farthest-point landmarks; the distances between them (to_earlier_[j][i] = d(l_j, l_i), i < j)
    const std::size_t L = (std::min)(number_of_landmarks, candidates.size());
    std::vector<double> nearest(m.number_of_vertices, std::numeric_limits<double>::infinity());
    landmarks_.assign(1, candidates.front());
    while(true)
    {
      dijkstra_.run(std::vector<std::pair<std::size_t, double>>(1, std::make_pair(landmarks_.back(), 0.)));
      std::vector<double> row(landmarks_.size() - 1);
      for(std::size_t i = 0; i + 1 < landmarks_.size(); ++i) row[i] = dijkstra_.distance(landmarks_[i]);
      to_earlier_.push_back(std::move(row));
      for(std::size_t v = 0; v < m.number_of_vertices; ++v) nearest[v] = (std::min)(nearest[v], dijkstra_.distance(v));
      if(landmarks_.size() == L) break;
      // the farthest candidate (an unreachable one first); ties to the smaller index
      std::size_t next = candidates.front();
      double far = -1.;
      for(std::size_t v : candidates)
        if(nearest[v] > far) { far = nearest[v]; next = v; }
      if(!(far > 0.)) break; // every candidate is a landmark or at distance 0 from one
      landmarks_.push_back(next);
    }
    for(std::size_t l : landmarks_) landmark_label_.push_back(label[l]);
  }

  /// the distortion of the map `image` (by vertex; a partner for every candidate)
  double operator()(const std::vector<long long>& image) const
  {
    double sum = 0.;
    std::size_t pairs = 0;
    for(std::size_t j = 1; j < landmarks_.size(); ++j)
    {
      dijkstra_.run(
        std::vector<std::pair<std::size_t, double>>(1, std::make_pair(std::size_t(image[landmarks_[j]]), 0.)));
      for(std::size_t i = 0; i < j; ++i)
      {
        if(landmark_label_[i] != landmark_label_[j]) continue;
        // pairs in different components of the mesh (infinite distances) do not count
        const double a = to_earlier_[j][i], b = dijkstra_.distance(std::size_t(image[landmarks_[i]]));
        if(std::isfinite(a) && std::isfinite(b)) { sum += std::abs(a - b); ++pairs; }
      }
    }
    return pairs > 0 ? sum / double(pairs) / std::sqrt(m_.area) : 0.;
  }

private:
  const Curves_mesh& m_;
  mutable Edge_dijkstra dijkstra_;
  std::vector<std::size_t> landmarks_;
  std::vector<long long> landmark_label_;
  std::vector<std::vector<double>> to_earlier_;
};

/// Distance along the mesh edges of every vertex to the nearest of the
/// curve vertices `curve_vertices`.
inline std::vector<double> distances_to_curve(const Curves_mesh& m, const std::vector<std::size_t>& curve_vertices)
{
  std::vector<std::pair<std::size_t, double>> sources;
  for(std::size_t v : curve_vertices) sources.emplace_back(v, 0.);
  Edge_dijkstra dijkstra(m);
  dijkstra.run(sources);
  std::vector<double> to_curve(m.number_of_vertices);
  for(std::size_t v = 0; v < to_curve.size(); ++v) to_curve[v] = dijkstra.distance(v);
  return to_curve;
}

/// `fixed_point_share()` of the map `image` (by vertex, -1 for none), given
/// the `distances_to_curve()` of its curve: the share of the vertices farther
/// than 0.1 sqrt(area) from the curve whose partner is within 0.03
/// sqrt(area) of themselves (along the mesh edges).
inline double fixed_point_share(const Curves_mesh& m, const std::vector<double>& to_curve,
                                const std::vector<long long>& image)
{
  const double unit = std::sqrt(m.area);
  const double far_from_curve = 0.1 * unit, near_itself = 0.03 * unit;
  Edge_dijkstra dijkstra(m);
  std::size_t far = 0, fixed = 0;
  for(std::size_t v = 0; v < m.number_of_vertices; ++v)
  {
    if(image[v] < 0 || !(to_curve[v] > far_from_curve)) continue;
    ++far;
    const std::size_t p = std::size_t(image[v]);
    if(p == v) { ++fixed; continue; }
    if(m.distance(v, p) > near_itself) continue; // the path along the edges is longer still
    dijkstra.run(std::vector<std::pair<std::size_t, double>>(1, std::make_pair(v, 0.)), near_itself);
    fixed += dijkstra.distance(p) <= near_itself;
  }
  return far > 0 ? double(fixed) / double(far) : 0.;
}

/// `symmetric_map_defect()`
inline double map_defect(double fixed_share, double distortion) { return distortion + 0.3 * fixed_share; }

/// The spectral refinement of `best` (`best[i]` for `verts[i]`), twice:
/// free, and with the vertices `axis` (of the curve `curve_vertices`) held
/// in place: they join each fit as their own partners, since a reflection
/// fixes its axis. `best` becomes the map of lower `map_defect()` (its
/// `Map_distortion` over `verts` and its `fixed_point_share()`); returns
/// true if that is the held one. Where the region has a part nearly
/// symmetric under turns (a head about the neck), the free projection keeps
/// it turned, an isometry of the part that the rest of the map does not
/// pin: SCAPE mesh024, seed 2, its nose mapped 0.147 sqrt(area) away
/// (distortion 0.0210, 90.9 % CR); held, 0.0205 and 100 %. Held always, a
/// curve off the axis pulls the map off (FAUST tr_reg_000, 99.5 -> 95.1 %,
/// distortion up), hence the comparison; by distortion alone, a held map
/// that keeps a patch in place can win (FAUST tr_reg_005, seed 1: 0.0123
/// against 0.0127 free, but 1.0 % of the far vertices fixed and 96.2
/// against 99.2 % CR), hence the fixed points in it.
template <class ConcurrencyTag>
bool refine_free_or_held(const Curves_mesh& m, const Spectral_refinement& refinement,
                         const std::vector<std::size_t>& verts, const std::vector<signed char>* side,
                         const std::vector<std::size_t>& axis, const std::vector<std::size_t>& curve_vertices,
                         std::vector<std::size_t>& best)
{
  std::vector<std::size_t> held = best;
  refinement.template refine<ConcurrencyTag>(best, side);
  if(axis.empty() || !refinement.ok()) return false;
  refinement.template refine<ConcurrencyTag>(held, side, &axis);
  std::vector<std::size_t> mapped;
  std::vector<long long> free_image(m.number_of_vertices, -1), held_image(m.number_of_vertices, -1);
  for(std::size_t i = 0; i < verts.size(); ++i)
    if(best[i] != Mirror_matcher::none && held[i] != Mirror_matcher::none)
    {
      mapped.push_back(verts[i]);
      free_image[verts[i]] = static_cast<long long>(best[i]);
      held_image[verts[i]] = static_cast<long long>(held[i]);
    }
  const Map_distortion distortion(m, mapped, std::vector<long long>(m.number_of_vertices, 0));
  const std::vector<double> to_curve = distances_to_curve(m, curve_vertices);
  auto defect = [&](const std::vector<long long>& image) {
    return map_defect(fixed_point_share(m, to_curve, image), distortion(image));
  };
  if(!(defect(held_image) < defect(free_image))) return false;
  best.swap(held);
  return true;
}

/// Dense mirror map of one region: the best partner (curves_mirror.h) of
/// every vertex of the region among the vertices of the region, refined under
/// locally weighted landmarks, then spectrally (ZoomOut), made an involution
/// greedily: the pairs
/// (x, best(x)) in increasing order of the residual are
/// matched when both ends are free (E is symmetric); a vertex left unmatched
/// keeps its best partner.
template <class ConcurrencyTag>
void dense_region_map(const Curves_mesh& m, const Geodesic_distance_matrix& D, const Irsa_curve& curve,
                      const std::vector<int>& label, int region, const Region_settings& st,
                      std::vector<std::ptrdiff_t>& partner, Progress* progress = nullptr,
                      double progress_from = 0., double progress_to = 1.)
{
  // the callback sees the end of each step, as a share of [progress_from, progress_to]
  auto step = [&](double share) {
    if(progress != nullptr) progress->step(progress_from + share * (progress_to - progress_from));
  };
  std::vector<std::size_t> verts;
  for(std::size_t v = 0; v < m.number_of_vertices; ++v)
    if(label[v] == region) verts.push_back(v);
  if(verts.empty()) return;
  std::vector<unsigned char> in_region(m.number_of_vertices, 0);
  for(std::size_t v : verts) in_region[v] = 1;
  std::vector<std::pair<std::size_t, std::size_t>> landmarks =
    curve_landmarks<ConcurrencyTag>(D, curve.a, curve.b, curve.eligible_pairs, in_region, st.number_of_landmarks,
                                    st.symmetry);
  std::vector<std::size_t> best;
  std::vector<double> residual;
  Mirror_matcher(D, landmarks).template best_partners<ConcurrencyTag>(verts, verts, best, residual);
  step(0.2);

  // slot of each vertex in `verts`
  std::vector<std::size_t> slot(m.number_of_vertices, Mirror_matcher::none);
  for(std::size_t i = 0; i < verts.size(); ++i) slot[verts[i]] = i;

  // Then under locally weighted landmarks (curves_mirror.h), a few rounds,
  // each with landmarks taken from the mutual sample pairs of the previous
  // round's map: the landmarks of the global match carry its distortion on
  // posed shapes. sigma: three times the spacing of the 2K landmark samples
  // were they spread evenly over the region. A sample mapped to itself gives
  // a landmark pair (s, s), right on the axis and wrong elsewhere: it makes
  // the vertices near it prefer themselves, and a limb whose samples the
  // global match keeps in place stays so. Such a pair is kept only within
  // `fixed_point_radius` sample spacings of the curve (a reflection fixes
  // its axis alone; the rule of the curves' parts, irsa_curves.h). On
  // FAUST's tr_reg_008 with seed 4 the arms mapped onto themselves (76.7 %
  // CR, with the whole body in the region); with the rule 99.5 %
  // (symmetry_map_benchmark --seed 4). The spectral refinement after the
  // rounds mends smaller such patches (tr_reg_002's head).
  double region_area = 0.;
  for(const auto& f : m.faces)
    if(in_region[f[0]] && in_region[f[1]] && in_region[f[2]]) region_area += triangle_area(m, f);
  std::vector<std::size_t> curve_vertices;
  for(const auto& polyline : curve.polylines)
    curve_vertices.insert(curve_vertices.end(), polyline.begin(), polyline.end());
  for(std::size_t round = 0; round < st.local_rounds && !landmarks.empty(); ++round)
  {
    if(round > 0)
    {
      std::vector<std::pair<std::size_t, std::size_t>> pairs =
        mutual_sample_pairs(D, slot, best, curve_vertices, st.fixed_point_radius * st.sample_spacing);
      if(pairs.size() < landmarks.size()) break;
      landmarks = spread_pairs(D, pairs, st.number_of_landmarks);
    }
    const Mirror_matcher mm(D, landmarks);
    const double sigma = 3. * std::sqrt(region_area / double(2 * mm.number_of_landmarks()));
    local_best_partners<ConcurrencyTag>(mm, verts, verts, sigma, best, residual);
    step(0.2 + 0.4 * double(round + 1) / double(st.local_rounds));
  }

  // Then the spectral refinement (symmetric_map_spectral.h), where no vertex
  // clearly on one side of the bisector of (a, b) may map to that same side:
  // ZoomOut alone can send a whole extremity onto itself (FAUST tr_reg_003's
  // raised hands: 98.6 -> 99.5 % CR). Only where the map so far keeps the
  // sides apart: where it does not, the bisector is not the map's axis (SCAPE
  // meshes whose top curve follows another symmetry: 15-87 % of the vertices
  // off the band map to their own side, and imposing the sides cost 65.2 ->
  // 62.8 % CR, measured with the regions' former tolerance of 1.0; on FAUST
  // it is 0-0.3 %). Measured again after the coarse-eigenfunction rule of
  // the curve extraction (SCAPE, seeds 0, 1, 2): the sides imposed
  // everywhere give 85.5 / 87.5 / 81.6 % against 84.7 / 90.7 / 81.7 %; they
  // mend legs that map onto themselves where the bisector is right (mesh004
  // 75.0 -> 88.6 %, seed 0) and break the map where it strays (mesh016,
  // seed 1: 77.3 -> 50.0 %). Computing both maps and keeping the one of
  // least symmetric_map_defect() would gain little: 86.0 against 85.7 % over
  // the 54 maps of seeds 0-2 at 1000 samples (at best 87.1 %), for a second
  // refinement. The residuals, which order the involution below, under the
  // last landmarks.
  // A given initial map (initial_vertex_map, as from global_reflection_map())
  // replaces the landmark match where its partner lies in the region: the
  // whole shape's reflection, found from the spectrum, is right on posed
  // shapes where the landmarks of the curve carry the pose's distortion
  // (SCAPE mesh044, 064: 88.6 and 100 % CR against 65.9 % for the map of
  // the same curves, symmetry_map_benchmark --log-runs). That map is a
  // ZoomOut map already, and the spectral refinement below is skipped:
  // refining the global reflection again with 150 functions lowered SCAPE's
  // mean CR from 98.0 to 96.8 % (mesh064 100 -> 84.1 %, with 15.6 % of the
  // far vertices held in place; seed 0, 1000 samples).
  const bool initial = !st.initial_map.empty();
  if(initial)
    for(std::size_t i = 0; i < verts.size(); ++i)
    {
      const std::size_t g = st.initial_map[verts[i]];
      if(g != Mirror_matcher::none && in_region[g]) best[i] = g;
    }
  bool moved = initial; // the partners differ from the landmark match's: new residuals
  if(st.eigenfunctions > 0 && !landmarks.empty() && !initial)
  {
    const std::vector<signed char> side = mirror_sides(D, curve.a, curve.b, st.side_margin);
    std::size_t off_band = 0, kept_side = 0;
    for(std::size_t i = 0; i < verts.size(); ++i)
      if(side[verts[i]] != 0 && best[i] != Mirror_matcher::none)
      {
        ++off_band;
        kept_side += side[best[i]] == side[verts[i]];
      }
    const bool use_sides = double(kept_side) <= st.side_violations * double(off_band);
    const Spectral_refinement refinement(m, D.sources(), verts, in_region, st.eigenfunctions);
    moved = refinement.ok();
    if(moved)
    {
      std::vector<std::size_t> axis; // the curve's vertices, one per sample spacing
      const double stride = (std::max)(1., st.sample_spacing / m.mean_edge_length);
      for(const auto& polyline : curve.polylines)
        for(double t = 0.; t < double(polyline.size()); t += stride) axis.push_back(polyline[std::size_t(t)]);
      refine_free_or_held<ConcurrencyTag>(m, refinement, verts, use_sides ? &side : nullptr, axis, curve_vertices,
                                          best);
    }
  }
  if(moved && !landmarks.empty())
  {
    const Mirror_matcher mm(D, landmarks);
    for(std::size_t i = 0; i < verts.size(); ++i)
      if(best[i] != Mirror_matcher::none) residual[i] = mm.residual(verts[i], best[i]);
  }
  step(0.95);

  std::vector<std::size_t> by_cost;
  for(std::size_t i = 0; i < verts.size(); ++i)
    if(best[i] != Mirror_matcher::none) by_cost.push_back(i);
  std::sort(by_cost.begin(), by_cost.end(), [&](std::size_t i, std::size_t j) {
    return residual[i] < residual[j] || (residual[i] == residual[j] && i < j);
  });
  std::vector<std::size_t> match(verts.size(), Mirror_matcher::none);
  for(std::size_t i : by_cost)
  {
    const std::size_t j = slot[best[i]];
    if(match[i] != Mirror_matcher::none || match[j] != Mirror_matcher::none) continue;
    match[i] = j;
    match[j] = i;
  }
  for(std::size_t i = 0; i < verts.size(); ++i)
  {
    if(match[i] != Mirror_matcher::none)
      partner[verts[i]] = std::ptrdiff_t(verts[match[i]]);
    else
      partner[verts[i]] = best[i] == Mirror_matcher::none ? -1 : std::ptrdiff_t(best[i]);
  }
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SYMMETRIC_MAP_DENSE_H
