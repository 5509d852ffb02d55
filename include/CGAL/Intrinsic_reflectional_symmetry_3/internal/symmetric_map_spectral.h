// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SYMMETRIC_MAP_SPECTRAL_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SYMMETRIC_MAP_SPECTRAL_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_mesh.h>

#include <CGAL/for_each.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/MatOp/SymShiftInvert.h>
#include <Spectra/SymGEigsShiftSolver.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

// Spectral refinement of a mirror map: ZoomOut (Melzi, Ren, Rodola, Sharma,
// Wonka, Ovsjanikov, SIGGRAPH Asia 2019), with the functional map kept
// orthogonal. Why: the landmark matches of curves_mirror.h decide every
// vertex alone, so a patch can settle on a wrong but self-consistent answer
// (on FAUST tr_reg_002 the side of the head maps to itself: samples matched
// to themselves become landmarks that favour the identity nearby). A map
// that is a near-isometry is, in the basis of the Laplace-Beltrami
// eigenfunctions, a near-orthogonal matrix C; projecting the map on C and
// back, with the basis growing a few functions at a time, replaces such
// patches by what the rest of the map implies.
//
// The eigenfunctions are those of the cotangent Laplacian of the region (the
// faces whose three vertices are in it, Neumann boundary), with lumped
// masses, from Spectra's shift-and-invert Lanczos solver (deterministic: a
// fixed start vector). Nearest neighbours in the spectral embedding are found
// exactly, by blocked products of float matrices over fixed row blocks (so
// the result does not depend on the thread count); ties go to the smaller
// index. The iterations run on the samples of the region (ZoomOut's own
// speed-up), the last one on every vertex.
//
// Measured (symmetry_map_benchmark, 1000 samples, CR by the protocol of Kim
// et al. 2010; column CR0% is the same run without this step; seed 0, with
// the regions' tolerance 1.5 and the fixed-point rule of symmetric_map_dense.h):
// FAUST 98.98 -> 99.74 %, its posed shapes 98.15 -> 99.50 % (tr_reg_002
// 96.5 -> 99.9 %), SCAPE 84.34 -> 84.72 % (65.15 -> 66.79 % before the
// coarse-eigenfunction rule of the curve extraction); on
// FAUST (5K vertices) the step costs about 1.5 s on two cores. Every vertex
// of the region is compared with every other at the last size, so the cost
// grows as the square of the region's size.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

/// Eigenfunctions of a region's Laplacian (see region_spectrum()).
struct Region_spectrum
{
  std::vector<std::size_t> rows;  // vertex index of each row
  Eigen::MatrixXd basis;          // rows x k
  Eigen::VectorXd values;         // the k eigenvalues, increasing
  Eigen::VectorXd mass;           // per row, sum 1
};

/// The first eigenfunctions of the region's Laplacian (L phi = lambda M
/// phi), M-orthonormal (M: lumped masses, normalised to total 1), as the
/// columns of `basis`: `k` of them, or a quarter of the rows if that is
/// fewer; rows: the vertices of the region that lie on a face of it, in
/// increasing order. Returns false (and no rows) when that leaves fewer than
/// `minimum` functions or the solver does not converge.
inline bool region_spectrum(const Curves_mesh& m, const std::vector<unsigned char>& in_region, std::size_t k,
                            Region_spectrum& out, std::size_t minimum = 2)
{
  out = Region_spectrum();
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> row(m.number_of_vertices, none);
  std::vector<std::array<std::size_t, 3>> faces;
  for(const auto& f : m.faces)
    if(in_region[f[0]] && in_region[f[1]] && in_region[f[2]])
      faces.push_back(f);
  for(const auto& f : faces)
    for(std::size_t v : f)
      if(row[v] == none) row[v] = 0;
  for(std::size_t v = 0; v < m.number_of_vertices; ++v)
    if(row[v] != none) { row[v] = out.rows.size(); out.rows.push_back(v); }
  const std::size_t n = out.rows.size();
  k = (std::min)(k, n / 4);
  if(k < (std::max)(minimum, std::size_t(2))) { out.rows.clear(); return false; }

  std::vector<Eigen::Triplet<double>> lt;
  lt.reserve(12 * faces.size());
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(Eigen::Index(n));
  double total = 0.;
  for(const auto& f : faces)
  {
    const double a = triangle_area(m, f);
    if(!(a > 0.)) continue;
    total += a;
    for(int c = 0; c < 3; ++c)
    {
      mass[Eigen::Index(row[f[c]])] += a / 3.;
      // the cotangent of the angle at corner c weighs the opposite edge
      // (by hand: CGAL's per-corner cotangent is not documented, and its
      // cotangent Laplacians, in Heat_method_3 and PMP, are internal and
      // take a whole FaceGraph, not a region of these arrays)
      const auto& o = m.points[f[c]];
      const auto& p = m.points[f[(c + 1) % 3]];
      const auto& q = m.points[f[(c + 2) % 3]];
      const double u[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
      const double w[3] = {q[0] - o[0], q[1] - o[1], q[2] - o[2]};
      const double dot = u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
      const double w_ = 0.5 * dot / (2. * a); // |u x w| = 2 a
      const int i = int(row[f[(c + 1) % 3]]), j = int(row[f[(c + 2) % 3]]);
      lt.emplace_back(i, j, -w_);
      lt.emplace_back(j, i, -w_);
      lt.emplace_back(i, i, w_);
      lt.emplace_back(j, j, w_);
    }
  }
  if(!(total > 0.)) { out.rows.clear(); return false; }
  mass /= total;
  // a vertex whose faces all have zero area: a small mass keeps M definite
  const double floor = 1e-3 / double(n);
  for(Eigen::Index i = 0; i < mass.size(); ++i) mass[i] = (std::max)(mass[i], floor);
  const Eigen::Index size = Eigen::Index(n);
  Eigen::SparseMatrix<double> L(size, size), M(size, size);
  L.setFromTriplets(lt.begin(), lt.end());
  std::vector<Eigen::Triplet<double>> mt;
  for(Eigen::Index i = 0; i < mass.size(); ++i) mt.emplace_back(int(i), int(i), mass[i]);
  M.setFromTriplets(mt.begin(), mt.end());

  typedef Spectra::SymShiftInvert<double, Eigen::Sparse, Eigen::Sparse> Op;
  typedef Spectra::SparseSymMatProd<double> B_op;
  Op op(L, M);
  B_op bop(M);
  const Eigen::Index nev = Eigen::Index(k);
  const Eigen::Index ncv = (std::min)(Eigen::Index(n), 2 * nev + 1);
  // shift below 0: L - sigma M is then definite (L is semi-definite)
  Spectra::SymGEigsShiftSolver<Op, B_op, Spectra::GEigsMode::ShiftInvert> solver(op, bop, nev, ncv, -1e-3);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-8, Spectra::SortRule::SmallestAlge);
  if(solver.info() != Spectra::CompInfo::Successful) { out.rows.clear(); return false; }
  out.basis = solver.eigenvectors();
  out.values = solver.eigenvalues();
  out.mass = mass;
  return true;
}

/// For each row r of `query`, `image[r]` becomes the row of P nearest to
/// row r of P C (Euclidean; ties to the smaller row). Exact, by products of
/// float matrices over fixed blocks of 256 queries, so that the sums, and the
/// result, do not depend on the thread count. With `side` (by row: -1, 0 or
/// +1), a row on a side (+1 or -1) is never sent to a row on the same side
/// (a reflection fixes only its axis), unless no other row is left.
template <class ConcurrencyTag>
void nearest_rows(const Eigen::MatrixXd& P, const Eigen::MatrixXd& C, const std::vector<std::size_t>& query,
                  std::vector<std::size_t>& image, const std::vector<signed char>* side = nullptr)
{
  const std::size_t block = 256;
  const Eigen::Index n = P.rows();
  Eigen::MatrixXd Pq(Eigen::Index(query.size()), P.cols());
  for(std::size_t i = 0; i < query.size(); ++i) Pq.row(Eigen::Index(i)) = P.row(Eigen::Index(query[i]));
  const Eigen::MatrixXf Q = (Pq * C).cast<float>();
  const Eigen::MatrixXf Pf = P.cast<float>();
  const Eigen::VectorXf norms = Pf.rowwise().squaredNorm();
  std::vector<std::size_t> blocks((query.size() + block - 1) / block);
  std::iota(blocks.begin(), blocks.end(), std::size_t(0));
  CGAL::for_each<ConcurrencyTag>(blocks, [&](std::size_t b) {
    const Eigen::Index r0 = Eigen::Index(b * block);
    const Eigen::Index nr = (std::min)(Eigen::Index(block), Eigen::Index(query.size()) - r0);
    // one column per query, so that each query's scan reads contiguous memory
    const Eigen::MatrixXf S = Pf * Q.middleRows(r0, nr).transpose();
    for(Eigen::Index i = 0; i < nr; ++i)
    {
      // |P_j - Q_i|^2 - |Q_i|^2
      const std::size_t r = query[std::size_t(r0 + i)];
      const int own = side != nullptr ? (*side)[r] : 0;
      const float* column = S.col(i).data();
      float best = std::numeric_limits<float>::infinity(), best_same = best;
      std::size_t arg = std::size_t(n), arg_same = 0;
      for(Eigen::Index j = 0; j < n; ++j)
      {
        const float d = norms[j] - 2.f * column[j];
        if(own != 0 && (*side)[std::size_t(j)] == own)
        {
          if(d < best_same) { best_same = d; arg_same = std::size_t(j); }
        }
        else if(d < best) { best = d; arg = std::size_t(j); }
      }
      image[r] = arg < std::size_t(n) ? arg : arg_same;
    }
    return true;
  });
}

/// ZoomOut on the rows of `s`: `image[r]` (a row index) is the current
/// partner of row r; on return, the refined one. The basis grows from `k0`
/// functions by `step` up to `k1`; at each size k, with P the first k
/// functions, C = argmin ||P C - P[image]|| over the rows of `subset`, made
/// orthogonal (the nearest orthogonal matrix, by SVD: an isometry's map is
/// orthogonal in an orthonormal basis), and each row of `subset` takes as
/// partner the row of P nearest to its row of P C. At the last size every
/// row does. Why a subset: the nearest neighbours cost a product of
/// |subset| x rows x k per size; the samples of the region, spread evenly,
/// determine C as well as all rows do (all rows are used when the subset
/// has fewer than 2 k1 rows).
/// With `last_map`, the C of the last size is written there. With `held`,
/// those rows join the fit as their own partners, whatever `image` says
/// (points of the axis, which a reflection fixes).
template <class ConcurrencyTag>
void zoomout(const Region_spectrum& s, std::size_t k0, std::size_t k1, std::size_t step,
             const std::vector<std::size_t>& subset, std::vector<std::size_t>& image,
             const std::vector<signed char>* side = nullptr, Eigen::MatrixXd* last_map = nullptr,
             const std::vector<std::size_t>* held = nullptr)
{
  const std::size_t n = s.rows.size();
  k1 = (std::min)(k1, std::size_t(s.basis.cols()));
  k0 = (std::min)(k0, k1);
  if(n == 0 || k1 == 0 || step == 0) return;
  std::vector<std::size_t> all(n);
  std::iota(all.begin(), all.end(), std::size_t(0));
  const std::vector<std::size_t>& rows = subset.size() >= 2 * k1 ? subset : all;

  for(std::size_t k = k0;; k = (std::min)(k + step, k1))
  {
    const Eigen::MatrixXd P = s.basis.leftCols(Eigen::Index(k));
    const std::size_t nh = held != nullptr ? held->size() : 0;
    Eigen::MatrixXd A(Eigen::Index(rows.size() + nh), P.cols()), B(Eigen::Index(rows.size() + nh), P.cols());
    for(std::size_t i = 0; i < rows.size(); ++i)
    {
      A.row(Eigen::Index(i)) = P.row(Eigen::Index(rows[i]));
      B.row(Eigen::Index(i)) = P.row(Eigen::Index(image[rows[i]]));
    }
    for(std::size_t i = 0; i < nh; ++i)
      A.row(Eigen::Index(rows.size() + i)) = B.row(Eigen::Index(rows.size() + i)) =
        P.row(Eigen::Index((*held)[i]));
    // least squares would be (A^T A)^-1 A^T B; A^T A is near a multiple of
    // the identity for evenly spread rows, and the scale goes with the SVD
    Eigen::MatrixXd C = A.transpose() * B;
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(C, Eigen::ComputeFullU | Eigen::ComputeFullV);
    C = svd.matrixU() * svd.matrixV().transpose();
    nearest_rows<ConcurrencyTag>(P, C, k == k1 ? all : rows, image, side);
    if(k == k1)
    {
      if(last_map != nullptr) *last_map = C;
      break;
    }
  }
}

/// Refines the mirror partners `best` (vertex indices; `best[i]` for
/// `verts[i]`, the vertices of a region) by ZoomOut with up to
/// `number_of_eigenfunctions` functions (from 30, 5 at a time), iterating on
/// the samples of the region (`sample_vertices`, in farthest-point order;
/// the first 1000 of them). The vertices of the region on no face of it keep
/// their partner; so does every vertex when the region has too few vertices
/// (fewer than 4 per function, or fewer than 10 functions) or the eigensolver
/// does not converge (`ok()` is then false). The spectrum is computed once,
/// for any number of refinements.
class Spectral_refinement
{
public:
  Spectral_refinement(const Curves_mesh& m, const std::vector<std::size_t>& sample_vertices,
                      const std::vector<std::size_t>& verts, const std::vector<unsigned char>& in_region,
                      std::size_t number_of_eigenfunctions)
    : row_of_(m.number_of_vertices, none), slot_(m.number_of_vertices, none)
  {
    if(!region_spectrum(m, in_region, number_of_eigenfunctions, spec_, 10)) return;
    for(std::size_t r = 0; r < spec_.rows.size(); ++r) row_of_[spec_.rows[r]] = r;
    for(std::size_t i = 0; i < verts.size(); ++i) slot_[verts[i]] = i;
    // the first samples in farthest-point order are spread evenly; 1000 of
    // them fix C as well as 3000 do (FAUST: the same rates) at a third of the
    // cost of the nearest-row searches
    const std::size_t max_subset = 1000;
    for(std::size_t v : sample_vertices)
      if(row_of_[v] != none && subset_.size() < max_subset) subset_.push_back(row_of_[v]);
    std::sort(subset_.begin(), subset_.end());
    subset_.erase(std::unique(subset_.begin(), subset_.end()), subset_.end());
  }

  bool ok() const { return !spec_.rows.empty(); }

  /// Refines `best` (nothing if not `ok()`). With `vertex_side` (by vertex
  /// index: -1, 0 or +1), no vertex goes to a vertex on its own side
  /// (nearest_rows()); with `held_vertices`, those of the region join each
  /// fit as their own partners (zoomout()).
  template <class ConcurrencyTag>
  void refine(std::vector<std::size_t>& best, const std::vector<signed char>* vertex_side = nullptr,
              const std::vector<std::size_t>* held_vertices = nullptr) const
  {
    if(!ok()) return;
    std::vector<std::size_t> image(spec_.rows.size());
    for(std::size_t r = 0; r < spec_.rows.size(); ++r)
    {
      const std::size_t b = best[slot_[spec_.rows[r]]];
      image[r] = (b != none && row_of_[b] != none) ? row_of_[b] : r;
    }
    std::vector<signed char> side;
    if(vertex_side != nullptr)
      for(std::size_t v : spec_.rows) side.push_back((*vertex_side)[v]);
    std::vector<std::size_t> held;
    if(held_vertices != nullptr)
      for(std::size_t v : *held_vertices)
        if(row_of_[v] != none) held.push_back(row_of_[v]);
    zoomout<ConcurrencyTag>(spec_, 30, std::size_t(spec_.basis.cols()), 5, subset_, image,
                            vertex_side != nullptr ? &side : nullptr, nullptr,
                            held_vertices != nullptr ? &held : nullptr);
    for(std::size_t r = 0; r < spec_.rows.size(); ++r)
      best[slot_[spec_.rows[r]]] = spec_.rows[image[r]];
  }

private:
  static constexpr std::size_t none = std::size_t(-1);
  Region_spectrum spec_;
  std::vector<std::size_t> row_of_, slot_, subset_;
};

/// Spectral_refinement, once. Returns true if the map was refined.
template <class ConcurrencyTag>
bool spectral_refinement(const Curves_mesh& m, const std::vector<std::size_t>& sample_vertices,
                         const std::vector<std::size_t>& verts, const std::vector<unsigned char>& in_region,
                         std::size_t number_of_eigenfunctions, std::vector<std::size_t>& best,
                         const std::vector<signed char>* vertex_side = nullptr,
                         const std::vector<std::size_t>* held_vertices = nullptr)
{
  const Spectral_refinement refinement(m, sample_vertices, verts, in_region, number_of_eigenfunctions);
  refinement.template refine<ConcurrencyTag>(best, vertex_side, held_vertices);
  return refinement.ok();
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SYMMETRIC_MAP_SPECTRAL_H
