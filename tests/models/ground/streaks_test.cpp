// Streaks along an object's path (models/ground/streaks.h): analytic profiles.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "models/ground/streaks.h"

namespace repose {
namespace {

// An object moving along y = 0 from x = -0.8 to 0.8 m in 16 steps of 0.1 m.
ObjectSpec mover(double z_m = 0.1) {
  ObjectSpec o;
  o.name = "ball";
  Keyframe a, b;
  a.pose.position_m = Eigen::Vector3d(-0.8, 0.0, z_m);
  b.time_s = 1.6;
  b.pose.position_m = Eigen::Vector3d(0.8, 0.0, z_m);
  o.keyframes = {a, b};
  return o;
}

TimeSpec steps_of(double step_s, double duration_s) {
  TimeSpec t;
  t.step_s = step_s;
  t.duration_s = duration_s;
  return t;
}

const Grid kGrid{200, 40, 0.01, -1.0, -0.2};

TEST(Streaks, AFlatFloorHasNone) {
  const StreakStats s = streaks_along_path(HeightField(kGrid, 0.03), mover(), steps_of(0.1, 1.6), 1e-4);
  EXPECT_GT(s.samples, 0);
  EXPECT_NEAR(s.rms_m, 0.0, 1e-15);
  EXPECT_NEAR(s.range_m, 0.0, 1e-15);
  EXPECT_EQ(s.ridges, 0);
}

TEST(Streaks, ARidgePerFrameIsCountedWithItsRms) {
  // z = A cos(2 pi x / 0.1): a ridge at every frame position (every 10 cells)
  HeightField h(kGrid, 0.0);
  const double amplitude = 0.005;
  for (int j = 0; j < kGrid.ny; ++j) {
    for (int i = 0; i < kGrid.nx; ++i) {
      h.at(i, j) = amplitude * std::cos(2.0 * std::numbers::pi * kGrid.centre_x(i) / 0.1);
    }
  }
  const StreakStats s = streaks_along_path(h, mover(), steps_of(0.1, 1.6), 1e-4);
  // 16 segments less the first and last: x in [-0.7, 0.7), 14 periods, and interior maxima only
  EXPECT_EQ(s.samples, 14 * 20);
  EXPECT_NEAR(s.rms_m, amplitude / std::sqrt(2.0), 0.05 * amplitude);
  // the crests fall between cell centres, which bilinear sampling cuts by up to 1 - cos(pi / 10)
  EXPECT_NEAR(s.range_m, 2.0 * amplitude, 0.1 * amplitude);
  EXPECT_EQ(s.ridges, 13);
  // below the prominence threshold nothing counts
  EXPECT_EQ(streaks_along_path(h, mover(), steps_of(0.1, 1.6), 3.0 * amplitude).ridges, 0);
}

TEST(Streaks, AnObjectThatDoesNotMoveAcrossHasNoPath) {
  ObjectSpec still = mover();
  still.keyframes.resize(1);
  EXPECT_EQ(streaks_along_path(HeightField(kGrid, 0.03), still, steps_of(0.1, 1.6), 1e-4).samples, 0);
}

}  // namespace
}  // namespace repose
