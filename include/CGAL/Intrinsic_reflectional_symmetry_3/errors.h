// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_ERRORS_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_ERRORS_H

#include <CGAL/disable_warnings.h>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The kinds of bad input the package reports.
enum class Input_problem
{
  unreadable_file,        ///< the file cannot be opened or parsed
  empty_mesh,             ///< no vertices or no faces
  not_triangle_mesh,      ///< a face is not a triangle
  non_manifold_vertex,    ///< the faces around a vertex form more than one fan
  non_manifold_edge,      ///< an edge is shared by more than two faces
  non_finite_coordinate,  ///< a coordinate is NaN or infinite
  degenerate_face,        ///< a face has (near) zero area or repeated vertices
  isolated_vertex,        ///< a vertex belongs to no face
  too_many_samples,       ///< more samples requested than the mesh has vertices
  invalid_parameter       ///< a named parameter is out of its range
};

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Human-readable name of a problem.
inline const char* to_string(Input_problem p)
{
  switch(p) {
    case Input_problem::unreadable_file:       return "unreadable file";
    case Input_problem::empty_mesh:            return "empty mesh";
    case Input_problem::not_triangle_mesh:     return "not a triangle mesh";
    case Input_problem::non_manifold_vertex:   return "non-manifold vertex";
    case Input_problem::non_manifold_edge:     return "non-manifold edge";
    case Input_problem::non_finite_coordinate: return "non-finite coordinate";
    case Input_problem::degenerate_face:       return "degenerate face";
    case Input_problem::isolated_vertex:       return "isolated vertex";
    case Input_problem::too_many_samples:      return "too many samples";
    case Input_problem::invalid_parameter:     return "invalid parameter";
  }
  return "unknown problem";
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The exception every function of the package throws on bad input.
/// `what()` names the problem and the first offending element; `problem()`
/// and `element()` give the same information to programs.
class Input_error : public std::runtime_error
{
public:
  /// `element` is the index of the first offending vertex, face or edge
  /// (in the order of the mesh's index maps, or of the file), or `no_element`.
  Input_error(Input_problem problem, const std::string& message,
              std::size_t element = no_element)
    : std::runtime_error(std::string(to_string(problem)) + ": " + message),
      problem_(problem), element_(element)
  {}

  static constexpr std::size_t no_element = std::size_t(-1);

  Input_problem problem() const { return problem_; }
  std::size_t element() const { return element_; }

private:
  Input_problem problem_;
  std::size_t element_;
};

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// What a function of the package throws when its `callback` named parameter
/// returns false: the computation stops there and returns nothing. `what()`
/// names the function that stopped.
class Operation_cancelled : public std::runtime_error
{
public:
  explicit Operation_cancelled(const std::string& message) : std::runtime_error(message) {}
};

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_ERRORS_H
