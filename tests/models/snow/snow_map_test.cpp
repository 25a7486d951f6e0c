#include "models/snow/snow_map.h"

#include <gtest/gtest.h>

#include "models/core/gl/osmesa_depth_renderer.h"
#include "snow_fixtures.h"

namespace repose {
namespace {

using testing::centred_grid;
using testing::plate;

TEST(SnowMap, APlateCoversExactlyTheCellsUnderItsTop) {
  const Grid grid = centred_grid(20);
  // 6 x 4 cells, edges on cell borders (centres never on an edge)
  TopDownRenderer renderer;
  const SnowMap map = make_object_snow_map("plate", {plate(0.03, 0.02, 0.1, 0.01, 0.0)}, grid, &renderer);
  int covered = 0;
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      const bool inside = std::abs(grid.centre_x(i) - 0.01) < 0.03 && std::abs(grid.centre_y(j)) < 0.02;
      EXPECT_EQ(map.covered(i, j), inside) << i << "," << j;
      if (inside) {
        EXPECT_NEAR(map.base_z(i, j), 0.1, 1e-12);
        ++covered;
      }
    }
  }
  EXPECT_EQ(covered, 24);
}

TEST(SnowMap, GroundMapIsTheHeightsOnTheSameGridAndSampledOnAnother) {
  const Grid grid = centred_grid(8);
  HeightField ground(grid);
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) ground.at(i, j) = 0.1 * grid.centre_x(i) + 0.05 * grid.centre_y(j);
  }
  const SnowMap same = make_ground_snow_map("ground", ground, grid);
  EXPECT_TRUE((same.base.z_m == ground.heights()).all());
  EXPECT_EQ(same.base.covered.cast<int>().sum(), 64);
  // a plane is reproduced by bilinear sampling inside the centres' hull
  const Grid coarse{4, 4, 0.02, grid.origin_x_m, grid.origin_y_m};
  const SnowMap resampled = make_ground_snow_map("ground", ground, coarse);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(resampled.base_z(i, j), 0.1 * coarse.centre_x(i) + 0.05 * coarse.centre_y(j), 1e-15);
    }
  }
}

// The OSMesa path renders the same maps as the CPU path, to its depth step.
TEST(SnowMap, OsmesaAndCpuMapsAgree) {
  const Grid grid = centred_grid(40);
  Pose pose;
  pose.position_m = Eigen::Vector3d(0.05, -0.03, 0.1);
  const std::vector<TriangleMesh> meshes = {plate(0.1, 0.05, 0.2, -0.05, 0.05), transformed(make_sphere(0.08, 24), pose)};
  TopDownRenderer cpu(SnowRenderer::kCpu), gl(SnowRenderer::kOsmesa);
  const SnowMap a = make_object_snow_map("g", meshes, grid, &cpu);
  const SnowMap b = make_object_snow_map("g", meshes, grid, &gl);
  int covered = 0;
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      ASSERT_EQ(a.covered(i, j), b.covered(i, j)) << i << "," << j;
      if (!a.covered(i, j)) continue;
      ++covered;
      EXPECT_NEAR(a.base_z(i, j), b.base_z(i, j), 1e-5) << i << "," << j;  // depth step ~0.25 um over 0.2 m
    }
  }
  EXPECT_GT(covered, 200);
}

}  // namespace
}  // namespace repose

namespace repose {
namespace {

// A table top at 5 cm (underside 4 cm) bounds the ground's snow at its
// underside; a block standing on the ground leaves no room; the table top
// itself (the ground lies below it) has no ceiling.
TEST(SnowMap, CeilingsAreTheUndersidesOfOtherGroupsAbove) {
  const HeightField ground(testing::centred_grid(20));
  Pose block_pose;
  block_pose.position_m = Eigen::Vector3d(0.06, 0.06, 0.02);
  const TriangleMesh block = transformed(make_box(Eigen::Vector3d(0.02, 0.02, 0.02)), block_pose);
  const SnowModel model = testing::plates_over_ground(ground, {testing::plate(0.03, 0.03, 0.05), block}, SnowOptions{});
  const SnowMap& g = model.maps[0];
  EXPECT_NEAR(g.ceiling_z(10, 10), 0.04, 1e-12);     // under the table top
  EXPECT_EQ(g.ceiling_z(16, 16), 0.0);               // under the block (its bottom on the ground)
  EXPECT_TRUE(std::isinf(g.ceiling_z(2, 2)));        // open ground
  EXPECT_TRUE(std::isinf(model.maps[1].ceiling_z(10, 10)));
  EXPECT_TRUE(std::isinf(model.maps[2].ceiling_z(16, 16)));
}

}  // namespace
}  // namespace repose
