#include "models/heightspan/heightspan_state.h"

#include <gtest/gtest.h>

#include "heightspan_fixtures.h"
#include "models/core/config/initial_height.h"

namespace repose {
namespace {

TEST(HeightSpanState, StartsWithEmptyMapsAtTheFirstPoseAndAccountsForTheGround) {
  Scene s = testing::bed_scene(40, 40, 0.005, 0.02,
                               {testing::mesh_object("bucket", testing::bucket_mesh(), {testing::key(0, 0.1, 0.1, 0.1)})}, 1);
  const HeightSpanModel model = build_heightspan_model(s);
  const HeightSpanState state = make_heightspan_state(model, make_initial_height(s));
  ASSERT_EQ(state.held.size(), 1u);
  EXPECT_FALSE(state.held[0].map.empty());
  EXPECT_EQ(held_m3(state), 0.0);
  EXPECT_FALSE(state.particles.built);
  EXPECT_NEAR(accounted_m3(state), 0.2 * 0.2 * 0.02, 1e-15);
  EXPECT_EQ(state.held[0].pose.position_m, Eigen::Vector3d(0.1, 0.1, 0.1));
}

TEST(HeightSpanState, TheGeneratorIsSeededFromTheScene) {
  Scene s = testing::bed_scene(10, 10, 0.01, 0.01, {}, 1);
  s.seed = 42;
  const HeightSpanModel model = build_heightspan_model(s);
  HeightSpanState a = make_heightspan_state(model, make_initial_height(s));
  HeightSpanState b = make_heightspan_state(model, make_initial_height(s));
  EXPECT_EQ(a.rng(), b.rng());
}

}  // namespace
}  // namespace repose
