#include "validation/bullet/bullet_debris_world.h"

#include <gtest/gtest.h>

#include "tests/validation/rigid/debris_test_world.h"

namespace repose {
namespace {

using namespace test_support;

// The house weighs 8 x 6 - 5 x 3 = 33 m^2 x 2.98 m x 300 kg/m^3 x 2 storeys
// = 58 t (5.8e5 N); a ground joint carries at most that.
constexpr double kStrongJointN = 2.0e6;

TEST(BulletDebrisWorld, AnUntouchedHouseStandsForTheWholeRun) {
  const DebrisSetup setup = house_on_flat_ground(kStrongJointN);
  ASSERT_EQ(setup.spec.joints.size(), 6u);
  const auto world = make_bullet_debris_world(setup.spec, {});
  const HouseOutcome out = run_house(*world, setup, 3.0);
  EXPECT_EQ(out.joints_broken, 0);
  EXPECT_LT(out.max_part_displacement_m, 1e-3);
  // the ground joints carry the house's weight (the parts start clear of the ground)
  double max_force_n = 0.0;
  for (double f : world->joint_forces_n()) max_force_n = std::max(max_force_n, f);
  EXPECT_GT(max_force_n, 0.1 * 5.8e5);
  EXPECT_LT(max_force_n, kStrongJointN);
}

TEST(BulletDebrisWorld, AHeavyFastBodyBreaksTheHouse) {
  DebrisSetup setup = house_on_flat_ground(kStrongJointN);
  throw_at_house(setup, 30.0);  // 84 t at 30 m/s: 2.5e6 N s, far beyond 2e6 N over a step
  const auto world = make_bullet_debris_world(setup.spec, {});
  const HouseOutcome out = run_house(*world, setup, 1.0);
  EXPECT_GT(out.joints_broken, 0);
  EXPECT_GT(out.max_part_displacement_m, 0.1);
}

TEST(BulletDebrisWorld, ASlowBodyLeavesAStrongHouseStanding) {
  DebrisSetup setup = house_on_flat_ground(1.0e9);
  throw_at_house(setup, 1.0);
  const auto world = make_bullet_debris_world(setup.spec, {});
  EXPECT_EQ(run_house(*world, setup, 1.0).joints_broken, 0);
}

}  // namespace
}  // namespace repose
