// Named parameters: every package tag set and read back, chained with CGAL's
// own names in both orders, and forwarded to a CGAL function.
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/generators.h>

#include <gtest/gtest.h>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::is_default_parameter;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

TEST(NamedParameters, EveryPackageTagIsReadBack)
{
  auto np = IRS::parameters::target_number_of_vertices(1000)
              .isotropic_remeshing(true)
              .number_of_samples(321)
              .number_of_threads(3)
              .number_of_signature_rings(5)
              .signature_radius(0.2)
              .sdf_cone_angle(1.5)
              .sdf_number_of_rays(17)
              .similarity_threshold(0.05)
              .distance_threshold(0.03)
              .axial_threshold(0.7);
  namespace np_ = IRS::internal_np;
  EXPECT_EQ(choose_parameter(get_parameter(np, np_::target_number_of_vertices), 0), 1000);
  EXPECT_TRUE(choose_parameter(get_parameter(np, np_::isotropic_remeshing), false));
  EXPECT_EQ(choose_parameter(get_parameter(np, np_::number_of_samples), 0), 321);
  EXPECT_EQ(choose_parameter(get_parameter(np, np_::number_of_threads), 0), 3);
  EXPECT_EQ(choose_parameter(get_parameter(np, np_::number_of_signature_rings), 0), 5);
  EXPECT_DOUBLE_EQ(choose_parameter(get_parameter(np, np_::signature_radius), 0.), 0.2);
  EXPECT_DOUBLE_EQ(choose_parameter(get_parameter(np, np_::sdf_cone_angle), 0.), 1.5);
  EXPECT_EQ(choose_parameter(get_parameter(np, np_::sdf_number_of_rays), 0), 17);
  EXPECT_DOUBLE_EQ(choose_parameter(get_parameter(np, np_::similarity_threshold), 0.), 0.05);
  EXPECT_DOUBLE_EQ(choose_parameter(get_parameter(np, np_::distance_threshold), 0.), 0.03);
  EXPECT_DOUBLE_EQ(choose_parameter(get_parameter(np, np_::axial_threshold), 0.), 0.7);
  EXPECT_TRUE((is_default_parameter<decltype(np), CGAL::internal_np::random_seed_t>::value));
}

TEST(NamedParameters, ChainsWithCGALNamesInBothOrders)
{
  Mesh m;
  auto vpm = get(CGAL::vertex_point, m);
  auto a = IRS::parameters::vertex_point_map(vpm).number_of_samples(10).random_seed(5u);
  auto b = IRS::parameters::random_seed(5u).vertex_point_map(vpm).number_of_samples(10);
  EXPECT_EQ(choose_parameter(get_parameter(a, CGAL::internal_np::random_seed), 0u), 5u);
  EXPECT_EQ(choose_parameter(get_parameter(b, CGAL::internal_np::random_seed), 0u), 5u);
  EXPECT_EQ(choose_parameter(get_parameter(a, IRS::internal_np::number_of_samples), 0), 10);
  EXPECT_FALSE((is_default_parameter<decltype(b), CGAL::internal_np::vertex_point_t>::value));
  EXPECT_TRUE((is_default_parameter<decltype(b), IRS::internal_np::axial_threshold_t>::value));
}

TEST(NamedParameters, PackIsAcceptedByCGALFunctions)
{
  Mesh m;
  CGAL::make_tetrahedron(K::Point_3(0,0,0), K::Point_3(1,0,0), K::Point_3(0,1,0), K::Point_3(0,0,1), m);
  auto np = IRS::parameters::number_of_samples(10).vertex_point_map(get(CGAL::vertex_point, m));
  const double area = CGAL::Polygon_mesh_processing::area(m, np.cgal());
  EXPECT_NEAR(area, 1.5 + std::sqrt(3.) / 2., 1e-12);
}
