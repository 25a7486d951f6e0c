// Settled grains as snow depth maps: grains on a plate, under it and beside
// it go to the right map; depth is the grains' surface above the map.

#include "validation/liggghts/grain_snow_depth.h"

#include <gtest/gtest.h>

#include "models/snow/snow_model.h"

namespace repose {
namespace {

// Ground of 10 x 10 cells of 1 cm; a plate over cells 3..6 (x and y), its top at 5 cm.
std::vector<SnowMap> ground_and_plate() {
  const Grid grid{10, 10, 0.01, 0.0, 0.0};
  const HeightField ground(grid, ArrayXXdR::Zero(10, 10));
  SnowOptions options;
  options.groups = {{"ground", true, {}}, {"plate", false, {"plate"}}};
  TriangleMesh plate = make_box(Eigen::Vector3d(0.02, 0.02, 0.005));
  plate = transformed(plate, Pose{Eigen::Vector3d(0.05, 0.05, 0.045), Eigen::Quaterniond::Identity()});
  SnowGroupGeometry g0{"ground", &ground, {}}, g1{"plate", nullptr, {plate}};
  return build_snow_model({g0, g1}, grid, options, TimeSpec{}, 1).maps;
}

GrainSet grains_at(const std::vector<Eigen::Vector3d>& centres, double radius) {
  GrainSet g;
  g.position_m.resize(static_cast<Eigen::Index>(centres.size()), 3);
  g.radius_m = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(centres.size()), radius);
  for (std::size_t k = 0; k < centres.size(); ++k) g.position_m.row(static_cast<Eigen::Index>(k)) = centres[k];
  return g;
}

TEST(GrainSnowDepth, GrainsGoToTheSurfaceTheyLieOn) {
  const auto maps = ground_and_plate();
  ASSERT_TRUE(maps[1].covered(4, 4));
  ASSERT_FALSE(maps[1].covered(1, 1));
  const double r = 0.004;
  const GrainSet g = grains_at({{0.045, 0.045, 0.05 + r},    // on the plate
                                {0.045, 0.045, r},           // under it, on the ground
                                {0.015, 0.015, r},           // on open ground
                                {0.072, 0.045, 0.05 + r},    // centre just past the plate's edge (0.07), resting on it
                                {0.075, 0.045, r},           // beside the plate, on the ground
                                {0.2, 0.045, r}},            // outside the grid
                               r);
  EXPECT_EQ(snow_map_of_grains(g, maps), (std::vector<int>{1, 0, 0, 1, 0, -1}));
}

TEST(GrainSnowDepth, DepthIsTheGrainsSurfaceAboveTheMap) {
  const auto maps = ground_and_plate();
  const double r = 0.004;
  const GrainSet g = grains_at({{0.045, 0.045, 0.05 + r}, {0.015, 0.015, r}}, r);
  const auto depth = grain_snow_depth(g, maps, SurfaceHeightOptions{});
  ASSERT_EQ(depth.size(), 2u);
  EXPECT_NEAR(depth[1](4, 4), 2 * r, 1e-12);  // the top of the grain on the plate, above the plate
  EXPECT_NEAR(depth[0](1, 1), 2 * r, 1e-12);
  EXPECT_EQ(depth[0](4, 4), 0.0);              // nothing under the plate
  EXPECT_EQ(depth[1](1, 1), 0.0);              // the plate has no surface there
  EXPECT_EQ(depth[0](8, 8), 0.0);
  // a probe sphere lowered onto a grain stops at its top too
  SurfaceHeightOptions probe;
  probe.probe_radius_m = 0.002;
  EXPECT_NEAR(grain_snow_depth(g, maps, probe)[1](4, 4), 2 * r, 1e-12);
}

}  // namespace
}  // namespace repose
