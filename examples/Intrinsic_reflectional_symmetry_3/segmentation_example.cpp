// Symmetry-aware segmentation (paper Sec. 4.1) next to CGAL's SDF
// segmentation with the same number of segments, on the same mesh.
// Prints the area of each segment of both; with an output directory, also
// writes both as PLY files with a colour per face (the manual's figure).
//
// usage: segmentation_example [mesh.off [output_dir]]
//        (default: the generated two snowmen joined by a tube, no files)

#include <CGAL/Intrinsic_reflectional_symmetry_3/Heat_method_geodesic_oracle.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/check_input.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_curves.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_transform.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/sampling.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/segmentation.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/shape_generators.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/signatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Face_index face_descriptor;

// prints the share of the area of each segment
void print_segments(const std::string& name, const Mesh& mesh, Mesh::Property_map<face_descriptor, std::size_t> segment,
                    std::size_t n)
{
  std::vector<double> area(n, 0.);
  for(face_descriptor f : faces(mesh)) area[segment[f]] += PMP::face_area(f, mesh);
  std::cout << name << ": " << n << " segment(s), % of the area:";
  for(double a : area) std::cout << ' ' << int(100. * a / PMP::area(mesh) + 0.5);
  std::cout << std::endl;
}

// writes the geometry of `mesh` with one colour per segment (CGAL's PLY writer stores "f:color")
void write_segments(const std::string& path, const Mesh& mesh, Mesh::Property_map<face_descriptor, std::size_t> segment)
{
  static const CGAL::IO::Color palette[] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40},
                                            {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {188, 189, 34}};
  Mesh out = mesh; // same face indices
  out.remove_all_property_maps();
  auto colour = out.add_property_map<face_descriptor, CGAL::IO::Color>("f:color").first;
  for(face_descriptor f : faces(out)) colour[f] = palette[segment[f] % 8];
  std::ofstream stream(path, std::ios::binary);
  CGAL::IO::write_PLY(stream, out);
}

int main(int argc, char** argv)
{
  Mesh mesh;
  try {
    if(argc > 1) IRS::read_mesh(argv[1], mesh); // throws Input_error naming the problem
    else mesh = IRS::generate_two_snowmen<Mesh>().mesh;
    IRS::check_input(mesh);
  } catch(const IRS::Input_error& e) {
    std::cerr << "bad input: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }

  // 1. the pipeline with the package's defaults, up to the IRSA curves (and the nested ones)
  const std::vector<std::size_t> samples = IRS::farthest_point_samples(mesh, IRS::parameters::random_seed(0u));
  const IRS::Heat_method_geodesic_oracle<Mesh> oracle(mesh);
  const IRS::Geodesic_distance_matrix D = IRS::compute_geodesic_distance_matrix(oracle, samples);
  std::vector<std::pair<std::size_t, std::size_t>> similar;
  IRS::similar_sample_pairs(IRS::compute_sdf_signatures(mesh, D), std::back_inserter(similar));
  auto tau = mesh.add_property_map<vertex_descriptor, double>("v:tau", 0.).first;
  const IRS::Irsa_voting_result voting = IRS::compute_irsa_transform(mesh, D, similar, tau);
  std::vector<IRS::Irsa_curve> curves;
  // nested symmetries: the axes of the limbs too, not only the body's (one segment per curve)
  IRS::extract_irsa_curves(mesh, D, voting, tau, std::back_inserter(curves),
                           IRS::parameters::nested_symmetries(true));
  std::cout << num_vertices(mesh) << " vertices, " << samples.size() << " samples, " << curves.size()
            << " IRSA curve(s)" << std::endl;

  // 2. symmetry-aware: CGAL's SDF over-segmentation merged by the curves' symmetric regions
  auto ours = mesh.add_property_map<face_descriptor, std::size_t>("f:symmetry_segment", 0).first;
  const std::size_t n = IRS::symmetry_aware_segmentation(mesh, D, curves, ours);
  print_segments("symmetry-aware", mesh, ours, n);

  // 3. CGAL's SDF segmentation alone, asked for as many segments
  auto sdf = mesh.add_property_map<face_descriptor, std::size_t>("f:sdf_segment", 0).first;
  const std::size_t m = IRS::Sdf_over_segmenter(n, n, n)(mesh, get(CGAL::vertex_point, mesh), sdf);
  print_segments("SDF segmentation", mesh, sdf, m);

  if(argc > 2) {
    const std::string dir = argv[2];
    write_segments(dir + "/symmetry_segmentation.ply", mesh, ours);
    write_segments(dir + "/sdf_segmentation.ply", mesh, sdf);
  }
  return EXIT_SUCCESS;
}
