// Leave-one-scene-out cross-validation on synthetic references made by the
// ground model itself: when every scene was made with the same parameters,
// each fold (fitted without one scene) predicts that scene; when one scene
// was made with other parameters, the fit on the others cannot predict it,
// and its cross-validated error exceeds its in-sample one. The same for a
// series (a scoop's held mass, height-span references): each fold's
// prediction of the scenes it did not fit is the run at the fold's values.
#include "validation/calibration/cross_validation.h"

#include <algorithm>
#include <cmath>
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
  ASSERT_EQ(fit.folds.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(fit.folds[k].left_out, k);
    EXPECT_NEAR(fit.folds[k].values[0], 0.7, 0.05) << k;
    EXPECT_FALSE(fit.folds[k].scenes[k].fit) << "the left-out scene is a prediction";
  }
  for (const SceneError& e : fit.scenes) {
    ASSERT_TRUE(e.cross_validated.has_value()) << e.name;
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
  ASSERT_EQ(fit.folds.size(), 3u);
  EXPECT_NEAR(fit.folds[2].values[0], 0.7, 0.05);
  EXPECT_GT(drag.cross_validated->rmse_m, drag.scores_fitted.rmse_m);
}

TEST(CrossValidation, HeldOutScenesStayOutAndOneFitSceneHasNoFolds) {
  const CalibrationProblem problem = problem_with_drag_alpha(0.7, true);
  CalibrationFit fit = fit_calibration(problem);
  EXPECT_EQ(cross_validate(problem, &fit), 2);
  EXPECT_FALSE(fit.scenes[2].cross_validated.has_value());
  EXPECT_EQ(fit.folds.size(), 2u);
  const CalibrationProblem single = problem.holding_out(problem.scenes()[1].entry.name);
  CalibrationFit single_fit = fit_calibration(single);
  EXPECT_EQ(cross_validate(single, &single_fit), 0);
  for (const SceneError& e : single_fit.scenes) EXPECT_FALSE(e.cross_validated.has_value());
  EXPECT_TRUE(single_fit.folds.empty());
}

// The largest relative error of a series at its times.
double worst_relative_error(const SeriesComparison& c) {
  double worst = 0.0;
  for (const double e : c.fitted_relative_error()) worst = std::max(worst, std::abs(e));
  return worst;
}

// tests/data/calibration/scoop_cv.yaml: scoops a (40 deg) and b (30 deg)
// fitted, a third at 40 deg held out; the repose angle fitted alone.
TEST(CrossValidation, EachFoldPredictsTheHeldMassOfTheScoopsItDidNotFitAtItsOwnValues) {
  const CalibrationProblem problem(load_calibration(kDir + "/scoop_cv.yaml"), solver_registry());
  CalibrationFit fit = fit_calibration(problem);
  ASSERT_EQ(cross_validate(problem, &fit), 2);
  ASSERT_EQ(fit.folds.size(), 2u);
  const CrossValidationFold& without_b = fit.folds[1];
  ASSERT_EQ(without_b.left_out, 1u);
  // the fold's values are the fit without b, to the bit, and it says how it got there
  const CalibrationFit alone = fit_calibration(problem.holding_out("scoop_b"));
  EXPECT_EQ(without_b.values, alone.values);
  EXPECT_EQ(without_b.iterations, alone.starts[alone.best_start].iterations);
  EXPECT_GT(without_b.iterations, 0);
  EXPECT_EQ(without_b.termination, alone.starts[alone.best_start].termination);
  EXPECT_NE(without_b.values, fit.values);
  ASSERT_EQ(without_b.scenes.size(), 3u);
  for (const std::size_t k : {std::size_t{1}, std::size_t{2}}) {
    const SceneError& predicted = without_b.scenes[k];
    EXPECT_FALSE(predicted.fit) << predicted.name;
    ASSERT_EQ(predicted.series.size(), 1u) << predicted.name;
    // the prediction is the run at the fold's values
    const PreparedScene& scene = problem.scenes()[k];
    const repose::Run run = problem.run_on_bed(scene, without_b.values, 0);
    const TimeSeries& held = run.series.at("mass_held_kg.bucket");
    const SeriesComparison& c = predicted.series[0];
    for (std::size_t t = 0; t < c.times_s.size(); ++t) EXPECT_DOUBLE_EQ(c.fitted[t], held.at(c.times_s[t])) << k;
  }
  // b, made at 30 deg, is predicted worse by the fold that did not see it
  // than by the fit that did
  EXPECT_GT(worst_relative_error(without_b.scenes[1].series[0]), worst_relative_error(fit.scenes[1].series[0]));
}

}  // namespace
}  // namespace repose
