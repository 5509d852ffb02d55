// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_HEAT_METHOD_GEODESIC_ORACLE_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_HEAT_METHOD_GEODESIC_ORACLE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/component_meshes.h>

#include <CGAL/Default.h>
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/boost/graph/named_params_helper.h>

#ifndef CGAL_EIGEN3_ENABLED
#error "Heat_method_geodesic_oracle needs Eigen: link CGAL::Eigen3_support (defines CGAL_EIGEN3_ENABLED)."
#endif

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
///
/// Geodesic distances by the heat method (Crane et al. 2013) on the intrinsic
/// Delaunay triangulation, using CGAL's
/// `CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3` with
/// `CGAL::Heat_method_3::Intrinsic_Delaunay`. The package's default oracle:
/// after one sparse factorisation per connected component, each source costs
/// two back-substitutions and a few linear passes over the mesh.
///
/// Heat-method distances are approximations (within about 1 % of the diameter
/// on a well-shaped mesh) and only approximately symmetric.
///
/// CGAL's solver object keeps its source set and work vectors, so it cannot
/// answer two queries at once. The constructor therefore builds, serially and
/// identically, one solver set ("worker") per thread that may call
/// `distances_from()`; a call borrows a free worker from a small
/// mutex-protected pool (waiting if none is free). All workers hold the same
/// factorisation and answer bit-identically, so the result does not depend on
/// which worker, or which thread, answers.
///
/// Each connected component is solved on its own copy of the component (the
/// Laplacian of a multi-component mesh is singular): vertices of other
/// components get `+infinity`.
///
/// \cgalModels `GeodesicDistanceOracle`
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam VertexPointMap a model of `ReadablePropertyMap` from the vertex
///         descriptors to a CGAL kernel's `Point_3`. Default: the mesh's
///         internal `CGAL::vertex_point` map.
template <typename TriangleMesh, typename VertexPointMap = CGAL::Default>
class Heat_method_geodesic_oracle
{
public:
  typedef TriangleMesh Triangle_mesh;
  typedef typename CGAL::Default::Get<
    VertexPointMap,
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type Vertex_point_map;

private:
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point_3;
  typedef internal::Component_meshes<Point_3>                          Components;
  typedef typename Components::Mesh                                      Mesh;
  typedef CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<
    Mesh, CGAL::Heat_method_3::Intrinsic_Delaunay>                       Solver;

  // one solver per component with faces (null for isolated vertices), plus scratch space
  struct Worker
  {
    std::vector<std::unique_ptr<Solver> > solvers;
    std::vector<double> buffer;
  };

  struct Pool
  {
    std::mutex mutex;
    std::condition_variable released;
    std::vector<Worker*> free_workers;
  };

public:
  /// precomputes the solvers; `tm` is copied and not used afterwards.
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{the positions of the vertices}
  ///     \cgalParamType{`Vertex_point_map`}
  ///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_index_map}
  ///     \cgalParamDescription{the vertex indices used by `distances_from()`}
  ///     \cgalParamType{a model of `ReadablePropertyMap` from vertex descriptors to `std::size_t`,
  ///                    numbering the vertices `0 .. num_vertices(tm)-1`}
  ///     \cgalParamDefault{`CGAL::get_initialized_vertex_index_map(tm, np)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_threads}
  ///     \cgalParamDescription{how many solver sets to build, that is, how many
  ///                           `distances_from()` calls can run at the same time.
  ///                           Each costs one factorisation and its memory.}
  ///     \cgalParamType{`int`, at least 1}
  ///     \cgalParamDefault{`tbb::this_task_arena::max_concurrency()` when TBB is linked, 1 otherwise}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws Input_error `empty_mesh`, `not_triangle_mesh`, `degenerate_face` (a face repeats a vertex),
  ///         `non_manifold_vertex` (a component that is not a manifold surface), or
  ///         `invalid_parameter` (vertex indices not in `0 .. n-1`, `number_of_threads < 1`)
  template <typename CGAL_NP_TEMPLATE_PARAMETERS>
  explicit Heat_method_geodesic_oracle(const TriangleMesh& tm,
                                       const CGAL_NP_CLASS& np = parameters::default_values())
    : components_(make_components(tm, np)), pool_(new Pool())
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
#ifdef CGAL_LINKED_WITH_TBB
    const int default_workers = (std::max)(1, tbb::this_task_arena::max_concurrency());
#else
    const int default_workers = 1;
#endif
    const int number_of_workers =
      static_cast<int>(choose_parameter(get_parameter(np, internal_np::number_of_threads), default_workers));
    if(number_of_workers < 1)
      throw Input_error(Input_problem::invalid_parameter,
                        "number_of_threads must be at least 1, not " + std::to_string(number_of_workers));

    // built serially: building touches (dynamic) property maps of the meshes
    workers_.resize(static_cast<std::size_t>(number_of_workers));
    for(auto& w : workers_) {
      w.reset(new Worker());
      for(std::size_t c = 0; c < components_->number_of_components(); ++c)
        w->solvers.emplace_back(components_->has_faces(c) ? new Solver(components_->mesh(c)) : nullptr);
      pool_->free_workers.push_back(w.get());
    }
  }

  Heat_method_geodesic_oracle(const Heat_method_geodesic_oracle&) = delete;
  Heat_method_geodesic_oracle& operator=(const Heat_method_geodesic_oracle&) = delete;
  Heat_method_geodesic_oracle(Heat_method_geodesic_oracle&&) = default;
  Heat_method_geodesic_oracle& operator=(Heat_method_geodesic_oracle&&) = default;

  /// number of vertices of the mesh
  std::size_t number_of_vertices() const { return components_->number_of_vertices(); }

  /// number of connected components of the mesh (isolated vertices included)
  std::size_t number_of_components() const { return components_->number_of_components(); }

  /// number of solver sets, that is, of queries that can run at the same time
  std::size_t number_of_workers() const { return workers_.size(); }

  /// writes the heat-method distance from vertex `source` to every vertex into
  /// `out[0 .. number_of_vertices()-1]` (`+infinity` in other components).
  /// Thread-safe; blocks while all workers are busy.
  /// \throws Input_error (`invalid_parameter`) if `source` is not a vertex index
  void distances_from(std::size_t source, float* out) const
  {
    check_source(source);
    Lease lease(*pool_, nullptr);
    compute(*lease.worker, source, out);
  }

  /// \cond SKIP_IN_MANUAL
  /// the same as `distances_from()`, answered by worker `worker`
  /// (`< number_of_workers()`); lets tests check that all workers agree.
  void distances_from_worker(std::size_t worker, std::size_t source, float* out) const
  {
    check_source(source);
    if(worker >= workers_.size())
      throw Input_error(Input_problem::invalid_parameter, "no worker " + std::to_string(worker), worker);
    Lease lease(*pool_, workers_[worker].get());
    compute(*lease.worker, source, out);
  }
  /// \endcond

private:
  // borrows a worker from the pool (a given one, or any) and gives it back on destruction
  struct Lease
  {
    Pool& pool;
    Worker* worker;

    Lease(Pool& p, Worker* wanted) : pool(p), worker(nullptr)
    {
      std::unique_lock<std::mutex> lock(pool.mutex);
      auto& f = pool.free_workers;
      if(wanted == nullptr) {
        pool.released.wait(lock, [&] { return !f.empty(); });
        worker = f.back();
        f.pop_back();
      } else {
        pool.released.wait(lock, [&] { return std::find(f.begin(), f.end(), wanted) != f.end(); });
        f.erase(std::find(f.begin(), f.end(), wanted));
        worker = wanted;
      }
    }
    ~Lease()
    {
      {
        std::lock_guard<std::mutex> lock(pool.mutex);
        pool.free_workers.push_back(worker);
      }
      pool.released.notify_all(); // notify_all: a waiter may want this particular worker
    }
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
  };

  template <typename NamedParameters>
  static std::unique_ptr<Components> make_components(const TriangleMesh& tm, const NamedParameters& np)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    const Vertex_point_map vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                  get_const_property_map(CGAL::vertex_point, tm));
    return std::unique_ptr<Components>(
      new Components(tm, vpm, CGAL::get_initialized_vertex_index_map(tm, np)));
  }

  void check_source(std::size_t source) const
  {
    if(source >= number_of_vertices())
      throw Input_error(Input_problem::invalid_parameter,
                        "source vertex index " + std::to_string(source) + " >= " +
                        std::to_string(number_of_vertices()), source);
  }

  void compute(Worker& worker, std::size_t source, float* out) const
  {
    components_->initialize_row(source, out);
    const std::size_t c = components_->component(source);
    if(!components_->has_faces(c))
      return; // an isolated vertex: 0 to itself, +infinity elsewhere
    const Mesh& mesh = components_->mesh(c);
    Solver& solver = *worker.solvers[c];
    solver.clear_sources();
    solver.add_source(components_->local_vertex(source));
    worker.buffer.assign(num_vertices(mesh), 0.);
    solver.estimate_geodesic_distances(
      boost::make_iterator_property_map(worker.buffer.begin(), get(boost::vertex_index, mesh)));
    const std::vector<std::size_t>& input_index = components_->input_indices(c);
    for(std::size_t i = 0; i < input_index.size(); ++i)
      out[input_index[i]] = static_cast<float>(worker.buffer[i]);
  }

  std::unique_ptr<Components> components_;            // heap: solvers refer to its meshes
  std::vector<std::unique_ptr<Worker> > workers_;
  std::unique_ptr<Pool> pool_;                         // heap: keeps the oracle movable
};

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_HEAT_METHOD_GEODESIC_ORACLE_H
