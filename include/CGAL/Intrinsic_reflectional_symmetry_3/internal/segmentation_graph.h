// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SEGMENTATION_GRAPH_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SEGMENTATION_GRAPH_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <queue>
#include <string>
#include <utility>
#include <vector>

// The dual graph of a triangle mesh (faces, their areas, the length of the
// edge each pair of neighbouring faces shares) and the label operations the
// segmentation needs: connected components of equal labels, merging of small
// components into the neighbour they share the longest boundary with, and
// deterministic relabelling. Everything is indexed by face index.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

struct Face_graph
{
  std::size_t number_of_faces = 0;
  std::vector<double> area;                    // by face index
  std::vector<std::size_t> offsets, neighbour; // CSR, neighbours across the face's edges
  std::vector<double> shared_length;           // same layout as `neighbour`
  double total_area = 0.;
};

template <class TriangleMesh, class VertexPointMap, class FaceIndexMap>
Face_graph make_face_graph(const TriangleMesh& tm, VertexPointMap vpm, FaceIndexMap fim)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  if(num_faces(tm) == 0)
    throw Input_error(Input_problem::empty_mesh, "the mesh has no faces");
  Face_graph g;
  g.number_of_faces = std::size_t(num_faces(tm));
  g.area.assign(g.number_of_faces, 0.);
  std::vector<std::vector<std::pair<std::size_t, double>>> adj(g.number_of_faces);
  for(auto f : faces(tm))
  {
    const std::size_t i = std::size_t(get(fim, f));
    if(i >= g.number_of_faces)
      throw Input_error(Input_problem::invalid_parameter, "face index " + std::to_string(i) + " out of range");
    const auto h = halfedge(f, tm);
    if(next(next(next(h, tm), tm), tm) != h)
      throw Input_error(Input_problem::not_triangle_mesh, "face " + std::to_string(i) + " is not a triangle", i);
    const auto& a = get(vpm, source(h, tm));
    const auto& b = get(vpm, target(h, tm));
    const auto& c = get(vpm, target(next(h, tm), tm));
    g.area[i] = std::sqrt(CGAL::to_double(CGAL::squared_area(a, b, c)));
    for(auto e : halfedges_around_face(h, tm))
    {
      const auto o = face(opposite(e, tm), tm);
      if(o == GT::null_face()) continue;
      const double len = std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(e, tm)),
                                                                          get(vpm, target(e, tm)))));
      adj[i].emplace_back(std::size_t(get(fim, o)), len);
    }
  }
  g.offsets.assign(g.number_of_faces + 1, 0);
  for(std::size_t i = 0; i < g.number_of_faces; ++i)
  {
    std::sort(adj[i].begin(), adj[i].end());
    g.offsets[i + 1] = g.offsets[i] + adj[i].size();
    for(const auto& nl : adj[i]) { g.neighbour.push_back(nl.first); g.shared_length.push_back(nl.second); }
    g.total_area += g.area[i];
  }
  return g;
}

// Connected components of the faces with equal labels (labels are any
// integers, -1 included). Components are numbered in the order of their
// smallest face index. Returns the number of components.
template <class Label>
std::size_t label_components(const Face_graph& g, const std::vector<Label>& label, std::vector<std::size_t>& comp)
{
  const std::size_t none = std::size_t(-1);
  comp.assign(g.number_of_faces, none);
  std::size_t n = 0;
  std::vector<std::size_t> stack;
  for(std::size_t s = 0; s < g.number_of_faces; ++s)
  {
    if(comp[s] != none) continue;
    comp[s] = n;
    stack.assign(1, s);
    while(!stack.empty())
    {
      const std::size_t f = stack.back();
      stack.pop_back();
      for(std::size_t k = g.offsets[f]; k < g.offsets[f + 1]; ++k)
      {
        const std::size_t o = g.neighbour[k];
        if(comp[o] == none && label[o] == label[s]) { comp[o] = n; stack.push_back(o); }
      }
    }
    ++n;
  }
  return n;
}

// Renumbers labels 0..n-1 in the order of their smallest face index; returns n.
template <class Label>
std::size_t compact_labels(std::vector<Label>& label)
{
  std::map<Label, Label> to;
  for(Label& l : label)
  {
    const auto it = to.emplace(l, Label(to.size())).first;
    l = it->second;
  }
  return to.size();
}

// Merges components into neighbours, smallest first, while the smallest
// mergeable one has less than `minimum_area` or there are more than
// `maximum_count` components. A component goes to the neighbour it shares
// the longest boundary with (ties: the smaller component id). Components
// without neighbours (a whole connected component of the mesh) stay.
// `comp` (values < n) is rewritten with the surviving ids, then compacted.
// The result depends only on the input (no hashing, deterministic ties).
// `must_merge` (optional, by component): components merged whatever their area.
inline std::size_t merge_small_components(const Face_graph& g, std::vector<std::size_t>& comp, std::size_t n,
                                          double minimum_area, std::size_t maximum_count,
                                          const std::vector<char>* must_merge = nullptr)
{
  if(n == 0) return 0;
  std::vector<double> area(n, 0.);
  std::vector<std::map<std::size_t, double>> adj(n);
  for(std::size_t f = 0; f < g.number_of_faces; ++f)
  {
    area[comp[f]] += g.area[f];
    for(std::size_t k = g.offsets[f]; k < g.offsets[f + 1]; ++k)
    {
      const std::size_t o = g.neighbour[k];
      if(comp[o] != comp[f]) adj[comp[f]][comp[o]] += g.shared_length[k];
    }
  }
  std::vector<std::size_t> parent(n);
  for(std::size_t i = 0; i < n; ++i) parent[i] = i;
  std::vector<char> alive(n, 1);
  std::size_t count = n;
  // forced components first (key -1), then by increasing area
  std::vector<char> forced(n, 0);
  if(must_merge != nullptr) forced = *must_merge;
  auto key = [&](std::size_t i) { return forced[i] ? -1. : area[i]; };
  typedef std::pair<double, std::size_t> Entry; // (key at push time, component)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for(std::size_t i = 0; i < n; ++i) queue.emplace(key(i), i);
  while(!queue.empty())
  {
    const Entry top = queue.top();
    queue.pop();
    const std::size_t c = top.second;
    if(!alive[c] || top.first != key(c)) continue; // stale entry
    if(!(forced[c] || area[c] < minimum_area || count > maximum_count)) break;
    if(adj[c].empty()) continue; // nothing to merge into: stays as it is
    std::size_t best = c;
    double best_len = -1.;
    for(const auto& nl : adj[c]) // prefer a neighbour that stays
      if(std::make_pair(!forced[nl.first], nl.second) > std::make_pair(best_len >= 0. && !forced[best], best_len))
      { best_len = nl.second; best = nl.first; }
    // merge c into best
    alive[c] = 0;
    parent[c] = best;
    area[best] += area[c];
    for(const auto& nl : adj[c])
    {
      if(nl.first == best) continue;
      adj[best][nl.first] += nl.second;
      auto& back = adj[nl.first];
      back.erase(c);
      back[best] += nl.second;
    }
    adj[best].erase(c);
    adj[c].clear();
    --count;
    queue.emplace(key(best), best);
  }
  auto find = [&](std::size_t i) { while(parent[i] != i) i = parent[i]; return i; };
  for(std::size_t& c : comp) c = find(c);
  return compact_labels(comp);
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SEGMENTATION_GRAPH_H
