// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_PERTURBED_COPIES_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_PERTURBED_COPIES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/number_type_config.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

// The perturbations of the robustness study (paper Fig. 10-11): vertex noise
// and small holes, seeded. Shared by test_voting and voting_benchmark. No API
// promise.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

// A copy of `m` with Gaussian noise on every vertex: isotropic, per-axis
// standard deviation s such that the mean displacement s * sqrt(8 / pi) is
// `level` mean edge lengths (the paper's noise level). Box-Muller on
// CGAL::Random, so the noise only depends on the seed.
template <typename Point>
CGAL::Surface_mesh<Point> noisy_copy(const CGAL::Surface_mesh<Point>& m, double level, double mean_edge_length, unsigned int seed)
{
  CGAL::Surface_mesh<Point> out = m;
  CGAL::Random rng(seed);
  const double s = level * mean_edge_length / std::sqrt(8. / CGAL_PI);
  auto gauss = [&] {
    double u = rng.get_double();
    while(u <= 0.) u = rng.get_double();
    return std::sqrt(-2. * std::log(u)) * std::cos(2. * CGAL_PI * rng.get_double());
  };
  for(auto v : out.vertices())
  {
    const Point p = out.point(v);
    const double dx = gauss(), dy = gauss(), dz = gauss();
    out.point(v) = Point(p.x() + s * dx, p.y() + s * dy, p.z() + s * dz);
  }
  return out;
}

// A copy of `m` with about `fraction` of its faces removed as `holes` small
// holes: each hole is the set of faces incident to a ball of vertices grown
// breadth-first from a random vertex, and holes stay at least two rings
// apart. `map` receives the new index of each old vertex (-1: removed).
// Returns false if a face could not be re-added, or if the result has a
// non-manifold vertex (a ball that is no disk pinches one: FAUST tr_reg_006,
// 8 holes, seed 11) or more connected components than `m` (a ball around a
// thin part cuts it off: tr_reg_005, same holes). The study is of small
// holes, so the caller tries another seed (holed_copy_from_seed()).
template <typename Point>
bool holed_copy(const CGAL::Surface_mesh<Point>& m, double fraction, std::size_t holes, unsigned int seed,
                CGAL::Surface_mesh<Point>& out, std::vector<std::ptrdiff_t>& map)
{
  typedef CGAL::Surface_mesh<Point> Surface_mesh_t;
  typedef typename Surface_mesh_t::Vertex_index Vertex;
  typedef typename Surface_mesh_t::size_type Size;
  const std::size_t nv = num_vertices(m), nf = num_faces(m);
  std::vector<char> removed_face(nf, 0), blocked(nv, 0), in_ball(nv, 0);
  CGAL::Random rng(seed);
  const std::size_t per_hole = (std::max)(std::size_t(1), std::size_t(fraction * double(nf) / double(holes)));
  for(std::size_t h = 0; h < holes; ++h)
  {
    Vertex c;
    for(int attempt = 0;; ++attempt)
    {
      c = Vertex(Size(rng.uniform_int<std::size_t>(0, nv - 1)));
      if(!blocked[c.idx()] && !m.is_border(c)) break;
      if(attempt > 1000) return false;
    }
    std::vector<Vertex> ball(1, c), queue(1, c);
    in_ball[c.idx()] = 1;
    std::size_t count = 0;
    auto add_faces = [&](Vertex v) {
      for(auto f : CGAL::faces_around_target(m.halfedge(v), m))
        if(f != Surface_mesh_t::null_face() && !removed_face[f.idx()]) { removed_face[f.idx()] = 1; ++count; }
    };
    add_faces(c);
    for(std::size_t q = 0; q < queue.size() && count < per_hole; ++q)
      for(auto u : CGAL::vertices_around_target(m.halfedge(queue[q]), m))
      {
        if(count >= per_hole) break;
        if(in_ball[u.idx()] || blocked[u.idx()]) continue;
        in_ball[u.idx()] = 1;
        ball.push_back(u);
        queue.push_back(u);
        add_faces(u);
      }
    // block the ball and two rings around it
    std::vector<Vertex> ring = ball;
    for(int r = 0; r < 3; ++r)
    {
      std::vector<Vertex> next;
      for(auto v : ring)
      {
        if(blocked[v.idx()] == 1) continue;
        blocked[v.idx()] = 1;
        for(auto u : CGAL::vertices_around_target(m.halfedge(v), m)) next.push_back(u);
      }
      ring.swap(next);
    }
    for(auto v : ring) blocked[v.idx()] = 1;
  }
  out.clear();
  map.assign(nv, -1);
  for(auto f : m.faces())
    if(!removed_face[f.idx()])
      for(auto v : CGAL::vertices_around_face(m.halfedge(f), m)) map[v.idx()] = 0;
  for(std::size_t v = 0; v < nv; ++v)
    if(map[v] == 0) map[v] = std::ptrdiff_t(out.add_vertex(m.point(Vertex(Size(v)))).idx());
  for(auto f : m.faces())
  {
    if(removed_face[f.idx()]) continue;
    std::vector<Vertex> vs;
    for(auto v : CGAL::vertices_around_face(m.halfedge(f), m))
      vs.push_back(Vertex(Size(map[v.idx()])));
    if(out.add_face(vs) == Surface_mesh_t::null_face()) return false;
  }
  std::vector<typename Surface_mesh_t::Halfedge_index> pinched;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(out, std::back_inserter(pinched));
  if(!pinched.empty()) return false;
  auto component_in = get(CGAL::dynamic_face_property_t<std::size_t>(), m);
  auto component_out = get(CGAL::dynamic_face_property_t<std::size_t>(), out);
  return CGAL::Polygon_mesh_processing::connected_components(out, component_out) ==
         CGAL::Polygon_mesh_processing::connected_components(m, component_in);
}

// The robustness studies' holes: the first seed tried, and how many seeds
// holed_copy_from_seed() tries from it.
constexpr unsigned int first_hole_seed = 11u, number_of_hole_seeds = 10u;

// holed_copy() with `seed`, or else with the next of up to `seeds` seeds
// (those holes would pinch a vertex or cut off a part); `seed` receives the
// seed used. False if none succeeds.
template <typename Point>
bool holed_copy_from_seed(const CGAL::Surface_mesh<Point>& m, double fraction, std::size_t holes, unsigned int& seed,
                          unsigned int seeds, CGAL::Surface_mesh<Point>& out, std::vector<std::ptrdiff_t>& map)
{
  for(unsigned int k = 0; k < seeds; ++k, ++seed)
    if(holed_copy(m, fraction, holes, seed, out, map)) return true;
  return false;
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_PERTURBED_COPIES_H
