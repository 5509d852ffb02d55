/*!
\ingroup PkgIntrinsicReflectionalSymmetry3Concepts
\cgalConcept

A geodesic distance oracle answers "how far is every vertex from this vertex,
along the surface?" for one triangle mesh. It is built once per mesh (that is
where factorisations and other precomputations happen) and then queried for
many sources, possibly from several threads at once.

Vertex indices are those of the mesh's vertex index map
(`CGAL::get_initialized_vertex_index_map()`), from `0` to
`number_of_vertices() - 1`. Vertices in another connected component than the
source get `+infinity`; a multi-component mesh is never an error.

\cgalHasModel `CGAL::Intrinsic_reflectional_symmetry_3::Heat_method_geodesic_oracle`
\cgalHasModel `CGAL::Intrinsic_reflectional_symmetry_3::Exact_geodesic_oracle`
\cgalHasModel `CGAL::Intrinsic_reflectional_symmetry_3::Dijkstra_geodesic_oracle`

\sa `CGAL::Intrinsic_reflectional_symmetry_3::compute_geodesic_distance_matrix()`
*/
class GeodesicDistanceOracle
{
public:
  /// the mesh type, a model of `FaceListGraph` and `HalfedgeListGraph`
  typedef unspecified_type Triangle_mesh;

  /// builds the oracle; `tm` must outlive it and stay unchanged.
  /// `np` may hold `vertex_point_map` and `vertex_index_map`.
  template <typename NamedParameters>
  GeodesicDistanceOracle(const Triangle_mesh& tm, const NamedParameters& np);

  /// number of vertices of the mesh
  std::size_t number_of_vertices() const;

  /// writes the geodesic distance from the vertex of index `source` to every
  /// vertex `v` into `out[index(v)]` (`out` has `number_of_vertices()` entries).
  /// Must be safe to call concurrently from several threads, and must give the
  /// same result whichever thread calls it.
  void distances_from(std::size_t source, float* out) const;
};
