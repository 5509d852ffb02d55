// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_VOTING_KERNEL_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_VOTING_KERNEL_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/dbscan.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/voting_common.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

// The fast per-pair voting of Alg. 1-2. It computes exactly what the literal
// reference (reference_voting.h) computes, in another order:
// - beta(a,b): f = d(a,.) - d(b,.) in one sweep of the two rows of D; the
//   bisector test then only runs in the vertex blocks where f can change sign
//   (per-block bounds decide most blocks from one vertex);
// - the three m'-independent distance tests: one scan of the similar pairs,
//   grouped by first sample, with a pair of windows per sample (or a grid
//   range query over (d(b,q), d(a,q)) when the similar pairs are many);
// - locality (DBSCAN) and the axial counts once per {a,b}: DBSCAN with
//   precomputed sample neighbourhoods, the axial counts on rows of the
//   transposed sample matrix with an early stop per pair;
// - the loop over m' in beta only evaluates d(p,m') ~ d(q,m') and the Gaussian.
// Votes are summed in the order of the canonical pair list, as the reference
// does, so mu and tau are bit-identical to it.
// Define CGAL_IRS_VOTING_STATS for a few extra counters (profiling only).

#ifndef CGAL_IRS_VOTING_STAGE
#define CGAL_IRS_VOTING_STAGE // profiling builds define it as a no-inline attribute
#endif

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

class Fast_voting
{
public:
  enum Outcome { voted, disconnected, no_boundary, no_support };

  struct Scratch
  {
    std::vector<float> f;                     // f = d(a,.) - d(b,.) at every vertex
    std::vector<std::uint32_t> vertex_stamp;  // beta marks
    std::uint32_t stamp = 0;
    std::vector<unsigned char> block_bits;
    std::vector<std::uint32_t> sample_stamp;  // membership in U
    std::vector<std::uint32_t> sample_slot;   // index in U
    std::uint32_t sstamp = 0;
    std::vector<float> dist_to_m;             // D(x, m) for every sample x
    std::vector<float> coordinates;           // (d(a,x), d(b,x)) for every sample x
    std::vector<std::size_t> b_side, cell_start, cell_items;
    struct Candidate { std::size_t i, j, p, q; };
    std::vector<Candidate> candidates;
    std::vector<std::size_t> points;          // U, increasing sample indices
    std::vector<int> labels;
    std::vector<std::size_t> kept;            // indices into candidates
    std::vector<std::size_t> cursor;          // grid construction
    std::vector<std::uint32_t> ss, ts;        // the kept pairs' samples
    std::vector<std::uint32_t> counts, order, os, ot, cs, ct;
    std::vector<std::size_t> compared;
#ifdef CGAL_IRS_VOTING_STATS
    std::size_t stat_scanned_blocks = 0, stat_unknown_blocks = 0;
    std::size_t stat_axial_checks = 0, stat_axial_pairs = 0, stat_axial_e2 = 0;
#endif
    // CPU seconds spent in each stage, summed over the pairs this scratch saw:
    // boundary, candidates (distance filter), locality, axial, support
    double stage_seconds[5] = {0., 0., 0., 0., 0.};
    // pair counts after each filter, summed over the voting pairs
    std::size_t total_candidates = 0, total_after_locality = 0, total_after_axial = 0;
    // sizes after each filter for the last pair (for statistics)
    std::size_t number_of_candidates = 0, number_after_locality = 0, number_after_axial = 0;
  };

  // `parallel`: build the indices with TBB (they do not depend on it)
  explicit Fast_voting(const Voting_setup& s, bool parallel = false) : s_(s), parallel_(parallel)
  {
    const std::size_t n = s.number_of_samples;
    // candidate pairs: by a scan of the similar pairs (P per voting pair)
    // unless they are many, by a range query over the samples otherwise
    use_pair_scan_ = s.similar_pairs.size() <= 32 * n;
    // the similar pairs grouped by first sample (they are sorted)
    first_offsets_.assign(n + 1, 0);
    partners_.reserve(s.similar_pairs.size());
    for(const auto& pr : s.similar_pairs) { ++first_offsets_[pr.first + 1]; partners_.push_back(std::uint32_t(pr.second)); }
    for(std::size_t i = 0; i < n; ++i) first_offsets_[i + 1] += first_offsets_[i];
    if(!use_pair_scan_)
    {
      // similarity as a bit matrix: O(1) membership for range-query hits
      words_per_row_ = (n + 63) / 64;
      similar_.assign(n * words_per_row_, 0);
      for(const auto& pr : s.similar_pairs)
      {
        similar_[pr.first * words_per_row_ + pr.second / 64] |= std::uint64_t(1) << (pr.second % 64);
        similar_[pr.second * words_per_row_ + pr.first / 64] |= std::uint64_t(1) << (pr.first % 64);
      }
    }
    // DBSCAN neighbourhoods of every sample, increasing: a query on U then
    // only filters a short list instead of testing all of U
    const double r = s.settings.locality_radius;
    std::vector<std::vector<std::uint32_t>> lists(n);
    for_each_index(n, [&](std::size_t i) {
      for(std::size_t j = 0; j < n; ++j)
        if(locality_neighbors(s.dss, i, j, r))
          lists[i].push_back(std::uint32_t(j));
    });
    neighbor_offsets_.assign(n + 1, 0);
    for(std::size_t i = 0; i < n; ++i)
    {
      neighbors_.insert(neighbors_.end(), lists[i].begin(), lists[i].end());
      neighbor_offsets_[i + 1] = neighbors_.size();
    }
    // the sample matrix transposed: column p of dss as a contiguous row, for
    // the axial-sym counts (d(s,p) for many s and a fixed p)
    dss_t_.resize(n * n);
    for_each_index(n, [&](std::size_t j) {
      for(std::size_t i = 0; i < n; ++i)
        dss_t_[j * n + i] = s.dss(i, j);
    });
    build_blocks();
  }

  // f(i) for i in [0, n), in parallel if asked; f must be thread-safe
  template <class F>
  void for_each_index(std::size_t n, F f) const
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(parallel_)
    {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          for(std::size_t i = range.begin(); i != range.end(); ++i) f(i);
                        });
      return;
    }
#endif
    for(std::size_t i = 0; i < n; ++i) f(i);
  }

  Scratch make_scratch() const
  {
    Scratch sc;
    sc.vertex_stamp.assign(s_.mesh.number_of_vertices, 0);
    sc.f.assign(s_.mesh.number_of_vertices, 0.f);
    sc.block_bits.assign(block_offsets_.size() - 1, 0);
    sc.sample_stamp.assign(s_.number_of_samples, 0);
    sc.sample_slot.assign(s_.number_of_samples, 0);
    sc.dist_to_m.assign(s_.number_of_samples, 0.f);
    sc.coordinates.assign(2 * s_.number_of_samples, 0.f);
    return sc;
  }

  /// True when samples i and j are DBSCAN neighbours (symmetric relation).
  static bool locality_neighbors(const Sample_distance_matrix& dss, std::size_t i, std::size_t j, double r)
  {
    const float d = (std::min)(dss(i, j), dss(j, i));
    return std::isfinite(d) && double(d) <= r;
  }

  bool similar(std::size_t i, std::size_t j) const
  {
    return (similar_[i * words_per_row_ + j / 64] >> (j % 64)) & 1u;
  }

  Outcome vote(std::size_t a, std::size_t b, Scratch& sc, std::size_t& midpoint,
               std::vector<std::size_t>& boundary, std::vector<double>& support,
               std::vector<std::pair<std::size_t, std::size_t>>& eligible) const
  {
    boundary.clear(); support.clear(); eligible.clear();
    sc.number_of_candidates = sc.number_after_locality = sc.number_after_axial = 0;
    const Sample_distance_matrix& dss = s_.dss;
    if(!std::isfinite(dss(a, b)))
      return disconnected;
    const Geodesic_distance_matrix& D = *s_.D;
    const float* ra = D.row(a);
    const float* rb = D.row(b);

    typedef std::chrono::steady_clock Clock;
    Clock::time_point t0 = Clock::now(), t1;
    auto lap = [&](int stage) {
      t1 = Clock::now();
      sc.stage_seconds[stage] += std::chrono::duration<double>(t1 - t0).count();
      t0 = t1;
    };

    find_boundary(a, b, ra, rb, sc, boundary);
    if(boundary.empty()) { lap(0); return no_boundary; }
    std::size_t m = boundary.front();
    double best = std::numeric_limits<double>::infinity();
    for(std::size_t v : boundary)
    {
      const double sum = double(ra[v]) + double(rb[v]);
      if(sum < best) { best = sum; m = v; }
    }
    midpoint = m;
    lap(0);

    find_candidates(a, b, m, sc);
    sc.number_of_candidates = sc.candidates.size();
    sc.total_candidates += sc.number_of_candidates;
    lap(1);
    if(sc.candidates.empty())
      return no_support;
    apply_locality(m, sc);
    sc.number_after_locality = sc.kept.size();
    sc.total_after_locality += sc.number_after_locality;
    lap(2);
    if(sc.kept.empty())
      return no_support;
    apply_axial(sc);
    sc.number_after_axial = sc.kept.size();
    sc.total_after_axial += sc.number_after_axial;
    lap(3);
    if(sc.kept.empty())
      return no_support;

    // mu(m') for every m' in beta; pairs in canonical order, as the reference
    support.assign(boundary.size(), 0.);
    const Distance_tolerance& tol = s_.settings.tolerance;
    const double inv_sigma2 = s_.settings.inv_sigma2;
    const std::size_t nb = boundary.size();
    for(std::size_t k : sc.kept)
    {
      const auto& c = sc.candidates[k];
      eligible.emplace_back(c.p, c.q);
      const float* rp = D.row(c.p);
      const float* rq = D.row(c.q);
      for(std::size_t i = 0; i < nb; ++i)
      {
        const float dp = rp[boundary[i]], dq = rq[boundary[i]];
        if(tol(dp, dq))
          support[i] += gaussian_weight(dp, inv_sigma2);
      }
    }
    lap(4);
    return voted;
  }

private:
  // Vertex blocks of about `block_size` vertices, grown by breadth-first
  // search so that they are compact on the surface whatever the vertex order,
  // and, for every sample x and block B with first vertex c, a bound
  // L(x, B) >= |d(x, v) - d(x, c)| over v in B, read from D itself (so no
  // Lipschitz assumption on the oracle). Then |f(v) - f(c)| <= L(a,B) + L(b,B),
  // and a block where |f(c)| exceeds that bound has one strict sign throughout.
  void build_blocks()
  {
    const Voting_mesh& mesh = s_.mesh;
    const std::size_t nv = mesh.number_of_vertices;
    const std::size_t block_size = 16;
    std::vector<std::size_t> block_of(nv, std::size_t(-1));
    block_offsets_.assign(1, 0);
    std::vector<std::size_t> queue;
    for(std::size_t seed = 0; seed < nv; ++seed)
    {
      if(block_of[seed] != std::size_t(-1)) continue;
      const std::size_t blk = block_offsets_.size() - 1;
      queue.assign(1, seed);
      block_of[seed] = blk;
      std::size_t count = 1;
      for(std::size_t h = 0; h < queue.size() && count < block_size; ++h)
      {
        const std::size_t v = queue[h];
        for(std::size_t k = mesh.adjacency_offsets[v]; k < mesh.adjacency_offsets[v + 1] && count < block_size; ++k)
        {
          const std::size_t u = mesh.adjacency[k];
          if(block_of[u] != std::size_t(-1)) continue;
          block_of[u] = blk;
          queue.push_back(u);
          ++count;
        }
      }
      for(std::size_t v : queue) block_vertices_.push_back(v);
      block_offsets_.push_back(block_vertices_.size());
    }
    const std::size_t nblocks = block_offsets_.size() - 1;
    std::vector<std::vector<std::size_t>> adj(nblocks);
    for(const auto& e : mesh.edges)
    {
      const std::size_t bu = block_of[e.first], bv = block_of[e.second];
      if(bu != bv) { adj[bu].push_back(bv); adj[bv].push_back(bu); }
    }
    block_adj_offsets_.assign(1, 0);
    for(auto& l : adj)
    {
      std::sort(l.begin(), l.end());
      l.erase(std::unique(l.begin(), l.end()), l.end());
      block_adj_.insert(block_adj_.end(), l.begin(), l.end());
      block_adj_offsets_.push_back(block_adj_.size());
    }

    const std::size_t n = s_.number_of_samples;
    const float inf = std::numeric_limits<float>::infinity();
    block_bound_.assign(n * nblocks, 0.f);
    for_each_index(n, [&](std::size_t x) {
      const float* r = s_.D->row(x);
      for(std::size_t blk = 0; blk < nblocks; ++blk)
      {
        const float dc = r[block_vertices_[block_offsets_[blk]]];
        double bound = 0.;
        for(std::size_t k = block_offsets_[blk] + 1; k < block_offsets_[blk + 1]; ++k)
        {
          const float dv = r[block_vertices_[k]];
          if(std::isfinite(dc) != std::isfinite(dv) || std::isnan(dv)) { bound = double(inf); break; }
          if(std::isfinite(dv)) bound = (std::max)(bound, std::abs(double(dv) - double(dc)));
        }
        // widened by more than the rounding to float
        block_bound_[x * nblocks + blk] = float(bound * (1. + 1e-6));
      }
    });
  }

  CGAL_IRS_VOTING_STAGE void find_boundary(std::size_t a, std::size_t b, const float* ra, const float* rb, Scratch& sc,
                     std::vector<std::size_t>& boundary) const
  {
    const Voting_mesh& mesh = s_.mesh;
    const std::size_t nblocks = block_offsets_.size() - 1;
    const float* la = block_bound_.data() + a * nblocks;
    const float* lb = block_bound_.data() + b * nblocks;
    // f everywhere, in one sequential sweep of the two rows: the block passes
    // below then read it in cache instead of reading D at scattered columns
    float* f = sc.f.data();
    for(std::size_t v = 0; v < mesh.number_of_vertices; ++v)
      f[v] = bisector_value(ra, rb, v);
    // pass 1: the sign of f over each block: 1: f < 0 throughout, 2: f > 0
    // throughout, 3: no finite value (another component), 4: mixed or zero.
    // The bound decides most blocks from their first vertex alone; the others
    // are classified vertex by vertex.
    for(std::size_t blk = 0; blk < nblocks; ++blk)
    {
      const std::size_t c = block_vertices_[block_offsets_[blk]];
      unsigned char status = 0;
      if(std::isnan(f[c]))
        status = (std::isfinite(la[blk]) && std::isfinite(lb[blk])) ? 3 : 0;
      else
      {
        // the margin covers the rounding of f(c) to float
        const double fc = f[c];
        const double bound = double(la[blk]) + double(lb[blk]) + 1e-6 * std::abs(fc);
        if(fc < -bound) status = 1;
        else if(fc > bound) status = 2;
      }
      if(status == 0)
      {
        unsigned char bits = 0; // 1: some f < 0, 2: some f > 0, 4: some f == 0
        for(std::size_t k = block_offsets_[blk]; k < block_offsets_[blk + 1]; ++k)
        {
          const float fv = f[block_vertices_[k]];
          bits |= (unsigned char)((fv < 0.f) | ((fv > 0.f) << 1) | ((fv == 0.f) << 2));
        }
        status = (bits == 1 || bits == 2) ? bits : (bits == 0 ? 3 : 4);
      }
      sc.block_bits[blk] = status;
    }
    if(++sc.stamp == 0)
    {
      std::fill(sc.vertex_stamp.begin(), sc.vertex_stamp.end(), 0);
      sc.stamp = 1;
    }
    // pass 2: the bisector test on the vertices of the mixed blocks, and of
    // the blocks next to a block of the opposite sign. A crossing edge either
    // has an endpoint in a mixed block, or joins two blocks of opposite signs.
    for(std::size_t blk = 0; blk < nblocks; ++blk)
    {
      const unsigned char status = sc.block_bits[blk];
      if(status == 3) continue;
      bool scan = (status == 4);
      for(std::size_t k = block_adj_offsets_[blk]; !scan && k < block_adj_offsets_[blk + 1]; ++k)
      {
        const unsigned char other = sc.block_bits[block_adj_[k]];
        scan = (other == 1 || other == 2) && other != status;
      }
      if(!scan) continue;
#ifdef CGAL_IRS_VOTING_STATS
      ++sc.stat_scanned_blocks; sc.stat_unknown_blocks += (status == 4);
#endif
      for(std::size_t k = block_offsets_[blk]; k < block_offsets_[blk + 1]; ++k)
      {
        const std::size_t v = block_vertices_[k];
        const float fv = f[v];
        if(fv == 0.f) { mark(v, sc, boundary); continue; }
        for(std::size_t l = mesh.adjacency_offsets[v]; l < mesh.adjacency_offsets[v + 1]; ++l)
        {
          const std::size_t u = mesh.adjacency[l];
          const std::size_t w = bisector_endpoint(v, fv, u, f[u]);
          if(w != std::size_t(-1)) mark(w, sc, boundary);
        }
      }
    }
    std::sort(boundary.begin(), boundary.end());
  }

  static void mark(std::size_t v, Scratch& sc, std::vector<std::size_t>& boundary)
  {
    if(sc.vertex_stamp[v] == sc.stamp) return;
    sc.vertex_stamp[v] = sc.stamp;
    boundary.push_back(v);
  }

  // Pairs {p,q} (p on a's side) that are similar and pass the three
  // m'-independent distance tests, in canonical order.
  CGAL_IRS_VOTING_STAGE void find_candidates(std::size_t a, std::size_t b, std::size_t m, Scratch& sc) const
  {
    const Sample_distance_matrix& dss = s_.dss;
    const Geodesic_distance_matrix& D = *s_.D;
    const Distance_tolerance& tol = s_.settings.tolerance;
    const std::size_t n = s_.number_of_samples;
    const float* dA = dss.row(a);
    const float* dB = dss.row(b);

    sc.candidates.clear();
    // d(x, m) for every sample x, read down the column of m in one go: the
    // independent loads overlap, unlike scattered reads inside the tests
    float* to_m = sc.dist_to_m.data();
    const std::size_t nv = D.number_of_vertices();
    const float* column = D.row(0) + m;
    for(std::size_t x = 0; x < n; ++x)
      to_m[x] = column[x * nv];
    // the m'-independent distance tests of a pair p (a's side), q (b's side)
    // that already passed d(a,p) ~ d(b,q) and d(a,q) ~ d(b,p)
    auto test_at_m = [&](std::size_t p, std::size_t q) {
      const float dpm = to_m[p], dqm = to_m[q];
      if(!tol(dpm, dqm))
        return;
      sc.candidates.push_back({(std::min)(p, q), (std::max)(p, q), p, q});
    };

    if(use_pair_scan_)
    {
      // a scan of the similar pairs, in their canonical order: the output
      // needs no sort; (d(a,.), d(b,.)) interleaved so that a pair reads its
      // two samples' coordinates with two loads
      float* co = sc.coordinates.data();
      for(std::size_t x = 0; x < n; ++x) { co[2 * x] = dA[x]; co[2 * x + 1] = dB[x]; }
      // The pairs come grouped by their first sample i, in canonical order.
      // Whichever of i and j is on a's side, the two tests say d(b,j) ~ d(a,i)
      // and d(a,j) ~ d(b,i): each i gets two windows (conservative intervals
      // of the test), each partner j costs four comparisons, and the exact
      // tests run on the few j inside both windows.
      for(std::size_t i = 0; i < n; ++i)
      {
        const std::size_t begin = first_offsets_[i], end = first_offsets_[i + 1];
        if(begin == end) continue;
        const float ai = co[2 * i], bi = co[2 * i + 1];
        const bool i_on_a = ai < bi;
        if(!i_on_a && !(bi < ai)) continue; // i on the bisector or in another component
        const auto w1 = tol.range(ai); // for d(b,j)
        const auto w2 = tol.range(bi); // for d(a,j)
        const float lo1 = float(w1.first), hi1 = float(w1.second);
        const float lo2 = float(w2.first), hi2 = float(w2.second);
        for(std::size_t k = begin; k < end; ++k)
        {
          const std::uint32_t j = partners_[k];
          const float aj = co[2 * j], bj = co[2 * j + 1];
          if(!((bj >= lo1) & (bj <= hi1) & (aj >= lo2) & (aj <= hi2)))
            continue;
          // (p, q) = (i, j) if i is on a's side, (j, i) otherwise; j must be
          // strictly on the other side
          if(i_on_a ? !(bj < aj) : !(aj < bj))
            continue;
          const std::size_t p = i_on_a ? i : j, q = i_on_a ? j : i;
          if(tol(co[2 * p], co[2 * q + 1]) && tol(co[2 * p + 1], co[2 * q]))
            test_at_m(p, q);
        }
      }
    }
    else
    {
      grid_candidates(dA, dB, sc, test_at_m);
      std::sort(sc.candidates.begin(), sc.candidates.end(),
                [](const Scratch::Candidate& x, const Scratch::Candidate& y)
                { return x.i < y.i || (x.i == y.i && x.j < y.j); });
    }
  }

  // Partners by a range query: a uniform grid over (d(b,q), d(a,q)) of the
  // samples q on b's side, queried at (d(a,p), d(b,p)) for each p on a's side.
  template <class Test>
  void grid_candidates(const float* dA, const float* dB, Scratch& sc, Test& test_at_m) const
  {
    const Distance_tolerance& tol = s_.settings.tolerance;
    const std::size_t n = s_.number_of_samples;
    sc.b_side.clear();
    double maxd = 0.;
    for(std::size_t q = 0; q < n; ++q)
      if(dB[q] < dA[q] && std::isfinite(dA[q]))
      {
        sc.b_side.push_back(q);
        maxd = (std::max)(maxd, double(dA[q]));
      }
    if(sc.b_side.empty())
      return;

    // a cell is about one tolerance wide
    double h = (std::max)({tol.eps * maxd, tol.floor, maxd / 128.});
    if(!(h > 0.)) h = 1.;
    const std::size_t g = std::size_t(maxd / h) + 1;
    auto cell_of = [&](double x) -> std::size_t {
      const double c = std::floor(x / h);
      return c < 0. ? 0 : (c >= double(g) ? g - 1 : std::size_t(c));
    };
    sc.cell_start.assign(g * g + 1, 0);
    for(std::size_t q : sc.b_side)
      ++sc.cell_start[cell_of(dB[q]) * g + cell_of(dA[q]) + 1];
    for(std::size_t c = 0; c < g * g; ++c)
      sc.cell_start[c + 1] += sc.cell_start[c];
    sc.cell_items.resize(sc.b_side.size());
    std::vector<std::size_t>& fill = sc.cursor;
    fill.assign(sc.cell_start.begin(), sc.cell_start.end() - 1);
    for(std::size_t q : sc.b_side)
      sc.cell_items[fill[cell_of(dB[q]) * g + cell_of(dA[q])]++] = q;

    for(std::size_t p = 0; p < n; ++p)
    {
      if(!(dA[p] < dB[p]) || !std::isfinite(dB[p]))
        continue;
      // q must satisfy d(b,q) ~ d(a,p) and d(a,q) ~ d(b,p)
      const auto r1 = tol.range(dA[p]);
      const auto r2 = tol.range(dB[p]);
      if(r1.second < 0. || r2.second < 0.) continue;
      const std::size_t x0 = cell_of(r1.first), x1 = cell_of(r1.second);
      const std::size_t y0 = cell_of(r2.first), y1 = cell_of(r2.second);
      for(std::size_t x = x0; x <= x1; ++x)
        for(std::size_t y = y0; y <= y1; ++y)
          for(std::size_t k = sc.cell_start[x * g + y]; k < sc.cell_start[x * g + y + 1]; ++k)
          {
            const std::size_t q = sc.cell_items[k];
            if(similar(p, q) && tol(dA[p], dB[q]) && tol(dB[p], dA[q]))
              test_at_m(p, q);
          }
    }
  }

  // Locality filter: DBSCAN over the candidates' points; keep the pairs whose
  // two points are in the cluster of the clustered point closest to m.
  CGAL_IRS_VOTING_STAGE void apply_locality(std::size_t /*m*/, Scratch& sc) const
  {
    sc.points.clear();
    if(++sc.sstamp == 0)
    {
      std::fill(sc.sample_stamp.begin(), sc.sample_stamp.end(), 0);
      sc.sstamp = 1;
    }
    for(const auto& c : sc.candidates)
    {
      sc.sample_stamp[c.p] = sc.sstamp;
      sc.sample_stamp[c.q] = sc.sstamp;
    }
    // U in increasing order, by a sweep of the stamps (cheaper than a sort)
    for(std::size_t x = 0; x < s_.number_of_samples; ++x)
      if(sc.sample_stamp[x] == sc.sstamp)
        sc.points.push_back(x);
    for(std::size_t i = 0; i < sc.points.size(); ++i)
      sc.sample_slot[sc.points[i]] = i;

    const std::uint32_t st = sc.sstamp;
    auto neighbors = [&](std::size_t i, std::vector<std::size_t>& out) {
      const std::size_t u = sc.points[i];
      for(std::size_t k = neighbor_offsets_[u]; k < neighbor_offsets_[u + 1]; ++k)
      {
        const std::size_t w = neighbors_[k];
        if(sc.sample_stamp[w] == st)
          out.push_back(sc.sample_slot[w]);
      }
    };
    dbscan(sc.points.size(), s_.settings.locality_min_points, neighbors, sc.labels);

    int cluster = -1;
    float best = std::numeric_limits<float>::infinity();
    for(std::size_t i = 0; i < sc.points.size(); ++i)
      if(sc.labels[i] >= 0 && (cluster < 0 || sc.dist_to_m[sc.points[i]] < best))
      {
        best = sc.dist_to_m[sc.points[i]];
        cluster = sc.labels[i];
      }
    sc.kept.clear();
    if(cluster < 0)
      return;
    for(std::size_t k = 0; k < sc.candidates.size(); ++k)
    {
      const auto& c = sc.candidates[k];
      if(sc.labels[sc.sample_slot[c.p]] == cluster && sc.labels[sc.sample_slot[c.q]] == cluster)
        sc.kept.push_back(k);
    }
  }

  // Axial-sym filter on the kept pairs: {p,q} stays if at least eps_AXS of
  // the kept pairs {s,t} (itself included) have d(s,p) ~ d(t,q) and
  // d(s,q) ~ d(t,p). For a pair {p,q}, the distances d(., p) and d(., q) are
  // two contiguous rows of the transposed sample matrix. The count of a pair
  // stops as soon as its verdict is certain, which gives the verdict of a full
  // count. To reach it sooner, the pairs {s,t} are visited in two phases: the
  // first few in canonical order, counted for every pair; then the others,
  // least "popular" first (fewest agreements in the first phase): they
  // disagree with most pairs and settle the failing ones early.
  CGAL_IRS_VOTING_STAGE void apply_axial(Scratch& sc) const
  {
    const Distance_tolerance& tol = s_.settings.tolerance;
    const std::size_t n = s_.number_of_samples;
    const std::size_t ne = sc.kept.size();
    // the pairs {s,t} compared with every pair, and their samples
    axial_comparison_pairs(ne, s_.settings.axial_sample_size, sc.compared);
    const std::size_t nc = sc.compared.size();
    // pass <=> count >= eps_AXS * nc <=> count >= needed (count is an integer)
    const std::size_t needed = std::size_t(std::ceil(s_.settings.axial_threshold * double(nc)));
    std::vector<std::uint32_t>& ss = sc.ss;
    std::vector<std::uint32_t>& ts = sc.ts;
    ss.resize(ne);
    ts.resize(ne);
    for(std::size_t l = 0; l < ne; ++l)
    {
      ss[l] = std::uint32_t(sc.candidates[sc.kept[l]].p);
      ts[l] = std::uint32_t(sc.candidates[sc.kept[l]].q);
    }
    auto row = [&](std::uint32_t x) { return dss_t_.data() + std::size_t(x) * n; };

    // phase 1: the first pairs {s,t}, for every pair {p,q}
    const std::size_t first = (std::min)(nc, std::size_t(32));
    std::vector<std::uint32_t>& cs = sc.cs;
    std::vector<std::uint32_t>& ct = sc.ct;
    cs.resize(nc);
    ct.resize(nc);
    for(std::size_t i = 0; i < nc; ++i) { cs[i] = ss[sc.compared[i]]; ct[i] = ts[sc.compared[i]]; }
    std::vector<std::uint32_t>& count = sc.counts;
    count.assign(ne, 0);
    for(std::size_t k = 0; k < ne; ++k)
    {
      const float* cp = row(ss[k]);
      const float* cq = row(ts[k]);
      std::uint32_t c = 0;
      for(std::size_t l = 0; l < first; ++l)
        c += std::uint32_t(tol(cp[cs[l]], cq[ct[l]]) & tol(cq[cs[l]], cp[ct[l]]));
      count[k] = c;
    }
    // phase 2: the other compared pairs, least popular first (popularity of a
    // compared pair: its own phase-1 count)
    std::vector<std::uint32_t>& order = sc.order;
    order.resize(nc - first);
    for(std::size_t i = first; i < nc; ++i) order[i - first] = std::uint32_t(i);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y)
                     { return count[sc.compared[x]] < count[sc.compared[y]]; });
    std::vector<std::uint32_t>& os = sc.os;
    std::vector<std::uint32_t>& ot = sc.ot;
    os.resize(order.size());
    ot.resize(order.size());
    for(std::size_t i = 0; i < order.size(); ++i) { os[i] = cs[order[i]]; ot[i] = ct[order[i]]; }

    const std::size_t rest = order.size();
    const std::size_t chunk = 16;
    std::size_t out = 0;
    for(std::size_t k = 0; k < ne; ++k)
    {
      std::size_t c = count[k];
      bool pass = c >= needed;
      if(!pass && c + rest >= needed)
      {
        const float* cp = row(ss[k]);
        const float* cq = row(ts[k]);
        for(std::size_t l0 = 0; l0 < rest; l0 += chunk)
        {
          const std::size_t l1 = (std::min)(rest, l0 + chunk);
          for(std::size_t l = l0; l < l1; ++l)
            c += std::size_t(tol(cp[os[l]], cq[ot[l]]) & tol(cq[os[l]], cp[ot[l]]));
#ifdef CGAL_IRS_VOTING_STATS
          sc.stat_axial_checks += l1 - l0;
#endif
          if(c >= needed) { pass = true; break; }
          if(c + (rest - l1) < needed) break;
        }
      }
#ifdef CGAL_IRS_VOTING_STATS
      sc.stat_axial_checks += first;
      sc.stat_axial_pairs += 1;
      sc.stat_axial_e2 += nc;
#endif
      if(pass)
        sc.kept[out++] = sc.kept[k];
    }
    sc.kept.resize(out);
  }

  const Voting_setup& s_;
  std::size_t words_per_row_ = 0;
  std::vector<std::uint64_t> similar_;
  std::vector<std::size_t> first_offsets_;
  std::vector<std::uint32_t> partners_;
  bool use_pair_scan_ = true;
  bool parallel_ = false;
  std::vector<std::size_t> neighbor_offsets_;
  std::vector<std::uint32_t> neighbors_;
  std::vector<std::size_t> block_offsets_, block_vertices_, block_adj_offsets_, block_adj_;
  std::vector<float> block_bound_; // L(x, B), sample-major
  std::vector<float> dss_t_;       // dss transposed
};

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_VOTING_KERNEL_H
