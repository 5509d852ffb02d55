// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_DBSCAN_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_DBSCAN_H

#include <CGAL/disable_warnings.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

// DBSCAN (Ester et al. 1996), written by hand: none of the package's
// dependencies (CGAL, Eigen, Boost, TBB) provides it.
//
// Points are 0..n-1. `neighbors(i, out)` must fill `out` with every point j
// (including i itself) at distance <= radius from i, in increasing order of j,
// and the relation must be symmetric. A point is a core point when it has at
// least `min_points` neighbours (itself included, as in the original paper).
// Clusters are numbered 0, 1, ... in the order of their first core point;
// noise gets -1. A border point reachable from several clusters joins the
// first one that reaches it; since points and neighbours are visited in index
// order, the labelling depends only on the neighbour relation, not on how the
// caller computes it (brute force or precomputed lists give the same labels).
//
// Returns the number of clusters. `buffers`: work lists, for callers that
// cluster many small sets (their capacity is kept from one call to the next).
struct Dbscan_buffers
{
  std::vector<std::size_t> nbrs, seeds;
};

template <class NeighborFunction>
std::size_t dbscan(std::size_t n, std::size_t min_points, NeighborFunction neighbors,
                   std::vector<int>& labels, Dbscan_buffers& buffers)
{
  const int undefined = -2, noise = -1;
  labels.assign(n, undefined);
  std::vector<std::size_t>& nbrs = buffers.nbrs;
  std::vector<std::size_t>& seeds = buffers.seeds;
  int cluster = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    if(labels[i] != undefined)
      continue;
    nbrs.clear();
    neighbors(i, nbrs);
    if(nbrs.size() < min_points) { labels[i] = noise; continue; }
    labels[i] = cluster;
    seeds.clear();
    for(std::size_t j : nbrs)
      if(j != i) seeds.push_back(j);
    for(std::size_t k = 0; k < seeds.size(); ++k)
    {
      const std::size_t j = seeds[k];
      if(labels[j] == noise) { labels[j] = cluster; continue; } // border point
      if(labels[j] != undefined) continue;
      labels[j] = cluster;
      nbrs.clear();
      neighbors(j, nbrs);
      if(nbrs.size() >= min_points) // j is a core point: expand through it
        for(std::size_t l : nbrs)
          if(labels[l] == undefined || labels[l] == noise)
            seeds.push_back(l);
    }
    ++cluster;
  }
  return std::size_t(cluster);
}

template <class NeighborFunction>
std::size_t dbscan(std::size_t n, std::size_t min_points, NeighborFunction neighbors,
                   std::vector<int>& labels)
{
  Dbscan_buffers buffers;
  return dbscan(n, min_points, neighbors, labels, buffers);
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_DBSCAN_H
