// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_PREPARE_HELPERS_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_PREPARE_HELPERS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>

#include <CGAL/Polygon_mesh_processing/border.h>
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

// Fills every boundary cycle of `m` with CGAL's triangulate, refine and fair
// (PMP::triangulate_refine_and_fair_hole()): new vertices and faces come after
// the existing ones, which keep their indices. Returns the number of cycles
// filled; a cycle whose fairing fails keeps its refined, unfaired patch, and
// one CGAL finds no triangulation for stays open (and is not counted).
template <typename Mesh>
std::size_t prepare_fill_holes(Mesh& m)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  std::vector<halfedge_descriptor> cycles;
  PMP::extract_boundary_cycles(m, std::back_inserter(cycles));
  std::size_t filled = 0;
  for(halfedge_descriptor h : cycles) {
    PMP::triangulate_refine_and_fair_hole(m, h, CGAL::Emptyset_iterator(), CGAL::Emptyset_iterator());
    filled += !is_border(h, m);
  }
  return filled;
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
