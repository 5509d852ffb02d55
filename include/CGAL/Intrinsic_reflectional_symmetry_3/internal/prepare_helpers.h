// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_PREPARE_HELPERS_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_PREPARE_HELPERS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

// Stops edge collapse on a Surface_mesh at a vertex count: CGAL 5.5's count
// predicates count edges or faces, whose relation to vertices depends on boundaries.
class Prepare_vertex_count_stop_predicate
{
public:
  explicit Prepare_vertex_count_stop_predicate(std::size_t number_of_vertices)
    : number_of_vertices_(number_of_vertices) {}

  template <typename FT, typename Profile>
  bool operator()(const FT& /*current_cost*/, const Profile& profile,
                  std::size_t /*initial_edge_count*/, std::size_t /*current_edge_count*/) const
  {
    // number_of_vertices(), not num_vertices(): the latter counts removed vertices
    return std::size_t(profile.surface_mesh().number_of_vertices()) <= number_of_vertices_;
  }

private:
  std::size_t number_of_vertices_;
};

struct Prepare_fill_outcome
{
  std::size_t filled = 0, left_open = 0;
};

// Fills the boundary cycles of `m` at most `maximum_length` long with CGAL's
// triangulate, refine and fair (PMP::triangulate_refine_and_fair_hole()): new
// vertices and faces come after the existing ones, which keep their indices.
// A cycle whose fairing fails keeps its refined, unfaired patch; one that is
// too long, or that CGAL finds no triangulation for, stays open.
template <typename Mesh>
Prepare_fill_outcome prepare_fill_holes(Mesh& m, double maximum_length)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  std::vector<halfedge_descriptor> cycles;
  PMP::extract_boundary_cycles(m, std::back_inserter(cycles));
  Prepare_fill_outcome outcome;
  for(halfedge_descriptor h : cycles) {
    // filling one cycle leaves the others' halfedges on the border
    if(CGAL::to_double(PMP::face_border_length(h, m)) <= maximum_length)
      PMP::triangulate_refine_and_fair_hole(m, h, CGAL::Emptyset_iterator(), CGAL::Emptyset_iterator());
    ++(is_border(h, m) ? outcome.left_open : outcome.filled);
  }
  return outcome;
}

inline void prepare_check_size(std::size_t given, std::size_t needed, const char* what)
{
  if(given < needed) {
    std::ostringstream os;
    os << given << " " << what << " given, " << needed << " needed";
    throw Input_error(Input_problem::invalid_parameter, os.str());
  }
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_PREPARE_HELPERS_H
