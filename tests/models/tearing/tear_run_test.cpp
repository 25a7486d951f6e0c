// Tear runs: a uniform sheet tears straight along its notch under the
// seed's twist; the run's bookkeeping; option checks. The along/across-grain
// comparison needs larger sheets and many seeds: experiments/tearing/.
#include "models/tearing/tear_run.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

// A uniform 21-cell sheet notched in its middle column under the seed's
// twist, and a run that stops when the tear is 24 mm deep.
SheetModel notched_twisted_sheet() {
  SheetSpec spec = free_sheet_spec(0.042, 21);
  spec.damping_per_s = 2e3;
  spec.grips = seed_twist_grips(0.042, 0.042, 0.006, 0.006, 4.0);
  spec.notch_length_m = 0.004;
  spec.notch_x_m = 0.021;
  return uniform_sheet(spec);
}

TearRunOptions stop_at_24_mm() {
  TearRunOptions options;
  options.duration_s = 0.02;
  options.stop_at_depth_m = 0.024;
  return options;
}

// The twist (left grip -z, right +z) maps onto itself under x -> W - x,
// z -> -z, and so do the uniform sheet and the notch in the middle column:
// the tear must stay in that column.
TEST(TearRun, AUniformSheetTearsStraightAlongItsNotchUnderTheTwist) {
  const SheetModel model = notched_twisted_sheet();
  TearRunOptions options = stop_at_24_mm();
  const TearRun run = run_tear(model, SheetParams{}, options);
  EXPECT_TRUE(run.path.holds_notch);
  EXPECT_GE(run.path.depth_m, 0.024 - 1e-12);
  EXPECT_LT(run.state.time_s, options.duration_s);  // it stopped at the depth
  EXPECT_EQ(run.path.stray_cells, 0);
  EXPECT_DOUBLE_EQ(run.path.tortuosity, 1.0);
  EXPECT_LT(run.path.roughness_m, 1e-12);
  for (const Eigen::Vector2d& p : run.path.points) EXPECT_DOUBLE_EQ(p.x(), 0.021);
  EXPECT_NEAR(run.tear_length_m, run.path.depth_m - 2 * model.cell_size_m, 1e-15);
  EXPECT_GT(run.peak_grip_force_n, 0.0);
  EXPECT_GT(run.grip_work_j, 0.0);
  EXPECT_NEAR(run.work_per_tear_length_j_per_m, run.grip_work_j / run.tear_length_m, 1e-12);
  // the tear's own share of the grips' work: positive, and less than all of it
  EXPECT_NEAR(run.fracture_energy_per_tear_length_j_per_m, run.state.torn_energy_j / run.tear_length_m, 1e-12);
  EXPECT_GT(run.fracture_energy_per_tear_length_j_per_m, 0.0);
  EXPECT_LT(run.fracture_energy_per_tear_length_j_per_m, run.work_per_tear_length_j_per_m);
}

// The run stops on the very step whose tear first reaches the depth, not
// up to 1/200 of the duration later: the same run one step shorter, without
// the stop, has not reached it. Over ~55,000 steps a check every 1/200 of
// them would stop on a multiple of ~277 steps and fail this.
TEST(TearRun, StopsOnTheStepTheTearReachesTheDepth) {
  const SheetModel model = notched_twisted_sheet();
  TearRunOptions options = stop_at_24_mm();
  const TearRun stopped = run_tear(model, SheetParams{}, options);
  ASSERT_GE(stopped.path.depth_m, 0.024 - 1e-12);
  ASSERT_GT(stopped.steps, 2);
  ASSERT_LT(stopped.steps, static_cast<long>(options.duration_s / stopped.time_step_s) - 2);
  options.stop_at_depth_m = 0.0;
  options.duration_s = (static_cast<double>(stopped.steps) - 1.5) * stopped.time_step_s;
  const TearRun shorter = run_tear(model, SheetParams{}, options);
  EXPECT_EQ(shorter.steps, stopped.steps - 1);
  EXPECT_LT(shorter.path.depth_m, 0.024 - 1e-12);
}

// The same with the implicit integrator at four times the explicit limit.
TEST(TearRun, TheImplicitIntegratorTearsTheUniformSheetStraightToo) {
  SheetSpec spec = free_sheet_spec(0.026, 13);
  spec.damping_per_s = 2e3;
  spec.grips = seed_twist_grips(0.026, 0.026, 0.004, 0.006, 4.0);
  spec.notch_length_m = 0.004;
  spec.notch_x_m = 0.013;
  const SheetModel model = uniform_sheet(spec);
  TearRunOptions options;
  options.integrator = TearRunOptions::Integrator::kImplicit;
  options.time_step_fraction = 4.0;
  options.duration_s = 0.01;
  options.stop_at_depth_m = 0.012;
  const TearRun run = run_tear(model, SheetParams{}, options);
  EXPECT_GE(run.path.depth_m, 0.012 - 1e-12);
  EXPECT_EQ(run.path.stray_cells, 0);
  for (const Eigen::Vector2d& p : run.path.points) EXPECT_DOUBLE_EQ(p.x(), 0.013);
  EXPECT_DOUBLE_EQ(run.time_step_s, 4.0 * run.stable_time_step_s);
}

TEST(TearRun, RefusesOptionsOutsideTheirRanges) {
  const SheetModel model = uniform_sheet(free_sheet_spec(0.01, 2));
  TearRunOptions options;
  options.time_step_fraction = 1.5;
  try {
    run_tear(model, SheetParams{}, options);
    FAIL() << "a step above the stable limit was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("time_step_fraction"), std::string::npos) << e.what();
  }
  options = {};
  options.duration_s = 0.0;
  EXPECT_THROW(run_tear(model, SheetParams{}, options), InputError);
}

}  // namespace
}  // namespace repose
