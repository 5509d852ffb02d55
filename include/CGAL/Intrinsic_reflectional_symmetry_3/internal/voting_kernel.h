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

#include <CGAL/use.h>

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
// - beta(a,b): vertex blocks of 16 (a Voting_index, which depends only on
//   the mesh and D and can be shared by several transforms, holds them and
//   per-block bounds with the distances to each block's first vertex). Per
//   pair, the sign of f = d(a,.) - d(b,.) over a block comes from the bound
//   or from a read of the block's vertices in the rows of D, as bit masks;
//   crossing edges are found with the masks (inside a block: a per-vertex
//   neighbour mask; between blocks: only on the blocks that are mixed or
//   next to a block of the opposite sign), and f is only read again at the
//   ends of the crossing edges;
// - the caller groups the voting pairs by midpoint m, so that the column
//   D(., m) (a cache miss per sample) is read once per midpoint;
// - the three m'-independent distance tests: d(p,m) ~ d(q,m), which does not
//   depend on {a,b}, once per midpoint over all similar pairs; then, per
//   pair, one flat, branch-free scan of the pairs that passed it against
//   per-sample windows (or a grid range query over (d(b,q), d(a,q)) when the
//   similar pairs are many), exact tests on the hits;
// - locality (DBSCAN) and the axial counts once per {a,b}: DBSCAN with
//   precomputed sample neighbourhoods; the axial counts compared pair by
//   compared pair (least popular first) for all undecided pairs at once, on
//   rows of the sample matrix whose columns are in a spatially coherent
//   sample order, each pair leaving as soon as its verdict is certain;
// - the loop over m' in beta only evaluates d(p,m') ~ d(q,m') (loads without
//   branches in between) and the Gaussian of the pairs that pass.
// Votes are summed in the order of the canonical pair list, as the reference
// does, so mu and tau are bit-identical to it.
// Define CGAL_IRS_VOTING_STATS for a few extra counters (profiling only).

#ifndef CGAL_IRS_VOTING_BLOCK_SIZE
#define CGAL_IRS_VOTING_BLOCK_SIZE 16 // vertices per block of the beta search
#endif

#ifndef CGAL_IRS_VOTING_STAGE
#define CGAL_IRS_VOTING_STAGE // profiling builds define it as a no-inline attribute
#endif

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

// index of the lowest set bit of x != 0 (x: 32 or 64 bits)
template <class Unsigned>
inline int ctz(Unsigned x)
{
#if defined(__GNUC__) || defined(__clang__)
  return sizeof(Unsigned) == 8 ? __builtin_ctzll(std::uint64_t(x)) : __builtin_ctz(std::uint32_t(x));
#else
  int k = 0;
  while(!(x & 1u)) { x >>= 1; ++k; }
  return k;
#endif
}

// appends the indices of the set bits of words [lo, hi] of `bits` to `out`,
// in increasing order, and clears those words
template <class Container>
void take_set_bits(std::uint64_t* bits, std::size_t lo, std::size_t hi, Container& out)
{
  for(std::size_t w = lo; w <= hi; ++w)
  {
    for(std::uint64_t x = bits[w]; x != 0; x &= x - 1)
      out.push_back(64 * w + std::size_t(ctz(x)));
    bits[w] = 0;
  }
}

// f(i) for i in [0, n), in parallel if `parallel`; f must be thread-safe
template <class F>
void for_each_index(bool parallel, std::size_t n, F f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& range) {
      for(std::size_t i = range.begin(); i != range.end(); ++i) f(i);
    });
    return;
  }
#else
  CGAL_USE(parallel);
#endif
  for(std::size_t i = 0; i < n; ++i) f(i);
}

/// What the fast voting precomputes from the mesh and the distance matrix
/// alone (not from the similar pairs nor the filter parameters): vertex
/// blocks with their edge lists and per-sample distance bounds (for beta),
/// and the sample matrix with its columns in a spatially coherent order (for
/// the axial-sym counts). Several transforms on the same (mesh, D) with
/// other similar pairs or parameters can share one index.
class Voting_index
{
public:
  Voting_index() = default;

  // `parallel`: build with TBB (the result does not depend on it)
  Voting_index(const Voting_setup& s, bool parallel)
    : D_(s.D), number_of_vertices_(s.mesh.number_of_vertices), number_of_samples_(s.number_of_samples),
      parallel_(parallel)
  {
    spatial_order(s);
    const std::size_t n = number_of_samples_;
    rows_.resize(n * n);
    for_each_index(n, [&](std::size_t i) {
      float* out = rows_.data() + i * n;
      const float* in = s.dss.row(i);
      for(std::size_t j = 0; j < n; ++j)
        out[rank_[j]] = in[j];
    });
    build_blocks(s.mesh);
  }

  /// True if this index was built for `s`'s distance matrix and mesh size.
  bool fits(const Voting_setup& s) const
  {
    return D_ == s.D && number_of_vertices_ == s.mesh.number_of_vertices &&
           number_of_samples_ == s.number_of_samples;
  }

  std::size_t number_of_blocks() const { return block_offsets_.size() - 1; }

  template <class F>
  void for_each_index(std::size_t n, F f) const { internal::for_each_index(parallel_, n, f); }

  const Geodesic_distance_matrix* D_ = nullptr;
  std::size_t number_of_vertices_ = 0, number_of_samples_ = 0;
  bool parallel_ = false;
  // blocks: vertices of block B at block_vertices_[block_offsets_[B] .. block_offsets_[B+1])
  std::vector<std::uint32_t> block_offsets_, block_vertices_;
  // neighbours inside the block of each position, as a bit mask
  std::vector<std::uint32_t> internal_mask_;
  // per block, its edges to other blocks: (position here, position there,
  // other block, local bit here | local bit there << 8), flat
  std::vector<std::uint32_t> ext_offsets_, ext_;
  // pairs of adjacent blocks (B1 < B2), flat
  std::vector<std::uint32_t> block_pairs_;
  std::vector<std::uint32_t> position_; // position of each vertex in the block order
  std::vector<float> block_info_;   // (d(x, first vertex of B), L(x, B)), sample-major
  std::vector<float> rows_;         // dss, columns in the order rank_
  std::vector<std::uint32_t> rank_; // position of each sample in a spatially coherent order

private:
  // A spatially coherent order of the samples: recursive bisection of the
  // sample set by the sign of d(x,.) - d(y,.) for two far apart samples x, y
  // (median split), down to groups of 16. Only the memory layout depends on it.
  void spatial_order(const Voting_setup& s)
  {
    const Sample_distance_matrix& dss = s.dss;
    const std::size_t n = s.number_of_samples;
    std::vector<std::uint32_t> order(n);
    for(std::size_t i = 0; i < n; ++i) order[i] = std::uint32_t(i);
    // finite stand-in for distances to other components (keeps the keys comparable)
    auto d = [&](std::size_t x, std::size_t i) {
      const float v = dss(x, i);
      return std::isfinite(v) ? double(v) : 1e30;
    };
    std::vector<std::pair<std::size_t, std::size_t>> todo(1, std::make_pair(std::size_t(0), n));
    while(!todo.empty())
    {
      const std::size_t lo = todo.back().first, hi = todo.back().second;
      todo.pop_back();
      if(hi - lo <= 16) continue;
      std::size_t x = order[lo], y = order[lo];
      double far = -1.;
      for(std::size_t k = lo; k < hi; ++k)
        if(d(order[lo], order[k]) > far) { far = d(order[lo], order[k]); x = order[k]; }
      far = -1.;
      for(std::size_t k = lo; k < hi; ++k)
        if(d(x, order[k]) > far) { far = d(x, order[k]); y = order[k]; }
      const std::size_t mid = lo + (hi - lo) / 2;
      std::nth_element(order.begin() + lo, order.begin() + mid, order.begin() + hi,
                       [&](std::uint32_t i, std::uint32_t j) {
                         const double ki = d(x, i) - d(y, i), kj = d(x, j) - d(y, j);
                         return ki < kj || (ki == kj && i < j);
                       });
      todo.emplace_back(lo, mid);
      todo.emplace_back(mid, hi);
    }
    rank_.resize(n);
    for(std::size_t i = 0; i < n; ++i) rank_[order[i]] = std::uint32_t(i);
  }

  // Vertex blocks of about `block_size` vertices, grown by breadth-first
  // search so that they are compact on the surface whatever the vertex order,
  // and, for every sample x and block B with first vertex c, a bound
  // L(x, B) >= |d(x, v) - d(x, c)| over v in B, read from D itself (so no
  // Lipschitz assumption on the oracle). Then |f(v) - f(c)| <= L(a,B) + L(b,B),
  // and a block where |f(c)| exceeds that bound has one strict sign throughout.
  void build_blocks(const Voting_mesh& mesh)
  {
    const std::size_t nv = mesh.number_of_vertices;
    const std::size_t block_size = CGAL_IRS_VOTING_BLOCK_SIZE;
    static_assert(CGAL_IRS_VOTING_BLOCK_SIZE >= 1 && CGAL_IRS_VOTING_BLOCK_SIZE <= 32, "blocks are 32-bit masks");
    const std::uint32_t none = std::uint32_t(-1);
    std::vector<std::uint32_t> block_of(nv, none);
    block_offsets_.assign(1, 0);
    std::vector<std::size_t> queue;
    for(std::size_t seed = 0; seed < nv; ++seed)
    {
      if(block_of[seed] != none) continue;
      const std::uint32_t blk = std::uint32_t(block_offsets_.size() - 1);
      queue.assign(1, seed);
      block_of[seed] = blk;
      std::size_t count = 1;
      for(std::size_t h = 0; h < queue.size() && count < block_size; ++h)
      {
        const std::size_t v = queue[h];
        for(std::size_t k = mesh.adjacency_offsets[v]; k < mesh.adjacency_offsets[v + 1] && count < block_size; ++k)
        {
          const std::size_t u = mesh.adjacency[k];
          if(block_of[u] != none) continue;
          block_of[u] = blk;
          queue.push_back(u);
          ++count;
        }
      }
      for(std::size_t v : queue) block_vertices_.push_back(std::uint32_t(v));
      block_offsets_.push_back(std::uint32_t(block_vertices_.size()));
    }
    const std::size_t nblocks = block_offsets_.size() - 1;
    position_.resize(nv);
    for(std::size_t k = 0; k < nv; ++k) position_[block_vertices_[k]] = std::uint32_t(k);
    // inside a block: for each position, the mask of its neighbours in the
    // block (bit = position - first position of the block); between blocks:
    // per block, the edges to other blocks as (position here, position
    // there, other block, local bits), every such edge in both blocks' lists
    internal_mask_.assign(nv, 0);
    ext_offsets_.assign(nblocks + 1, 0);
    for(const auto& e : mesh.edges)
    {
      const std::uint32_t bu = block_of[e.first], bv = block_of[e.second];
      const std::uint32_t pu = position_[e.first], pv = position_[e.second];
      if(bu == bv)
      {
        internal_mask_[pu] |= std::uint32_t(1) << (pv - block_offsets_[bu]);
        internal_mask_[pv] |= std::uint32_t(1) << (pu - block_offsets_[bu]);
      }
      else { ++ext_offsets_[bu + 1]; ++ext_offsets_[bv + 1]; }
    }
    for(std::size_t blk = 0; blk < nblocks; ++blk)
      ext_offsets_[blk + 1] += ext_offsets_[blk];
    ext_.resize(4 * std::size_t(ext_offsets_.back()));
    std::vector<std::uint32_t> fill(ext_offsets_.begin(), ext_offsets_.end() - 1);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> bpairs;
    auto put = [&](std::uint32_t bx, std::uint32_t px, std::uint32_t by, std::uint32_t py) {
      const std::size_t k = fill[bx]++;
      ext_[4 * k] = px;
      ext_[4 * k + 1] = py;
      ext_[4 * k + 2] = by;
      ext_[4 * k + 3] = (px - block_offsets_[bx]) | ((py - block_offsets_[by]) << 8);
    };
    for(const auto& e : mesh.edges)
    {
      const std::uint32_t bu = block_of[e.first], bv = block_of[e.second];
      if(bu == bv) continue;
      const std::uint32_t pu = position_[e.first], pv = position_[e.second];
      put(bu, pu, bv, pv);
      put(bv, pv, bu, pu);
      bpairs.emplace_back((std::min)(bu, bv), (std::max)(bu, bv));
    }
    std::sort(bpairs.begin(), bpairs.end());
    bpairs.erase(std::unique(bpairs.begin(), bpairs.end()), bpairs.end());
    for(const auto& bp : bpairs) { block_pairs_.push_back(bp.first); block_pairs_.push_back(bp.second); }

    // The bounds, read from the rows of D. (A copy of D in block order would
    // make the reads of a block contiguous, but its allocation and copy cost
    // more than they save: page faults on n x V floats, then reads of a few
    // blocks per pair. Even with 5,124 voting pairs, camel at 300 samples,
    // eps_SIM 0.2, the boundary stage took 0.19 s with the copy as without
    // it, and the copy 10-40 ms.) Each row is read in vertex order
    // (sequentially: the block order scatters the reads over the row), each
    // vertex raising the bound of its block. A term |d(x,v) - d(x,c)| is
    // computed without branches: infinite where exactly one of the two is
    // finite or either is NaN, 0 where both are infinite (another component),
    // so c's own term is 0 unless d(x,c) is NaN. (The maximum does not depend
    // on the order.)
    const std::size_t n = number_of_samples_;
    const float inf = std::numeric_limits<float>::infinity();
    block_info_.resize(2 * n * nblocks);
    for_each_index(n, [&](std::size_t x) {
      const float* r = D_->row(x);
      const std::uint32_t* bv = block_vertices_.data();
      const std::uint32_t* of = block_of.data();
      float* info = block_info_.data() + 2 * x * nblocks;
      for(std::size_t blk = 0; blk < nblocks; ++blk)
      {
        info[2 * blk] = r[bv[block_offsets_[blk]]];
        info[2 * blk + 1] = 0.f;
      }
      for(std::size_t v = 0; v < nv; ++v)
      {
        const std::uint32_t blk = of[v];
        const float dc = info[2 * blk], dv = r[v];
        const float e = dv == dc ? 0.f : std::abs(dv - dc);
        info[2 * blk + 1] = (std::max)(info[2 * blk + 1], e == e ? e : inf);
      }
      for(std::size_t blk = 0; blk < nblocks; ++blk)
      {
        const float bound = info[2 * blk + 1];
        // widened by more than the rounding of the difference
        info[2 * blk + 1] = float(double(bound) * (1. + 2e-6));
      }
    });
  }
};

class Fast_voting
{
  typedef std::chrono::steady_clock Clock;

public:
  enum Outcome { voted, disconnected, no_boundary, no_support };

  struct Scratch
  {
    std::vector<unsigned char> block_bits;    // beta: sign status of each block
    std::vector<unsigned char> block_scan;    // beta: blocks whose edges are tested
    std::vector<std::uint32_t> found;         // beta, with repetitions
    std::vector<std::uint64_t> vertex_bits;   // beta: a bit per vertex, zero between calls
    std::vector<std::uint32_t> undecided;     // beta: blocks the bounds leave undecided
    std::vector<std::uint32_t> negative_mask, positive_mask, zero_mask; // beta: signs of f per block
    std::vector<std::uint32_t> sample_stamp;  // membership in U
    std::vector<std::uint64_t> sample_bits;   // U as a bit set, zero between calls
    std::vector<std::uint32_t> sample_slot;   // index in U
    std::uint32_t sstamp = 0;
    std::vector<float> dist_to_m;             // D(x, m) for every sample x
    std::size_t loaded_midpoint = std::size_t(-1);
    std::vector<std::uint32_t> pairs_at_m;    // pair scan: the similar pairs (i, j) with d(i,m) ~ d(j,m), flat
    std::size_t number_of_pairs_at_m = 0;
    std::vector<float> coordinates;           // (d(a,x), d(b,x)) for every sample x
    std::vector<float> windows;               // pair scan: intervals per sample
    std::vector<std::uint32_t> hits;          // pair scan: pairs inside the windows
    std::vector<std::size_t> b_side, cell_start, cell_items;
    struct Candidate { std::size_t i, j, p, q; };
    std::vector<Candidate> candidates;
    std::vector<std::size_t> points;          // U, increasing sample indices
    std::vector<int> labels;
    Dbscan_buffers dbscan_buffers;
    std::vector<std::size_t> kept;            // indices into candidates
    std::vector<std::size_t> cursor;          // grid construction
    std::vector<std::uint32_t> ss, ts;        // the kept pairs' samples
    std::vector<std::uint32_t> counts, order, os, ot, rp, rq, active, axial_counts, line_start;
    std::vector<unsigned char> axial_pass;
    std::vector<std::size_t> compared;
    std::vector<std::uint32_t> pass;          // support: boundary positions that pass
    std::vector<float> pass_distance;
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
  // `shared`: a Voting_index built for the same (mesh, D), or nullptr
  explicit Fast_voting(const Voting_setup& s, bool parallel = false, const Voting_index* shared = nullptr)
    : s_(s), parallel_(parallel)
  {
    const std::size_t n = s.number_of_samples;
    // candidate pairs: by a scan of the similar pairs (P per voting pair)
    // unless they are many, by a range query over the samples otherwise
    use_pair_scan_ = s.similar_pairs.size() <= 32 * n;
    // the similar pairs as a flat array of 32-bit sample indices, for the scan
    if(use_pair_scan_)
    {
      pair_samples_.reserve(2 * s.similar_pairs.size());
      for(const auto& pr : s.similar_pairs)
      {
        pair_samples_.push_back(std::uint32_t(pr.first));
        pair_samples_.push_back(std::uint32_t(pr.second));
      }
    }
    else
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
    if(shared != nullptr && shared->fits(s))
      ix_ = shared;
    else
    {
      own_ = Voting_index(s, parallel);
      ix_ = &own_;
    }
  }

  template <class F>
  void for_each_index(std::size_t n, F f) const { internal::for_each_index(parallel_, n, f); }

  Scratch make_scratch() const
  {
    Scratch sc;
    sc.block_bits.assign(ix_->number_of_blocks(), 0);
    sc.block_scan.assign(ix_->number_of_blocks(), 0);
    sc.negative_mask.assign(ix_->number_of_blocks(), 0);
    sc.positive_mask.assign(ix_->number_of_blocks(), 0);
    sc.zero_mask.assign(ix_->number_of_blocks(), 0);
    sc.vertex_bits.assign((s_.mesh.number_of_vertices + 63) / 64, 0);
    sc.sample_stamp.assign(s_.number_of_samples, 0);
    sc.sample_bits.assign((s_.number_of_samples + 63) / 64, 0);
    sc.sample_slot.assign(s_.number_of_samples, 0);
    sc.dist_to_m.assign(s_.number_of_samples, 0.f);
    sc.coordinates.assign(2 * s_.number_of_samples, 0.f);
    sc.windows.assign(4 * s_.number_of_samples, 0.f);
    sc.pairs_at_m.assign(pair_samples_.size(), 0);
    sc.hits.assign(pair_samples_.size() / 2, 0);
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

  /// The whole vote of the pair {a, b} (a < b): boundary_and_midpoint(),
  /// load_midpoint() and support(), in that order.
  Outcome vote(std::size_t a, std::size_t b, Scratch& sc, std::size_t& midpoint,
               std::vector<std::size_t>& boundary, std::vector<double>& support_values,
               std::vector<std::pair<std::size_t, std::size_t>>& eligible) const
  {
    support_values.clear(); eligible.clear();
    const Outcome o = boundary_and_midpoint(a, b, sc, midpoint, boundary);
    if(o != voted)
      return o;
    load_midpoint(midpoint, sc);
    return support(a, b, midpoint, boundary, sc, support_values, eligible);
  }

  /// beta(a, b) and its midpoint m; `voted` if beta is not empty.
  Outcome boundary_and_midpoint(std::size_t a, std::size_t b, Scratch& sc, std::size_t& midpoint,
                                std::vector<std::size_t>& boundary) const
  {
    boundary.clear();
    if(!std::isfinite(s_.dss(a, b)))
      return disconnected;
    const float* ra = s_.D->row(a);
    const float* rb = s_.D->row(b);
    const Clock::time_point t0 = Clock::now();
    find_boundary(a, b, sc, boundary);
    if(!boundary.empty())
    {
      std::size_t m = boundary.front();
      double best = std::numeric_limits<double>::infinity();
      for(std::size_t v : boundary)
      {
        const double sum = double(ra[v]) + double(rb[v]);
        if(sum < best) { best = sum; m = v; }
      }
      midpoint = m;
    }
    sc.stage_seconds[0] += std::chrono::duration<double>(Clock::now() - t0).count();
    return boundary.empty() ? no_boundary : voted;
  }

  /// D(x, m) for every sample x, into the scratch. This column of D costs one
  /// cache miss per sample: the caller groups the voting pairs by midpoint
  /// (about ten pairs per midpoint on real shapes) and loads it once per group.
  void load_midpoint(std::size_t m, Scratch& sc) const
  {
    if(sc.loaded_midpoint == m)
      return;
    const Clock::time_point t0 = Clock::now();
    const Geodesic_distance_matrix& D = *s_.D;
    const std::size_t nv = D.number_of_vertices();
    const float* column = D.row(0) + m;
    float* to_m = sc.dist_to_m.data();
    for(std::size_t x = 0; x < s_.number_of_samples; ++x)
      to_m[x] = column[x * nv];
    sc.loaded_midpoint = m;
    if(use_pair_scan_)
    {
      // The test d(p,m) ~ d(q,m) does not depend on a, b nor on which of
      // the two samples is p: applied once here, it leaves the scans of the
      // group's pairs a fraction of the similar pairs (canonical order kept).
      const Distance_tolerance& tol = s_.settings.tolerance;
      const std::size_t np = pair_samples_.size() / 2;
      const std::uint32_t* ps = pair_samples_.data();
      std::uint32_t* out = sc.pairs_at_m.data(); // sized by make_scratch()
      std::size_t nm = 0;
      for(std::size_t k = 0; k < np; ++k)
      {
        const std::uint32_t i = ps[2 * k], j = ps[2 * k + 1];
        out[2 * nm] = i;
        out[2 * nm + 1] = j;
        nm += std::size_t(tol(to_m[i], to_m[j]));
      }
      sc.number_of_pairs_at_m = nm;
    }
    sc.stage_seconds[1] += std::chrono::duration<double>(Clock::now() - t0).count();
  }

  /// The filters and mu along beta for the pair {a, b} whose boundary and
  /// midpoint are given; load_midpoint(midpoint) must have been called.
  Outcome support(std::size_t a, std::size_t b, std::size_t m, const std::vector<std::size_t>& boundary,
                  Scratch& sc, std::vector<double>& support_values,
                  std::vector<std::pair<std::size_t, std::size_t>>& eligible) const
  {
    support_values.clear(); eligible.clear();
    sc.number_of_candidates = sc.number_after_locality = sc.number_after_axial = 0;
    CGAL_assertion(sc.loaded_midpoint == m);
    const Geodesic_distance_matrix& D = *s_.D;
    Clock::time_point t0 = Clock::now(), t1;
    auto lap = [&](int stage) {
      t1 = Clock::now();
      sc.stage_seconds[stage] += std::chrono::duration<double>(t1 - t0).count();
      t0 = t1;
    };

    find_candidates(a, b, sc);
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
    support_values.assign(boundary.size(), 0.);
    const Distance_tolerance& tol = s_.settings.tolerance;
    const double inv_sigma2 = s_.settings.inv_sigma2;
    const std::size_t nb = boundary.size();
    // the loads from D are cache misses: they are issued without branches
    // in between (so that they overlap), the few that pass are weighted after
    std::vector<std::uint32_t>& pass = sc.pass;
    std::vector<float>& pd = sc.pass_distance;
    pass.resize(nb);
    pd.resize(nb);
    for(std::size_t k : sc.kept)
    {
      const auto& c = sc.candidates[k];
      eligible.emplace_back(c.p, c.q);
      const float* rp = D.row(c.p);
      const float* rq = D.row(c.q);
      std::size_t np = 0;
      for(std::size_t i = 0; i < nb; ++i)
      {
        const float dp = rp[boundary[i]], dq = rq[boundary[i]];
        pass[np] = std::uint32_t(i);
        pd[np] = dp;
        np += std::size_t(tol(dp, dq));
      }
      for(std::size_t j = 0; j < np; ++j)
        support_values[pass[j]] += gaussian_weight(pd[j], inv_sigma2);
    }
    lap(4);
    return voted;
  }

private:
  CGAL_IRS_VOTING_STAGE void find_boundary(std::size_t a, std::size_t b, Scratch& sc,
                                           std::vector<std::size_t>& boundary) const
  {
    const Voting_index& ix = *ix_;
    const std::size_t nblocks = ix.number_of_blocks();
    const std::uint32_t* offsets = ix.block_offsets_.data();
    const std::uint32_t* bverts = ix.block_vertices_.data();
    // (d(x, c), L(x, B)) for the first vertex c of each block B, for x = a and b
    const float* ia = ix.block_info_.data() + 2 * a * nblocks;
    const float* ib = ix.block_info_.data() + 2 * b * nblocks;
    // f is evaluated where needed: at the block centres from the table, and at
    // the vertices of the few blocks near the bisector from the rows of D
    // (f at position k is f at vertex bverts[k])
    const float* pa = s_.D->row(a);
    const float* pb = s_.D->row(b);
    auto f = [&](std::size_t k) { return bisector_value(pa, pb, bverts[k]); };
    unsigned char* status_of = sc.block_bits.data();
    unsigned char* scan = sc.block_scan.data();
    // per block, which of its vertices (bit = position in the block) have
    // f < 0, f > 0, f == 0 (none of them: f is NaN, another component)
    std::uint32_t* neg = sc.negative_mask.data();
    std::uint32_t* pos = sc.positive_mask.data();
    std::uint32_t* zero = sc.zero_mask.data();
    // pass 1: the sign of f over each block: 1: f < 0 throughout, 2: f > 0
    // throughout, 3: no finite value (another component), 4: mixed or zero.
    // The bound decides most blocks from their first vertex alone (then f is
    // finite and of one strict sign at every vertex of the block); the others
    // (0 until then) are classified vertex by vertex once all the blocks have
    // been seen, their reads of the rows of a and b (cache misses: the rows
    // change at every pair) prefetched meanwhile.
    std::vector<std::uint32_t>& undecided = sc.undecided;
    undecided.clear();
    for(std::size_t blk = 0; blk < nblocks; ++blk)
    {
      const float la = ia[2 * blk + 1], lb = ib[2 * blk + 1];
      const float fcf = ia[2 * blk] - ib[2 * blk]; // == f(c)
      const std::uint32_t size = offsets[blk + 1] - offsets[blk];
      const std::uint32_t full = size >= 32 ? ~std::uint32_t(0) : (std::uint32_t(1) << size) - 1;
      unsigned char status = 0;
      if(std::isnan(fcf))
        status = (std::isfinite(la) && std::isfinite(lb)) ? 3 : 0;
      else
      {
        // the margin covers the rounding of f(c) to float
        const double fc = fcf;
        const double bound = double(la) + double(lb) + 1e-6 * std::abs(fc);
        if(fc < -bound) status = 1;
        else if(fc > bound) status = 2;
      }
      if(status == 0)
      {
        undecided.push_back(std::uint32_t(blk));
#if defined(__GNUC__) || defined(__clang__)
        for(std::uint32_t k = offsets[blk]; k < offsets[blk + 1]; ++k)
        {
          __builtin_prefetch(pa + bverts[k]);
          __builtin_prefetch(pb + bverts[k]);
        }
#endif
      }
      status_of[blk] = status;
      scan[blk] = 0;
      neg[blk] = status == 1 ? full : 0; pos[blk] = status == 2 ? full : 0; zero[blk] = 0;
    }
    for(std::uint32_t blk : undecided)
    {
      const std::uint32_t first = offsets[blk], size = offsets[blk + 1] - first;
      std::uint32_t n_mask = 0, p_mask = 0, z_mask = 0;
      for(std::uint32_t k = 0; k < size; ++k)
      {
        const float fv = f(first + k);
        n_mask |= std::uint32_t(fv < 0.f) << k;
        p_mask |= std::uint32_t(fv > 0.f) << k;
        z_mask |= std::uint32_t(fv == 0.f) << k;
      }
      const unsigned bits = unsigned(n_mask != 0) | (unsigned(p_mask != 0) << 1) | (unsigned(z_mask != 0) << 2);
      const unsigned char status = (bits == 1 || bits == 2) ? (unsigned char)bits : (bits == 0 ? 3 : 4);
      status_of[blk] = status;
      scan[blk] = (unsigned char)(status == 4);
      neg[blk] = n_mask; pos[blk] = p_mask; zero[blk] = z_mask;
    }
    // A crossing edge either has an endpoint in a mixed block, or joins two
    // blocks of opposite strict signs (statuses 1 and 2: xor 3): both are scanned.
    const std::uint32_t* bp = ix.block_pairs_.data();
    const std::size_t nbp = ix.block_pairs_.size() / 2;
    for(std::size_t k = 0; k < nbp; ++k)
    {
      const std::uint32_t x = bp[2 * k], y = bp[2 * k + 1];
      const unsigned char opposite = (unsigned char)((status_of[x] ^ status_of[y]) == 3);
      scan[x] |= opposite;
      scan[y] |= opposite;
    }
    // pass 2: on the scanned blocks, the zeros of f and the crossing edges
    // (f < 0 at one end, f > 0 at the other), found with the sign masks; only
    // the crossing edges read f again, to pick their endpoint in beta
    std::vector<std::uint32_t>& found = sc.found;
    const std::uint32_t* ext_offsets = ix.ext_offsets_.data();
    const std::uint32_t* ext = ix.ext_.data();
    const std::uint32_t* inside = ix.internal_mask_.data();
    std::size_t nf = 0;
    // bisector_endpoint() of a crossing edge, by positions
    auto endpoint = [&](std::uint32_t pu, std::uint32_t pv) {
      const std::uint32_t u = bverts[pu], v = bverts[pv];
      const float au = std::abs(f(pu)), av = std::abs(f(pv));
      return au < av ? u : (av < au ? v : (std::min)(u, v));
    };
    auto push = [&](std::uint32_t w) {
      if(nf == found.size()) found.resize(2 * nf + 64);
      found[nf++] = w;
    };
    for(std::size_t blk = 0; blk < nblocks; ++blk)
    {
      if(!scan[blk] || status_of[blk] == 3) continue;
#ifdef CGAL_IRS_VOTING_STATS
      ++sc.stat_scanned_blocks; sc.stat_unknown_blocks += (status_of[blk] == 4);
#endif
      const std::uint32_t first = offsets[blk];
      const std::uint32_t nb = neg[blk], pb_ = pos[blk];
      // zeros, and the edges inside the block, from their end where f < 0
      // (a block of one strict sign has neither)
      if(status_of[blk] == 4)
      {
        for(std::uint32_t z = zero[blk]; z != 0; z &= z - 1)
          push(bverts[first + std::uint32_t(ctz(z))]);
        for(std::uint32_t m = nb; m != 0; m &= m - 1)
        {
          const std::uint32_t k = std::uint32_t(ctz(m));
          for(std::uint32_t c = inside[first + k] & pb_; c != 0; c &= c - 1)
            push(endpoint(first + k, first + std::uint32_t(ctz(c))));
        }
      }
      // edges to other blocks (an edge between two scanned blocks is found
      // from both: the set of vertices below drops the repetition, which
      // costs less than a test per edge)
      for(std::size_t k = ext_offsets[blk]; k < ext_offsets[blk + 1]; ++k)
      {
        const std::uint32_t other = ext[4 * k + 2];
        const std::uint32_t bits = ext[4 * k + 3], lu = bits & 0xff, lv = bits >> 8;
        const std::uint32_t cross = (((nb >> lu) & (pos[other] >> lv)) | ((pb_ >> lu) & (neg[other] >> lv))) & 1u;
        if(cross)
          push(endpoint(ext[4 * k], ext[4 * k + 1]));
      }
    }
    // sorted and without repetitions: through a bit set of the vertices
    // (a sweep of V / 64 words is cheaper than sorting the found vertices)
    std::uint64_t* bits = sc.vertex_bits.data();
    std::size_t lo = sc.vertex_bits.size(), hi = 0;
    for(std::size_t k = 0; k < nf; ++k)
    {
      const std::size_t w = found[k] / 64;
      bits[w] |= std::uint64_t(1) << (found[k] % 64);
      lo = (std::min)(lo, w);
      hi = (std::max)(hi, w);
    }
    boundary.clear();
    if(nf > 0) take_set_bits(bits, lo, hi, boundary);
  }

  // Pairs {p,q} (p on a's side) that are similar and pass the three
  // m'-independent distance tests, in canonical order.
  CGAL_IRS_VOTING_STAGE void find_candidates(std::size_t a, std::size_t b, Scratch& sc) const
  {
    const Sample_distance_matrix& dss = s_.dss;
    const Distance_tolerance& tol = s_.settings.tolerance;
    const std::size_t n = s_.number_of_samples;
    const float* dA = dss.row(a);
    const float* dB = dss.row(b);

    sc.candidates.clear();
    // d(x, m) for every sample x: loaded by load_midpoint(m)
    const float* to_m = sc.dist_to_m.data();
    // the last m'-independent distance test (range queries) of a pair p (a's
    // side), q (b's side) that already passed d(a,p) ~ d(b,q) and d(a,q) ~ d(b,p)
    auto test_at_m = [&](std::size_t p, std::size_t q) {
      const float dpm = to_m[p], dqm = to_m[q];
      if(!tol(dpm, dqm))
        return;
      sc.candidates.push_back({(std::min)(p, q), (std::max)(p, q), p, q});
    };

    if(use_pair_scan_)
    {
      // A scan of the similar pairs {i, j} (i < j) that passed the test at m
      // (load_midpoint()), in their canonical order (the output needs no
      // sort). Whichever of i and j is on a's side, the two tests say
      // d(b,j) ~ d(a,i) and d(a,j) ~ d(b,i): a window test on j's
      // coordinates (d(a,j), d(b,j)) against conservative intervals of the
      // test computed once per sample i. The scan is one flat loop
      // without branches that compacts the few pairs inside both windows;
      // the exact tests then run on those.
      float* co = sc.coordinates.data(); // (d(a,x), d(b,x))
      float* win = sc.windows.data();    // intervals for d(b,j) and d(a,j)
      const float eps = float(tol.eps), floor = float(tol.floor);
      const float inv = 1.f / (1.f - eps);
      for(std::size_t x = 0; x < n; ++x)
      {
        const float ax = dA[x], bx = dB[x];
        co[2 * x] = ax; co[2 * x + 1] = bx;
        // Distance_tolerance::range() in single precision, with a slack of
        // 1e-5 that covers the rounding (a window only has to be conservative);
        // NaN bounds (infinite distances) reject everything, as the exact test does
        const float sa = 1e-5f * (ax + floor) + 1e-30f, sb = 1e-5f * (bx + floor) + 1e-30f;
        win[4 * x] = (std::min)(ax * (1.f - eps), ax - floor) - sa;
        win[4 * x + 1] = (std::max)(ax * inv, ax + floor) + sa;
        win[4 * x + 2] = (std::min)(bx * (1.f - eps), bx - floor) - sb;
        win[4 * x + 3] = (std::max)(bx * inv, bx + floor) + sb;
      }
      const std::size_t np = sc.number_of_pairs_at_m;
      std::uint32_t* hits = sc.hits.data(); // sized by make_scratch()
      std::size_t nh = 0;
      const std::uint32_t* ps = sc.pairs_at_m.data();
      for(std::size_t k = 0; k < np; ++k)
      {
        const std::uint32_t i = ps[2 * k], j = ps[2 * k + 1];
        const float aj = co[2 * j], bj = co[2 * j + 1];
        const float* w = win + 4 * std::size_t(i);
        hits[nh] = std::uint32_t(k);
        nh += std::size_t((bj >= w[0]) & (bj <= w[1]) & (aj >= w[2]) & (aj <= w[3]));
      }
      for(std::size_t h = 0; h < nh; ++h)
      {
        const std::uint32_t i = ps[2 * std::size_t(hits[h])], j = ps[2 * std::size_t(hits[h]) + 1];
        const float ai = co[2 * i], bi = co[2 * i + 1], aj = co[2 * j], bj = co[2 * j + 1];
        // (p, q) = (i, j) if i is strictly on a's side and j strictly on b's
        // side, (j, i) in the opposite case
        std::size_t p, q;
        if(ai < bi && bj < aj) { p = i; q = j; }
        else if(bi < ai && aj < bj) { p = j; q = i; }
        else continue;
        if(tol(co[2 * p], co[2 * q + 1]) && tol(co[2 * p + 1], co[2 * q]))
          sc.candidates.push_back({i, j, p, q});
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
    std::uint64_t* bits = sc.sample_bits.data();
    for(const auto& c : sc.candidates)
    {
      sc.sample_stamp[c.p] = sc.sstamp;
      sc.sample_stamp[c.q] = sc.sstamp;
      bits[c.p / 64] |= std::uint64_t(1) << (c.p % 64);
      bits[c.q / 64] |= std::uint64_t(1) << (c.q % 64);
    }
    // U in increasing order, by a sweep of a bit set (cheaper than a sort,
    // and than a sweep of the stamps)
    if(!sc.sample_bits.empty()) take_set_bits(bits, 0, sc.sample_bits.size() - 1, sc.points);
    for(std::size_t i = 0; i < sc.points.size(); ++i)
      sc.sample_slot[sc.points[i]] = i;

    const std::uint32_t st = sc.sstamp;
    auto neighbors = [&](std::size_t i, std::vector<std::size_t>& out) {
      const std::size_t u = sc.points[i];
      const std::size_t k0 = neighbor_offsets_[u], k1 = neighbor_offsets_[u + 1];
      // one resize and a branch-free compaction, not a push_back per neighbour
      const std::size_t old = out.size();
      out.resize(old + (k1 - k0));
      std::size_t* o = out.data() + old;
      std::size_t no = 0;
      for(std::size_t k = k0; k < k1; ++k)
      {
        const std::size_t w = neighbors_[k];
        o[no] = sc.sample_slot[w];
        no += std::size_t(sc.sample_stamp[w] == st);
      }
      out.resize(old + no);
    };
    dbscan(sc.points.size(), s_.settings.locality_min_points, neighbors, sc.labels, sc.dbscan_buffers);

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
  // the compared pairs {s,t} (all kept pairs or an evenly spread sample of
  // them; itself included) have d(s,p) ~ d(t,q) and d(s,q) ~ d(t,p). The
  // count of a pair stops as soon as its verdict is certain, which gives the
  // verdict of the full count. The compared pairs are visited least
  // "popular" first (fewest agreements with the first 16 compared pairs):
  // they disagree with most pairs and settle the failing ones (most) early.
  // They are taken 16 at a time by all undecided pairs together, so that
  // their 32 rows of the sample matrix stay in cache (L2) while the pairs'
  // columns (in a spatially coherent order) are read. (16 rather than 8:
  // half the passes over the undecided pairs, and with the default eps_AXS a
  // failing pair needs 26 disagreements, so it seldom leaves earlier; 32
  // rows fit in L2, 64 do not and were measured slower.)
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
    // d(s, x) = rows_[s * n + rank_[x]]: the rows of the compared samples,
    // read at the columns of the pairs' samples
    auto row = [&](std::uint32_t s) { return ix_->rows_.data() + std::size_t(s) * n; };
    std::vector<std::uint32_t>& rp = sc.rp;
    std::vector<std::uint32_t>& rq = sc.rq;
    rp.resize(ne);
    rq.resize(ne);
    for(std::size_t k = 0; k < ne; ++k) { rp[k] = ix_->rank_[ss[k]]; rq[k] = ix_->rank_[ts[k]]; }
    auto agree = [&](std::size_t k, std::uint32_t s, std::uint32_t t) {
      const float* rs = row(s);
      const float* rt = row(t);
      return std::uint32_t(tol(rs[rp[k]], rt[rq[k]]) & tol(rs[rq[k]], rt[rp[k]]));
    };

    // popularity of each compared pair: its agreements with the first 16
    // compared pairs (the relation is symmetric up to the asymmetry of D;
    // 16 orders about as well as 32 at half the cost)
    const std::size_t chunk = 16;
    // agreements of the pair whose samples are at columns (cp, cq) with the
    // `chunk` pairs whose rows are srow, trow: loads first, then the tests in
    // a loop the compiler vectorises
    auto agreements = [&](const float* const* srow, const float* const* trow, std::uint32_t cp, std::uint32_t cq) {
      float sp[chunk], tq[chunk], sq[chunk], tp[chunk];
      for(std::size_t l = 0; l < chunk; ++l)
      {
        sp[l] = srow[l][cp]; tq[l] = trow[l][cq];
        sq[l] = srow[l][cq]; tp[l] = trow[l][cp];
      }
      std::uint32_t a = 0;
      for(std::size_t l = 0; l < chunk; ++l)
        a += std::uint32_t(tol(sp[l], tq[l]) & tol(sq[l], tp[l]));
      return a;
    };
    const std::size_t first = (std::min)(nc, chunk);
    std::vector<std::uint32_t>& count = sc.counts;
    count.assign(nc, 0);
    if(first == chunk)
    {
      const float* srow[chunk];
      const float* trow[chunk];
      for(std::size_t l = 0; l < chunk; ++l) { srow[l] = row(ss[sc.compared[l]]); trow[l] = row(ts[sc.compared[l]]); }
      for(std::size_t i = 0; i < nc; ++i)
        count[i] = agreements(srow, trow, rp[sc.compared[i]], rq[sc.compared[i]]);
    }
    else
      for(std::size_t i = 0; i < nc; ++i)
      {
        std::uint32_t c = 0;
        for(std::size_t l = 0; l < first; ++l)
          c += agree(sc.compared[i], ss[sc.compared[l]], ts[sc.compared[l]]);
        count[i] = c;
      }
    // the compared pairs are visited least popular first: they disagree with
    // most pairs and settle the failing ones (most) early
    std::vector<std::uint32_t>& order = sc.order;
    order.resize(nc);
    for(std::size_t i = 0; i < nc; ++i) order[i] = std::uint32_t(i);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y)
                     { return count[x] < count[y]; });
    std::vector<std::uint32_t>& os = sc.os;
    std::vector<std::uint32_t>& ot = sc.ot;
    os.resize(nc);
    ot.resize(nc);
    for(std::size_t i = 0; i < nc; ++i) { os[i] = ss[sc.compared[order[i]]]; ot[i] = ts[sc.compared[order[i]]]; }

    // All undecided pairs take the next few compared pairs together (their
    // rows stay in cache), in the order of their first sample's column; a
    // pair leaves as soon as its verdict is certain, which is the verdict of
    // the full count.
    // (A counting sort by the cache line of the column: the order only
    // matters for locality, and a comparison sort cost more than it saved.)
    std::vector<std::uint32_t>& active = sc.active;
    active.resize(ne);
    {
      std::vector<std::uint32_t>& start = sc.line_start;
      start.assign(n / 16 + 2, 0);
      for(std::size_t k = 0; k < ne; ++k) ++start[rp[k] / 16 + 1];
      for(std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
      for(std::size_t k = 0; k < ne; ++k) active[start[rp[k] / 16]++] = std::uint32_t(k);
    }
    std::vector<std::uint32_t>& c = sc.axial_counts;
    c.assign(ne, 0);
    std::vector<unsigned char>& pass = sc.axial_pass;
    pass.assign(ne, needed == 0 ? 1 : 0);
    if(needed == 0) active.clear();
    for(std::size_t l0 = 0; l0 < nc && !active.empty(); l0 += chunk)
    {
      const std::size_t l1 = (std::min)(nc, l0 + chunk);
      const std::size_t w = l1 - l0;
      const float* srow[chunk];
      const float* trow[chunk];
      for(std::size_t l = 0; l < w; ++l) { srow[l] = row(os[l0 + l]); trow[l] = row(ot[l0 + l]); }
      std::size_t out = 0;
      for(std::size_t idx = 0; idx < active.size(); ++idx)
      {
        const std::uint32_t k = active[idx];
        const std::uint32_t cp = rp[k], cq = rq[k];
        std::uint32_t ck = c[k];
        if(w == chunk)
          ck += agreements(srow, trow, cp, cq);
        else
          for(std::size_t l = l0; l < l1; ++l)
            ck += agree(k, os[l], ot[l]);
        c[k] = ck;
#ifdef CGAL_IRS_VOTING_STATS
        sc.stat_axial_checks += l1 - l0;
#endif
        if(ck >= needed) pass[k] = 1;
        else if(ck + (nc - l1) >= needed) active[out++] = k; // still undecided
      }
      active.resize(out);
    }
#ifdef CGAL_IRS_VOTING_STATS
    sc.stat_axial_pairs += ne;
    sc.stat_axial_e2 += ne * nc;
#endif
    std::size_t out = 0;
    for(std::size_t k = 0; k < ne; ++k)
      if(pass[k])
        sc.kept[out++] = sc.kept[k];
    sc.kept.resize(out);
  }

  const Voting_setup& s_;
  std::size_t words_per_row_ = 0;
  std::vector<std::uint64_t> similar_;
  std::vector<std::uint32_t> pair_samples_; // the similar pairs (i, j), flat
  bool use_pair_scan_ = true;
  bool parallel_ = false;
  std::vector<std::size_t> neighbor_offsets_;
  std::vector<std::uint32_t> neighbors_;
  Voting_index own_;                  // built here unless a shared one is given
  const Voting_index* ix_ = nullptr;
};

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_VOTING_KERNEL_H
