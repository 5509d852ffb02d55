// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers
//
// Helpers shared by the test programs.

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_TEST_SUPPORT_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_TEST_SUPPORT_H

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/shape_generators.h>
#include <CGAL/Random.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace irs_test {

typedef std::vector<std::pair<std::size_t, std::size_t>> Pairs;

// Similar pairs steered by known mirror maps: {i, j} where j is the sample
// geodesically nearest to the mirror vertex of sample i, for the symmetries
// in `which`; plus each other pair with probability `noise` (seeded).
inline Pairs mirror_similar_pairs(const std::vector<CGAL::Intrinsic_reflectional_symmetry_3::Known_symmetry>& symmetries,
                                  const std::vector<std::size_t>& which,
                                  const CGAL::Intrinsic_reflectional_symmetry_3::Geodesic_distance_matrix& D,
                                  double noise, unsigned int seed)
{
  const std::size_t n = D.number_of_sources();
  std::vector<char> similar(n * n, 0);
  for(std::size_t k : which)
  {
    const auto& mirror = symmetries[k].mirror;
    for(std::size_t i = 0; i < n; ++i)
    {
      if(mirror[D.sources()[i]] < 0) continue;
      const std::size_t mv = std::size_t(mirror[D.sources()[i]]);
      std::size_t best = i;
      float best_d = std::numeric_limits<float>::infinity();
      for(std::size_t j = 0; j < n; ++j)
        if(D(j, mv) < best_d) { best_d = D(j, mv); best = j; }
      if(best != i) similar[(std::min)(i, best) * n + (std::max)(i, best)] = 1;
    }
  }
  CGAL::Random rng(seed);
  Pairs pairs;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j)
      if(similar[i * n + j] || rng.get_double() < noise) pairs.emplace_back(i, j);
  return pairs;
}

// What a `callback` named parameter sees: the advancements it is called with,
// and whether it asks to stop once one reaches `stop_at` (> 1: never). The
// functions serialise the calls, so the vector needs no lock.
struct Recording_callback
{
  std::shared_ptr<std::vector<double>> seen = std::make_shared<std::vector<double>>();
  double stop_at = 2.;
  bool operator()(double x) const
  {
    seen->push_back(x);
    return x < stop_at;
  }
  // called at least once, with non-decreasing values in [0, 1] ending at 1
  void expect_complete() const
  {
    ASSERT_FALSE(seen->empty());
    for(std::size_t i = 0; i < seen->size(); ++i)
    {
      EXPECT_GE((*seen)[i], 0.);
      EXPECT_LE((*seen)[i], 1.);
      if(i > 0) EXPECT_GE((*seen)[i], (*seen)[i - 1]);
    }
    EXPECT_EQ(seen->back(), 1.);
  }
};

template <typename F>
void expect_cancelled(F f, const std::string& function)
{
  try
  {
    f();
    ADD_FAILURE() << function << ": no Operation_cancelled";
  }
  catch(const CGAL::Intrinsic_reflectional_symmetry_3::Operation_cancelled& e)
  {
    EXPECT_NE(std::string(e.what()).find(function), std::string::npos) << e.what();
  }
}

} // namespace irs_test

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_TEST_SUPPORT_H
