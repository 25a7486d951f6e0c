// The speed/accuracy ladder on a synthetic reference: the ground model at the
// reference's own resolution and parameters reproduces it exactly (RMSE 0),
// other resolutions do not, and every rung has a positive wall time.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"

#include "validation/calibration/calibration_ladder.h"
#include "validation/calibration/calibration_loader.h"
#include "validation/calibration/calibration_problem.h"

namespace repose {
namespace {

TEST(CalibrationLadder, OwnResolutionAtTheReferenceParametersHasNoError) {
  const CalibrationProblem problem(load_calibration_from_string(
      "scenes:\n"
      "  - scene: scenes/indent.yaml\n"
      "    reference: {heuristic: {ground.sand.alpha: 0.7, ground.sand.repose_angle_deg: 35, ground.sand.sigma: 0.15}}\n"
      "    observables: [{kind: height_field}]\n"
      "parameters:\n"
      "  - {name: ground.sand.alpha, initial: 0.7}\n"
      "  - {name: ground.sand.repose_angle_deg, initial: 35}\n"
      "  - {name: ground.sand.sigma, initial: 0.15}\n"
      "ladder: {heuristic_cell_sizes_m: [0.008, 0.002], timing_repeats: 1}\n",
      std::string(REPOSE_SOURCE_DIR) + "/tests/data/calibration/inline.yaml"), solver_registry());
  const Ladder ladder = measure_ladder(problem, problem.initial_values());
  EXPECT_EQ(ladder.scene, "calib_indent");
  ASSERT_EQ(ladder.rungs.size(), 4u);  // 8, 4 (the scene's own, added), 2 mm, multires
  bool own = false;
  for (const LadderRung& r : ladder.rungs) {
    SCOPED_TRACE(r.label);
    EXPECT_GT(r.wall_time_s, 0.0);
    EXPECT_TRUE(std::isfinite(r.rmse_m));
    if (r.kind == "ground" && std::abs(r.resolution_m - 0.004) < 1e-12) {
      own = true;
      EXPECT_EQ(r.rmse_m, 0.0);
    } else if (r.kind == "ground") {
      EXPECT_GT(r.rmse_m, 0.0);
    }
  }
  EXPECT_TRUE(own);
  EXPECT_FALSE(ladder.liggghts_over_ground_time.has_value());  // no LIGGGHTS rung listed
}

}  // namespace
}  // namespace repose
