// A calibration's references: a scene's several seed folders (the same DEM
// scene on different random beds) become one reference, their mean, and
// their spread the scene's noise floor; holding a scene out leaves the
// others' fit alone.
#include "validation/calibration/calibration_problem.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"
#include "models/core/base/error.h"
#include "models/core/io/npy_io.h"
#include "models/core/solver/run.h"
#include "validation/calibration/calibration_fit.h"
#include "validation/calibration/calibration_loader.h"
#include "validation/observables/heap_flank.h"
#include "tests/validation/calibration/tiny_snow_table.h"
#include "tests/support/temp_dir.h"

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
  const test_support::TempDir temp;
  const fs::path& root = temp.path;
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
}

// A scene entry's cell_size_m runs the solver on coarser cells than its
// reference: the seeds' surfaces are averaged onto them, volume kept, and
// the fit compares there. Cells finer than the reference's, or that do not
// divide the scene, are refused by name and place.
TEST(CalibrationProblem, ASceneOnCoarserCellsAveragesItsReferenceOntoThem) {
  const test_support::TempDir temp;
  const fs::path a = seed_folder(temp.path, "seed1", 0.020, 0.004), b = seed_folder(temp.path, "seed2", 0.022, 0.006);
  auto yaml = [&](const std::string& cells) {
    return "scenes:\n  - scene: " + kDir + "/scenes/indent.yaml\n    cell_size_m: " + cells +
           "\n    reference: {data: [" + a.string() + ", " + b.string() +
           "]}\n    observables: [{kind: height_field}]\n"
           "parameters:\n  - {name: ground.sand.alpha, initial: 0.5}\n"
           "solver: {starts: 1, max_iterations: 2}\n";
  };
  const CalibrationProblem problem(load_calibration_from_string(yaml("0.008"), kDir + "/inline.yaml"), solver_registry());
  const PreparedScene& s = problem.scenes().front();
  EXPECT_EQ(s.scene.ground.grid.nx, 8);
  EXPECT_EQ(s.scene.ground.grid.cell_size_m, 0.008);
  EXPECT_EQ(s.reference_cell_size_m, 0.004);
  for (const HeightField* f : {&s.initial, &s.reference_final, &s.seed_initial[1], &s.seed_final[0]}) {
    EXPECT_EQ(f->grid(), s.scene.ground.grid);
  }
  // the imprint, 4 x 4 fine cells from (6, 6), is 2 x 2 coarse cells from (3, 3)
  EXPECT_DOUBLE_EQ(s.reference_final.at(3, 3), 0.021 - 0.005);
  EXPECT_DOUBLE_EQ(s.reference_final.at(2, 3), 0.021);
  EXPECT_NEAR(s.reference_final.volume_m3(), 0.021 * 0.064 * 0.064 - 0.005 * 0.016 * 0.016, 1e-15);
  const CalibrationFit fit = fit_calibration(problem);
  ASSERT_TRUE(fit.scenes.front().noise.has_value());
  EXPECT_NEAR(fit.scenes.front().noise->rmse_m, 0.002 * 0.25, 1e-12);  // the same 2 mm on a sixteenth of the area
  for (const std::string bad : {"0.002", "0.006"}) {
    try {
      CalibrationProblem(load_calibration_from_string(yaml(bad), kDir + "/inline.yaml"), solver_registry());
      FAIL() << "accepted cell_size_m " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("inline.yaml:3:18: cell_size_m: " + bad), std::string::npos) << e.what();
    }
  }
}

TEST(CalibrationProblem, HoldingOutASceneMovesItOutOfTheFitResiduals) {
  const CalibrationProblem problem(load_calibration(kDir + "/synthetic.yaml"), solver_registry());
  const std::string name = problem.scenes()[1].entry.name;
  const CalibrationProblem held = problem.holding_out(name);
  EXPECT_FALSE(held.scene_named(name).fit());
  EXPECT_TRUE(problem.scene_named(name).fit());
  EXPECT_EQ(held.fit_residual_count(), problem.fit_residual_count() - problem.scene_named(name).residual_count);
}


// A series observable (the mass a bucket holds at given times) against a
// heuristic reference: the reference's values are its run's series at those
// times, and the residuals vanish at the reference's parameters and not away
// from them.
TEST(CalibrationProblem, ASeriesObservableComparesTheHeldMassAtItsTimes) {
  const std::string yaml = "scenes:\n  - scene: " + kDir + "/scenes/scoop.yaml\n"
                           "    reference: {heuristic: {heightspan.sand.repose_angle_deg: 40}}\n"
                           "    observables: [{kind: series, name: mass_held_kg.bucket, times_s: [0.6, 0.8, 1.2]}]\n"
                           "parameters:\n  - {name: heightspan.sand.repose_angle_deg, initial: 25}\n";
  const CalibrationProblem problem(load_calibration_from_string(yaml, kDir + "/inline.yaml"), solver_registry());
  const PreparedScene& s = problem.scenes().front();
  ASSERT_EQ(s.reference_values.size(), 1u);
  ASSERT_EQ(s.reference_values[0].size(), 3u);
  EXPECT_GT(s.reference_values[0][0], 0.0) << "the dragged bucket holds sand";
  std::vector<double> at_reference = problem.initial_values();
  at_reference[0] = 40.0 * std::numbers::pi / 180.0;
  const repose::Run run = problem.run_on_bed(s, at_reference, 0);
  const TimeSeries& held = run.series.at("mass_held_kg.bucket");
  EXPECT_EQ(held.unit, "kg");
  EXPECT_DOUBLE_EQ(s.reference_values[0][1], held.at(0.8));
  for (const double r : problem.residuals(s, run.field("height_final"), run.series)) EXPECT_EQ(r, 0.0);
  const repose::Run away = problem.run_on_bed(s, problem.initial_values(), 0);
  double sum = 0.0;
  for (const double r : problem.residuals(s, away.field("height_final"), away.series)) sum += r * r;
  EXPECT_GT(sum, 0.0);
  // a run without the series is refused by name
  EXPECT_THROW(problem.residuals(s, run.field("height_final")), InputError);
}

// A data reference's series come from each seed's held_mass.csv
// (held_mass_series.h) and are averaged over the seeds.
TEST(CalibrationProblem, DataSeriesAreEachSeedsHeldMassCsvAveraged) {
  const test_support::TempDir temp;
  const fs::path& root = temp.path;
  std::vector<std::string> dirs;
  for (const auto& [name, scale] : {std::pair{"seed1", 1.0}, std::pair{"seed2", 3.0}}) {
    const fs::path dir = root / name;
    fs::create_directories(dir);
    ArrayXXdR flat = ArrayXXdR::Constant(24, 40, 0.03);
    write_npy_2d((dir / "height_initial.npy").string(), flat);
    write_npy_2d((dir / "height_final.npy").string(), flat);
    std::ofstream(dir / "held_mass.csv") << "time_s,bucket_mass_kg\n0,0\n1," << 0.1 * scale << "\n";
    dirs.push_back(dir.string());
  }
  const std::string yaml = "scenes:\n  - scene: " + kDir + "/scenes/scoop.yaml\n    reference: {data: [" + dirs[0] +
                           ", " + dirs[1] +
                           "]}\n    observables: [{kind: series, name: mass_held_kg.bucket, times_s: [0.5, 1.0]}]\n"
                           "parameters:\n  - {name: heightspan.sand.sigma, initial: 0.1}\n";
  const CalibrationProblem problem(load_calibration_from_string(yaml, kDir + "/inline.yaml"), solver_registry());
  const PreparedScene& s = problem.scenes().front();
  ASSERT_EQ(s.seed_series.size(), 2u);
  EXPECT_DOUBLE_EQ(s.reference_values[0][0], 0.5 * (0.05 + 0.15));  // linear between the samples, then the mean
  EXPECT_DOUBLE_EQ(s.reference_values[0][1], 0.5 * (0.1 + 0.3));
}

// A measure observable (a run's scalar measure: the peak force on a wall)
// against data seeds: each seed's value comes from its manifest.json's run
// record and the reference is their mean; a run is compared by its own
// measure, and a run without it is refused by name.
TEST(CalibrationProblem, AMeasureObservableComparesTheSeedsMeanWithTheRunsMeasure) {
  const test_support::TempDir temp;
  const fs::path& root = temp.path;
  std::vector<std::string> dirs;
  for (const auto& [name, force] : {std::pair{"seed1", 0.4}, std::pair{"seed2", 0.6}}) {
    const fs::path dir = seed_folder(root, name, 0.02, 0.004);
    repose::Run record;
    record.solver = "liggghts";
    record.set("chute.peak.force_n", force, "N");
    std::ofstream(dir / "manifest.json") << nlohmann::json{{"run", record}}.dump();
    dirs.push_back(dir.string());
  }
  const std::string yaml = "scenes:\n  - scene: " + kDir + "/scenes/indent.yaml\n    reference: {data: [" + dirs[0] +
                           ", " + dirs[1] +
                           "]}\n    observables: [{kind: measure, name: chute.peak.force_n, weight: 2}]\n"
                           "parameters:\n  - {name: ground.sand.alpha, initial: 0.5}\n";
  const CalibrationProblem problem(load_calibration_from_string(yaml, kDir + "/inline.yaml"), solver_registry());
  const PreparedScene& s = problem.scenes().front();
  ASSERT_EQ(s.seed_measures.size(), 2u);
  ASSERT_EQ(s.reference_values[0].size(), 1u);
  EXPECT_DOUBLE_EQ(s.reference_values[0][0], 0.5);
  const HeightField& surface = s.reference_final;
  const std::vector<double> r = problem.residuals(s, surface, {}, {{"chute.peak.force_n", 0.8}});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_DOUBLE_EQ(r[0], 2.0 * (0.8 - 0.5));
  try {
    problem.residuals(s, surface, {}, {{"chute.front_arrival_s", 0.3}});
    ADD_FAILURE() << "a run without the measure was compared";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("chute.peak.force_n"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("chute.front_arrival_s"), std::string::npos) << e.what();
  }
}

// A seed folder whose final surface is the flat bed with a cone of the given
// flank angle (deg) and height, its apex over the centre of cell (ci, cj).
fs::path cone_seed_folder(const fs::path& root, const std::string& name, double angle_deg, int ci, int cj) {
  const fs::path dir = root / name;
  fs::create_directories(dir);
  ArrayXXdR initial = ArrayXXdR::Constant(16, 16, 0.02);
  ArrayXXdR final_height = initial;
  for (int j = 0; j < 16; ++j) {
    for (int i = 0; i < 16; ++i) {
      const double r = 0.004 * std::hypot(i - ci, j - cj);
      final_height(j, i) += std::max(0.0, 0.015 - std::tan(angle_deg * std::numbers::pi / 180.0) * r);
    }
  }
  write_npy_2d((dir / "height_initial.npy").string(), initial);
  write_npy_2d((dir / "height_final.npy").string(), final_height);
  return dir;
}

// A heap's flank (issue 12: the dumped heap of a scoop) is compared with the
// mean of each seed's flank, not with the flank of the seeds' mean surface
// (two heaps side by side average to a lower, wider one); by default heights
// are taken above the initial surface's mean.
TEST(CalibrationProblem, AHeapFlankObservableComparesTheMeanOfTheSeedsFlanks) {
  const test_support::TempDir temp;
  const fs::path& root = temp.path;
  const fs::path a = cone_seed_folder(root, "seed1", 20.0, 7, 7), b = cone_seed_folder(root, "seed2", 30.0, 9, 8);
  const std::string yaml = "scenes:\n  - scene: " + kDir + "/scenes/indent.yaml\n    reference: {data: [" + a.string() +
                           ", " + b.string() +
                           "]}\n    observables: [{kind: heap_flank, weight: 3, reach_m: 0.05}]\n"
                           "parameters:\n  - {name: ground.sand.alpha, initial: 0.5}\n";
  const CalibrationProblem problem(load_calibration_from_string(yaml, kDir + "/inline.yaml"), solver_registry());
  const PreparedScene& s = problem.scenes().front();
  HeapFlankOptions options;
  options.base_height_m = 0.02;
  options.reach_m = 0.05;
  const double one = heap_flank(s.seed_final[0], options).mean_rad, two = heap_flank(s.seed_final[1], options).mean_rad;
  EXPECT_NEAR(one, 20.0 * std::numbers::pi / 180.0, 0.05);
  EXPECT_NEAR(two, 30.0 * std::numbers::pi / 180.0, 0.05);
  ASSERT_EQ(s.reference_values[0].size(), 1u);
  EXPECT_DOUBLE_EQ(s.reference_values[0][0], 0.5 * (one + two));
  EXPECT_GT(std::abs(heap_flank(s.reference_final, options).mean_rad - 0.5 * (one + two)), 0.02);
  // a run whose final surface is seed 1's: residual weight * (its flank - the mean)
  const std::vector<double> r = problem.residuals(s, s.seed_final[0], {}, {});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_DOUBLE_EQ(r[0], 3.0 * (one - 0.5 * (one + two)));
}

// beds: each: the solver runs on each seed's own bed and every observable is
// the mean of its values on the beds, as the reference's per-seed
// observables are the mean of the seeds'. Two cones that nothing moves (no
// object, repose angle 60 deg): on their own beds the solver's flank is the
// reference's exactly; on the mean bed (the two cones averaged, a lower,
// wider heap) it is not.
TEST(CalibrationProblem, EachBedRunsTheSolverOnEverySeedsOwnBed) {
  const test_support::TempDir temp;
  const fs::path& root = temp.path;
  const fs::path a = cone_seed_folder(root, "seed1", 20.0, 7, 7), b = cone_seed_folder(root, "seed2", 30.0, 9, 8);
  for (const fs::path& dir : {a, b}) {
    fs::copy_file(dir / "height_final.npy", dir / "height_initial.npy", fs::copy_options::overwrite_existing);
  }
  const fs::path scene = root / "still.yaml";
  std::ofstream(scene) << "name: still\ntime: {step_s: 0.02, duration_s: 0.1}\n"
                          "ground:\n  extent_m: [0.064, 0.064]\n  cell_size_m: 0.004\n  origin_m: [0.0, 0.0]\n"
                          "  initial_height: {kind: flat, height_m: 0.02}\n  material: sand\n";
  const auto problem_with = [&](const std::string& beds) {
    const std::string yaml = "scenes:\n  - scene: " + scene.string() + "\n    beds: " + beds + "\n    reference: {data: [" +
                             a.string() + ", " + b.string() +
                             "]}\n    observables: [{kind: heap_flank, weight: 3, reach_m: 0.05, base_height_m: 0.02}, "
                             "{kind: height_field}]\n"
                             "parameters:\n  - {name: ground.sand.repose_angle_deg, initial: 60}\n";
    return CalibrationProblem(load_calibration_from_string(yaml, root.string() + "/inline.yaml"), solver_registry());
  };
  const CalibrationProblem each = problem_with("each");
  const PreparedScene& s = each.scenes().front();
  ASSERT_EQ(s.bed_count(), 2u);
  const std::vector<repose::Run> runs = each.runs(s, each.initial_values());
  ASSERT_EQ(runs.size(), 2u);
  for (std::size_t bed = 0; bed < 2; ++bed) {
    EXPECT_EQ((runs[bed].field("height_initial").heights() - s.seed_initial[bed].heights()).abs().maxCoeff(), 0.0) << bed;
    EXPECT_LT((runs[bed].field("height_final").heights() - s.seed_final[bed].heights()).abs().maxCoeff(), 1e-12) << bed;
  }
  // the flank and each bed's change from its own start (none)
  const std::vector<double> r = each.residuals(s, runs);
  ASSERT_EQ(r.size(), 1u + 16u * 16u);
  for (const double v : r) EXPECT_NEAR(v, 0.0, 1e-9);
  EXPECT_LT((each.mean_final(s, runs).heights() - s.reference_final.heights()).abs().maxCoeff(), 1e-12);
  // each bed's flank is its seed's, so the paired error has no spread, and
  // the beds' values average to the compared one
  const SceneError e = scene_error(each, s, each.initial_values(), each.initial_values());
  ASSERT_EQ(e.series.size(), 1u);
  const SeriesComparison& flank = e.series[0];
  ASSERT_EQ(flank.fitted_per_bed.size(), 2u);
  for (std::size_t bed = 0; bed < 2; ++bed) EXPECT_NEAR(flank.fitted_per_bed[bed][0], flank.seeds[bed][0], 1e-9) << bed;
  EXPECT_DOUBLE_EQ(flank.fitted[0], 0.5 * (flank.fitted_per_bed[0][0] + flank.fitted_per_bed[1][0]));
  ASSERT_EQ(flank.paired_standard_error().size(), 1u);
  EXPECT_NEAR(flank.paired_standard_error()[0], 0.0, 1e-9);

  const CalibrationProblem mean = problem_with("mean");
  const PreparedScene& m = mean.scenes().front();
  ASSERT_EQ(m.bed_count(), 1u);
  EXPECT_TRUE(scene_error(mean, m, mean.initial_values(), mean.initial_values()).series[0].fitted_per_bed.empty());
  EXPECT_GT(std::abs(mean.residuals(m, mean.runs(m, mean.initial_values()))[0]), 3.0 * 0.02);
}

// The snow model's parameters through the generic binding: two entries of
// one scene compare two snow maps (field:), share their runs, and the fit
// recovers the angle of repose a synthetic reference was made with.
TEST(CalibrationProblem, SnowMapsAreComparedByFieldAndTheAngleIsRecovered) {
  const test_support::TempDir temp;
  const fs::path& root = temp.path;
  const fs::path scene = root / "table.yaml";
  std::ofstream(scene) << testing::tiny_snow_table_yaml(6.0);
  const std::string entry = "  - scene: " + scene.string() + "\n    reference: {heuristic: {snow.repose_angle_deg: 40}}\n" +
                            "    observables: [{kind: height_field}]\n";
  const std::string yaml = "scenes:\n" + entry + "    name: top\n    field: snow_depth_final.table\n" + entry +
                           "    name: ground\n    field: snow_depth_final.ground\n"
                           "parameters:\n  - {name: snow.repose_angle_deg, initial: 25, bounds: [5, 85], step: 2}\n"
                           "solver: {starts: 1, max_iterations: 20, threads: 1}\n";
  const CalibrationProblem problem(load_calibration_from_string(yaml, root.string() + "/inline.yaml"), solver_registry());
  ASSERT_EQ(problem.scenes().size(), 2u);
  EXPECT_EQ(problem.scenes()[0].entry.field, "snow_depth_final.table");
  // the reference's table snow is not its ground snow: the fields are told apart
  EXPECT_GT((problem.scenes()[0].reference_final.heights() - problem.scenes()[1].reference_final.heights()).abs().maxCoeff(),
            1e-3);
  const CalibrationFit fit = fit_calibration(problem);
  EXPECT_NEAR(fit.values[0] * 180.0 / 3.141592653589793, 40.0, 2.0);
  EXPECT_LT(fit.final_cost, 1e-3 * fit.initial_cost);
  // a data reference must hold the compared field
  const fs::path folder = seed_folder(root, "seed1", 0.0, 0.0);
  const std::string bad = "scenes:\n  - scene: " + scene.string() + "\n    field: snow_depth_final.table\n" +
                          "    reference: {data: " + folder.string() + "}\n    observables: [{kind: height_field}]\n"
                          "parameters:\n  - {name: snow.repose_angle_deg, initial: 25}\n";
  try {
    load_calibration_from_string(bad, root.string() + "/bad.yaml");
    ADD_FAILURE() << "a reference without snow_depth_final.table.npy was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("snow_depth_final.table.npy"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace repose
