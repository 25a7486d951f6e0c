// The speed/accuracy ladder on a synthetic reference: the ground model at the
// reference's own resolution and parameters reproduces it exactly (RMSE 0),
// other resolutions do not, and every rung has a positive wall time.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"

#include "validation/calibration/calibration_ladder.h"
#include "validation/calibration/calibration_loader.h"
#include "validation/calibration/calibration_problem.h"
#include "models/core/io/npy_io.h"
#include "tests/support/temp_dir.h"

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

// The held mass on each heuristic rung of a scoop whose reference is the
// height-span model itself at 40 deg: at the scene's own cells and those
// values the rung holds exactly the reference's mass at every time; on
// cells twice as coarse it holds another (the ladder would show it).
TEST(CalibrationLadder, EachRungCarriesItsSeriesBesideTheReferences) {
  const CalibrationProblem problem(load_calibration_from_string(
      "scenes:\n"
      "  - scene: scenes/scoop.yaml\n"
      "    reference: {heuristic: {heightspan.sand.repose_angle_deg: 40}}\n"
      "    observables: [{kind: series, name: mass_held_kg.bucket, times_s: [0.6, 0.8]}, {kind: height_field}]\n"
      "parameters:\n"
      "  - {name: heightspan.sand.repose_angle_deg, initial: 40, bounds: [5, 60], step: 3}\n"
      "ladder: {heuristic_cell_sizes_m: [0.01], multires: false, timing_repeats: 1}\n",
      std::string(REPOSE_SOURCE_DIR) + "/tests/data/calibration/inline.yaml"), solver_registry());
  const Ladder ladder = measure_ladder(problem, problem.initial_values());
  ASSERT_EQ(ladder.rungs.size(), 2u);  // 10 mm, 5 mm (the scene's own)
  for (const LadderRung& r : ladder.rungs) {
    SCOPED_TRACE(r.label);
    ASSERT_EQ(r.series.size(), 1u);
    const SeriesComparison& c = r.series.front();
    EXPECT_EQ(c.series, "mass_held_kg.bucket");
    ASSERT_EQ(c.fitted.size(), 2u);
    ASSERT_EQ(c.reference.size(), 2u);
    EXPECT_GT(c.reference[1], 0.0);  // the bucket holds sand at 0.8 s
    for (const double e : c.fitted_relative_error()) {
      if (r.label == ladder.own_rung) {
        EXPECT_EQ(e, 0.0);
      } else {
        EXPECT_TRUE(std::isfinite(e));
      }
    }
    if (r.label != ladder.own_rung) {
      EXPECT_NE(c.fitted, c.reference);
    }
  }
}

namespace fs = std::filesystem;

// A LIGGGHTS run folder on the indentation grid (16 x 16): a flat bed with a
// square imprint `depth_m` deep, and its cost.
void write_run(const fs::path& dir, double depth_m) {
  fs::create_directories(dir);
  ArrayXXdR initial = ArrayXXdR::Constant(16, 16, 0.02), final_height = initial;
  final_height.block(6, 6, 4, 4) -= depth_m;
  write_npy_2d((dir / "height_initial.npy").string(), initial);
  write_npy_2d((dir / "height_final.npy").string(), final_height);
  std::ofstream(dir / "liggghts_manifest.json") << R"({"wall_time_s": 10.0, "cpu_time_s": 8.0})";
}

// A Bullet run folder: no LIGGGHTS record, its engine and cost in manifest.json.
void write_bullet_run(const fs::path& dir, double depth_m) {
  write_run(dir, depth_m);
  fs::remove(dir / "liggghts_manifest.json");
  std::ofstream(dir / "manifest.json")
      << R"({"solver": "bullet", "run": {"solver": "bullet", "measures": {}, "wall_s": 3.0, "cpu_s": 2.0}})";
}

// The ladder of a calibration whose reference is seeds seed1 and seed2 under
// `root` (written by the caller) on the indentation scene with a dem section,
// and whose ladder lists the run folders `rungs` under `root`.
Ladder ladder_over(const fs::path& root, const std::vector<std::string>& rungs, const std::string& observables = "{kind: height_field}") {
  const std::string source = std::string(REPOSE_SOURCE_DIR) + "/tests/data/calibration/scenes/indent.yaml";
  std::ifstream in(source);
  std::ofstream(root / "indent_dem.yaml") << in.rdbuf() << "dem: {grain_radius_m: 0.002, time_step_s: 1.0e-5}\n";
  const std::string scene = (root / "indent_dem.yaml").string();
  std::string yaml = fmt::format(
      "scenes:\n  - scene: {0}\n    reference: {{data: [{1}, {2}]}}\n    observables: [{3}]\n"
      "parameters:\n  - {{name: ground.sand.alpha, initial: 0.7}}\n"
      "ladder:\n  heuristic_cell_sizes_m: [0.008]\n  multires: false\n  timing_repeats: 1\n  references:\n",
      scene, (root / "seed1").string(), (root / "seed2").string(), observables);
  for (const std::string& rung : rungs) yaml += fmt::format("    - {{scene: {}, data: {}}}\n", scene, (root / rung).string());
  const CalibrationProblem problem(load_calibration_from_string(yaml, (root / "inline.yaml").string()), solver_registry());
  return measure_ladder(problem, problem.initial_values());
}

// Two seeds of the reference, 4 and 6 mm deep, and another LIGGGHTS run, 5 mm deep.
void write_seeds_and_other(const fs::path& root) {
  write_run(root / "seed1", 0.004);
  write_run(root / "seed2", 0.006);
  write_run(root / "other", 0.005);
}

// A reference of two seeds: a LIGGGHTS rung that is one of them is compared
// with the other (not with a mean that holds it), so its error is the seeds'
// difference; another run is compared with their mean; the ladder carries
// the reference's noise floor. Every rung carries how much faster than the
// finest LIGGGHTS run it is (that run's CPU time over its own).
TEST(CalibrationLadder, ASeedsOwnRunIsComparedWithTheOtherSeeds) {
  const test_support::TempDir temp;
  const fs::path& root = temp.path;
  write_seeds_and_other(root);
  const Ladder ladder = ladder_over(root, {"seed1", "other"});
  // Δh of the seeds differ by 2 mm on 16 of 256 cells; "other" differs from their mean by 0 mm
  const double seeds_apart = 0.002 * 0.25;
  ASSERT_TRUE(ladder.noise_floor_m.has_value());
  EXPECT_NEAR(*ladder.noise_floor_m, seeds_apart, 1e-12);
  int liggghts = 0;
  for (const LadderRung& r : ladder.rungs) {
    if (r.kind != "liggghts") continue;
    ++liggghts;
    if (r.label.find("one seed") != std::string::npos) {
      EXPECT_NEAR(r.rmse_m, seeds_apart, 1e-12);
    } else {
      EXPECT_NEAR(r.rmse_m, 0.0, 1e-12);
    }
    EXPECT_EQ(r.cpu_time_s.value_or(0.0), 8.0);
  }
  EXPECT_EQ(liggghts, 2);
  // every rung's speed against the finest LIGGGHTS run (both record 8 CPU s), named at the scene's own cells
  EXPECT_EQ(ladder.own_rung, "ground 4 mm");
  for (const LadderRung& r : ladder.rungs) {
    SCOPED_TRACE(r.label);
    ASSERT_TRUE(r.cpu_time_s.has_value());
    ASSERT_TRUE(r.liggghts_cpu_over_this.has_value());
    EXPECT_DOUBLE_EQ(*r.liggghts_cpu_over_this, 8.0 / *r.cpu_time_s);
    if (r.label == ladder.own_rung) {
      ASSERT_TRUE(ladder.liggghts_over_ground_cpu_time.has_value());
      EXPECT_DOUBLE_EQ(*ladder.liggghts_over_ground_cpu_time, *r.liggghts_cpu_over_this);
    }
  }
}

// A bucket's held mass (held_mass.csv) at two times.
void write_held_mass(const fs::path& dir, double at_1s_kg) {
  std::ofstream(dir / "held_mass.csv") << fmt::format("time_s,bucket_mass_kg\n0,0\n1,{}\n2,{}\n", at_1s_kg, at_1s_kg);
}

// A particle run's held mass is a rung's series too: a seed's own run
// against the other seeds' mean, another run against all seeds' mean; the
// ground model's rungs, which hold nothing, carry none.
TEST(CalibrationLadder, AReferenceRunsSeriesIsComparedLikeItsGround) {
  const test_support::TempDir temp;
  const fs::path& root = temp.path;
  write_seeds_and_other(root);
  write_held_mass(root / "seed1", 0.10);
  write_held_mass(root / "seed2", 0.20);
  write_held_mass(root / "other", 0.12);
  const Ladder ladder =
      ladder_over(root, {"seed1", "other"}, "{kind: height_field}, {kind: series, name: mass_held_kg.bucket, times_s: [1.0]}");
  int with_series = 0;
  for (const LadderRung& r : ladder.rungs) {
    SCOPED_TRACE(r.label);
    if (r.kind != "liggghts") {
      EXPECT_TRUE(r.series.empty());
      continue;
    }
    ++with_series;
    ASSERT_EQ(r.series.size(), 1u);
    const SeriesComparison& c = r.series.front();
    ASSERT_EQ(c.fitted.size(), 1u);
    if (r.label.find("one seed") != std::string::npos) {
      EXPECT_DOUBLE_EQ(c.fitted[0], 0.10);
      EXPECT_DOUBLE_EQ(c.reference[0], 0.20);  // seed 2 alone
      EXPECT_DOUBLE_EQ(c.fitted_relative_error()[0], -0.5);
    } else {
      EXPECT_DOUBLE_EQ(c.fitted[0], 0.12);
      EXPECT_DOUBLE_EQ(c.reference[0], 0.15);  // both seeds' mean
      EXPECT_NEAR(c.fitted_relative_error()[0], -0.2, 1e-12);
    }
  }
  EXPECT_EQ(with_series, 2);
}

// Another engine's canonical run is a rung of its own, named after the
// engine its manifest names, scored against the LIGGGHTS reference; the
// speed ratio stays LIGGGHTS' (none here: no LIGGGHTS rung).
TEST(CalibrationLadder, AnotherEnginesRunIsARungScoredAgainstTheReference) {
  const test_support::TempDir temp;
  const fs::path& root = temp.path;
  write_run(root / "seed1", 0.004);
  write_run(root / "seed2", 0.006);
  write_bullet_run(root / "bullet", 0.007);
  const Ladder ladder = ladder_over(root, {"bullet"});
  const LadderRung& bullet = ladder.rungs.back();
  EXPECT_EQ(bullet.kind, "bullet");
  EXPECT_EQ(bullet.label, "Bullet d = 4 mm");
  EXPECT_EQ(bullet.cpu_time_s.value_or(0.0), 2.0);
  // 7 mm deep against the seeds' mean of 5 mm, on 16 of 256 cells
  EXPECT_NEAR(bullet.rmse_m, 0.002 * 0.25, 1e-12);
  EXPECT_FALSE(ladder.liggghts_over_ground_time.has_value());
  EXPECT_FALSE(bullet.liggghts_cpu_over_this.has_value());
}

}  // namespace
}  // namespace repose
