#include "models/snow/top_down_renderer.h"

#include <gtest/gtest.h>

#include "snow_fixtures.h"

namespace repose {
namespace {

// Both paths see the highest of two stacked plates, and nothing beside them.
TEST(TopDownRenderer, BothPathsKeepTheHighestSurface) {
  const Grid grid = testing::centred_grid(10);
  const std::vector<TriangleMesh> meshes = {testing::plate(0.02, 0.02, 0.03), testing::plate(0.01, 0.01, 0.07)};
  for (SnowRenderer kind : {SnowRenderer::kCpu, SnowRenderer::kOsmesa}) {
    TopDownRenderer r(kind);
    const DepthImage img = r.render(meshes, grid);
    EXPECT_NEAR(img.z(5, 5), 0.07, 1e-6);
    EXPECT_NEAR(img.z(3, 5), 0.03, 1e-6);
    EXPECT_FALSE(img.is_covered(0, 0));
    EXPECT_EQ(img.covered.cast<int>().sum(), 16);
  }
}

}  // namespace
}  // namespace repose
