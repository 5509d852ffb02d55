// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_REGIONS_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_REGIONS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

// Symmetry-support-controlled grass-fire region growing (paper Sec. 3.4).
//
// All curves burn at once. A fire starts at every curve vertex with positive
// support mu and spreads along the mesh edges at the speed mu(seed) / mu_max
// (mu_max: the largest support over all curves), so arrival time = (edge-path
// length + ignition) / speed: strong parts of strong curves claim more
// surface. The ignition length delays weak seeds: without it every curve
// vertex would burn at time 0 and a weak curve would wall off a strong
// curve's front wherever it crosses its region. Spreading from the whole
// curve, a front moves away from it along shortest paths, i.e. orthogonally
// to it. A vertex belongs to the first front that reaches it (fronts stop
// where they meet), and a front only enters the vertices its curve supports
// (fronts stop where support ends; see curves_mirror.h for the support).

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

/// What the region growing needs of one curve.
struct Region_seed_curve
{
  std::vector<std::size_t> vertices;  // curve vertices
  std::vector<double> support;        // mu at each
  std::vector<unsigned char> mask;    // by vertex index: 1 where the curve's symmetry holds
};

struct Region_growing_result
{
  std::vector<int> label;     // by vertex index: curve index or -1
  std::vector<double> time;   // arrival time (+inf where unreached)
};

/// Scales the support of the seeds for `grow_regions()`: the curves of the
/// paper's selection by the largest support among them (strong curves claim
/// more surface), a nested curve (`nested[c]`) by its own largest support:
/// its support comes from a part that is small next to the shape, and its
/// front would otherwise not even reach across that part before the front of
/// the whole shape's axis.
inline void scale_seed_support(std::vector<Region_seed_curve>& seeds, const std::vector<bool>& nested)
{
  auto largest = [](const Region_seed_curve& c) {
    double m = 0.;
    for(double s : c.support) m = (std::max)(m, s);
    return m;
  };
  double top = 0.;
  for(std::size_t c = 0; c < seeds.size(); ++c)
    if(!nested[c]) top = (std::max)(top, largest(seeds[c]));
  for(std::size_t c = 0; c < seeds.size(); ++c)
  {
    const double scale = nested[c] ? largest(seeds[c]) : top;
    if(scale > 0.)
      for(double& s : seeds[c].support) s /= scale;
  }
}

/// Grows the regions of `curves` on `m`; `ignition` is a length.
inline Region_growing_result grow_regions(const Curves_mesh& m, const std::vector<Region_seed_curve>& curves,
                                          double ignition)
{
  const std::size_t nv = m.number_of_vertices;
  const double inf = std::numeric_limits<double>::infinity();
  Region_growing_result r;
  r.label.assign(nv, -1);
  r.time.assign(nv, inf);

  double mu_max = 0.;
  for(const auto& c : curves)
    for(double s : c.support) mu_max = (std::max)(mu_max, s);
  if(!(mu_max > 0.)) return r;

  // the fire: entries (time, curve, vertex, speed); ties broken by curve then
  // vertex index, so the labelling is deterministic
  typedef std::tuple<double, std::size_t, std::size_t, double> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for(std::size_t c = 0; c < curves.size(); ++c)
    for(std::size_t i = 0; i < curves[c].vertices.size(); ++i)
    {
      const double s = curves[c].support[i] / mu_max;
      if(s > 0.) queue.push(Entry(ignition / s, c, curves[c].vertices[i], s));
    }
  while(!queue.empty())
  {
    const Entry e = queue.top();
    queue.pop();
    const double t = std::get<0>(e);
    const std::size_t c = std::get<1>(e), v = std::get<2>(e);
    const double s = std::get<3>(e);
    if(r.label[v] >= 0) continue; // already burnt (first arrival wins)
    r.label[v] = int(c);
    r.time[v] = t;
    for(std::size_t k = m.adjacency_offsets[v]; k < m.adjacency_offsets[v + 1]; ++k)
    {
      const std::size_t w = m.adjacency[k];
      if(r.label[w] >= 0 || !curves[c].mask[w]) continue;
      queue.push(Entry(t + m.edge_length[m.adjacency_edge[k]] / s, c, w, s));
    }
  }
  return r;
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_REGIONS_H
