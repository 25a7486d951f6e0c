// The bearing sinkage of a body of any shape: a flat box's patch is its
// footprint and its sinkage Bekker's plate sinkage; a sphere's patch widens
// with depth, so its sinkage grows more slowly than a plate's with load.
#include "models/ground/bearing_sinkage.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

DepthImage underside_of(const TriangleMesh& body, const Pose& pose, const Grid& grid) {
  return depth_image_cpu({transformed(body, pose)}, grid, ViewFrom::kBelow);
}

TEST(BearingSinkage, FlatBoxPatchIsItsFootprint) {
  const Grid grid = centred_grid(40, 40, 0.005);  // box edges on cell edges: 20 x 10 cells
  const DepthImage u = underside_of(make_box({0.05, 0.025, 0.02}), Pose{{0, 0, 0.1}, {}}, grid);
  const ContactPatch p = patch_below(u, 0.08 + 1e-12);  // the ray cast's bottom, to round-off
  EXPECT_EQ(p.cells, 200);
  EXPECT_NEAR(p.area_m2, 0.005, 1e-15);
  EXPECT_NEAR(p.width_m, 0.05, 1e-12);  // the shorter side
  EXPECT_EQ(patch_below(u, 0.0799).cells, 0);
}

TEST(BearingSinkage, FlatBoxSinksAsBekkersPlate) {
  const Grid grid = centred_grid(40, 40, 0.005);
  const DepthImage u = underside_of(make_box({0.05, 0.05, 0.02}), Pose{{0, 0, 0.1}, {}}, grid);
  const BekkerBearing sand;
  for (const double load : {5.0, 20.0, 80.0}) {
    EXPECT_NEAR(bearing_sinkage_m(sand, u, 0.04, load), bekker_sinkage_m(sand, load / 0.01, 0.1), 1e-9) << load;
  }
  EXPECT_EQ(bearing_sinkage_m(sand, u, 0.04, 0.0), 0.0);
  // a load no footprint bears: buried to its height
  EXPECT_EQ(bearing_sinkage_m(sand, u, 0.04, 1e9), 0.04);
}

TEST(BearingSinkage, SpherePatchWidensSoSinkageGrowsSlowerThanAPlates) {
  const double r = 0.05;
  const Grid grid = centred_grid(100, 100, 0.001);
  const DepthImage u = underside_of(make_sphere(r, 64), Pose{{0, 0, 0.2}, {}}, grid);
  const BekkerBearing sand;
  double previous = 0.0;
  for (const double load : {2.0, 8.0, 32.0}) {
    const double z = bearing_sinkage_m(sand, u, 2 * r, load);
    EXPECT_GT(z, previous);
    // at z the patch (a disc of radius sqrt(2 r z - z^2)) carries the load at Bekker's pressure
    const double a = std::sqrt(2 * r * z - z * z);
    const double bekker_load = bekker_pressure_pa(sand, z, std::sqrt(3.0) * a) * std::numbers::pi * a * a;
    EXPECT_NEAR(bekker_load / load, 1.0, 0.1) << load << " N: z " << z;
    previous = z;
  }
  // four times the load: a plate sinks 4^(1/n) = 3.5 times deeper, the sphere far less
  EXPECT_LT(bearing_sinkage_m(sand, u, 2 * r, 32.0) / bearing_sinkage_m(sand, u, 2 * r, 8.0), 3.0);
}

}  // namespace
}  // namespace repose
