#include "models/snow/snow_step.h"

#include <gtest/gtest.h>

#include "snow_fixtures.h"

namespace repose {
namespace {

TEST(SnowStep, AccumulationAddsProbabilityTimesDepthAndLedgersIt) {
  const HeightField ground(testing::centred_grid(4));
  const SnowModel model = testing::plates_over_ground(ground, {}, SnowOptions{});
  SnowState state = make_snow_state(model);
  SnowProbability p{{ArrayXXdR::Constant(4, 4, 0.5)}, 1};
  p.per_map[0](1, 2) = 0.0;
  accumulate_snow(p, 0.004, model.grid, &state);
  EXPECT_EQ(state.depth_m[0](0, 0), 0.002);
  EXPECT_EQ(state.depth_m[0](1, 2), 0.0);
  EXPECT_NEAR(state.ledger.fallen_m3, 15 * 0.002 * 1e-4, 1e-18);
  EXPECT_NEAR(snow_imbalance_m3(state, model.grid), 0.0, 1e-18);
}

TEST(SnowStep, TheLastStepEndsAtTheDuration) {
  const HeightField ground(testing::centred_grid(3));
  SnowModel model = testing::plates_over_ground(ground, {}, SnowOptions{});
  model.time.step_s = 0.4;
  model.time.duration_s = 1.0;
  model.options.snowfall = SnowfallRate(1e-3);
  SnowState state = make_snow_state(model);
  const SnowProbability p{{ArrayXXdR::Ones(3, 3)}, 1};
  double fallen = 0.0;
  for (int k = 0; k < model.time.step_count(); ++k) fallen += step_snow(model, SnowParams{}, p, &state).snowfall_depth_m;
  EXPECT_EQ(model.time.step_count(), 3);
  EXPECT_DOUBLE_EQ(state.time_s, 1.0);
  EXPECT_NEAR(fallen, 1e-3, 1e-18);
}

}  // namespace
}  // namespace repose
