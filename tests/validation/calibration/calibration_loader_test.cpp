#include "validation/calibration/calibration_loader.h"

#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"
#include "models/ground/material.h"
#include "models/core/base/error.h"
#include "validation/calibration/calibration_problem.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

const std::string kDir = std::string(REPOSE_SOURCE_DIR) + "/tests/data/calibration";
constexpr double kDeg = std::numbers::pi / 180.0;

std::string first_line(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

TEST(CalibrationLoader, ReadsTheSyntheticCalibration) {
  const CalibrationSpec spec = load_calibration(kDir + "/synthetic.yaml");
  EXPECT_EQ(spec.name, "synthetic");
  ASSERT_EQ(spec.scenes.size(), 3u);
  EXPECT_EQ(spec.scenes[0].reference.kind, ReferenceSpec::Kind::kHeuristic);
  ASSERT_EQ(spec.scenes[0].reference.values.size(), 3u);
  EXPECT_EQ(spec.scenes[0].reference.values[1].first, "ground.sand.repose_angle_deg");
  EXPECT_DOUBLE_EQ(spec.scenes[0].reference.values[1].second, 35.0);
  EXPECT_EQ(spec.fitted_solver, "ground");
  EXPECT_EQ(spec.scenes[2].observables[1].kind, ObservableSpec::Kind::kFurrowArea);
  EXPECT_EQ(spec.scenes[2].observables[1].samples, 25);
  ASSERT_EQ(spec.parameters.size(), 3u);
  // as written: degrees (the solver's unit for it) until the problem resolves them
  EXPECT_DOUBLE_EQ(spec.parameters[1].file_initial, 28.0);
  EXPECT_DOUBLE_EQ(*spec.parameters[1].file_lower, 15.0);
  EXPECT_DOUBLE_EQ(*spec.parameters[1].file_step, 2.0);
  EXPECT_EQ(spec.parameters[1].label(), "ground.sand.repose_angle_deg");
  // radians inside, once resolved against the ground solver's declaration
  const CalibrationProblem problem(spec, solver_registry());
  EXPECT_DOUBLE_EQ(problem.spec().parameters[1].initial, 28.0 * kDeg);
  EXPECT_DOUBLE_EQ(problem.spec().parameters[1].lower, 15.0 * kDeg);
  EXPECT_DOUBLE_EQ(problem.spec().parameters[1].step, 2.0 * kDeg);
  EXPECT_EQ(problem.spec().parameters[1].unit, "deg");
  EXPECT_EQ(spec.solver.seed, 3u);
  EXPECT_EQ(spec.solver.starts, 1);
  EXPECT_FALSE(spec.ladder.has_value());
}

TEST(CalibrationLoader, DefaultsFillBoundsAndSteps) {
  const CalibrationSpec spec = load_calibration_from_string(
      "scenes: [{scene: scenes/indent.yaml, reference: {heuristic: {ground.sand.alpha: 0.7}}, observables: [{kind: height_field}]}]\n"
      "parameters: [{name: ground.sand.sigma, initial: 0.1}]\n",
      kDir + "/inline.yaml");
  const CalibrationProblem problem(spec, solver_registry());
  const ParameterSpec& p = problem.spec().parameters[0];
  EXPECT_EQ(p.solver, "ground");
  EXPECT_EQ(p.name, "sand.sigma");
  EXPECT_GT(p.lower, 0.0);
  EXPECT_DOUBLE_EQ(p.upper, kSigmaMax);
  EXPECT_NEAR(p.step, 0.05 * (p.upper - p.lower), 1e-15);
  EXPECT_EQ(spec.scenes[0].role, CalibrationScene::Role::kFit);
  EXPECT_EQ(spec.solver.loss, CalibrationSolverSpec::Loss::kNone);
}

TEST(CalibrationLoader, ReadsTheDefaultCalibration) {
  const CalibrationSpec spec = load_calibration(std::string(REPOSE_SOURCE_DIR) + "/experiments/calibration_default.yaml");
  ASSERT_TRUE(spec.ladder.has_value());
  EXPECT_GE(spec.ladder->heuristic_cell_sizes_m.size(), 3u);
  EXPECT_GE(spec.ladder->references.size(), 1u);
  EXPECT_EQ(spec.scenes[0].reference.kind, ReferenceSpec::Kind::kData);
}

TEST(CalibrationLoader, ReadsTheScoopCalibrationsSeriesObservables) {
  const CalibrationSpec spec =
      load_calibration(std::string(REPOSE_SOURCE_DIR) + "/experiments/heightspan_scoop_fit.yaml");
  EXPECT_EQ(spec.fitted_solver, "heightspan");
  ASSERT_GE(spec.scenes.size(), 2u);
  const ObservableSpec& held = spec.scenes[0].observables[0];
  EXPECT_EQ(held.kind, ObservableSpec::Kind::kSeries);
  EXPECT_EQ(held.series, "mass_held_kg.bucket");
  EXPECT_EQ(held.times_s, (std::vector<double>{0.5, 0.8, 1.0, 1.3, 1.6, 2.3}));  // during the drag, then the stages
  EXPECT_EQ(spec.scenes.back().role, CalibrationScene::Role::kHeldOut);
  EXPECT_EQ(spec.scenes.back().observables[0].times_s, (std::vector<double>{1.0, 1.3, 1.6, 2.3}));  // the stages
  // the dumped heap's flank, measured as experiments/heightspan/dump_flank.py does, on both scoops
  for (const CalibrationScene& scene : spec.scenes) {
    const ObservableSpec& flank = scene.observables.back();
    ASSERT_EQ(flank.kind, ObservableSpec::Kind::kHeapFlank);
    ASSERT_TRUE(flank.region.has_value() && flank.base_height_m.has_value());
    EXPECT_EQ(flank.region->x_min_m, 0.15);
    EXPECT_EQ(*flank.base_height_m, 0.025);
    EXPECT_EQ(flank.reach_m, 0.1);
    EXPECT_GT(flank.weight, 0.0);
  }
}

TEST(CalibrationLoader, ReadsTheBulletChuteCalibrationsMeasureObservables) {
  const CalibrationSpec spec = load_calibration(std::string(REPOSE_SOURCE_DIR) + "/experiments/bullet_chute_fit.yaml");
  EXPECT_EQ(spec.fitted_solver, "bullet");
  bool measure = false;
  for (const ObservableSpec& o : spec.scenes[0].observables) {
    if (o.kind != ObservableSpec::Kind::kMeasure) continue;
    measure = true;
    EXPECT_FALSE(o.measure.empty());
    EXPECT_TRUE(o.times_s.empty());
  }
  EXPECT_TRUE(measure);
  ASSERT_EQ(spec.scenes.size(), 6u);
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(spec.scenes[k].role, k < 3 ? CalibrationScene::Role::kFit : CalibrationScene::Role::kHeldOut);
  }
}

// Entries of one scene file with their own `seed` run the calibrated solver
// on their own beds: the seed reaches each prepared scene (the run memory keys
// on it, so the three beds are three runs, not one remembered).
TEST(CalibrationLoader, EachSceneEntrysSeedReachesItsPreparedScene) {
  const CalibrationSpec spec = load_calibration(std::string(REPOSE_SOURCE_DIR) + "/experiments/bullet_chute_fit.yaml");
  for (std::size_t k = 0; k < spec.scenes.size(); ++k) {
    ASSERT_TRUE(spec.scenes[k].seed.has_value()) << k;
    EXPECT_EQ(*spec.scenes[k].seed, k % 3 + 1) << k;
  }
  const CalibrationProblem problem(spec, solver_registry());
  for (std::size_t k = 0; k < problem.scenes().size(); ++k) EXPECT_EQ(problem.scenes()[k].scene.seed, k % 3 + 1) << k;
}

// Every file in bad/ starts with "# expect: TEXT": loading it (and making it
// ready, which checks its parameters against the solver's declarations) must
// fail with one line that names the file and contains TEXT.
TEST(CalibrationLoader, MalformedFilesGiveClearErrors) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kDir + "/bad")) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    const std::string header = first_line(entry.path());
    const std::string prefix = "# expect: ";
    ASSERT_EQ(header.rfind(prefix, 0), 0u) << entry.path() << " lacks an '# expect:' first line";
    const std::string expected = header.substr(prefix.size());
    try {
      CalibrationProblem problem(load_calibration(entry.path().string()), solver_registry());
      ADD_FAILURE() << entry.path() << " loaded without an error";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(expected), std::string::npos) << entry.path() << "\n  got: " << message;
      EXPECT_EQ(message.rfind(entry.path().string(), 0), 0u) << "the message does not start with the file: " << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
  EXPECT_GE(files, 10);
}

TEST(CalibrationLoader, MissingFileIsAnInputError) {
  EXPECT_THROW(load_calibration(kDir + "/no_such_file.yaml"), InputError);
  EXPECT_THROW(load_calibration(kDir), InputError);
}

}  // namespace
}  // namespace repose
