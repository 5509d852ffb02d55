// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_LEVEL_SET_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_LEVEL_SET_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/curves_mesh.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/voting_common.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

// The voted boundary beta(a, b) as a curve: the zero level set of
// f = d(a,.) - d(b,.), linear in each face, is a set of polylines through the
// faces where f changes sign. Each crossing edge carries one vertex of beta
// (the endpoint with the smaller |f|, the rule of the voting), so walking the
// level set from face to face orders the vertices of beta along the curve, and
// the length of each face's segment is the measure for the line integral
// nu = int_beta tau * mu (trapezoidal rule: half of a segment's length goes to
// the beta vertex of each of its two crossing edges).

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

/// One polyline of the level set, as beta vertices in order along it.
struct Level_set_polyline
{
  std::vector<std::size_t> vertices; // beta vertices, consecutive duplicates merged
  std::vector<double> weights;       // share of the curve's length carried by each
  bool closed = false;               // a loop (else it ends at the border or at another component)
};

class Level_set_tracer
{
public:
  explicit Level_set_tracer(const Curves_mesh& m)
    : m_(m), edge_stamp_(m.edges.size(), 0), edge_slot_(m.edges.size(), 0)
  {}

  /// Crossing test of the level set: sign classes f >= 0 and f < 0, so a
  /// vertex with f == 0 is a crossing point of its edges to negative vertices.
  static bool crosses(float fu, float fv) { return (fu >= 0.f) != (fv >= 0.f); }

  /// the beta vertex of a crossing edge (the rule of `bisector_endpoint()`,
  /// extended to f == 0: such a vertex is in beta and has the smaller |f|)
  static std::size_t beta_vertex(std::size_t u, float fu, std::size_t v, float fv)
  {
    const float au = std::abs(fu), av = std::abs(fv);
    if(au < av) return u;
    if(av < au) return v;
    return (std::min)(u, v);
  }

  /// Traces the level set of f = D(a,.) - D(b,.) near `boundary` (the
  /// vertices of beta(a, b) as found by the voting: every crossing edge has
  /// one endpoint in it). Faces with a non-finite value are skipped.
  void trace(const Geodesic_distance_matrix& D, std::size_t a, std::size_t b,
             const std::vector<std::size_t>& boundary, std::vector<Level_set_polyline>& out)
  {
    const float* ra = D.row(a);
    const float* rb = D.row(b);
    trace_function([&](std::size_t v) { return ra[v] - rb[v]; },
                   [&](std::size_t v) { return std::isfinite(ra[v]) && std::isfinite(rb[v]); }, boundary, out);
  }

  /// The same for any vertex function `f` (float values; `finite(v)` says
  /// where it is defined): its zero level set near `boundary`, every crossing
  /// edge having one endpoint in it (all vertices will do).
  template <class F, class Finite>
  void trace_function(const F& f, const Finite& finite, const std::vector<std::size_t>& boundary,
                      std::vector<Level_set_polyline>& out)
  {
    out.clear();
    next_stamp();

    // crossing edges around beta, in increasing edge order
    crossing_.clear();
    for(std::size_t v : boundary)
    {
      if(!finite(v)) continue;
      const float fv = f(v);
      for(std::size_t k = m_.adjacency_offsets[v]; k < m_.adjacency_offsets[v + 1]; ++k)
      {
        const std::size_t u = m_.adjacency[k], e = m_.adjacency_edge[k];
        if(edge_stamp_[e] == stamp_ || !finite(u)) continue;
        if(crosses(fv, f(u)))
        {
          edge_stamp_[e] = stamp_;
          crossing_.push_back(e);
        }
      }
    }
    std::sort(crossing_.begin(), crossing_.end());
    for(std::size_t i = 0; i < crossing_.size(); ++i) edge_slot_[crossing_[i]] = i;

    // each crossing edge: its beta vertex, its crossing point, and the (at
    // most two) crossed faces around it; a face is crossed when its three
    // values are finite and it has exactly two crossing edges
    const std::size_t nc = crossing_.size();
    beta_.assign(nc, 0);
    point_.assign(nc, {{0., 0., 0.}});
    faces_.assign(nc, {{Curves_mesh::none, Curves_mesh::none}});
    for(std::size_t i = 0; i < nc; ++i)
    {
      const std::size_t e = crossing_[i];
      const std::size_t u = m_.edges[e].first, v = m_.edges[e].second;
      const float fu = f(u), fv = f(v);
      beta_[i] = beta_vertex(u, fu, v, fv);
      const double t = double(fu) / (double(fu) - double(fv)); // in [0, 1]
      for(int c = 0; c < 3; ++c)
        point_[i][c] = (1. - t) * m_.points[u][c] + t * m_.points[v][c];
      int slot = 0;
      for(std::size_t face : m_.edge_faces[e])
        if(face != Curves_mesh::none && other_crossing(face, e, f, finite) != Curves_mesh::none)
          faces_[i][slot++] = face;
    }

    // walk: open chains first (from an end), then loops, each from its
    // smallest crossing edge
    visited_.assign(nc, 0);
    auto degree = [&](std::size_t i) {
      return int(faces_[i][0] != Curves_mesh::none) + int(faces_[i][1] != Curves_mesh::none);
    };
    for(int pass = 0; pass < 2; ++pass)
      for(std::size_t i = 0; i < nc; ++i)
      {
        if(visited_[i]) continue;
        if(pass == 0 && degree(i) != 1) continue;
        Level_set_polyline pl;
        walk(i, f, finite, pl);
        if(!pl.vertices.empty()) out.push_back(std::move(pl));
      }
  }

  /// The line-integral weight of every vertex of `boundary` (sorted): the
  /// sum of its shares over all polylines (0 for a vertex on no crossing edge).
  static void weights_on_boundary(const std::vector<Level_set_polyline>& polylines,
                                  const std::vector<std::size_t>& boundary, std::vector<double>& w)
  {
    w.assign(boundary.size(), 0.);
    for(const auto& pl : polylines)
      for(std::size_t i = 0; i < pl.vertices.size(); ++i)
      {
        const auto it = std::lower_bound(boundary.begin(), boundary.end(), pl.vertices[i]);
        if(it != boundary.end() && *it == pl.vertices[i])
          w[std::size_t(it - boundary.begin())] += pl.weights[i];
      }
  }

private:
  template <class F, class Finite>
  std::size_t other_crossing(std::size_t face, std::size_t e, const F& f, const Finite& finite) const
  {
    const auto& vs = m_.faces[face];
    if(!finite(vs[0]) || !finite(vs[1]) || !finite(vs[2])) return Curves_mesh::none;
    std::size_t other = Curves_mesh::none;
    int count = 0;
    for(int k = 0; k < 3; ++k)
    {
      if(crosses(f(vs[k]), f(vs[(k + 1) % 3])))
      {
        ++count;
        if(m_.face_edges[face][k] != e) other = m_.face_edges[face][k];
      }
    }
    return count == 2 ? other : Curves_mesh::none;
  }

  template <class F, class Finite>
  void walk(std::size_t start, const F& f, const Finite& finite, Level_set_polyline& pl)
  {
    std::vector<std::size_t> chain(1, start);   // crossing-edge slots in order
    visited_[start] = 1;
    std::size_t prev_face = Curves_mesh::none, cur = start;
    bool closed = false;
    for(;;)
    {
      std::size_t face = Curves_mesh::none;
      for(std::size_t fc : faces_[cur])
        if(fc != Curves_mesh::none && fc != prev_face) { face = fc; break; }
      if(face == Curves_mesh::none) break;
      const std::size_t e2 = other_crossing(face, crossing_[cur], f, finite);
      if(e2 == Curves_mesh::none || edge_stamp_[e2] != stamp_) break;
      const std::size_t nxt = edge_slot_[e2];
      if(nxt == start) { closed = true; break; }
      if(visited_[nxt]) break;
      visited_[nxt] = 1;
      chain.push_back(nxt);
      prev_face = face;
      cur = nxt;
    }
    // segment lengths between consecutive crossing points; half to each end
    const std::size_t n = chain.size();
    std::vector<double> share(n, 0.);
    const std::size_t segments = closed ? n : n - 1;
    for(std::size_t s = 0; s < segments; ++s)
    {
      const auto& p = point_[chain[s]];
      const auto& q = point_[chain[(s + 1) % n]];
      const double len = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                   (p[2] - q[2]) * (p[2] - q[2]));
      share[s] += 0.5 * len;
      share[(s + 1) % n] += 0.5 * len;
    }
    pl.closed = closed;
    for(std::size_t s = 0; s < n; ++s)
    {
      const std::size_t v = beta_[chain[s]];
      if(!pl.vertices.empty() && pl.vertices.back() == v)
        pl.weights.back() += share[s];
      else
      {
        pl.vertices.push_back(v);
        pl.weights.push_back(share[s]);
      }
    }
    if(closed && pl.vertices.size() > 1 && pl.vertices.front() == pl.vertices.back())
    {
      pl.weights.front() += pl.weights.back();
      pl.vertices.pop_back();
      pl.weights.pop_back();
    }
  }

  void next_stamp()
  {
    if(++stamp_ == 0)
    {
      std::fill(edge_stamp_.begin(), edge_stamp_.end(), 0u);
      stamp_ = 1;
    }
  }

  const Curves_mesh& m_;
  std::vector<std::uint32_t> edge_stamp_;
  std::vector<std::size_t> edge_slot_;
  std::uint32_t stamp_ = 0;
  std::vector<std::size_t> crossing_, beta_;
  std::vector<std::array<double, 3>> point_;
  std::vector<std::array<std::size_t, 2>> faces_;
  std::vector<unsigned char> visited_;
};

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_CURVES_LEVEL_SET_H
