// One step of the ground model: pressing a sphere straight down.
#include "models/ground/ground_step.h"

#include <gtest/gtest.h>

#include "models/ground/displacement.h"
#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

constexpr double kGround = 0.05;  // m
constexpr double kRadius = 0.1;   // m

// A ball of radius 0.1 m lowered from above a 0.05 m ground to `depth_m`
// into it over the first step, then held.
GroundModel pressed_ball(int n, double h, double depth_m, const Material& material, TriangleMesh body = {}) {
  ObjectSpec ball = sphere(kRadius, {at(0, 0, 0, kGround + kRadius + 0.01), at(1, 0, 0, kGround + kRadius - depth_m)});
  if (!body.empty()) ball.body = std::move(body);
  return build_ground_model(flat_scene(centred_grid(n, n, h), kGround, material, {ball}, 3));
}

TEST(GroundStep, VolumeBalancesForEveryAlpha) {
  for (const double alpha : {0.0, 0.3, 0.8, 1.0}) {
    Material m = sand();
    m.alpha = alpha;
    const GroundModel model = pressed_ball(64, 0.01, 0.04, m);
    const GroundState state = run_steps(model, default_params(model), kGround, 3);
    expect_balanced(state.ledger, state.height.volume_m3());
    EXPECT_TRUE(state.height.all_finite());
  }
}

TEST(GroundStep, AlphaOneCompressesNothing) {
  const GroundModel model = pressed_ball(64, 0.01, 0.04, sand());
  const GroundState state = run_steps(model, default_params(model), kGround, 3);
  EXPECT_EQ(state.ledger.compressed_m3, 0.0);
  EXPECT_NEAR(state.height.volume_m3(), state.ledger.initial_m3, 1e-12);
  EXPECT_GT(state.height.max_height_m(), kGround + 1e-3);  // a rim was pushed up
}

TEST(GroundStep, AlphaZeroDisplacesNothing) {
  Material snow;
  material_preset("snow", &snow);
  const GroundModel model = pressed_ball(64, 0.01, 0.04, snow);
  const GroundParams params = default_params(model);
  GroundState state = make_ground_state(model, HeightField(model.grid, kGround));
  auto renderer = make_cpu_underside_renderer();
  step(model, params, *renderer, &state);
  // nothing rises: every cell is at the ground or below, the removed volume is compressed
  EXPECT_LE(state.height.max_height_m(), kGround);
  EXPECT_NEAR(state.ledger.compressed_m3, state.ledger.initial_m3 - state.height.volume_m3(), 1e-15);
  EXPECT_GT(state.ledger.compressed_m3, 0.0);
}

TEST(GroundStep, NoCellAboveTheUnderside) {
  for (const char* preset : {"sand", "mud", "snow"}) {
    Material m;
    ASSERT_TRUE(material_preset(preset, &m));
    const GroundModel model = pressed_ball(48, 0.01, 0.05, m);
    const GroundState state = run_steps(model, default_params(model), kGround, 3);
    const TriangleMesh ball = transformed(model.objects[0].body, model.objects[0].pose_at(3.0));
    const DepthImage under = depth_image_cpu({ball}, model.grid, ViewFrom::kBelow);
    for (int j = 0; j < model.grid.ny; ++j) {
      for (int i = 0; i < model.grid.nx; ++i) {
        if (under.is_covered(i, j)) {
          EXPECT_LE(state.height.at(i, j), under.z(i, j) + 1e-12) << preset << i << "," << j;
        }
      }
    }
  }
}

// The crater of a symmetric press is symmetric under the grid's symmetries.
TEST(GroundStep, PressedSphereLeavesASymmetricCrater) {
  for (const char* preset : {"sand", "mud", "snow"}) {
    Material m;
    ASSERT_TRUE(material_preset(preset, &m));
    const GroundModel model = pressed_ball(40, 0.01, 0.045, m, make_octasphere(kRadius, 4));
    const GroundState state = run_steps(model, default_params(model), kGround, 3);
    const ArrayXXdR& a = state.height.heights();
    const int n = model.grid.nx;
    double worst = 0.0;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        worst = std::max(worst, std::abs(a(j, i) - a(j, n - 1 - i)));  // x mirror
        worst = std::max(worst, std::abs(a(j, i) - a(n - 1 - j, i)));  // y mirror
        worst = std::max(worst, std::abs(a(j, i) - a(i, j)));          // diagonal
      }
    }
    EXPECT_LT(worst, 1e-10) << preset;
    EXPECT_LT(state.height.min_height_m(), kGround - 0.04) << preset;  // a crater was made
  }
}

TEST(GroundStep, RepeatIsBitIdentical) {
  const GroundModel model = pressed_ball(64, 0.01, 0.04, sand());
  const GroundState a = run_steps(model, default_params(model), kGround, 3);
  const GroundState b = run_steps(model, default_params(model), kGround, 3);
  EXPECT_TRUE((a.height.heights() == b.height.heights()).all());
  EXPECT_EQ(a.ledger.compressed_m3, b.ledger.compressed_m3);
}

// Dragging: the material goes forward and sideways, never behind the object.
TEST(GroundStep, DragNeverPushesBackwards) {
  Material m = sand();
  m.repose_angle_rad = 90 * kDeg;  // no erosion, to see displacement alone
  // starts already sunk in at x = -0.1 and moves 4 cells along +x
  ObjectSpec ball = sphere(kRadius, {at(0, -0.1, 0, kGround + kRadius - 0.03), at(1, -0.06, 0, kGround + kRadius - 0.03)});
  const GroundModel model = build_ground_model(flat_scene(centred_grid(64, 64, 0.01), kGround, m, {ball}, 1));
  GroundState state = make_ground_state(model, HeightField(model.grid, kGround));
  auto renderer = make_cpu_underside_renderer();
  step(model, default_params(model), *renderer, &state);
  // behind the object's rear (x < -0.1 - r) nothing rose
  for (int j = 0; j < 64; ++j) {
    for (int i = 0; i < 64; ++i) {
      if (model.grid.centre_x(i) < -0.1 - kRadius) {
        EXPECT_LE(state.height.at(i, j), kGround) << i << "," << j;
      }
    }
  }
  EXPECT_GT(state.height.max_height_m(), kGround);
  expect_balanced(state.ledger, state.height.volume_m3());
}

TEST(GroundStep, IsDragNeedsHorizontalMotionAndNotDownwards) {
  EXPECT_TRUE(is_drag({0.1, 0, 0}, 1e-6));
  EXPECT_TRUE(is_drag({0.1, 0, 0.05}, 1e-6));
  EXPECT_FALSE(is_drag({0.1, 0, -0.05}, 1e-6));
  EXPECT_FALSE(is_drag({0, 0, 0.1}, 1e-6));
}

// Two objects in one step: the ground stays under both.
TEST(GroundStep, TwoObjectsBalanceAndStayUnderBoth) {
  ObjectSpec a = sphere(0.08, {at(0, -0.06, 0, 0.2), at(1, -0.06, 0, kGround + 0.08 - 0.03)});
  ObjectSpec b = sphere(0.08, {at(0, 0.07, 0, 0.2), at(1, 0.07, 0, kGround + 0.08 - 0.03)});
  const GroundModel model = build_ground_model(flat_scene(centred_grid(48, 48, 0.01), kGround, sand(), {a, b}, 3));
  const GroundState state = run_steps(model, default_params(model), kGround, 3);
  expect_balanced(state.ledger, state.height.volume_m3());
  for (const ObjectSpec& o : model.objects) {
    const DepthImage under = depth_image_cpu({transformed(o.body, o.pose_at(3))}, model.grid, ViewFrom::kBelow);
    for (int j = 0; j < 48; ++j) {
      for (int i = 0; i < 48; ++i) {
        if (under.is_covered(i, j)) {
          EXPECT_LE(state.height.at(i, j), under.z(i, j) + 1e-12);
        }
      }
    }
  }
}

}  // namespace
}  // namespace repose
