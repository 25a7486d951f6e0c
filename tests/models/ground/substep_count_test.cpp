// Counts derived from the input are bounded before they are used.
#include "models/ground/substep_count.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/ground/simulate_ground.h"
#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

// A ball that turns half a turn in its one step.
Scene turning(double max_substep_angle_rad) {
  ObjectSpec ball = sphere(0.03, {at(0, 0, 0, 0.07), at(1, 0.05, 0, 0.07)});
  ball.keyframes[1].pose.orientation = Eigen::AngleAxisd(3.0, Eigen::Vector3d::UnitY());
  Scene scene = flat_scene(centred_grid(16, 16, 0.01), 0.05, sand(), {ball}, 1);
  scene.ground_model.max_substep_angle_rad = max_substep_angle_rad;
  return scene;
}

void expect_refused(const Scene& scene, const char* option) {
  const GroundModel model = build_ground_model(scene);
  try {
    simulate_ground(model, default_params(model), HeightField(model.grid, 0.05));
    FAIL() << "accepted " << option << " = " << scene.ground_model.max_substep_angle_rad;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(option), std::string::npos) << e.what();
  }
}

// 1e-300 rad once overflowed the integer conversion (undefined behaviour,
// then one substep); 1e-6 deg asked for 3e6 substeps in one step.
TEST(SubstepCount, ATinyMaxSubstepAngleIsRefusedNamingTheOption) {
  expect_refused(turning(1e-300), "max_substep_angle_deg");
  expect_refused(turning(1e-6 * kDeg), "max_substep_angle_deg");
}

// step() alone (without simulate_ground's check) refuses too.
TEST(SubstepCount, StepRefusesTooManySubsteps) {
  const GroundModel model = build_ground_model(turning(1e-300));
  GroundState state = make_ground_state(model, HeightField(model.grid, 0.05));
  auto renderer = make_cpu_underside_renderer();
  EXPECT_THROW(step(model, default_params(model), *renderer, &state), InputError);
}

TEST(SubstepCount, ASaneAngleRuns) {
  const GroundModel model = build_ground_model(turning(5 * kDeg));
  const GroundRun run = simulate_ground(model, default_params(model), HeightField(model.grid, 0.05));
  EXPECT_TRUE(run.final_height.all_finite());
}

TEST(SubstepCount, ACoarseFactorBeyondTheGridIsRefused) {
  Scene scene = turning(5 * kDeg);
  scene.ground_model.coarse_factor = 1 << 30;
  const GroundModel model = build_ground_model(scene);
  EXPECT_THROW(check_counts(model), InputError);
}

}  // namespace
}  // namespace repose
