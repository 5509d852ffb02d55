/*!
\ingroup PkgIntrinsicReflectionalSymmetry3Concepts
\cgalConcept

An over-segmenter is the black-box mesh segmentation whose parts the
symmetric (PIRS) regions merge in `symmetry_aware_segmentation()` (paper
Sec. 4.1: over-segment the model into about 20 parts, then give each part to
the region that covers the largest area of it; by default only where that
region covers at least 80 % of the part, see `minimum_region_coverage`). It splits the faces of a
triangle mesh into parts, typically along concave creases (minima rule), in
more parts than the final segmentation has.

Part ids are any non-negative integers; they need not be consecutive, and a
part need not be connected: `merge_over_segmentation()` first splits every
part into its connected pieces. The result must depend only on the mesh (the
same parts for the same input, whatever the thread count), and the mesh must
not be modified.

\cgalHasModel `CGAL::Intrinsic_reflectional_symmetry_3::Sdf_over_segmenter`

\sa `CGAL::Intrinsic_reflectional_symmetry_3::symmetry_aware_segmentation()`
\sa `CGAL::Intrinsic_reflectional_symmetry_3::merge_over_segmentation()`
*/
class OverSegmenter
{
public:
  /// writes the part of every face of `tm` into `part` and returns the
  /// number of parts (one more than the largest id written, or a larger bound).
  ///
  /// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
  /// \tparam VertexPointMap a model of `ReadablePropertyMap` with the vertex
  ///         descriptor as key and a point type of a \cgal kernel as value type
  /// \tparam FacePartMap a model of `WritablePropertyMap` with the face
  ///         descriptor as key and `std::size_t` as value type
  ///
  /// \param tm the triangle mesh (read only)
  /// \param vpm the positions of the vertices of `tm` (the `vertex_point_map`
  ///        named parameter of the calling function, or `get(CGAL::vertex_point, tm)`)
  /// \param part receives the part of every face
  ///
  /// Bad input should be reported by throwing
  /// `CGAL::Intrinsic_reflectional_symmetry_3::Input_error`.
  template <typename TriangleMesh, typename VertexPointMap, typename FacePartMap>
  std::size_t operator()(const TriangleMesh& tm, VertexPointMap vpm, FacePartMap part) const;
};
