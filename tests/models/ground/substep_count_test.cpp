// Counts derived from the input are bounded before they are used.
#include "models/ground/substep_count.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/ground/simulate_ground.h"
#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

// A ball that turns half a turn in its one step. The options are set on the
// model directly, past their validate(): the model's own count check is the
// second line of defence.
GroundModel turning(double max_substep_angle_rad, int coarse_factor = 2) {
  ObjectSpec ball = sphere(0.03, {at(0, 0, 0, 0.07), at(1, 0.05, 0, 0.07)});
  ball.keyframes[1].pose.orientation = Eigen::AngleAxisd(3.0, Eigen::Vector3d::UnitY());
  GroundModel model = build_ground_model(flat_scene(centred_grid(16, 16, 0.01), 0.05, sand(), {ball}, 1));
  model.options.max_substep_angle_rad = max_substep_angle_rad;
  model.options.coarse_factor = coarse_factor;
  return model;
}

void expect_refused(const GroundModel& model, const char* option) {
  try {
    simulate_ground(model, default_params(model), HeightField(model.grid, 0.05));
    FAIL() << "accepted " << option << " = " << model.options.max_substep_angle_rad;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(option), std::string::npos) << e.what();
  }
}

std::string option_error(double max_substep_angle_rad) {
  try {
    GroundModelSpec options;
    options.max_substep_angle_rad = max_substep_angle_rad;
    validate(options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// 1e-300 rad once overflowed the integer conversion (undefined behaviour,
// then one substep); 1e-6 deg asked for 3e6 substeps in one step. The
// option's rule refuses both, naming the key.
TEST(SubstepCount, ATinyMaxSubstepAngleIsRefusedNamingTheOption) {
  EXPECT_NE(option_error(1e-300).find("max_substep_angle_deg"), std::string::npos);
  EXPECT_NE(option_error(1e-6 * kDeg).find("max_substep_angle_deg"), std::string::npos);
  EXPECT_EQ(option_error(5 * kDeg), "");
}

// Within the option's range the count can still be too large for one step
// (0.01 deg over a half turn: 17,000 substeps): the model refuses it, also
// when the option bypassed its rule.
TEST(SubstepCount, TheModelRefusesTooManySubsteps) {
  expect_refused(turning(0.01 * kDeg), "max_substep_angle_deg");
  expect_refused(turning(1e-300), "max_substep_angle_deg");
}

// step() alone (without simulate_ground's check) refuses too.
TEST(SubstepCount, StepRefusesTooManySubsteps) {
  const GroundModel model = turning(1e-300);
  GroundState state = make_ground_state(model, HeightField(model.grid, 0.05));
  auto renderer = make_cpu_underside_renderer();
  EXPECT_THROW(step(model, default_params(model), *renderer, &state), InputError);
}

TEST(SubstepCount, ASaneAngleRuns) {
  const GroundModel model = turning(5 * kDeg);
  const GroundRun run = simulate_ground(model, default_params(model), HeightField(model.grid, 0.05));
  EXPECT_TRUE(run.final_height.all_finite());
}

TEST(SubstepCount, ACoarseFactorBeyondTheGridIsRefused) {
  EXPECT_THROW(check_counts(turning(5 * kDeg, 1 << 30)), InputError);
  EXPECT_THROW(check_counts(turning(5 * kDeg, 64)), InputError);  // within the option's range, beyond 16 cells
  EXPECT_NO_THROW(check_counts(turning(5 * kDeg, 2)));
}

}  // namespace
}  // namespace repose
