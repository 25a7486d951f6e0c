#include "models/snow/snow_state.h"

#include <gtest/gtest.h>

#include "snow_fixtures.h"

namespace repose {
namespace {

TEST(SnowState, FreshStateIsEmptyAndBalanced) {
  const HeightField ground(testing::centred_grid(6));
  const SnowModel model = testing::plates_over_ground(ground, {testing::plate(0.01, 0.01, 0.02)}, SnowOptions{});
  SnowState s = make_snow_state(model);
  ASSERT_EQ(s.depth_m.size(), 2u);
  EXPECT_EQ(snow_on_maps_m3(s, model.grid), 0.0);
  s.depth_m[1](2, 2) = 0.5;
  s.ledger.fallen_m3 = 0.5 * 1e-4 + 2e-6;
  s.ledger.left_scene_m3 = 2e-6;
  EXPECT_NEAR(snow_imbalance_m3(s, model.grid), 0.0, 1e-18);
}

}  // namespace
}  // namespace repose
