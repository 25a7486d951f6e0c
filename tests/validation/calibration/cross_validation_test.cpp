// Leave-one-scene-out cross-validation on synthetic references made by the
// ground model itself: when every scene was made with the same parameters,
// each fold (fitted without one scene) predicts that scene; when one scene
// was made with other parameters, the fit on the others cannot predict it,
// and its cross-validated error exceeds its in-sample one.
#include "validation/calibration/cross_validation.h"

#include <string>

#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"
#include "validation/calibration/calibration_loader.h"

namespace repose {
namespace {

const std::string kDir = std::string(REPOSE_SOURCE_DIR) + "/tests/data/calibration";

// Indentation and drag, references at alpha 0.7 unless the drag's is given;
// alpha fitted alone (theta and sigma at the references' values).
CalibrationProblem problem_with_drag_alpha(double drag_alpha, bool drag_held_out = false) {
  const std::string fixed = "ground.sand.repose_angle_deg: 35, ground.sand.sigma: 0.15";
  const std::string yaml =
      "scenes:\n"
      "  - scene: scenes/indent.yaml\n"
      "    reference: {heuristic: {ground.sand.alpha: 0.7, " + fixed + "}}\n"
      "    observables: [{kind: height_field}]\n"
      "  - scene: scenes/pile.yaml\n"
      "    reference: {heuristic: {ground.sand.alpha: 0.7, " + fixed + "}}\n"
      "    observables: [{kind: height_field}]\n"
      "  - scene: scenes/drag.yaml\n" +
      std::string(drag_held_out ? "    role: held_out\n" : "") +
      "    reference: {heuristic: {ground.sand.alpha: " + std::to_string(drag_alpha) + ", " + fixed + "}}\n"
      "    observables: [{kind: height_field}]\n"
      "parameters:\n"
      "  - {name: ground.sand.alpha, initial: 0.4, bounds: [0, 1], step: 0.05}\n"
      "  - {name: ground.sand.repose_angle_deg, initial: 35, fixed: true}\n"
      "  - {name: ground.sand.sigma, initial: 0.15, fixed: true}\n"
      "solver: {starts: 1, max_iterations: 20, threads: 2}\n";
  return CalibrationProblem(load_calibration_from_string(yaml, kDir + "/inline.yaml"), solver_registry());
}

TEST(CrossValidation, EveryFoldPredictsTheSceneItLeftOutWhenTheScenesAgree) {
  const CalibrationProblem problem = problem_with_drag_alpha(0.7);
  CalibrationFit fit = fit_calibration(problem);
  EXPECT_EQ(cross_validate(problem, &fit), 3);
  for (const SceneError& e : fit.scenes) {
    ASSERT_TRUE(e.cross_validated.has_value()) << e.name;
    EXPECT_NEAR(e.cross_validated_values[0], 0.7, 0.05) << e.name;
    // the scene's change is predicted, not only fitted
    EXPECT_LT(e.cross_validated->rmse_m, 0.1 * e.cross_validated->rmse_nothing_m) << e.name;
    EXPECT_GT(e.cross_validated->skill, 0.9) << e.name;
  }
}

TEST(CrossValidation, ASceneMadeWithOtherParametersIsNotPredicted) {
  const CalibrationProblem problem = problem_with_drag_alpha(0.1);
  CalibrationFit fit = fit_calibration(problem);
  cross_validate(problem, &fit);
  const SceneError& drag = fit.scenes[2];
  ASSERT_TRUE(drag.cross_validated.has_value());
  // the fold without the drag sees only alpha 0.7 and fits it
  EXPECT_NEAR(drag.cross_validated_values[0], 0.7, 0.05);
  EXPECT_GT(drag.cross_validated->rmse_m, drag.scores_fitted.rmse_m);
}

TEST(CrossValidation, HeldOutScenesStayOutAndOneFitSceneHasNoFolds) {
  const CalibrationProblem problem = problem_with_drag_alpha(0.7, true);
  CalibrationFit fit = fit_calibration(problem);
  EXPECT_EQ(cross_validate(problem, &fit), 2);
  EXPECT_FALSE(fit.scenes[2].cross_validated.has_value());
  const CalibrationProblem single = problem.holding_out(problem.scenes()[1].entry.name);
  CalibrationFit single_fit = fit_calibration(single);
  EXPECT_EQ(cross_validate(single, &single_fit), 0);
  for (const SceneError& e : single_fit.scenes) EXPECT_FALSE(e.cross_validated.has_value());
}

}  // namespace
}  // namespace repose
