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
// diagonal at the last size (an isometry's map commutes with the Laplacian)
// among those that reverse the orientation (a rotation flips eigenfunctions
// too).
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

/// the rings of edges around a vertex over which orientation_reversed_share()
/// fits the map: one face is too small a patch, a nearest-neighbour map
/// being noisy at the scale of an edge
constexpr int orientation_rings = 2;

/// The vertices within `rings` rings of edges of `v` (`v` first), into
/// `ring`; `mark` (by vertex, stamped with `stamp`) tells those already taken,
/// so that one array serves many calls with distinct stamps
inline void vertex_rings(const Curves_mesh& m, std::size_t v, int rings, std::vector<std::size_t>& mark,
                         std::size_t stamp, std::vector<std::size_t>& ring)
{
  ring.assign(1, v);
  mark[v] = stamp;
  for(std::size_t begin = 0, r = 0; r < std::size_t(rings); ++r)
  {
    const std::size_t end = ring.size();
    for(std::size_t i = begin; i < end; ++i)
      for(std::size_t k = m.adjacency_offsets[ring[i]]; k < m.adjacency_offsets[ring[i] + 1]; ++k)
        if(mark[m.adjacency[k]] != stamp)
        {
          mark[m.adjacency[k]] = stamp;
          ring.push_back(m.adjacency[k]);
        }
    begin = end;
  }
}

/// The share of the area of `m` (one third of each face's area to each
/// corner), over the vertices counted, around which the vertex map `image`
/// (by vertex index; negative or Curves_mesh::none: no image) turns the
/// surface over. Around a vertex `v` with an image, the vertices within
/// `orientation_rings` rings of edges and their images, taken in the tangent
/// planes at `v` and at its image (right-handed frames about the
/// area-weighted vertex normals), give the least-squares linear map between
/// the two planes; a negative determinant reverses the orientation. A
/// reflection reverses it, a rotation keeps it: near 1 for a reflection,
/// near 0 for the half turn that swaps the ends of a capsule as the
/// reflection about its middle circle does (both flip the same
/// eigenfunctions). A vertex counts where at least three of its neighbours
/// have an image and the fit is not degenerate; 0 where none counts. With
/// `vertex_subset`, over those vertices alone.
template <class Image>
double orientation_reversed_share(const Curves_mesh& m, const std::vector<Image>& image,
                                  const std::vector<std::size_t>* vertex_subset = nullptr)
{
  const std::size_t n = m.number_of_vertices, none = Curves_mesh::none;
  auto point = [&](std::size_t v) { return Eigen::Vector3d(m.points[v][0], m.points[v][1], m.points[v][2]); };
  std::vector<Eigen::Vector3d> normal(n, Eigen::Vector3d::Zero());
  std::vector<double> vertex_area(n, 0.);
  for(const auto& f : m.faces)
  {
    const Eigen::Vector3d a = (point(f[1]) - point(f[0])).cross(point(f[2]) - point(f[0]));
    for(std::size_t v : f)
    {
      normal[v] += a;
      vertex_area[v] += a.norm() / 6.;
    }
  }
  auto image_of = [&](std::size_t v) {
    const long long p = static_cast<long long>(image[v]);
    return p < 0 || std::size_t(p) >= n ? none : std::size_t(p);
  };
  // a right-handed tangent frame (the rows of the result) about the normal at v
  auto frame = [&](std::size_t v, Eigen::Matrix<double, 2, 3>& tangent) {
    if(normal[v].squaredNorm() == 0.) return false;
    const Eigen::Vector3d z = normal[v].normalized();
    const Eigen::Vector3d helper = std::abs(z[0]) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d t1 = helper.cross(z).normalized();
    tangent.row(0) = t1.transpose();
    tangent.row(1) = z.cross(t1).transpose();
    return true;
  };
  std::vector<std::size_t> ring, mark(n, none);
  double reversed = 0., counted = 0.;
  const std::size_t number_of_checks = vertex_subset != nullptr ? vertex_subset->size() : n;
  for(std::size_t c = 0; c < number_of_checks; ++c)
  {
    const std::size_t v = vertex_subset != nullptr ? (*vertex_subset)[c] : c;
    const std::size_t w = v < n ? image_of(v) : none;
    Eigen::Matrix<double, 2, 3> at_v, at_w;
    if(w == none || !frame(v, at_v) || !frame(w, at_w)) continue;
    vertex_rings(m, v, orientation_rings, mark, c, ring);
    // sum of y x^T over the neighbours: its determinant has the sign of the fit's
    Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
    std::size_t used = 0;
    for(std::size_t i = 1; i < ring.size(); ++i)
    {
      const std::size_t u = ring[i], iu = image_of(u);
      if(iu == none) continue;
      M += (at_w * (point(iu) - point(w))) * (at_v * (point(u) - point(v))).transpose();
      ++used;
    }
    const double det = M.determinant();
    if(used < 3 || det == 0.) continue;
    counted += vertex_area[v];
    if(det < 0.) reversed += vertex_area[v];
  }
  return counted > 0. ? reversed / counted : 0.;
}

/// the samples (the first ones) around which a candidate map's orientation
/// is read
constexpr std::size_t global_reflection_orientation_checks = 300;

/// the least orientation_reversed_share() of a reflection: most of the
/// surface turned over (a rotation turns none of it)
constexpr double reflection_min_reversed_share = 0.5;

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
/// map is a reflection (few samples held in place, the orientation reversed). Deterministic: a fixed solver start and exact nearest
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
  struct Candidate
  {
    unsigned pattern;
    double fixed_share, off_diagonal;
    Eigen::MatrixXd map;
  };
  std::vector<Candidate> candidates;
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
    if(fixed_share <= global_reflection_max_fixed_share)
      candidates.push_back(Candidate{pattern, fixed_share, off_diagonal, C});
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.off_diagonal < b.off_diagonal; });

  // A rotation flips eigenfunctions as a reflection does (the half turn of a
  // bent capsule or of a figure with two mirror planes), but keeps the
  // orientation: the most diagonal candidate that turns the surface over, read
  // around the first samples (their rings mapped alone, a fraction of the
  // cost of the whole map)
  std::vector<std::size_t> check_vertices, check_rows, ring, mark(m.number_of_vertices, none);
  for(std::size_t i = 0; i < sample_vertices.size() && check_vertices.size() < global_reflection_orientation_checks; ++i)
  {
    const std::size_t v = sample_vertices[i];
    // a sample within the rings of an earlier one adds little: the next
    if(v >= m.number_of_vertices || row_of[v] == none || mark[v] != none) continue;
    check_vertices.push_back(v);
    vertex_rings(m, v, orientation_rings, mark, v, ring);
    for(std::size_t u : ring)
      if(row_of[u] != none) check_rows.push_back(row_of[u]);
  }
  std::sort(check_rows.begin(), check_rows.end());
  check_rows.erase(std::unique(check_rows.begin(), check_rows.end()), check_rows.end());
  const Candidate* kept = nullptr;
  std::vector<std::size_t> check_image(spectrum.rows.size(), none), vertex_image(m.number_of_vertices, none);
  for(const Candidate& c : candidates)
  {
    // only the check rows are written, and read
    nearest_rows<ConcurrencyTag>(spectrum.basis, c.map, check_rows, check_image);
    for(std::size_t r : check_rows) vertex_image[spectrum.rows[r]] = spectrum.rows[check_image[r]];
    if(orientation_reversed_share(m, vertex_image, &check_vertices) >= reflection_min_reversed_share)
    {
      kept = &c;
      break;
    }
  }
  if(kept == nullptr) return out;
  out.pattern = kept->pattern;
  out.fixed_share = kept->fixed_share;
  out.off_diagonal_share = kept->off_diagonal;

  // the kept map on every vertex of the spectrum
  const std::size_t n = spectrum.rows.size();
  std::vector<std::size_t> rows(n), image(n);
  std::iota(rows.begin(), rows.end(), std::size_t(0));
  nearest_rows<ConcurrencyTag>(spectrum.basis, kept->map, rows, image);
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
