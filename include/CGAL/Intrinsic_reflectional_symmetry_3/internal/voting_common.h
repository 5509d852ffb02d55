// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_VOTING_COMMON_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_VOTING_COMMON_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/draw_pairs.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

// What the literal reference (reference_voting.h) and the fast voting
// (irsa_transform.h) share: the exact definitions of "approximately equal",
// of the Gaussian weight and of the bisector vertices, the input checks, and
// the per-transform set-up. Sharing them is what lets the two implementations
// agree bit for bit; the loops and data structures are what differ.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

/// The paper's equality test x ~ y between two geodesic distances:
/// |x - y| <= max(eps * max(x, y), floor), evaluated in single precision
/// (like the distances themselves; the test runs in the innermost loops).
/// Infinite (other component) or NaN distances are never equal to anything.
struct Distance_tolerance
{
  double eps = 0.02;   // eps_DIS, relative
  double floor = 0.;   // absolute floor, in the mesh's length unit
  float eps_f = 0.02f, floor_f = 0.f;

  void set(double relative, double absolute)
  {
    eps = relative; floor = absolute;
    eps_f = float(relative); floor_f = float(absolute);
  }

  bool operator()(float x, float y) const
  {
    // Without branches. Capping the limit at the largest float makes the test
    // false when x or y is infinite (|x - y| is then infinite or NaN), and
    // every comparison with NaN is false; finite values are unaffected.
    const float limit = (std::min)((std::max)(eps_f * (std::max)(x, y), floor_f),
                                   (std::numeric_limits<float>::max)());
    return std::abs(x - y) <= limit;
  }

  // A closed interval [lo, hi] that contains every finite y >= 0 with
  // (*this)(x, y), widened against rounding. Used by range queries, which
  // then apply the exact test.
  std::pair<double, double> range(double x) const
  {
    const double slack = 1e-5 * (x + floor) + 1e-30;
    const double lo = (std::min)(x * (1. - eps), x - floor) - slack;
    const double hi = (eps < 1.) ? (std::max)(x / (1. - eps), x + floor) + slack
                                 : std::numeric_limits<double>::infinity();
    return std::make_pair(lo, hi);
  }
};

/// exp(-d^2 / sigma^2), the weight of one vote (Alg. 2)
inline double gaussian_weight(float d, double inv_sigma2)
{
  const double dd = d;
  return std::exp(-dd * dd * inv_sigma2);
}

/// Bisector value f(v) = d(a, v) - d(b, v), in single precision like the
/// distances (the rounding never changes the sign, and f == 0 exactly when
/// the two distances are equal); NaN at vertices of another component.
inline float bisector_value(const float* row_a, const float* row_b, std::size_t v)
{
  return row_a[v] - row_b[v];
}

/// Of the two endpoints of an edge whose f values have strictly opposite
/// signs, the one that belongs to beta(a, b): the one with the smaller |f|,
/// the smaller vertex index on a tie. Returns `none` if the edge does not
/// cross the bisector.
inline std::size_t bisector_endpoint(std::size_t u, float fu, std::size_t v, float fv)
{
  const bool cross = (fu < 0.f && fv > 0.f) || (fu > 0.f && fv < 0.f);
  if(!cross)
    return std::size_t(-1);
  const float au = std::abs(fu), av = std::abs(fv);
  if(au < av) return u;
  if(av < au) return v;
  return (std::min)(u, v);
}

/// Sample-to-sample distances: dss(i, j) = D(i, sources[j]), the distance
/// from sample i to sample j read in row i (the matrix need not be exactly
/// symmetric: the heat method is not). Stored densely for cache locality.
class Sample_distance_matrix
{
public:
  Sample_distance_matrix() = default;
  explicit Sample_distance_matrix(const Geodesic_distance_matrix& D)
    : n_(D.number_of_sources()), data_(n_ * n_)
  {
    for(std::size_t i = 0; i < n_; ++i)
    {
      const float* r = D.row(i);
      float* out = data_.data() + i * n_;
      for(std::size_t j = 0; j < n_; ++j)
        out[j] = r[D.sources()[j]];
    }
  }
  std::size_t size() const { return n_; }
  float operator()(std::size_t i, std::size_t j) const { return data_[i * n_ + j]; }
  const float* row(std::size_t i) const { return data_.data() + i * n_; }

private:
  std::size_t n_ = 0;
  std::vector<float> data_;
};

/// Vertex adjacency of the mesh by vertex index: every edge once (u < v) and a
/// compressed adjacency list.
struct Voting_mesh
{
  std::size_t number_of_vertices = 0;
  std::vector<std::pair<std::size_t, std::size_t>> edges;  // u < v, sorted
  std::vector<std::size_t> adjacency_offsets;              // size nv + 1
  std::vector<std::size_t> adjacency;                      // neighbours, increasing
  double mean_edge_length = 0.;
};

template <class TriangleMesh, class NamedParameters>
Voting_mesh make_voting_mesh(const TriangleMesh& tm, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                             get_const_property_map(CGAL::vertex_point, tm));
  auto vim = CGAL::get_initialized_vertex_index_map(tm, np);

  Voting_mesh m;
  m.number_of_vertices = std::size_t(num_vertices(tm));
  double total = 0.;
  for(auto e : edges(tm))
  {
    std::size_t u = std::size_t(get(vim, source(e, tm)));
    std::size_t v = std::size_t(get(vim, target(e, tm)));
    if(u == v) continue;
    if(v < u) std::swap(u, v);
    m.edges.emplace_back(u, v);
    total += CGAL::to_double(Polygon_mesh_processing::edge_length(
               halfedge(e, tm), tm, CGAL::parameters::vertex_point_map(vpm)));
  }
  if(!m.edges.empty())
    m.mean_edge_length = total / double(m.edges.size());
  std::sort(m.edges.begin(), m.edges.end());
  m.edges.erase(std::unique(m.edges.begin(), m.edges.end()), m.edges.end());

  std::vector<std::size_t> degree(m.number_of_vertices + 1, 0);
  for(const auto& e : m.edges) { ++degree[e.first]; ++degree[e.second]; }
  m.adjacency_offsets.assign(m.number_of_vertices + 1, 0);
  for(std::size_t v = 0; v < m.number_of_vertices; ++v)
    m.adjacency_offsets[v + 1] = m.adjacency_offsets[v] + degree[v];
  m.adjacency.resize(m.adjacency_offsets.back());
  std::vector<std::size_t> fill(m.adjacency_offsets.begin(), m.adjacency_offsets.end() - 1);
  for(const auto& e : m.edges) // edges sorted => each list comes out increasing
  {
    m.adjacency[fill[e.first]++] = e.second;
    m.adjacency[fill[e.second]++] = e.first;
  }
  for(std::size_t v = 0; v < m.number_of_vertices; ++v)
    std::sort(m.adjacency.begin() + m.adjacency_offsets[v], m.adjacency.begin() + m.adjacency_offsets[v + 1]);
  return m;
}

/// Filter parameters after defaults and unit conversion.
struct Voting_settings
{
  Distance_tolerance tolerance;        // eps_DIS and the absolute floor
  double floor_in_edge_lengths = 0.;   // the floor as given by the user
  double axial_threshold = 0.8;        // eps_AXS
  double locality_radius = 0.;         // DBSCAN radius, absolute
  double locality_radius_in_spacings = 0.;
  std::size_t locality_min_points = 1; // DBSCAN minimum number of points
  std::size_t axial_sample_size = 0;   // pairs {s,t} the axial-sym counts look at (0: all)
  double sigma = 0.;                   // Gaussian width
  double inv_sigma2 = 0.;
  double mean_sample_spacing = 0.;
};

// Defaults (see irsa_transform.h for the measurements behind them).
constexpr double default_distance_threshold = 0.02;
constexpr double default_axial_threshold = 0.80;
constexpr double default_distance_tolerance_floor = 2.0;
constexpr double default_locality_radius = 2.0;
constexpr std::size_t default_locality_min_points = 5;
constexpr std::size_t default_axial_sample_size = 128;

/// Everything both implementations need, computed once per transform.
struct Voting_setup
{
  const Geodesic_distance_matrix* D = nullptr;
  std::size_t number_of_samples = 0;
  Voting_settings settings;
  Voting_mesh mesh;
  Sample_distance_matrix dss;
  std::vector<std::pair<std::size_t, std::size_t>> similar_pairs; // canonical: i < j, sorted, unique
  std::vector<std::size_t> voting_pairs;                          // indices into similar_pairs, increasing
  unsigned int random_seed = 0;
};

inline void check_voting_parameter(bool ok, const std::string& message)
{
  if(!ok)
    throw Input_error(Input_problem::invalid_parameter, message);
}

/// The similar pairs with i < j, sorted lexicographically, without
/// duplicates. Throws on an index out of range or a pair {i, i}.
inline std::vector<std::pair<std::size_t, std::size_t>>
canonical_similar_pairs(const std::vector<std::pair<std::size_t, std::size_t>>& pairs, std::size_t n)
{
  std::vector<std::pair<std::size_t, std::size_t>> out;
  out.reserve(pairs.size());
  for(std::size_t k = 0; k < pairs.size(); ++k)
  {
    std::size_t i = pairs[k].first, j = pairs[k].second;
    if(i >= n || j >= n)
      throw Input_error(Input_problem::invalid_parameter,
                        "similar pair " + std::to_string(k) + " refers to sample " +
                        std::to_string((std::max)(i, j)) + " but the distance matrix has " +
                        std::to_string(n) + " rows", k);
    if(i == j)
      throw Input_error(Input_problem::invalid_parameter,
                        "similar pair " + std::to_string(k) + " pairs sample " + std::to_string(i) +
                        " with itself", k);
    if(j < i) std::swap(i, j);
    out.emplace_back(i, j);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// Reads and checks the named parameters, and computes the per-transform data.
template <class TriangleMesh, class NamedParameters>
Voting_setup make_voting_setup(const TriangleMesh& tm, const Geodesic_distance_matrix& D,
                               const std::vector<std::pair<std::size_t, std::size_t>>& similar_pairs,
                               const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace inp = Intrinsic_reflectional_symmetry_3::internal_np;

  Voting_setup s;
  s.D = &D;
  s.number_of_samples = D.number_of_sources();

  const std::size_t nv = std::size_t(num_vertices(tm));
  if(D.number_of_vertices() != nv)
    throw Input_error(Input_problem::invalid_parameter,
                      "the distance matrix has " + std::to_string(D.number_of_vertices()) +
                      " columns but the mesh has " + std::to_string(nv) + " vertices");
  for(std::size_t i = 0; i < s.number_of_samples; ++i)
    if(D.sources()[i] >= nv)
      throw Input_error(Input_problem::invalid_parameter,
                        "sample " + std::to_string(i) + " is not a vertex index", i);

  Voting_settings& st = s.settings;
  const double eps = choose_parameter(get_parameter(np, inp::distance_threshold), default_distance_threshold);
  st.floor_in_edge_lengths =
    choose_parameter(get_parameter(np, inp::distance_tolerance_floor), default_distance_tolerance_floor);
  st.axial_threshold = choose_parameter(get_parameter(np, inp::axial_threshold), default_axial_threshold);
  st.locality_radius_in_spacings =
    choose_parameter(get_parameter(np, inp::locality_radius), default_locality_radius);
  const double min_points =
    double(choose_parameter(get_parameter(np, inp::locality_min_points), default_locality_min_points));
  const double axial_sample =
    double(choose_parameter(get_parameter(np, inp::axial_sample_size), default_axial_sample_size));
  const double cap = double(choose_parameter(get_parameter(np, inp::maximum_number_of_voting_pairs),
                                             std::numeric_limits<std::size_t>::max()));
  s.random_seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);

  check_voting_parameter(std::isfinite(eps) && eps >= 0. && eps < 1.,
                  "distance_threshold must be in [0, 1)");
  check_voting_parameter(std::isfinite(st.floor_in_edge_lengths) && st.floor_in_edge_lengths >= 0.,
                  "distance_tolerance_floor must be finite and >= 0");
  check_voting_parameter(st.axial_threshold >= 0. && st.axial_threshold <= 1.,
                  "axial_threshold must be in [0, 1]");
  check_voting_parameter(std::isfinite(st.locality_radius_in_spacings) && st.locality_radius_in_spacings > 0.,
                  "locality_radius must be finite and > 0");
  check_voting_parameter(min_points >= 1., "locality_min_points must be >= 1");
  check_voting_parameter(cap >= 0., "maximum_number_of_voting_pairs must be >= 0");
  check_voting_parameter(axial_sample >= 0., "axial_sample_size must be >= 0");
  st.axial_sample_size = std::size_t(axial_sample);
  st.locality_min_points = std::size_t(min_points);

  s.mesh = make_voting_mesh(tm, np);
  st.tolerance.set(eps, st.floor_in_edge_lengths * s.mesh.mean_edge_length);

  s.dss = Sample_distance_matrix(D);
  const std::size_t n = s.number_of_samples;
  // sigma: largest finite sample-to-sample distance; spacing: mean distance
  // from a sample to its nearest other sample (same component).
  double sigma = 0., spacing = 0.;
  std::size_t spaced = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    float nearest = std::numeric_limits<float>::infinity();
    const float* r = s.dss.row(i);
    for(std::size_t j = 0; j < n; ++j)
    {
      if(!std::isfinite(r[j])) continue;
      sigma = (std::max)(sigma, double(r[j]));
      if(j != i) nearest = (std::min)(nearest, r[j]);
    }
    if(std::isfinite(nearest)) { spacing += nearest; ++spaced; }
  }
  st.sigma = sigma;
  st.inv_sigma2 = sigma > 0. ? 1. / (sigma * sigma) : 0.;
  st.mean_sample_spacing = spaced > 0 ? spacing / double(spaced) : 0.;
  st.locality_radius = st.locality_radius_in_spacings * st.mean_sample_spacing;

  s.similar_pairs = canonical_similar_pairs(similar_pairs, n);
  s.voting_pairs = draw_pairs(s.similar_pairs.size(),
                              cap >= double(s.similar_pairs.size()) ? s.similar_pairs.size() : std::size_t(cap),
                              s.random_seed);
  return s;
}

/// The pairs {s,t} (positions in the list of `number_of_eligible` pairs that
/// passed the locality filter) that the axial-sym count of every pair looks
/// at: all of them, or, if there are more than `sample_size` (> 0), the
/// `sample_size` positions floor(i * number_of_eligible / sample_size),
/// evenly spread over the list.
inline void axial_comparison_pairs(std::size_t number_of_eligible, std::size_t sample_size,
                                   std::vector<std::size_t>& out)
{
  out.clear();
  if(sample_size == 0 || number_of_eligible <= sample_size)
    for(std::size_t l = 0; l < number_of_eligible; ++l) out.push_back(l);
  else
    for(std::size_t i = 0; i < sample_size; ++i)
      out.push_back(std::size_t((unsigned long long)(i) * number_of_eligible / sample_size));
}

/// Orients a similar pair for the voting pair {a, b}: returns (p, q) with p
/// strictly on a's side (d(a,p) < d(b,p)) and q strictly on b's side, or
/// false when both lie on the same side or one is on the bisector.
inline bool orient_pair(const Sample_distance_matrix& dss, std::size_t a, std::size_t b,
                        std::size_t i, std::size_t j, std::size_t& p, std::size_t& q)
{
  const bool i_on_a = dss(a, i) < dss(b, i), i_on_b = dss(b, i) < dss(a, i);
  const bool j_on_a = dss(a, j) < dss(b, j), j_on_b = dss(b, j) < dss(a, j);
  if(i_on_a && j_on_b) { p = i; q = j; return true; }
  if(j_on_a && i_on_b) { p = j; q = i; return true; }
  return false;
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_VOTING_COMMON_H
