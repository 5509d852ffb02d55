// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_REPAIR_PROTOCOL_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_REPAIR_PROTOCOL_H

#include <CGAL/disable_warnings.h>

// The damage step of the part-repair protocol (part_repair.h): a limb is cut
// off by a plane and the cut is capped. No API promise.

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/repair_mesh.h>

#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/linear_least_squares_fitting_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

/// The vertices a plane cut removes: the plane is fitted to the vertices at
/// geodesic (edge-graph) distance `length` from `tip` (within one mean edge
/// length), oriented towards the tip; the removed part is the connected set of
/// vertices on the tip's side of the plane that contains the tip.
inline std::vector<std::size_t> limb_vertices(const Repair_soup& s, const std::vector<std::vector<std::size_t> >& nb,
                                              std::size_t tip, double length, double mean_edge)
{
  const std::vector<double> d = soup_dijkstra(s, nb, {tip});
  std::vector<Repair_point> ring;
  for(std::size_t v = 0; v < d.size(); ++v)
    if(std::abs(d[v] - length) <= mean_edge) ring.push_back(s.points[v]);
  if(ring.size() < 3)
    throw Input_error(Input_problem::invalid_parameter,
                      "limb cut: no vertex at geodesic distance " + std::to_string(length) + " from the tip", tip);
  Repair_plane plane;
  Repair_point centroid;
  CGAL::linear_least_squares_fitting_3(ring.begin(), ring.end(), plane, centroid, CGAL::Dimension_tag<0>(),
                                       Repair_kernel(), CGAL::Default_diagonalize_traits<double, 3>());
  Repair_vector n = plane.orthogonal_vector();
  n = n / std::sqrt(n.squared_length());
  if((s.points[tip] - centroid) * n < 0.) n = -n;
  std::vector<char> side(s.points.size(), 0);
  for(std::size_t v = 0; v < s.points.size(); ++v) side[v] = ((s.points[v] - centroid) * n > 0.);
  if(!side[tip])
    throw Input_error(Input_problem::invalid_parameter, "limb cut: the tip is not beyond the cut plane", tip);
  std::vector<std::ptrdiff_t> label;
  label_components(nb, side, label);
  std::vector<std::size_t> out;
  for(std::size_t v = 0; v < s.points.size(); ++v)
    if(label[v] == label[tip]) out.push_back(v);
  return out;
}

/// Removes the triangles touching `removed` and fills every border loop with
/// `triangulate_refine_and_fair_hole()`; throws if the result is not closed.
template <typename TriangleMesh>
void cut_and_cap(const Repair_soup& s, const std::vector<char>& removed, TriangleMesh& out)
{
  Repair_soup kept;
  kept.points = s.points;
  for(const Repair_triangle& t : s.triangles)
    if(!removed[t[0]] && !removed[t[1]] && !removed[t[2]]) kept.triangles.push_back(t);
  const Repair_soup compacted = compact_soup(kept);
  Repair_surface m;
  std::string defect;
  // a faired cap first; a flat one if the faired cap bulges into the surface
  for(int fair = 1; fair >= 0; --fair)
  {
    m = soup_to_surface(compacted);
    std::vector<Repair_surface::Halfedge_index> borders;
    CGAL::Polygon_mesh_processing::extract_boundary_cycles(m, std::back_inserter(borders));
    for(Repair_surface::Halfedge_index h : borders)
    {
      std::vector<Repair_surface::Face_index> fs;
      std::vector<Repair_surface::Vertex_index> vs;
      if(fair)
        CGAL::Polygon_mesh_processing::triangulate_refine_and_fair_hole(m, h, std::back_inserter(fs), std::back_inserter(vs));
      else
        CGAL::Polygon_mesh_processing::triangulate_and_refine_hole(m, h, std::back_inserter(fs), std::back_inserter(vs));
    }
    m.collect_garbage();
    defect = mesh_defect(m);
    const std::size_t first_cap_face = compacted.triangles.size();
    if(defect.empty() &&
       self_intersects_new(m, [first_cap_face](Repair_surface::Face_index f) { return std::size_t(f) >= first_cap_face; }))
      defect = "self-intersecting";
    if(defect.empty()) break;
  }
  if(!defect.empty())
    throw Input_error(Input_problem::invalid_parameter, "limb cut: the capped mesh is " + defect);
  Repair_soup r;
  r.points.assign(m.points().begin(), m.points().end());
  for(auto f : faces(m))
  {
    Repair_triangle t;
    int i = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) t[std::size_t(i++)] = std::size_t(v);
    r.triangles.push_back(t);
  }
  repair_soup_to_mesh(r, out, "limb cut");
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_REPAIR_PROTOCOL_H
