#include "models/snow/ground_surface_mesh.h"

#include <gtest/gtest.h>

#include "models/core/geometry/depth_image.h"
#include "snow_fixtures.h"

namespace repose {
namespace {

TEST(GroundSurfaceMesh, OneVertexPerCellTwoTrianglesPerSquareFacingUp) {
  HeightField ground(testing::centred_grid(5));
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i) ground.at(i, j) = 0.01 * i * j;
  }
  const TriangleMesh mesh = ground_surface_mesh(ground);
  EXPECT_EQ(mesh.V.rows(), 25);
  EXPECT_EQ(mesh.F.rows(), 2 * 4 * 4);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    EXPECT_GT((b - a).cross(c - a).z(), 0.0) << f;  // counter-clockwise from above
  }
  // the top-down image between the centres is the bilinear-ish surface; at a
  // square's middle it lies between the four corner heights
  const Grid fine{4, 4, 0.01, ground.grid().origin_x_m + 0.005, ground.grid().origin_y_m + 0.005};
  const DepthImage img = depth_image_cpu({mesh}, fine, ViewFrom::kAbove);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      ASSERT_TRUE(img.is_covered(i, j));
      const double lo = std::min({ground.at(i, j), ground.at(i + 1, j), ground.at(i, j + 1), ground.at(i + 1, j + 1)});
      const double hi = std::max({ground.at(i, j), ground.at(i + 1, j), ground.at(i, j + 1), ground.at(i + 1, j + 1)});
      EXPECT_GE(img.z(i, j), lo - 1e-15);
      EXPECT_LE(img.z(i, j), hi + 1e-15);
    }
  }
}

TEST(GroundSurfaceMesh, SingleRowOrCellHasNoTriangles) {
  EXPECT_TRUE(ground_surface_mesh(HeightField(Grid{1, 1, 0.01, 0, 0})).empty());
  EXPECT_TRUE(ground_surface_mesh(HeightField(Grid{7, 1, 0.01, 0, 0})).empty());
}

}  // namespace
}  // namespace repose
