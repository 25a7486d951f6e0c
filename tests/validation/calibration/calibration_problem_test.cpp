// A calibration's references: a scene's several seed folders (the same DEM
// scene on different random beds) become one reference, their mean, and
// their spread the scene's noise floor; holding a scene out leaves the
// others' fit alone.
#include "validation/calibration/calibration_problem.h"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"
#include "models/core/io/npy_io.h"
#include "validation/calibration/calibration_fit.h"
#include "validation/calibration/calibration_loader.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

const std::string kDir = std::string(REPOSE_SOURCE_DIR) + "/tests/data/calibration";

// A seed folder on the indentation scene's 16 x 16 grid: a bed at `bed_m`
// with a square imprint `depth_m` deep in its middle.
fs::path seed_folder(const fs::path& root, const std::string& name, double bed_m, double depth_m) {
  const fs::path dir = root / name;
  fs::create_directories(dir);
  ArrayXXdR initial = ArrayXXdR::Constant(16, 16, bed_m);
  ArrayXXdR final_height = initial;
  final_height.block(6, 6, 4, 4) -= depth_m;
  write_npy_2d((dir / "height_initial.npy").string(), initial);
  write_npy_2d((dir / "height_final.npy").string(), final_height);
  return dir;
}

TEST(CalibrationProblem, SeedFoldersAreAveragedAndTheirSpreadIsTheNoiseFloor) {
  const fs::path root = fs::temp_directory_path() / ("repose_seeds_" + std::to_string(::getpid()));
  fs::remove_all(root);
  const fs::path a = seed_folder(root, "seed1", 0.020, 0.004), b = seed_folder(root, "seed2", 0.022, 0.006);
  const std::string yaml = "scenes:\n  - scene: " + kDir + "/scenes/indent.yaml\n    reference: {data: [" + a.string() +
                           ", " + b.string() +
                           "]}\n    observables: [{kind: height_field}]\n"
                           "parameters:\n  - {name: ground.sand.alpha, initial: 0.5}\n"
                           "solver: {starts: 1, max_iterations: 2}\n";
  const CalibrationProblem problem(load_calibration_from_string(yaml, kDir + "/inline.yaml"), solver_registry());
  const PreparedScene& s = problem.scenes().front();
  ASSERT_EQ(s.seed_initial.size(), 2u);
  EXPECT_DOUBLE_EQ(s.initial.at(0, 0), 0.021);
  EXPECT_DOUBLE_EQ(s.reference_final.at(7, 7), 0.021 - 0.005);
  const CalibrationFit fit = fit_calibration(problem);
  const auto& noise = fit.scenes.front().noise;
  ASSERT_TRUE(noise.has_value());
  EXPECT_EQ(noise->seeds, 2);
  // Δh differs by 2 mm on 16 of 256 cells: RMSE 2 mm * sqrt(16/256)
  EXPECT_NEAR(noise->pair_rmse_m, 0.002 * 0.25, 1e-12);
  EXPECT_NEAR(noise->rmse_m, 0.002 * 0.25, 1e-12);
  fs::remove_all(root);
}

TEST(CalibrationProblem, HoldingOutASceneMovesItOutOfTheFitResiduals) {
  const CalibrationProblem problem(load_calibration(kDir + "/synthetic.yaml"), solver_registry());
  const std::string name = problem.scenes()[1].entry.name;
  const CalibrationProblem held = problem.holding_out(name);
  EXPECT_FALSE(held.scene_named(name).fit());
  EXPECT_TRUE(problem.scene_named(name).fit());
  EXPECT_EQ(held.fit_residual_count(), problem.fit_residual_count() - problem.scene_named(name).residual_count);
}

}  // namespace
}  // namespace repose
