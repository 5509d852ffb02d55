// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_MIRROR_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_MIRROR_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_mesh.h>

#include <CGAL/for_each.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

// The reflection induced by an IRSA curve, vertex by vertex. Landmarks are
// mirror sample pairs (p_k, q_k) of the curve. The mirror partner of a
// vertex x is the vertex y minimising
//   E(x, y) = sum_k (d(x,p_k) - d(y,q_k))^2 + (d(x,q_k) - d(y,p_k))^2,
// all distances read in the sample rows of the distance matrix. A reflection
// maps p_k to q_k and preserves distances, so E vanishes at the mirror; it
// also vanishes at y = x on the axis (its fixed points), and E(x, y) = E(y, x).
// No side test is needed: off the axis, y = x or a point on the same side
// does not match the swapped distances. The residual sqrt(E / (2K)) of the
// best partner says how well the reflection holds at x: it is the support of
// the symmetry at x, which bounds the regions.
//
// The search is exact and fast: with s(v) the mean of the 2K distances from
// v to the landmark samples (invariant under the reflection), Cauchy-Schwarz
// gives E(x, y) >= 2K (s(x) - s(y))^2, so candidates are visited in order of
// |s(y) - s(x)| and the search stops when that bound exceeds the best E.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

/// Up to `K` of `pairs` (in order of preference), well spread: farthest-point
/// subsampling from the first, the distance of a pair to the chosen ones
/// being measured from its p to the nearer sample of each chosen pair.
inline std::vector<std::pair<std::size_t, std::size_t>>
spread_pairs(const Geodesic_distance_matrix& D, const std::vector<std::pair<std::size_t, std::size_t>>& all,
             std::size_t K)
{
  std::vector<std::pair<std::size_t, std::size_t>> lm;
  std::vector<double> dmin(all.size(), std::numeric_limits<double>::max());
  std::size_t next = 0;
  while(lm.size() < (std::min)(K, all.size()))
  {
    lm.push_back(all[next]);
    const std::size_t p = all[next].first, q = all[next].second;
    double far = -1.;
    std::size_t far_i = 0;
    for(std::size_t i = 0; i < all.size(); ++i)
    {
      const std::size_t vi = D.sources()[all[i].first];
      const double d = (std::min)(D(p, vi), D(q, vi));
      if(std::isfinite(d)) dmin[i] = (std::min)(dmin[i], d);
      if(dmin[i] > far) { far = dmin[i]; far_i = i; }
    }
    if(!(far > 0.)) break;
    next = far_i;
  }
  return lm;
}

/// Tolerance of the residual: a vertex x supports the reflection when the
/// residual of its best partner is at most
/// `scale * (floor + eps * mean distance from x to the landmarks)`, the
/// form of the voting's distance test (eps_DIS, absolute floor).
struct Symmetry_tolerance
{
  double floor = 0.;
  double eps = 0.02;
  double scale = 1.;
};

/// The landmarks of a curve, spread: its voting pair (a, b) first, then its
/// eligible pairs.
inline std::vector<std::pair<std::size_t, std::size_t>>
choose_landmarks(const Geodesic_distance_matrix& D, std::size_t a, std::size_t b,
                 const std::vector<std::pair<std::size_t, std::size_t>>& pairs, std::size_t K)
{
  std::vector<std::pair<std::size_t, std::size_t>> all(1, std::make_pair(a, b));
  all.insert(all.end(), pairs.begin(), pairs.end());
  return spread_pairs(D, all, K);
}

class Mirror_matcher
{
public:
  static constexpr std::size_t none = std::size_t(-1);

  Mirror_matcher(const Geodesic_distance_matrix& D, const std::vector<std::pair<std::size_t, std::size_t>>& landmarks)
    : K_(landmarks.size()), nv_(D.number_of_vertices()), landmarks_(landmarks)
  {
    u_.resize(nv_ * 2 * K_);
    s_.assign(nv_, 0.);
    for(std::size_t k = 0; k < K_; ++k)
    {
      const float* rp = D.row(landmarks[k].first);
      const float* rq = D.row(landmarks[k].second);
      for(std::size_t v = 0; v < nv_; ++v)
      {
        u_[v * 2 * K_ + 2 * k] = rp[v];
        u_[v * 2 * K_ + 2 * k + 1] = rq[v];
        s_[v] += double(rp[v]) + double(rq[v]);
      }
    }
    for(std::size_t v = 0; v < nv_; ++v) s_[v] = K_ > 0 ? s_[v] / double(2 * K_) : 0.;
  }

  std::size_t number_of_landmarks() const { return K_; }
  const std::vector<std::pair<std::size_t, std::size_t>>& landmarks() const { return landmarks_; }
  /// mean distance from `x` to the landmark samples (invariant under the reflection)
  double mean_landmark_distance(std::size_t x) const { return s_[x]; }

  /// For each x of `X`, the best partner among `Y` (vertex indices) and the
  /// residual sqrt(E / (2K)); `none` and +inf without finite candidates.
  /// Ties go to the smaller vertex index.
  template <class ConcurrencyTag>
  void best_partners(const std::vector<std::size_t>& X, const std::vector<std::size_t>& Y,
                     std::vector<std::size_t>& best, std::vector<double>& residual) const
  {
    best.assign(X.size(), none);
    residual.assign(X.size(), std::numeric_limits<double>::infinity());
    if(K_ == 0) return;
    std::vector<std::size_t> ys;
    for(std::size_t y : Y) if(std::isfinite(s_[y])) ys.push_back(y);
    std::sort(ys.begin(), ys.end(), [&](std::size_t i, std::size_t j) { return s_[i] < s_[j] || (s_[i] == s_[j] && i < j); });
    std::vector<double> key(ys.size());
    for(std::size_t i = 0; i < ys.size(); ++i) key[i] = s_[ys[i]];
    const std::size_t L = 2 * K_;
    const double twoK = double(L);

    std::vector<std::size_t> rows(X.size());
    std::iota(rows.begin(), rows.end(), std::size_t(0));
    CGAL::for_each<ConcurrencyTag>(rows, [&](std::size_t i) {
      const std::size_t x = X[i];
      if(!std::isfinite(s_[x]) || ys.empty()) return true;
      const float* ux = u_.data() + x * L;
      double be = std::numeric_limits<double>::infinity();
      std::size_t bj = none;
      auto test = [&](std::size_t y) {
        const float* uy = u_.data() + y * L;
        double e = 0.;
        for(std::size_t k = 0; k < L; k += 2)
        {
          // the reflection swaps p_k and q_k
          const double d0 = double(ux[k]) - double(uy[k + 1]);
          const double d1 = double(ux[k + 1]) - double(uy[k]);
          e += d0 * d0 + d1 * d1;
          if(e > be) return; // cannot win any more
        }
        if(e < be || (e == be && y < bj)) { be = e; bj = y; }
      };
      // walk outwards from s(x) in both directions, nearer key first
      std::ptrdiff_t hi = std::lower_bound(key.begin(), key.end(), s_[x]) - key.begin();
      std::ptrdiff_t lo = hi - 1;
      const std::ptrdiff_t n = std::ptrdiff_t(key.size());
      for(;;)
      {
        const double dlo = lo >= 0 ? s_[x] - key[std::size_t(lo)] : std::numeric_limits<double>::infinity();
        const double dhi = hi < n ? key[std::size_t(hi)] - s_[x] : std::numeric_limits<double>::infinity();
        const double d = (std::min)(dlo, dhi);
        if(!(twoK * d * d <= be)) break; // also stops when both ends are exhausted
        if(dlo <= dhi) test(ys[std::size_t(lo--)]);
        else test(ys[std::size_t(hi++)]);
      }
      best[i] = bj;
      residual[i] = bj == none ? std::numeric_limits<double>::infinity() : std::sqrt(be / twoK);
      return true;
    });
  }

  /// sqrt(E(x, y) / (2K))
  double residual(std::size_t x, std::size_t y) const
  {
    const float* ux = u_.data() + x * 2 * K_;
    const float* uy = u_.data() + y * 2 * K_;
    double e = 0.;
    for(std::size_t k = 0; k < 2 * K_; k += 2)
    {
      const double d0 = double(ux[k]) - double(uy[k + 1]);
      const double d1 = double(ux[k + 1]) - double(uy[k]);
      e += d0 * d0 + d1 * d1;
    }
    return K_ > 0 ? std::sqrt(e / double(2 * K_)) : std::numeric_limits<double>::infinity();
  }

  bool within(double residual, std::size_t x, const Symmetry_tolerance& tol) const
  {
    return residual <= tol.scale * (tol.floor + tol.eps * s_[x]);
  }

  /// the 2K distances from `v` to the landmark samples: d(v, p_k), d(v, q_k), k = 0..K-1
  const float* landmark_distances(std::size_t v) const { return u_.data() + v * 2 * K_; }

private:
  std::size_t K_ = 0, nv_ = 0;
  std::vector<std::pair<std::size_t, std::size_t>> landmarks_;
  std::vector<float> u_;
  std::vector<double> s_;
};

/// Mirror partners under locally weighted landmarks. Why: on a posed shape
/// (an arm raised on one side only) the distances to far landmarks are not
/// preserved by the reflection, and E of Mirror_matcher::best_partners()
/// averages their distortion into every vertex (on FAUST with ground-truth
/// landmarks: a median error twice that of the rest poses); near x the shape
/// is nearly isometric to its mirror. The partner of each `X[i]` becomes the
/// vertex y of `Y` minimising
///   E_w(x, y) = sum_k w_k(x) ((d(x,p_k) - d(y,q_k))^2 + (d(x,q_k) - d(y,p_k))^2),
///   w_k(x) = exp(-(min(d(x,p_k), d(x,q_k)) / sigma)^2),
/// landmarks farther than 3 sigma ignored, and `residual[i]` becomes
/// sqrt(E_w / (2 sum w)). The search is exhaustive and exact, landmark by
/// landmark over all candidates at once (by decreasing weight, so that most
/// candidates are rejected after a few terms, each term read from a
/// landmark-major copy of the candidates' distances, contiguous in memory):
/// a candidate leaves as soon as its partial sum exceeds E_w of the current
/// `best[i]`. Every remaining candidate's sum is then complete, and added in
/// the same order as a candidate-by-candidate scan would add it, so the
/// result is that scan's. A vertex with fewer than 3 landmarks within
/// 3 sigma keeps its partner. Ties go to the smaller vertex index.
template <class ConcurrencyTag>
void local_best_partners(const Mirror_matcher& mm, const std::vector<std::size_t>& X,
                         const std::vector<std::size_t>& Y, double sigma, std::vector<std::size_t>& best,
                         std::vector<double>& residual)
{
  const std::size_t K = mm.number_of_landmarks();
  if(K == 0 || !(sigma > 0.)) return;
  const std::size_t ny = Y.size();
  // column c of the copy: d(Y[t], p_k) for c = 2k, d(Y[t], q_k) for c = 2k + 1
  std::vector<float> column(2 * K * ny);
  for(std::size_t t = 0; t < ny; ++t)
  {
    const float* uy = mm.landmark_distances(Y[t]);
    for(std::size_t c = 0; c < 2 * K; ++c) column[c * ny + t] = uy[c];
  }
  std::vector<std::size_t> rows(X.size());
  std::iota(rows.begin(), rows.end(), std::size_t(0));
  CGAL::for_each<ConcurrencyTag>(rows, [&](std::size_t i) {
    if(best[i] == Mirror_matcher::none) return true;
    const float* ux = mm.landmark_distances(X[i]);
    std::vector<std::pair<double, std::size_t>> active; // (weight, k), decreasing weight
    double wsum = 0.;
    for(std::size_t k = 0; k < K; ++k)
    {
      const double d = (std::min)(double(ux[2 * k]), double(ux[2 * k + 1]));
      if(!(d <= 3. * sigma)) continue;
      active.emplace_back(std::exp(-(d / sigma) * (d / sigma)), k);
      wsum += active.back().first;
    }
    if(active.size() < 3) return true;
    std::sort(active.begin(), active.end(), [](const std::pair<double, std::size_t>& l,
                                               const std::pair<double, std::size_t>& r) {
      return l.first > r.first || (l.first == r.first && l.second < r.second);
    });
    // landmark k's term of E_w(x, y), from x's and y's distances to p_k and q_k
    auto term = [](double w, double xp, double xq, float yp, float yq) {
      const double d0 = xp - double(yq), d1 = xq - double(yp);
      return w * (d0 * d0 + d1 * d1);
    };
    // E_w of the current partner: the bound every candidate must meet
    std::size_t bj = best[i];
    double be = 0.;
    const float* ub = mm.landmark_distances(bj);
    for(const auto& wk : active)
      be += term(wk.first, ux[2 * wk.second], ux[2 * wk.second + 1], ub[2 * wk.second], ub[2 * wk.second + 1]);
    std::vector<double> e(ny, 0.);
    std::vector<std::size_t> alive(ny);
    std::iota(alive.begin(), alive.end(), std::size_t(0));
    for(const auto& wk : active)
    {
      const double xp = ux[2 * wk.second], xq = ux[2 * wk.second + 1];
      const float* yp = column.data() + (2 * wk.second) * ny;     // d(y, p_k)
      const float* yq = column.data() + (2 * wk.second + 1) * ny; // d(y, q_k)
      std::size_t kept = 0;
      for(std::size_t t : alive)
      {
        e[t] += term(wk.first, xp, xq, yp[t], yq[t]);
        if(e[t] <= be) alive[kept++] = t;
      }
      alive.resize(kept);
      if(alive.empty()) break;
    }
    for(std::size_t t : alive)
    {
      const std::size_t y = Y[t];
      if(e[t] < be || (e[t] == be && y < bj)) { be = e[t]; bj = y; }
    }
    best[i] = bj;
    residual[i] = std::sqrt(be / (2. * wsum));
    return true;
  });
}

/// Landmarks spread over where the reflection holds. Starting from
/// `initial`, each round matches every sample whose vertex is `allowed` to
/// its best partner among those samples, and takes `K` well-spread pairs of
/// the initial pairs that agree with the current landmarks (a voted pair can
/// be wrong, and one wrong landmark raises E everywhere) and of the new
/// mutual matches within the tolerance. Far from the voted pairs, distances
/// to them alone locate points poorly; sample pairs found this way reach the
/// whole part where the reflection holds. Of the landmark sets of all
/// rounds, the one under which the reflection holds at the most samples of
/// `allowed` is returned (the paper's prominence of a symmetry: the area of
/// the part it generates); ties go to the earlier round.
template <class ConcurrencyTag>
std::vector<std::pair<std::size_t, std::size_t>>
spread_landmarks(const Geodesic_distance_matrix& D, const std::vector<std::pair<std::size_t, std::size_t>>& initial,
                 const std::vector<unsigned char>& allowed, const Symmetry_tolerance& tol, std::size_t K,
                 std::size_t rounds)
{
  if(initial.empty()) return initial;
  const std::size_t ns = D.number_of_sources();
  std::vector<std::size_t> sample_vertices, sample_of;
  for(std::size_t i = 0; i < ns; ++i)
    if(allowed[D.sources()[i]]) { sample_vertices.push_back(D.sources()[i]); sample_of.push_back(i); }
  std::vector<std::size_t> slot(D.number_of_vertices(), Mirror_matcher::none);
  for(std::size_t i = 0; i < sample_vertices.size(); ++i) slot[sample_vertices[i]] = i;

  std::vector<std::pair<std::size_t, std::size_t>> lm = initial, best_lm = initial;
  std::size_t best_count = 0;
  for(std::size_t r = 0; r <= rounds; ++r)
  {
    const Mirror_matcher mm(D, lm);
    std::vector<std::size_t> best;
    std::vector<double> residual;
    mm.template best_partners<ConcurrencyTag>(sample_vertices, sample_vertices, best, residual);
    // how many samples have a partner within the tolerance
    std::size_t count = 0;
    for(std::size_t i = 0; i < sample_vertices.size(); ++i)
      count += mm.within(residual[i], sample_vertices[i], tol);
    if(r == 0 || count > best_count) { best_count = count; best_lm = lm; }
    if(r == rounds) break;
    std::vector<std::pair<std::size_t, std::size_t>> found;
    for(const auto& pq : initial)
    {
      const std::size_t vp = D.sources()[pq.first], vq = D.sources()[pq.second];
      if(mm.within(mm.residual(vp, vq), vp, tol)) found.push_back(pq);
    }
    if(found.empty()) found = initial;
    for(std::size_t i = 0; i < sample_vertices.size(); ++i)
    {
      if(best[i] == Mirror_matcher::none) continue;
      const std::size_t j = slot[best[i]];
      if(j < i || best[j] != sample_vertices[i]) continue; // each mutual pair once
      if(!mm.within(residual[i], sample_vertices[i], tol)) continue;
      found.emplace_back(sample_of[i], sample_of[j]);
    }
    lm = spread_pairs(D, found, K);
  }
  return best_lm;
}

/// The vertices where the reflection of a curve holds: the curve vertices,
/// and every vertex whose best partner (over the whole mesh) has a residual
/// within the tolerance. Indexed by vertex index. With `partner`, also the
/// best partner of every vertex (`Mirror_matcher::none` where there is none).
template <class ConcurrencyTag>
std::vector<unsigned char> symmetry_support_mask(const Geodesic_distance_matrix& D,
                                                 const std::vector<std::size_t>& curve_vertices,
                                                 const std::vector<std::pair<std::size_t, std::size_t>>& landmarks,
                                                 const Symmetry_tolerance& tol,
                                                 std::vector<std::size_t>* partner = nullptr)
{
  const std::size_t nv = D.number_of_vertices();
  std::vector<unsigned char> mask(nv, 0);
  for(std::size_t v : curve_vertices) mask[v] = 1;
  if(partner) partner->assign(nv, Mirror_matcher::none);
  if(landmarks.empty()) return mask;
  const Mirror_matcher mm(D, landmarks);
  std::vector<std::size_t> all(nv), best;
  std::iota(all.begin(), all.end(), std::size_t(0));
  std::vector<double> residual;
  mm.template best_partners<ConcurrencyTag>(all, all, best, residual);
  for(std::size_t x = 0; x < nv; ++x)
    if(mm.within(residual[x], x, tol)) mask[x] = 1;
  if(partner) partner->swap(best);
  return mask;
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_MIRROR_H
