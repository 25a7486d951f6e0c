#include "validation/rigid/rigid_simulation.h"

#include <gtest/gtest.h>

#include <limits>

#include "tests/validation/rigid/fake_world.h"

namespace repose {
namespace {

GrainSet three_grains() {
  GrainSet g;
  g.position_m.resize(3, 3);
  g.position_m << 0.5, 0.5, 0.1, 0.2, 0.8, 0.002, 0.9, 0.1, 0.3;
  g.radius_m = Eigen::VectorXd::Constant(3, 0.002);
  return g;
}

TEST(RigidSimulation, LostGrainsAreThoseOutsideTheBoxOrNotFinite) {
  const RigidBounds box{0.0, 1.0, 0.0, 1.0, 0.5};
  GrainSet g = three_grains();
  EXPECT_TRUE(lost_grains(g, box).empty());
  g.position_m(0, 0) = 1.01;                                        // beyond a wall
  g.position_m(1, 2) = -0.01;                                       // under the floor
  g.position_m(2, 1) = std::numeric_limits<double>::quiet_NaN();   // not finite
  EXPECT_EQ(lost_grains(g, box), (std::vector<long>{0, 1, 2}));
  g = three_grains();
  g.position_m(2, 2) = 2.0;  // above the walls' top: thrown up, not lost
  EXPECT_TRUE(lost_grains(g, box).empty());
  EXPECT_THROW(demand_no_grain_lost(GrainSet{Eigen::RowVector3d(5, 5, 5), Eigen::VectorXd::Constant(1, 0.1)}, box, "x", "y"),
               std::runtime_error);
}

TEST(RigidSimulation, SettlingStopsAtTheFirstCheckBelowTheThreshold) {
  RigidWorldSpec spec;
  spec.grains = three_grains();
  test_support::FakeWorld world(spec, 0.5, false, nullptr);  // energy 0.5^k, steps of 0.01 s
  const RigidPhaseSummary s = settle(world, 0.01, 0.03, 10.0);  // checks every 3 steps: 0.5^9 < 0.01 < 0.5^6
  EXPECT_TRUE(s.settled);
  EXPECT_EQ(s.steps, 9);
  test_support::FakeWorld slow(spec, 0.999, false, nullptr);
  const RigidPhaseSummary t = settle(slow, 0.01, 0.03, 0.1);
  EXPECT_FALSE(t.settled);
  EXPECT_EQ(t.steps, 10);
}

TEST(RigidSimulation, TheRunPlacesEachObjectAtItsKeyframedPoseAtTheEndOfEachStep) {
  ObjectSpec o;
  Keyframe a, b;
  a.time_s = 0.0;
  b.time_s = 0.1;
  b.pose.position_m = {0.0, 0.0, 1.0};
  o.keyframes = {a, b};
  RigidWorldSpec spec;
  spec.grains = three_grains();
  test_support::FakeWorldLog log;
  test_support::FakeWorld world(spec, 0.5, false, &log);
  const RigidPhaseSummary s = run_motion(world, {o}, 0.05);
  ASSERT_EQ(s.steps, 5);
  ASSERT_EQ(log.poses.size(), 5u);
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(log.poses[k][0].position_m.z(), 0.1 * (k + 1), 1e-12);
}

}  // namespace
}  // namespace repose
