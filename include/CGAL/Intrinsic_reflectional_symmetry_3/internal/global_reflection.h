// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_GLOBAL_REFLECTION_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_GLOBAL_REFLECTION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_mesh.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/symmetric_map_spectral.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

// The whole shape's intrinsic reflection, found from the spectrum alone: an
// intrinsic symmetry maps each simple Laplace eigenfunction to +-itself
// (Ovsjanikov, Sun, Guibas 2008), so its functional map on the first ones is
// diagonal with entries +-1. Each sign pattern of the first
// `global_reflection_flipped_functions` non-constant functions starts a
// ZoomOut (Melzi et al. 2019, zoomout() of symmetric_map_spectral.h) on the
// samples; the pattern kept is the one whose map is a symmetry: it moves
// (nearly) every sample off itself, and its functional map stays closest to
// diagonal at the last size (an isometry's map commutes with the Laplacian).
// Why: on posed humans (SCAPE mesh016, 044, 064) the curves of the voting
// miss the left-right axis at every seed, because the bent limbs make other
// local reflections as well supported; the spectrum sees the shape whole.
// The IRSA pipeline then votes again with only the sample pairs that this
// map swaps (pairs_consistent_with_map() of symmetric_map.h), so that the
// curves, regions and map come from the paper's stages as before.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

/// the non-constant eigenfunctions whose signs are tried (2^6 - 1 patterns:
/// the identity's is left out)
constexpr std::size_t global_reflection_flipped_functions = 6;

/// the eigenfunctions of the last ZoomOut size (the constant one included)
constexpr std::size_t global_reflection_eigenfunctions = 31;

/// a sample whose image lies within this share of sqrt(area) of itself is
/// held in place (as in fixed_point_share())
constexpr double global_reflection_near_itself = 0.03;

/// the largest share of samples held in place for a symmetry (as
/// suspect_fixed_point_share)
constexpr double global_reflection_max_fixed_share = 0.1;

struct Global_reflection
{
  bool found = false;
  std::vector<std::size_t> partner;  // by vertex index; Curves_mesh::none off the spectrum's rows
  unsigned pattern = 0;              // bit i set: eigenfunction i + 1 changes sign
  double fixed_share = 0.;           // of the samples
  double off_diagonal_share = 0.;    // of the last functional map's squared norm
};

/// The global reflection of `m` (see above), iterating on the vertices
/// `sample_vertices` (at least 2 `global_reflection_eigenfunctions` of them
/// on faces, spread evenly: farthest-point samples). Not found (`found`
/// false, no partners) where the spectrum cannot be computed or no pattern's
/// map is a symmetry. Deterministic: a fixed solver start and exact nearest
/// rows (nearest_rows()).
template <class ConcurrencyTag>
Global_reflection global_reflection(const Curves_mesh& m, const std::vector<std::size_t>& sample_vertices)
{
  Global_reflection out;
  const std::size_t none = Curves_mesh::none;
  Region_spectrum spectrum;
  if(!region_spectrum(m, std::vector<unsigned char>(m.number_of_vertices, 1), global_reflection_eigenfunctions,
                      spectrum, global_reflection_flipped_functions + 2))
    return out;
  const std::size_t k = std::size_t(spectrum.basis.cols());
  std::vector<std::size_t> row_of(m.number_of_vertices, none);
  for(std::size_t r = 0; r < spectrum.rows.size(); ++r) row_of[spectrum.rows[r]] = r;

  // the spectrum on the samples alone: ZoomOut's iterations need no more
  Region_spectrum on_samples;
  for(std::size_t v : sample_vertices)
    if(v < m.number_of_vertices && row_of[v] != none) on_samples.rows.push_back(row_of[v]);
  std::sort(on_samples.rows.begin(), on_samples.rows.end());
  on_samples.rows.erase(std::unique(on_samples.rows.begin(), on_samples.rows.end()), on_samples.rows.end());
  const std::size_t ns = on_samples.rows.size();
  if(ns < 2 * k) return out;
  on_samples.basis.resize(Eigen::Index(ns), Eigen::Index(k));
  for(std::size_t i = 0; i < ns; ++i) on_samples.basis.row(Eigen::Index(i)) = spectrum.basis.row(Eigen::Index(on_samples.rows[i]));
  std::vector<std::size_t> all(ns);
  std::iota(all.begin(), all.end(), std::size_t(0));

  const double near_itself = global_reflection_near_itself * std::sqrt(m.area);
  const std::size_t k0 = global_reflection_flipped_functions + 1;
  double best_off_diagonal = std::numeric_limits<double>::infinity();
  Eigen::MatrixXd best_map;
  for(unsigned pattern = 1; pattern < (1u << global_reflection_flipped_functions); ++pattern)
  {
    Eigen::MatrixXd C0 = Eigen::MatrixXd::Identity(Eigen::Index(k0), Eigen::Index(k0));
    for(std::size_t i = 0; i < global_reflection_flipped_functions; ++i)
      if(pattern & (1u << i)) C0(Eigen::Index(i + 1), Eigen::Index(i + 1)) = -1.;
    std::vector<std::size_t> image(ns);
    nearest_rows<ConcurrencyTag>(on_samples.basis.leftCols(Eigen::Index(k0)), C0, all, image);
    Eigen::MatrixXd C;
    zoomout<ConcurrencyTag>(on_samples, k0, k, 3, all, image, nullptr, &C);
    std::size_t fixed = 0;
    for(std::size_t i = 0; i < ns; ++i)
      fixed += m.distance(spectrum.rows[on_samples.rows[i]], spectrum.rows[on_samples.rows[image[i]]]) < near_itself;
    const double fixed_share = double(fixed) / double(ns);
    const double norm = C.squaredNorm();
    const double off_diagonal = norm > 0. ? 1. - C.diagonal().squaredNorm() / norm : 1.;
    if(fixed_share <= global_reflection_max_fixed_share && off_diagonal < best_off_diagonal)
    {
      best_off_diagonal = off_diagonal;
      best_map = C;
      out.pattern = pattern;
      out.fixed_share = fixed_share;
      out.off_diagonal_share = off_diagonal;
    }
  }
  if(best_map.size() == 0) return out;

  // the kept map on every vertex of the spectrum
  const std::size_t n = spectrum.rows.size();
  std::vector<std::size_t> rows(n), image(n);
  std::iota(rows.begin(), rows.end(), std::size_t(0));
  nearest_rows<ConcurrencyTag>(spectrum.basis, best_map, rows, image);
  out.partner.assign(m.number_of_vertices, none);
  for(std::size_t r = 0; r < n; ++r) out.partner[spectrum.rows[r]] = spectrum.rows[image[r]];
  out.found = true;
  return out;
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_GLOBAL_REFLECTION_H
