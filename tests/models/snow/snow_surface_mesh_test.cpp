#include "models/snow/snow_surface_mesh.h"

#include <gtest/gtest.h>

#include "snow_fixtures.h"

namespace repose {
namespace {

TEST(SnowSurfaceMesh, CoversSnowyCellsAtBasePlusDepth) {
  const Grid grid = testing::centred_grid(10);
  TopDownRenderer renderer;
  const SnowMap map = make_object_snow_map("plate", {testing::plate(0.02, 0.02, 0.1)}, grid, &renderer);  // 4 x 4 cells
  ArrayXXdR depth = ArrayXXdR::Constant(10, 10, 0.01);
  const TriangleMesh mesh = snow_surface_mesh(map, depth);
  EXPECT_EQ(mesh.V.rows(), 16);     // only the covered cells, though the depth is set everywhere
  EXPECT_EQ(mesh.F.rows(), 2 * 9);  // 3 x 3 squares
  EXPECT_LT((mesh.V.col(2).array() - 0.11).abs().maxCoeff(), 1e-12);
  depth(4, 4) = 0.0;  // a bare cell leaves the four squares around it out
  EXPECT_EQ(snow_surface_mesh(map, depth).F.rows(), 2 * 5);
}

}  // namespace
}  // namespace repose
