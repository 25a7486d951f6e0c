#include "models/snow/shadow_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "models/snow/snowfall_directions.h"
#include "snow_fixtures.h"

namespace repose {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(ShadowMap, LightFrameIsOrthonormalRightHandedAndTheWorldFrameForVerticalSnow) {
  const LightFrame vertical = light_frame(Eigen::Vector3d(0, 0, -1));
  EXPECT_EQ(vertical.u, Eigen::Vector3d::UnitX());
  EXPECT_EQ(vertical.v, Eigen::Vector3d::UnitY());
  EXPECT_EQ(vertical.w, Eigen::Vector3d::UnitZ());
  for (double tilt : {0.1, 0.7, 1.4}) {
    for (double az : {0.0, 1.0, 2.5, -2.0}) {
      const LightFrame f = light_frame(travel_vector({tilt, az}));
      EXPECT_NEAR(f.u.dot(f.v), 0.0, 1e-15);
      EXPECT_NEAR(f.u.dot(f.w), 0.0, 1e-15);
      EXPECT_NEAR(f.v.dot(f.w), 0.0, 1e-15);
      EXPECT_NEAR(f.u.cross(f.v).dot(f.w), 1.0, 1e-15);
    }
  }
}

TEST(ShadowMap, BiasGrowsWithTheTiltOfTheDirection) {
  EXPECT_DOUBLE_EQ(shadow_bias_m(Eigen::Vector3d(0, 0, -1), 0.01, 1.5), 0.015);
  EXPECT_NEAR(shadow_bias_m(travel_vector({45 * kDeg, 0.3}), 0.01, 1.0), 0.02, 1e-15);
}

// A plate at 5 cm shadows the ground under it along a 45 deg direction: the
// shadow is the footprint shifted 5 cm downwind, as geometry says.
TEST(ShadowMap, TiltedShadowIsTheFootprintShiftedDownwind) {
  const HeightField ground(testing::centred_grid(30));
  const SnowModel model = testing::plates_over_ground(ground, {testing::plate(0.03, 0.03, 0.05)}, SnowOptions{});
  TopDownRenderer renderer;
  const ShadowMap shadow = render_shadow_map(model.occluders, model.maps, travel_vector({45 * kDeg, 0.0}), 0.0025,
                                             1.0, &renderer);
  const Grid& g = model.grid;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const double x = g.centre_x(i), y = g.centre_y(j);
      const bool lit = shadow.is_lit({x, y, 0.0});
      // a ground point is shadowed when its ray up-wind (towards -x) at 45 deg
      // meets the 1 cm thick plate: x - z in [-3, 3] cm for some z in [4, 5] cm,
      // so for x in [1, 8] cm and |y| < 3 cm; a pixel's margin either side
      if (std::abs(y) > 0.035 || x > 0.085 || x < 0.005) {
        EXPECT_TRUE(lit) << x << "," << y;
      }
      if (std::abs(y) < 0.025 && x > 0.015 && x < 0.075) {
        EXPECT_FALSE(lit) << x << "," << y;
      }
    }
  }
}

}  // namespace
}  // namespace repose
