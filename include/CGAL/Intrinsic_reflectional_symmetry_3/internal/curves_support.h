// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_SUPPORT_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_SUPPORT_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/voting_common.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

/// The local symmetry support of Alg. 2 at the vertices `at`, voted by the
/// pairs `pairs` (p, q samples, already past the four filters):
/// mu(m') = sum of exp(-d(p,m')^2 / sigma^2) over the pairs with
/// d(p,m') ~ d(q,m'). The same tolerance, weight and summation order (pairs
/// in the given order) as the voting, so with a voting pair's eligible pairs
/// it reproduces the voting's mu exactly.
inline void support_at(const Geodesic_distance_matrix& D, const Distance_tolerance& tol, double inv_sigma2,
                       const std::vector<std::pair<std::size_t, std::size_t>>& pairs,
                       const std::vector<std::size_t>& at, std::vector<double>& mu)
{
  mu.assign(at.size(), 0.);
  for(const auto& pq : pairs)
  {
    const float* rp = D.row(pq.first);
    const float* rq = D.row(pq.second);
    for(std::size_t i = 0; i < at.size(); ++i)
    {
      const float dp = rp[at[i]], dq = rq[at[i]];
      if(tol(dp, dq))
        mu[i] += gaussian_weight(dp, inv_sigma2);
    }
  }
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_SUPPORT_H
