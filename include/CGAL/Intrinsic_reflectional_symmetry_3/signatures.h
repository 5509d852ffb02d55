// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SIGNATURES_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SIGNATURES_H

#include <CGAL/disable_warnings.h>

/// \file signatures.h
/// SDF map signatures and the similarity filter (paper, section 3.3):
/// for a sample `p`, `b` equally spaced geodesic rings around `p` bound `b`
/// bins; the signature is the vector of the area-weighted mean shape
/// diameter function (SDF, Shapira et al. 2008) in each bin. Two samples pass
/// the similarity filter when their signatures differ (L2) by less than
/// `eps_SIM` times the larger of the two norms.
///
/// Three steps, each usable on its own:
/// 1. `vertex_sdf_values()`: raw SDF per vertex (CGAL's `sdf_values()` per
///    face, then an area-weighted average over the faces around each vertex);
/// 2. `compute_sdf_signatures()` / `sdf_signatures()`: one signature per
///    row of a `Geodesic_distance_matrix`;
/// 3. `passes_similarity_filter()`, `similar_sample_pairs()`.
///
/// Units: SDF values and the signature radius are lengths in the mesh's
/// units. Raw SDF values scale with the mesh, so signatures scale too and the
/// relative filter is scale-invariant.

// Boost's disjoint_sets.hpp calls get(T*, i) unqualified: it must be parsed
// before boost/graph/detail/adjacency_list.hpp (pulled in by CGAL headers
// below) declares boost::detail::get, which would hide boost::get from it.
#include <boost/property_map/property_map.hpp>
#include <boost/pending/disjoint_sets.hpp>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/draw_pairs.h>

#include <CGAL/mesh_segmentation.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/for_each.h>
#include <CGAL/tags.h>

#include <boost/property_map/property_map.hpp>
#include <boost/range/iterator_range.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Default of the `similarity_threshold` named parameter: the paper's `eps_SIM`.
constexpr double default_similarity_threshold = 0.025;

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Default of the `maximum_similar_pairs_per_sample` named parameter of
/// `similar_sample_pairs()`. Real shapes whose SDF tells their parts apart
/// pass 2-52 pairs per sample (FAUST 5-6 at 1,250 samples, SCAPE 10-17 at
/// 3,000, 59 of the 63 PSB models of the benchmark 2-52 at `min(3000, V/4)`);
/// a nearly uniform SDF (a cup's walls, a bearing's ring, a table) passes
/// 100-450, and the voting, whose cost grows as the square of the similar
/// pairs, then takes many minutes.
constexpr double default_maximum_similar_pairs_per_sample = 64.;

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Default of the `number_of_signature_rings` named parameter: the paper's `b`.
constexpr std::size_t default_number_of_signature_rings = 6;

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The default signature radius is this fraction of the square root of the
/// mesh area (see `sdf_signatures()`).
constexpr double default_signature_radius_ratio = 0.1;

namespace internal {

inline void check_parameter(bool ok, const std::string& what)
{
  if(!ok) throw Input_error(Input_problem::invalid_parameter, what);
}

template <typename TriangleMesh, typename NamedParameters>
void check_triangle_mesh(const TriangleMesh& tm, const NamedParameters&)
{
  if(num_vertices(tm) == 0 || num_faces(tm) == 0)
    throw Input_error(Input_problem::empty_mesh, "the mesh has no vertices or no faces");
  if(!CGAL::is_triangle_mesh(tm))
    throw Input_error(Input_problem::not_triangle_mesh, "the mesh has a face that is not a triangle");
}

} // namespace internal

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The area of each vertex: a third of the areas of its incident faces.
/// Indexed by vertex index.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{the vertex indices}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class (its squared area of a triangle)}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{a \cgal kernel deduced from the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::vector<double> vertex_areas(const TriangleMesh& tm, const CGAL_NP_CLASS& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, CGAL_NP_CLASS>::const_type VPM;
  typedef typename GetGeomTraits<TriangleMesh, CGAL_NP_CLASS>::type GT;
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  const GT gt = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);

  std::vector<double> area(num_vertices(tm), 0.);
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    const auto a = source(h, tm), b = target(h, tm), c = target(next(h, tm), tm);
    const double fa = std::sqrt(CGAL::to_double(
      gt.compute_squared_area_3_object()(get(vpm, a), get(vpm, b), get(vpm, c))));
    for(auto v : {a, b, c}) area[get(vim, v)] += fa / 3.;
  }
  return area;
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The shape diameter function at each vertex, indexed by vertex index.
///
/// CGAL's `CGAL::sdf_values()` gives one value per face (the robust mean
/// length of the rays cast inwards in a cone around the inward normal); each
/// vertex gets the area-weighted mean of its incident faces.
///
/// The values are RAW: `sdf_values()` is called with `postprocess = false`,
/// which skips `sdf_values_postprocessing()`. That postprocessing smooths
/// (bilateral filter) and then normalises linearly to [0,1] with the mesh's
/// minimum and maximum: `(s - min) / (max - min)`. The affine map would make
/// the relative similarity filter meaningless (the thinnest part maps to 0,
/// where any difference is "large") and every value would depend on the
/// extreme parts of the whole mesh. Raw values are lengths, so signatures are
/// proportional to the mesh scale and the filter is scale-invariant; the
/// ring averages of the signatures do the smoothing. Faces where no ray hit
/// anything (CGAL marks them -1; only on open or odd meshes) take the mean of
/// their valid edge-neighbours, repeatedly, then the smallest valid value
/// (what CGAL's postprocessing does too); 0 if no face has a value.
///
/// Mirror-image faces do not get exactly the same value: CGAL orients each
/// face's pattern of rays from the face normal alone, not mirror-equivariantly,
/// so on anisotropic parts (an ellipsoid, a limb) the 25 default rays give
/// mirror faces values about 2.4 % apart on average (15 % at worst; 0.6 % and
/// 3 % with 100 rays). Raise `sdf_number_of_rays` when the similarity filter
/// must be strict (see `sdf_signatures()`).
///
/// The input mesh is not modified and not copied: with an explicit vertex
/// point map, `sdf_values()` takes the const mesh (checked for
/// `Surface_mesh` and `Polyhedron_3`), and face values go to a vector
/// indexed by the face index map, not to a property added to the mesh.
/// Cost: one AABB tree and
/// `sdf_number_of_rays` ray casts per face (sequential; about 0.5 s for 3.6K
/// faces and 25 rays).
///
/// \pre the mesh is outward oriented (rays are cast against the face normals)
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{sdf_cone_angle}
///     \cgalParamDescription{opening angle, in radians, of the cone of rays of each face}
///     \cgalParamType{double, in (0, pi]}
///     \cgalParamDefault{`2 pi / 3` (CGAL's default)}
///   \cgalParamNEnd
///   \cgalParamNBegin{sdf_number_of_rays}
///     \cgalParamDescription{number of rays cast per face}
///     \cgalParamType{std::size_t, at least 1}
///     \cgalParamDefault{25 (CGAL's default)}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{the vertex indices}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{the face indices}
///     \cgalParamType{a model of `ReadablePropertyMap` with `face_descriptor` as key and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `SegmentationGeomTraits`}
///     \cgalParamDefault{a \cgal kernel deduced from the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Input_error `empty_mesh`, `not_triangle_mesh`, or `invalid_parameter`
template <typename TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::vector<double> vertex_sdf_values(const TriangleMesh& tm, const CGAL_NP_CLASS& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, CGAL_NP_CLASS>::const_type VPM;
  typedef typename GetGeomTraits<TriangleMesh, CGAL_NP_CLASS>::type GT;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;

  internal::check_triangle_mesh(tm, np);
  const double cone_angle = choose_parameter(get_parameter(np, internal_np::sdf_cone_angle), 2.0 / 3.0 * CGAL_PI);
  const auto rays_parameter = choose_parameter(get_parameter(np, internal_np::sdf_number_of_rays), std::size_t(25));
  internal::check_parameter(cone_angle > 0. && cone_angle <= CGAL_PI,
                            "sdf_cone_angle must be in (0, pi], got " + std::to_string(cone_angle));
  internal::check_parameter(rays_parameter >= 1, "sdf_number_of_rays must be at least 1"); // also if signed and negative
  const std::size_t rays = static_cast<std::size_t>(rays_parameter);

  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  const GT gt = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);

  // raw SDF per face, into a vector indexed by face index (no property added to the mesh)
  std::vector<double> face_sdf(num_faces(tm), -1.);
  auto face_sdf_map = boost::make_iterator_property_map(face_sdf.begin(), fim);
  CGAL::sdf_values(tm, face_sdf_map, cone_angle, rays, false /* raw */, vpm, gt);

  // faces without a value: mean of valid neighbours, as long as that helps
  bool changed = true;
  while(changed) {
    changed = false;
    std::vector<std::pair<std::size_t, double> > fills;
    for(face_descriptor f : faces(tm)) {
      if(face_sdf[get(fim, f)] >= 0.) continue;
      double sum = 0.;
      int count = 0;
      for(auto h : halfedges_around_face(halfedge(f, tm), tm)) {
        const face_descriptor g = face(opposite(h, tm), tm);
        if(g == boost::graph_traits<TriangleMesh>::null_face()) continue;
        const double s = face_sdf[get(fim, g)];
        if(s >= 0.) { sum += s; ++count; }
      }
      if(count > 0) fills.emplace_back(get(fim, f), sum / count);
    }
    for(const auto& fv : fills) face_sdf[fv.first] = fv.second;
    changed = !fills.empty();
  }
  double smallest = std::numeric_limits<double>::infinity();
  for(double s : face_sdf) if(s >= 0.) smallest = (std::min)(smallest, s);
  for(double& s : face_sdf) if(s < 0.) s = std::isfinite(smallest) ? smallest : 0.;

  // area-weighted mean over the faces around each vertex
  std::vector<double> sum(num_vertices(tm), 0.), weight(num_vertices(tm), 0.);
  std::vector<int> count(num_vertices(tm), 0);
  for(face_descriptor f : faces(tm)) {
    const auto h = halfedge(f, tm);
    const auto a = source(h, tm), b = target(h, tm), c = target(next(h, tm), tm);
    const double fa = std::sqrt(CGAL::to_double(
      gt.compute_squared_area_3_object()(get(vpm, a), get(vpm, b), get(vpm, c))));
    const double s = face_sdf[get(fim, f)];
    for(auto v : {a, b, c}) {
      const std::size_t i = get(vim, v);
      sum[i] += fa * s;
      weight[i] += fa;
      ++count[i];
    }
  }
  std::vector<double> vertex_sdf(num_vertices(tm), 0.);
  for(std::size_t i = 0; i < vertex_sdf.size(); ++i)
    vertex_sdf[i] = weight[i] > 0. ? sum[i] / weight[i] : 0.;
  // a vertex whose faces all have zero area: plain mean
  for(face_descriptor f : faces(tm)) {
    for(auto v : vertices_around_face(halfedge(f, tm), tm)) {
      const std::size_t i = get(vim, v);
      if(weight[i] == 0. && count[i] > 0) vertex_sdf[i] += face_sdf[get(fim, f)] / count[i];
    }
  }
  return vertex_sdf;
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// SDF map signatures of a set of samples: a flat row-major table with one
/// row of `number_of_rings()` ring averages per sample (row `i` belongs to
/// the sample of row `i` of the `Geodesic_distance_matrix` it was computed
/// from, vertex `sources()[i]`).
class Sdf_signatures
{
public:
  /// a signature: a range of `number_of_rings()` doubles
  typedef boost::iterator_range<const double*> Signature;

  Sdf_signatures() = default;

  /// an all-zero table
  Sdf_signatures(std::vector<std::size_t> sources, std::size_t number_of_rings, double radius)
    : sources_(std::move(sources)), rings_(number_of_rings), radius_(radius),
      data_(sources_.size() * number_of_rings, 0.)
  {}

  std::size_t number_of_samples() const { return sources_.size(); }
  /// `b`, the length of each signature
  std::size_t number_of_rings() const { return rings_; }
  /// the radius of the outermost ring (mesh length units)
  double radius() const { return radius_; }
  /// vertex index of the sample of each row
  const std::vector<std::size_t>& sources() const { return sources_; }

  double* row(std::size_t i) { return data_.data() + i * rings_; }
  const double* row(std::size_t i) const { return data_.data() + i * rings_; }
  /// the signature of row `i`
  Signature signature(std::size_t i) const { return Signature(row(i), row(i) + rings_); }
  /// ring `k` of row `i`
  double operator()(std::size_t i, std::size_t k) const { return data_[i * rings_ + k]; }
  /// all values, row after row
  const std::vector<double>& data() const { return data_; }

private:
  std::vector<std::size_t> sources_;
  std::size_t rings_ = 0;
  double radius_ = 0.;
  std::vector<double> data_;
};

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// SDF map signatures from per-vertex values: for row `i` of `distances`
/// (distances from sample `i` to every vertex), ring `k` (`0 <= k < b`) is
/// the mean of `vertex_sdf`, weighted by `vertex_area`, over the vertices `v`
/// with `k R / b <= distances(i, v) < (k + 1) R / b` (the last ring includes
/// `R`), `R` being the signature radius. Vertices farther than `R`, or in
/// another component (`+infinity`), are ignored.
///
/// Empty rings (small radius, coarse mesh) never give NaN: an empty ring
/// takes the value of the ring inside it, and an empty first ring (only if
/// the sample's own distance is not ~0) takes the SDF of the sample vertex.
///
/// The default radius is `default_signature_radius_ratio` (0.1) times the
/// square root of the total area (the sum of `vertex_area`): a scale-free
/// length that depends on the mesh only, not on which samples or which
/// distance backend are used, so that signatures computed in separate calls
/// agree (0.35 for a unit sphere). Measured on the generated shapes
/// (test_signatures.cpp, heat-method distances, 600 to 4K vertices):
/// - a larger radius makes the signatures of mirror pairs agree better
///   (ellipsoid, 25 rays, 1.8K vertices: 75-81 % of mirror pairs pass at
///   0.1, 85-93 % at 0.15, 90-97 % at 0.2), but it breaks PARTIAL symmetry:
///   on the two snowmen the snowmen's own mirror pairs pass at 96-97 % with
///   0.1, 73-88 % with 0.15 and 42-73 % with 0.2, because the rings of more
///   and more pairs reach the tube on one side only. 0.1 favours partial
///   symmetry, the point of the method.
/// - the low ellipsoid figures come from the SDF, not from the rings: with
///   CGAL's 25 rays per face, the ray pattern's orientation (which is not
///   mirror-equivariant) biases the SDF by 2.4 % on average (15 % at worst)
///   between mirror faces on anisotropic parts, as much as `eps_SIM`. With
///   `sdf_number_of_rays(100)` the bias drops to 0.6 % and 100 % of the
///   ellipsoid's mirror pairs pass at any radius from 0.05 to 0.2
///   (snowman: 99.7 % already with 25 rays).
///
/// Rows are computed in parallel with `ConcurrencyTag = Parallel_tag`; each
/// row depends only on its own data, so the result does not depend on the
/// thread count.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_signature_rings}
///     \cgalParamDescription{`b`, the number of rings (the signature length)}
///     \cgalParamType{std::size_t, at least 1}
///     \cgalParamDefault{6 (the paper's value)}
///   \cgalParamNEnd
///   \cgalParamNBegin{signature_radius}
///     \cgalParamDescription{`R`, the geodesic radius of the outermost ring, in mesh length units}
///     \cgalParamType{double, positive}
///     \cgalParamDefault{0.1 times the square root of the mesh area}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Input_error `invalid_parameter` if the sizes disagree or a parameter is out of range
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename CGAL_NP_TEMPLATE_PARAMETERS>
Sdf_signatures sdf_signatures(const std::vector<double>& vertex_sdf, const std::vector<double>& vertex_area,
                              const Geodesic_distance_matrix& distances,
                              const CGAL_NP_CLASS& np = parameters::default_values())
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
#endif
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const std::size_t n = distances.number_of_vertices();
  internal::check_parameter(vertex_sdf.size() == n && vertex_area.size() == n,
                            "vertex_sdf (" + std::to_string(vertex_sdf.size()) + "), vertex_area (" +
                            std::to_string(vertex_area.size()) + ") and the distance matrix (" +
                            std::to_string(n) + " vertices) disagree");
  const auto rings_parameter = choose_parameter(get_parameter(np, internal_np::number_of_signature_rings),
                                                default_number_of_signature_rings);
  internal::check_parameter(rings_parameter >= 1, "number_of_signature_rings must be at least 1"); // also if signed and negative
  const std::size_t b = static_cast<std::size_t>(rings_parameter);
  const double total_area = std::accumulate(vertex_area.begin(), vertex_area.end(), 0.);
  const double radius = choose_parameter(get_parameter(np, internal_np::signature_radius),
                                         default_signature_radius_ratio * std::sqrt(total_area));
  internal::check_parameter(radius > 0. && std::isfinite(radius),
                            "signature_radius must be positive and finite, got " + std::to_string(radius));

  Sdf_signatures signatures(distances.sources(), b, radius);
  std::vector<std::size_t> rows(distances.number_of_sources());
  std::iota(rows.begin(), rows.end(), std::size_t(0));
  const double width = radius / double(b);
  CGAL::for_each<ConcurrencyTag>(rows, [&](std::size_t i) {
    std::vector<double> sum(b, 0.), weight(b, 0.);
    const float* d = distances.row(i);
    for(std::size_t v = 0; v < n; ++v) {
      const double dv = double(d[v]);
      if(!(dv <= radius)) continue; // also skips +inf and NaN
      const std::size_t k = (std::min)(b - 1, std::size_t(dv / width));
      sum[k] += vertex_area[v] * vertex_sdf[v];
      weight[k] += vertex_area[v];
    }
    double* out = signatures.row(i);
    double previous = vertex_sdf[distances.sources()[i]];
    for(std::size_t k = 0; k < b; ++k) {
      out[k] = weight[k] > 0. ? sum[k] / weight[k] : previous;
      previous = out[k];
    }
    return true;
  });
  return signatures;
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// SDF map signatures of the samples of `distances` (its rows), computed on
/// `tm`: `vertex_sdf_values(tm, np)` and `vertex_areas(tm, np)` followed by
/// `sdf_signatures(...)`. Takes the named parameters of all three
/// (`sdf_cone_angle`, `sdf_number_of_rays`, `number_of_signature_rings`,
/// `signature_radius`, `vertex_point_map`, `vertex_index_map`,
/// `face_index_map`, `geom_traits`).
///
/// `distances` must be indexed like `tm`'s vertex index map.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
Sdf_signatures compute_sdf_signatures(const TriangleMesh& tm, const Geodesic_distance_matrix& distances,
                                      const CGAL_NP_CLASS& np = parameters::default_values())
{
  internal::check_triangle_mesh(tm, np);
  internal::check_parameter(distances.number_of_vertices() == num_vertices(tm),
                            "the distance matrix has " + std::to_string(distances.number_of_vertices()) +
                            " columns but the mesh has " + std::to_string(num_vertices(tm)) + " vertices");
  return sdf_signatures<ConcurrencyTag>(vertex_sdf_values(tm, np), vertex_areas(tm, np), distances, np);
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The similarity filter of the paper: `true` if
/// `||a - b||_2 < similarity_threshold * max(||a||_2, ||b||_2)`.
/// `a` and `b` are ranges of numbers of the same length (for example
/// `Sdf_signatures::signature(i)`). Two zero signatures do not pass.
template <typename SignatureA, typename SignatureB>
bool passes_similarity_filter(const SignatureA& a, const SignatureB& b,
                              double similarity_threshold = default_similarity_threshold)
{
  double diff = 0., na = 0., nb = 0.;
  auto ib = std::begin(b);
  for(auto ia = std::begin(a); ia != std::end(a); ++ia, ++ib) {
    const double x = double(*ia), y = double(*ib);
    diff += (x - y) * (x - y);
    na += x * x;
    nb += y * y;
  }
  return std::sqrt(diff) < similarity_threshold * std::sqrt((std::max)(na, nb));
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Writes every pair `{i, j}` of rows (`i < j`, as `std::pair<std::size_t,
/// std::size_t>` of row indices, not vertex indices) whose signatures pass
/// the similarity filter, in lexicographic order, to `out`.
///
/// Where more than `maximum_similar_pairs_per_sample` times the number of
/// samples pass, only that many are written, drawn uniformly at random with
/// `random_seed`. Signatures that let that many pairs through do not tell
/// the parts of the shape apart (a cup's walls, a bearing's ring: 100-450
/// pairs per sample pass, against 2-52 on shapes whose SDF varies), and the
/// voting's cost grows as the square of the similar pairs (PSB cup_036:
/// 543K similar pairs, 239 per sample, 23 minutes of voting on one core).
/// The draw is uniform rather than the most similar pairs: the SDF is
/// measured by rays in space, so the pairs of an extrinsic mirror have the
/// most equal signatures, and ranking by similarity would favour them over
/// the intrinsic symmetries the method is for (a bent capsule's top curve
/// becomes its bending plane).
///
/// Only pairs whose norms are within a factor `1 - eps` of each other can
/// pass (`| ||a|| - ||b|| | <= ||a - b||`), so the rows are sorted by norm
/// and each is compared with its neighbours in that order only.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{similarity_threshold}
///     \cgalParamDescription{`eps_SIM`, relative L2 tolerance}
///     \cgalParamType{double, in [0, 1)}
///     \cgalParamDefault{0.025 (the paper's value)}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_similar_pairs_per_sample}
///     \cgalParamDescription{at most this many pairs per sample are written, drawn at random;
///       `std::numeric_limits<double>::infinity()` for the paper's filter without a cap}
///     \cgalParamType{double >= 0}
///     \cgalParamDefault{`default_maximum_similar_pairs_per_sample` (64)}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{seed of that draw}
///     \cgalParamType{unsigned int}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the output iterator past the last pair
template <typename OutputIterator, typename CGAL_NP_TEMPLATE_PARAMETERS>
OutputIterator similar_sample_pairs(const Sdf_signatures& signatures, OutputIterator out,
                                    const CGAL_NP_CLASS& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double eps = choose_parameter(get_parameter(np, internal_np::similarity_threshold),
                                      default_similarity_threshold);
  internal::check_parameter(eps >= 0. && eps < 1.,
                            "similarity_threshold must be in [0, 1), got " + std::to_string(eps));
  const double per_sample = choose_parameter(get_parameter(np, internal_np::maximum_similar_pairs_per_sample),
                                             default_maximum_similar_pairs_per_sample);
  internal::check_parameter(per_sample >= 0.,
                            "maximum_similar_pairs_per_sample must be >= 0, got " + std::to_string(per_sample));
  const std::size_t s = signatures.number_of_samples();
  std::vector<double> norm(s);
  for(std::size_t i = 0; i < s; ++i) {
    double n2 = 0.;
    for(double x : signatures.signature(i)) n2 += x * x;
    norm[i] = std::sqrt(n2);
  }
  std::vector<std::size_t> order(s);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return norm[a] < norm[b]; });

  std::vector<std::pair<std::size_t, std::size_t> > pairs;
  for(std::size_t p = 0; p < s; ++p) {
    const std::size_t i = order[p];
    for(std::size_t q = p + 1; q < s; ++q) {
      const std::size_t j = order[q];
      // norm[j] - norm[i] >= eps * norm[j]: neither j nor any later row can pass (tiny slack for rounding)
      if(norm[j] * (1. - eps) > norm[i] * (1. + 1e-12)) break;
      if(passes_similarity_filter(signatures.signature(i), signatures.signature(j), eps))
        pairs.emplace_back((std::min)(i, j), (std::max)(i, j));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  const double cap = per_sample * double(s);
  if(double(pairs.size()) > cap) {
    const unsigned int seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
    const std::vector<std::size_t> kept = internal::draw_pairs(pairs.size(), std::size_t(cap), seed);
    for(std::size_t k = 0; k < kept.size(); ++k) pairs[k] = pairs[kept[k]]; // kept[k] >= k
    pairs.resize(kept.size());
  }
  return std::copy(pairs.begin(), pairs.end(), out);
}

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SIGNATURES_H
