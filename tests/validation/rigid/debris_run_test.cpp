#include "validation/rigid/debris_run.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/validation/rigid/debris_test_world.h"

namespace repose {
namespace {

// Elements sliding at a constant velocity; parts given a fixed offset after
// `break_after` steps, when every joint breaks.
class SlidingWorld final : public DebrisWorld {
 public:
  SlidingWorld(const DebrisSetup& setup, Eigen::Vector3d v, long break_after)
      : spec_(setup.spec), v_(std::move(v)), break_after_(break_after) {}
  void step() override {
    ++steps_;
    for (DebrisElement& e : spec_.elements) e.centre_m += v_ * time_step_s();
  }
  double time_step_s() const override { return 0.01; }
  GrainSet elements() const override {
    GrainSet g;
    g.position_m.resize(static_cast<Eigen::Index>(spec_.elements.size()), 3);
    g.radius_m.resize(g.position_m.rows());
    g.velocity_m_s.resize(g.position_m.rows(), 3);
    for (std::size_t i = 0; i < spec_.elements.size(); ++i) {
      g.position_m.row(static_cast<Eigen::Index>(i)) = spec_.elements[i].centre_m.transpose();
      g.velocity_m_s.row(static_cast<Eigen::Index>(i)) = v_.transpose();
      g.radius_m(static_cast<Eigen::Index>(i)) = spec_.elements[i].radius_m;
    }
    return g;
  }
  std::vector<Pose> part_poses() const override {
    std::vector<Pose> out;
    for (std::size_t p = 0; p < spec_.parts.size(); ++p) {
      const double shift = steps_ > break_after_ && p == 0 ? 0.5 : 0.0;
      out.push_back({spec_.parts[p].centre_m + Eigen::Vector3d(shift, 0, 0), Eigen::Quaterniond::Identity()});
    }
    return out;
  }
  std::vector<bool> joints_broken() const override { return std::vector<bool>(spec_.joints.size(), steps_ > break_after_); }
  std::vector<double> joint_forces_n() const override { return std::vector<double>(spec_.joints.size(), 1.0); }
  // kPartForceN along x on every part until the joints break, nothing after.
  std::vector<Eigen::Vector3d> part_element_forces_n() const override {
    const Eigen::Vector3d f = steps_ > break_after_ ? Eigen::Vector3d::Zero() : Eigen::Vector3d(kPartForceN, 0, 0);
    return std::vector<Eigen::Vector3d>(spec_.parts.size(), f);
  }
  static constexpr double kPartForceN = 10.0;

 private:
  DebrisWorldSpec spec_;
  Eigen::Vector3d v_;
  long break_after_;
  long steps_ = 0;
};

TEST(DebrisRun, TheFrontMovesAtTheElementsSpeedAlongTheFlow) {
  DebrisSetup setup = test_support::house_on_flat_ground(1.0e6);
  for (int k = 0; k < 9; ++k) setup.spec.elements.push_back({Eigen::Vector3d(k, 0, 50), Eigen::Vector3d::Zero(), 0.2});
  setup.flow_direction = Eigen::Vector2d(0.6, 0.8);
  SlidingWorld world(setup, Eigen::Vector3d(3.0, 4.0, 0.0), 1000);
  DebrisRunOptions options;
  options.frame_interval_s = 0.1;
  const DebrisRunResult r = run_debris(world, setup, 1.0, options);
  ASSERT_EQ(r.frames.size(), 11u);
  for (const DebrisFrame& f : r.frames) EXPECT_NEAR(f.front_speed_m_s, 5.0, 1e-9);  // |v| along the flow
  EXPECT_NEAR(r.runout_m, 5.0, 1e-9);
  EXPECT_EQ(r.steps, 100);
  ASSERT_EQ(r.buildings.size(), 1u);
  EXPECT_EQ(r.buildings[0].joints_broken, 0);
  EXPECT_EQ(r.buildings[0].parts_moved, 0);
  EXPECT_EQ(r.buildings[0].static_joint_force_n, 1.0);
}

TEST(DebrisRun, PartsMovedAndJointsBrokenAreCountedPerBuilding) {
  const DebrisSetup setup = test_support::house_on_flat_ground(1.0e6);
  SlidingWorld world(setup, Eigen::Vector3d::Zero(), 10);
  const DebrisRunResult r = run_debris(world, setup, 0.5);
  EXPECT_EQ(r.buildings[0].parts, 4);
  EXPECT_EQ(r.buildings[0].parts_moved, 1);  // 0.5 m > the 5 cm threshold
  EXPECT_NEAR(r.buildings[0].max_displacement_m, 0.5, 1e-12);
  EXPECT_EQ(r.buildings[0].joints_broken, 6);
  EXPECT_EQ(r.frames.back().joints_broken, 6);
}

// SlidingWorld pushes every part with kPartForceN for 10 steps of 0.01 s.
TEST(DebrisRun, TheBuildingForceIsTheSumOverItsPartsBinnedInTime) {
  const DebrisSetup setup = test_support::house_on_flat_ground(1.0e6);
  SlidingWorld world(setup, Eigen::Vector3d::Zero(), 10);
  DebrisRunOptions options;
  options.force_interval_s = 0.05;
  const DebrisRunResult r = run_debris(world, setup, 0.3, options);
  ASSERT_EQ(r.force_time_s.size(), 6u);
  EXPECT_NEAR(r.force_time_s.back(), 0.3, 1e-12);
  for (const BuildingOutcome& b : r.buildings) {
    const double f = b.parts * SlidingWorld::kPartForceN;
    ASSERT_EQ(b.force_n.size(), 6u);
    EXPECT_NEAR(b.force_n[0], f, 1e-9);
    EXPECT_NEAR(b.force_n[1], f, 1e-9);
    EXPECT_EQ(b.force_n[2], 0.0);
    EXPECT_NEAR(b.peak_force_n, f, 1e-9);
    EXPECT_NEAR(b.impulse_n_s, f * 0.1, 1e-9);
  }
}

TEST(DebrisRun, TheFrontIsAQuantileAlongTheDirection) {
  GrainSet g;
  g.position_m.resize(100, 3);
  g.radius_m = Eigen::VectorXd::Constant(100, 0.1);
  for (int i = 0; i < 100; ++i) g.position_m.row(i) << 0.0, i, 0.0;
  EXPECT_DOUBLE_EQ(debris_front_m(g, Eigen::Vector2d(0, 10), Eigen::Vector2d(0, 1), 1.0), 89.0);
  EXPECT_DOUBLE_EQ(debris_front_m(g, Eigen::Vector2d(0, 10), Eigen::Vector2d(0, 1), 0.98), 87.0);
}

TEST(DebrisRun, BadOptionsAreRefusedNamingTheField) {
  DebrisRunOptions o;
  o.front_quantile = 0.0;
  EXPECT_THROW(o.validate(), InputError);
  try {
    o.validate();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("front_quantile"), std::string::npos);
  }
}

}  // namespace
}  // namespace repose
