// The fit against the canonical LIGGGHTS run data/dem_indent: it lowers the
// cost, and the same file and seed give bit-identical results, whatever the
// number of threads.
#include <fstream>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"

#include "validation/calibration/calibration_fit.h"
#include "validation/calibration/calibration_loader.h"
#include "validation/calibration/calibration_problem.h"
#include "tests/validation/calibration/tiny_snow_table.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

std::string dem_indent_calibration(int threads, int seed) {
  return "scenes:\n"
         "  - scene: scenes/dem_indent.yaml\n"
         "    reference: {data: ../data/dem_indent}\n"
         "    observables:\n"
         "      - {kind: height_field, region_m: {x: [0.008, 0.072], y: [0.008, 0.072]}}\n"
         "      - {kind: crater_depth, region_m: {x: [0.024, 0.056], y: [0.024, 0.056]}}\n"
         "parameters:\n"
         "  - {name: ground.sand.alpha, initial: 0.9, step: 0.05}\n"
         "  - {name: ground.sand.repose_angle_deg, initial: 25, bounds: [15, 60], step: 3}\n"
         "solver: {starts: 2, max_iterations: 4, seed: " +
         std::to_string(seed) + ", threads: " + std::to_string(threads) + "}\n";
}

CalibrationFit fit_dem_indent(int threads, int seed) {
  const std::string pretend = std::string(REPOSE_SOURCE_DIR) + "/experiments/calibration_fit_test.yaml";
  const CalibrationProblem problem(load_calibration_from_string(dem_indent_calibration(threads, seed), pretend), solver_registry());
  return fit_calibration(problem);
}

TEST(CalibrationFit, AgainstDemIndentReducesCostAndRepeatsBitForBit) {
  const CalibrationFit a = fit_dem_indent(2, 5);
  const CalibrationFit b = fit_dem_indent(1, 5);
  EXPECT_LT(a.final_cost, a.initial_cost);
  EXPECT_LT(a.scenes[0].rmse_fitted_m, a.scenes[0].rmse_initial_m);
  ASSERT_EQ(a.starts.size(), 2u);
  EXPECT_EQ(a.values, b.values);  // exact
  EXPECT_EQ(a.final_cost, b.final_cost);
  for (std::size_t s = 0; s < a.starts.size(); ++s) {
    EXPECT_EQ(a.starts[s].initial_free, b.starts[s].initial_free);
    EXPECT_EQ(a.starts[s].cost_per_iteration, b.starts[s].cost_per_iteration);
  }
  // another seed moves the Halton starts (start 0 is the file's initial values)
  const CalibrationFit c = fit_dem_indent(2, 6);
  EXPECT_EQ(c.starts[0].initial_free, a.starts[0].initial_free);
  EXPECT_NE(c.starts[1].initial_free, a.starts[1].initial_free);
}

// The report scores each entry on its own field (field:): a snow map is
// compared with the reference's snow map, not with the model's ground
// surface. At the parameters the synthetic reference was made with, the
// table's snow is reproduced exactly; the ground surface is not it.
TEST(CalibrationFit, SceneErrorScoresTheEntrysField) {
  const std::string dir = std::string(REPOSE_SOURCE_DIR) + "/experiments";
  const test_support::TempDir temp;
  const std::string scene = (temp.path / "scene_error_table.yaml").string();
  std::ofstream(scene) << testing::tiny_snow_table_yaml(4.0);
  const std::string yaml = "scenes:\n  - scene: " + scene + "\n    name: top\n    field: snow_depth_final.table\n" +
                           "    reference: {heuristic: {snow.repose_angle_deg: 40}}\n"
                           "    observables: [{kind: height_field}]\n"
                           "parameters:\n  - {name: snow.repose_angle_deg, initial: 25, bounds: [5, 85]}\n";
  const CalibrationProblem problem(load_calibration_from_string(yaml, dir + "/inline.yaml"), solver_registry());
  const double deg = 3.141592653589793 / 180.0;
  const SceneError e = scene_error(problem, problem.scenes().front(), {25 * deg}, {40 * deg});
  EXPECT_GT(e.scores_fitted.rmse_nothing_m, 1e-3);  // the table holds snow
  EXPECT_LT(e.rmse_fitted_m, 1e-12);
  EXPECT_GT(e.rmse_initial_m, 1e-4);  // a shallower angle leaves a different pile
}

// A solve that stalls (every parameter ends within a tenth of its
// derivative step of the start) without failing is solved again with a
// damped first step (calibration_fit.h: Ceres' nearly Gauss-Newton first
// step, projected onto the bounds, can leave nothing), and the better of the
// two is kept; one that moves, or fails, is not retried.
TEST(CalibrationFit, AStalledSolveIsRetriedWithADampedFirstStep) {
  const std::vector<double> steps{0.1, 3.0};
  std::vector<double> radii;
  // the first solve ends at `first_end` with cost `first_cost`; the damped one moves to (0.5, 10) at cost `damped_cost`
  const auto solve = [&radii](std::vector<double> first_end, double first_cost, double damped_cost) {
    return [&radii, first_end, first_cost, damped_cost](double radius) {
      radii.push_back(radius);
      const bool first = radius == kFirstTrustRegionRadius;
      CalibrationStart s;
      s.initial_free = {1.0, 20.0};
      s.final_free = first ? first_end : std::vector<double>{0.5, 10.0};
      s.iterations = first ? 1 : 3;
      s.final_cost = first ? first_cost : damped_cost;
      s.termination = first ? "CONVERGENCE: Parameter tolerance reached." : "CONVERGENCE: Function tolerance reached.";
      return s;
    };
  };
  const CalibrationStart retried = solve_or_retry_damped(solve({0.995, 20.2}, 2.0, 0.5), steps);
  EXPECT_EQ(radii, (std::vector<double>{kFirstTrustRegionRadius, kDampedTrustRegionRadius}));
  EXPECT_LT(kDampedTrustRegionRadius, kFirstTrustRegionRadius);
  EXPECT_EQ(retried.iterations, 3);
  EXPECT_EQ(retried.final_cost, 0.5);
  EXPECT_NE(retried.termination.find("retried with a damped first step"), std::string::npos) << retried.termination;
  EXPECT_NE(retried.termination.find("Parameter tolerance"), std::string::npos) << retried.termination;
  radii.clear();
  const CalibrationStart kept = solve_or_retry_damped(solve({0.995, 20.2}, 2.0, 3.0), steps);  // the retry is worse
  EXPECT_EQ(radii.size(), 2u);
  EXPECT_EQ(kept.final_cost, 2.0);
  EXPECT_NE(kept.termination.find("did no better"), std::string::npos) << kept.termination;
  radii.clear();
  EXPECT_EQ(solve_or_retry_damped(solve({0.995, 20.4}, 2.0, 0.5), steps).final_cost, 2.0);  // moved 0.4 of a 3 step
  EXPECT_EQ(solve_or_retry_damped(solve({0.98, 20.0}, 2.0, 0.5), steps).final_cost, 2.0);   // moved 0.02 of a 0.1 step
  EXPECT_EQ(solve_or_retry_damped(solve({1.0, 20.0}, std::numeric_limits<double>::infinity(), 0.5), steps).iterations,
            1);  // failed
  EXPECT_EQ(radii.size(), 3u);
}

}  // namespace
}  // namespace repose
