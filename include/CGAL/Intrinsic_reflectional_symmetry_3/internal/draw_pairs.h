// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_DRAW_PAIRS_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_DRAW_PAIRS_H

// A seeded draw without replacement, written out (not std::sample, whose
// algorithm, hence its result for a seed, differs between standard libraries).

#include <CGAL/Random.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

/// Indices 0 .. number_of_pairs - 1: all of them, or `cap` of them drawn
/// uniformly without replacement with CGAL::Random(seed) (partial
/// Fisher-Yates), in increasing order (the voting pairs of a capped vote, the
/// similar pairs that `similar_sample_pairs()` keeps).
inline std::vector<std::size_t> draw_pairs(std::size_t number_of_pairs, std::size_t cap, unsigned int seed)
{
  std::vector<std::size_t> idx(number_of_pairs);
  for(std::size_t k = 0; k < number_of_pairs; ++k) idx[k] = k;
  if(cap >= number_of_pairs)
    return idx;
  CGAL::Random rng(seed);
  for(std::size_t k = 0; k < cap; ++k)
  {
    const std::size_t j = rng.uniform_int<std::size_t>(k, number_of_pairs - 1);
    std::swap(idx[k], idx[j]);
  }
  idx.resize(cap);
  std::sort(idx.begin(), idx.end());
  return idx;
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_DRAW_PAIRS_H
