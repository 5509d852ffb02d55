// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_REFERENCE_VOTING_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_REFERENCE_VOTING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_transform.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/dbscan.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/voting_common.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

// The literal reference of the paper's Alg. 1 and 2, written for clarity and
// not for speed (O(voting pairs x |beta| x similar pairs)): it is the oracle
// the fast voting of irsa_transform.h is tested against. The loops are the
// pseudocode's: for each voting pair {a,b}, for each m' in beta(a,b), for each
// similar pair {p,q}, the filters in order. As Sec. 3.5 says, the locality
// (DBSCAN) and axial-sym filters do not depend on m' and are computed once per
// {a,b}, the first time a pair reaches them, and cached.
//
// It shares with the fast code only the definitions in voting_common.h
// (equality test, Gaussian, bisector rule, input checks) and the DBSCAN
// routine, called here with brute-force neighbour queries.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

class Reference_voting
{
public:
  explicit Reference_voting(const Voting_setup& s) : s_(s) {}

  // Alg. 1. `tau` is indexed by vertex index.
  Irsa_voting_result run(std::vector<double>& tau) const
  {
    Irsa_voting_result result;
    fill_result_header(s_, result);
    const Geodesic_distance_matrix& D = *s_.D;
    const Sample_distance_matrix& dss = s_.dss;
    const auto& pairs = s_.similar_pairs;
    const Distance_tolerance& tol = s_.settings.tolerance;
    tau.assign(s_.mesh.number_of_vertices, 0.);

    for(std::size_t voting_index : s_.voting_pairs) // pairs that passed the similarity filter
    {
      const std::size_t a = pairs[voting_index].first, b = pairs[voting_index].second;
      if(!std::isfinite(dss(a, b))) { ++result.number_of_disconnected_pairs; continue; }

      Irsa_voting_pair record;
      record.a = a;
      record.b = b;
      record.boundary = boundary(a, b);
      if(record.boundary.empty()) { ++result.number_of_pairs_without_boundary; continue; }
      const std::size_t m = midpoint(a, b, record.boundary);
      record.midpoint = m;

      Cache cache;
      for(std::size_t m_prime : record.boundary)
      {
        // Alg. 2: SymmetrySupport(a, b, m', S)
        double h = 0.;
        for(std::size_t k = 0; k < pairs.size(); ++k)
        {
          // similarity filter: {p,q} is in the list of similar pairs
          std::size_t p, q;
          // distance filter: opposite sides, then the four equalities
          if(!orient_pair(dss, a, b, pairs[k].first, pairs[k].second, p, q))
            continue;
          if(!(tol(dss(a, p), dss(b, q)) && tol(dss(a, q), dss(b, p)) &&
               tol(D(p, m), D(q, m)) && tol(D(p, m_prime), D(q, m_prime))))
            continue;
          // locality filter, then axial-sym filter (once per {a,b})
          if(!cache.computed) compute_cache(a, b, m, cache);
          if(!cache.local[k]) continue;
          if(!cache.axial[k]) continue;
          h += gaussian_weight(D(p, m_prime), s_.settings.inv_sigma2);
        }
        record.support.push_back(h);
      }
      for(std::size_t i = 0; i < record.boundary.size(); ++i)
        tau[record.boundary[i]] += record.support[i];

      if(!cache.computed) compute_cache(a, b, m, cache);
      for(std::size_t k = 0; k < pairs.size(); ++k)
        if(cache.axial[k])
        {
          std::size_t p, q;
          orient_pair(dss, a, b, pairs[k].first, pairs[k].second, p, q);
          record.eligible_pairs.emplace_back(p, q);
        }
      if(record.eligible_pairs.empty()) { ++result.number_of_pairs_without_support; continue; }
      result.voting_pairs.push_back(std::move(record));
    }
    return result;
  }

  // beta(a,b) by a scan of every vertex and every edge
  std::vector<std::size_t> boundary(std::size_t a, std::size_t b) const
  {
    const float* ra = s_.D->row(a);
    const float* rb = s_.D->row(b);
    std::vector<std::size_t> beta;
    for(std::size_t v = 0; v < s_.mesh.number_of_vertices; ++v)
      if(bisector_value(ra, rb, v) == 0.f)
        beta.push_back(v);
    for(const auto& e : s_.mesh.edges)
    {
      const std::size_t w = bisector_endpoint(e.first, bisector_value(ra, rb, e.first),
                                              e.second, bisector_value(ra, rb, e.second));
      if(w != std::size_t(-1))
        beta.push_back(w);
    }
    std::sort(beta.begin(), beta.end());
    beta.erase(std::unique(beta.begin(), beta.end()), beta.end());
    return beta;
  }

  std::size_t midpoint(std::size_t a, std::size_t b, const std::vector<std::size_t>& beta) const
  {
    std::size_t m = beta.front();
    double best = std::numeric_limits<double>::infinity();
    for(std::size_t v : beta)
    {
      const double s = double((*s_.D)(a, v)) + double((*s_.D)(b, v));
      if(s < best) { best = s; m = v; }
    }
    return m;
  }

private:
  struct Cache
  {
    bool computed = false;
    std::vector<char> local; // per similar pair: passed the locality filter
    std::vector<char> axial; // per similar pair: passed the axial-sym filter too
  };

  void compute_cache(std::size_t a, std::size_t b, std::size_t m, Cache& cache) const
  {
    const Geodesic_distance_matrix& D = *s_.D;
    const Sample_distance_matrix& dss = s_.dss;
    const auto& pairs = s_.similar_pairs;
    const Distance_tolerance& tol = s_.settings.tolerance;
    const std::size_t np = pairs.size();
    cache.computed = true;
    cache.local.assign(np, 0);
    cache.axial.assign(np, 0);

    // pairs that pass the similarity and m'-independent distance tests
    std::vector<std::size_t> passed;
    std::vector<std::size_t> ps(np), qs(np);
    for(std::size_t k = 0; k < np; ++k)
    {
      std::size_t p, q;
      if(!orient_pair(dss, a, b, pairs[k].first, pairs[k].second, p, q))
        continue;
      if(tol(dss(a, p), dss(b, q)) && tol(dss(a, q), dss(b, p)) && tol(D(p, m), D(q, m)))
      {
        passed.push_back(k);
        ps[k] = p;
        qs[k] = q;
      }
    }

    // locality: DBSCAN over their points, brute-force neighbourhoods
    std::vector<std::size_t> points;
    for(std::size_t k : passed) { points.push_back(ps[k]); points.push_back(qs[k]); }
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    const double r = s_.settings.locality_radius;
    auto neighbors = [&](std::size_t i, std::vector<std::size_t>& out) {
      for(std::size_t j = 0; j < points.size(); ++j)
      {
        const float d = (std::min)(dss(points[i], points[j]), dss(points[j], points[i]));
        if(std::isfinite(d) && double(d) <= r)
          out.push_back(j);
      }
    };
    std::vector<int> labels;
    dbscan(points.size(), s_.settings.locality_min_points, neighbors, labels);
    // the cluster that contains beta: the one of the clustered point closest to m
    int cluster = -1;
    float best = std::numeric_limits<float>::infinity();
    for(std::size_t i = 0; i < points.size(); ++i)
      if(labels[i] >= 0 && (cluster < 0 || D(points[i], m) < best))
      {
        best = D(points[i], m);
        cluster = labels[i];
      }
    auto label_of = [&](std::size_t u) {
      return labels[std::size_t(std::lower_bound(points.begin(), points.end(), u) - points.begin())];
    };
    std::vector<std::size_t> eligible;
    for(std::size_t k : passed)
      if(cluster >= 0 && label_of(ps[k]) == cluster && label_of(qs[k]) == cluster)
      {
        cache.local[k] = 1;
        eligible.push_back(k);
      }

    // axial-sym: count the eligible {s,t} (all, or an evenly spread sample of
    // them) that agree with {p,q}
    std::vector<std::size_t> compared;
    axial_comparison_pairs(eligible.size(), s_.settings.axial_sample_size, compared);
    for(std::size_t k : eligible)
    {
      std::size_t count = 0;
      for(std::size_t position : compared)
      {
        const std::size_t l = eligible[position];
        if(tol(dss(ps[l], ps[k]), dss(qs[l], qs[k])) && tol(dss(ps[l], qs[k]), dss(qs[l], ps[k])))
          ++count;
      }
      if(double(count) >= s_.settings.axial_threshold * double(compared.size()))
        cache.axial[k] = 1;
    }
  }

  const Voting_setup& s_;
};

/// The reference IRSA transform with the same inputs, parameters and result
/// as `compute_irsa_transform()`; tau is returned by vertex index.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Irsa_voting_result reference_irsa_transform(const TriangleMesh& tm, const Geodesic_distance_matrix& D,
                                            const std::vector<std::pair<std::size_t, std::size_t>>& similar_pairs,
                                            std::vector<double>& tau,
                                            const NamedParameters& np = parameters::default_values())
{
  const Voting_setup setup = make_voting_setup(tm, D, similar_pairs, np);
  return Reference_voting(setup).run(tau);
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_REFERENCE_VOTING_H
