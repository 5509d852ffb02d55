// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_MESH_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_MESH_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

// The mesh as flat arrays indexed like the distance matrix (vertex index map,
// face index map): what curve extraction, region growing and the symmetric
// map read in their loops. Built once per call from the BGL interface.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

struct Curves_mesh
{
  std::size_t number_of_vertices = 0;
  std::vector<std::array<double, 3>> points;           // by vertex index
  std::vector<std::array<std::size_t, 3>> faces;       // vertex indices, by face index
  std::vector<std::array<std::size_t, 3>> face_edges;  // edge k joins corners k and k+1
  std::vector<std::pair<std::size_t, std::size_t>> edges;      // u < v, sorted
  std::vector<std::array<std::size_t, 2>> edge_faces;  // -1 where missing (border)
  std::vector<double> edge_length;
  // vertex adjacency (CSR): neighbour and edge id, neighbours increasing
  std::vector<std::size_t> adjacency_offsets, adjacency, adjacency_edge;
  // faces around each vertex (CSR), increasing
  std::vector<std::size_t> vertex_face_offsets, vertex_faces;
  double mean_edge_length = 0.;
  double area = 0.;

  static constexpr std::size_t none = std::size_t(-1);

  double distance(std::size_t u, std::size_t v) const
  {
    const auto& p = points[u];
    const auto& q = points[v];
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  }

  std::size_t edge_between(std::size_t u, std::size_t v) const
  {
    const auto first = adjacency.begin() + std::ptrdiff_t(adjacency_offsets[u]);
    const auto last = adjacency.begin() + std::ptrdiff_t(adjacency_offsets[u + 1]);
    const auto it = std::lower_bound(first, last, v);
    if(it == last || *it != v) return none;
    return adjacency_edge[std::size_t(it - adjacency.begin())];
  }
};

inline double triangle_area(const Curves_mesh& m, const std::array<std::size_t, 3>& f)
{
  const auto& a = m.points[f[0]];
  const auto& b = m.points[f[1]];
  const auto& c = m.points[f[2]];
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

template <class TriangleMesh, class NamedParameters>
Curves_mesh make_curves_mesh(const TriangleMesh& tm, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);

  Curves_mesh m;
  m.number_of_vertices = std::size_t(num_vertices(tm));
  const std::size_t nf = std::size_t(num_faces(tm));
  m.points.assign(m.number_of_vertices, {{0., 0., 0.}});
  for(auto v : vertices(tm))
  {
    const std::size_t i = std::size_t(get(vim, v));
    if(i >= m.number_of_vertices)
      throw Input_error(Input_problem::invalid_parameter, "vertex index " + std::to_string(i) + " out of range");
    const auto& p = get(vpm, v);
    m.points[i] = {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  }
  m.faces.assign(nf, {{0, 0, 0}});
  for(auto f : faces(tm))
  {
    const std::size_t i = std::size_t(get(fim, f));
    if(i >= nf)
      throw Input_error(Input_problem::invalid_parameter, "face index " + std::to_string(i) + " out of range");
    auto h = halfedge(f, tm);
    if(next(next(next(h, tm), tm), tm) != h)
      throw Input_error(Input_problem::not_triangle_mesh, "face " + std::to_string(i) + " is not a triangle", i);
    for(int k = 0; k < 3; ++k, h = next(h, tm))
      m.faces[i][k] = std::size_t(get(vim, target(h, tm)));
  }

  // edges from the faces: (u, v, face) sorted, then grouped
  std::vector<std::array<std::size_t, 4>> half; // u, v, face, corner
  half.reserve(3 * nf);
  for(std::size_t f = 0; f < nf; ++f)
    for(std::size_t k = 0; k < 3; ++k)
    {
      std::size_t u = m.faces[f][k], v = m.faces[f][(k + 1) % 3];
      if(v < u) std::swap(u, v);
      half.push_back({{u, v, f, k}});
    }
  std::sort(half.begin(), half.end());
  m.face_edges.assign(nf, {{Curves_mesh::none, Curves_mesh::none, Curves_mesh::none}});
  double total = 0.;
  for(std::size_t i = 0; i < half.size();)
  {
    std::size_t j = i;
    const std::size_t e = m.edges.size();
    m.edges.emplace_back(half[i][0], half[i][1]);
    std::array<std::size_t, 2> ef = {{Curves_mesh::none, Curves_mesh::none}};
    for(; j < half.size() && half[j][0] == half[i][0] && half[j][1] == half[i][1]; ++j)
    {
      if(j - i < 2) ef[j - i] = half[j][2];
      m.face_edges[half[j][2]][half[j][3]] = e;
    }
    m.edge_faces.push_back(ef);
    m.edge_length.push_back(m.distance(half[i][0], half[i][1]));
    total += m.edge_length.back();
    i = j;
  }
  if(!m.edges.empty()) m.mean_edge_length = total / double(m.edges.size());

  std::vector<std::size_t> degree(m.number_of_vertices + 1, 0);
  for(const auto& e : m.edges) { ++degree[e.first + 1]; ++degree[e.second + 1]; }
  m.adjacency_offsets.assign(m.number_of_vertices + 1, 0);
  for(std::size_t v = 0; v < m.number_of_vertices; ++v)
    m.adjacency_offsets[v + 1] = m.adjacency_offsets[v] + degree[v + 1];
  m.adjacency.resize(m.adjacency_offsets.back());
  m.adjacency_edge.resize(m.adjacency_offsets.back());
  {
    std::vector<std::size_t> fill(m.adjacency_offsets.begin(), m.adjacency_offsets.end() - 1);
    // edges sorted by (u, v): u's list gets v in increasing order; v's list
    // gets u in increasing order too (u increases along the sorted list)
    for(std::size_t e = 0; e < m.edges.size(); ++e)
    {
      const std::size_t u = m.edges[e].first, v = m.edges[e].second;
      m.adjacency[fill[u]] = v; m.adjacency_edge[fill[u]++] = e;
      m.adjacency[fill[v]] = u; m.adjacency_edge[fill[v]++] = e;
    }
    for(std::size_t v = 0; v < m.number_of_vertices; ++v)
    {
      // sort by neighbour, keeping edge ids attached
      std::vector<std::pair<std::size_t, std::size_t>> l;
      for(std::size_t k = m.adjacency_offsets[v]; k < m.adjacency_offsets[v + 1]; ++k)
        l.emplace_back(m.adjacency[k], m.adjacency_edge[k]);
      std::sort(l.begin(), l.end());
      for(std::size_t k = 0; k < l.size(); ++k)
      {
        m.adjacency[m.adjacency_offsets[v] + k] = l[k].first;
        m.adjacency_edge[m.adjacency_offsets[v] + k] = l[k].second;
      }
    }
  }

  std::fill(degree.begin(), degree.end(), 0);
  for(const auto& f : m.faces) for(std::size_t v : f) ++degree[v + 1];
  m.vertex_face_offsets.assign(m.number_of_vertices + 1, 0);
  for(std::size_t v = 0; v < m.number_of_vertices; ++v)
    m.vertex_face_offsets[v + 1] = m.vertex_face_offsets[v] + degree[v + 1];
  m.vertex_faces.resize(m.vertex_face_offsets.back());
  {
    std::vector<std::size_t> fill(m.vertex_face_offsets.begin(), m.vertex_face_offsets.end() - 1);
    for(std::size_t f = 0; f < nf; ++f)
      for(std::size_t v : m.faces[f]) m.vertex_faces[fill[v]++] = f; // f increasing
  }

  for(const auto& f : m.faces) m.area += triangle_area(m, f);
  return m;
}

/// Multi-source Dijkstra along the mesh edges (Euclidean edge lengths).
/// Written by hand rather than with Boost: it runs many times per call on
/// small neighbourhoods, stops at `cutoff`, and only touches the vertices it
/// reaches (a stamp marks them), so its cost is proportional to the area it
/// covers. Results are read with `distance(v)` (+inf where not reached).
class Edge_dijkstra
{
public:
  explicit Edge_dijkstra(const Curves_mesh& m)
    : m_(m), dist_(m.number_of_vertices, std::numeric_limits<double>::infinity()),
      stamp_(m.number_of_vertices, 0), source_(m.number_of_vertices, Curves_mesh::none),
      parent_(m.number_of_vertices, Curves_mesh::none)
  {}

  /// distances from the `sources` (vertex indices, each with an initial
  /// distance) up to `cutoff`; the vertices reached, in order of settling,
  /// are returned by `reached()`
  template <class SourceRange>
  void run(const SourceRange& sources, double cutoff = std::numeric_limits<double>::infinity())
  {
    next_stamp();
    reached_.clear();
    typedef std::pair<double, std::size_t> Entry;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for(const auto& s : sources)
    {
      const std::size_t v = s.first;
      const double d0 = s.second;
      if(d0 > cutoff) continue;
      if(stamp_[v] != stamp_value_ || d0 < dist_[v])
      {
        stamp_[v] = stamp_value_;
        dist_[v] = d0;
        source_[v] = v;
        parent_[v] = Curves_mesh::none;
        queue.push(Entry(d0, v));
      }
    }
    while(!queue.empty())
    {
      const Entry top = queue.top();
      queue.pop();
      const std::size_t v = top.second;
      if(top.first > dist_[v]) continue; // stale
      reached_.push_back(v);
      for(std::size_t k = m_.adjacency_offsets[v]; k < m_.adjacency_offsets[v + 1]; ++k)
      {
        const std::size_t w = m_.adjacency[k];
        const double d = top.first + m_.edge_length[m_.adjacency_edge[k]];
        if(d > cutoff) continue;
        if(stamp_[w] != stamp_value_ || d < dist_[w])
        {
          stamp_[w] = stamp_value_;
          dist_[w] = d;
          source_[w] = source_[v];
          parent_[w] = v;
          queue.push(Entry(d, w));
        }
      }
    }
  }

  double distance(std::size_t v) const
  {
    return stamp_[v] == stamp_value_ ? dist_[v] : std::numeric_limits<double>::infinity();
  }
  /// the source whose shortest path reaches `v` (none if not reached)
  std::size_t source(std::size_t v) const { return stamp_[v] == stamp_value_ ? source_[v] : Curves_mesh::none; }
  std::size_t parent(std::size_t v) const { return stamp_[v] == stamp_value_ ? parent_[v] : Curves_mesh::none; }
  const std::vector<std::size_t>& reached() const { return reached_; }

private:
  void next_stamp()
  {
    if(++stamp_value_ == 0)
    {
      std::fill(stamp_.begin(), stamp_.end(), 0u);
      stamp_value_ = 1;
    }
  }

  const Curves_mesh& m_;
  std::vector<double> dist_;
  std::vector<unsigned> stamp_;
  std::vector<std::size_t> source_, parent_;
  std::vector<std::size_t> reached_;
  unsigned stamp_value_ = 0;
};

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_MESH_H
