// `--solver tearing` through the registry: parameters, a run's measures and
// fields, determinism, the files it writes, values outside their interval.
#include "models/tearing/tearing_solver.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"
#include "models/core/base/error.h"
#include "models/core/config/scene_loader.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

// A 3 cm sheet, 15 cells, twisted for 2 ms.
Scene small_scene() {
  return load_scene_from_string(
      "name: t\nseed: 5\ntime: {step_s: 0.001, duration_s: 0.002}\n"
      "ground: {extent_m: [0.1, 0.1], resolution: [2, 2], initial_height: {kind: flat, height_m: 0}, material: sand}\n"
      "tearing:\n  width_m: 0.03\n  height_m: 0.03\n  cells_x: 15\n  notch_length_m: 0.004\n  notch_x_m: 0.015\n"
      "  twist: {grip_depth_m: 0.006, gap_m: 0.004, speed_m_per_s: 4}\n",
      "/tmp/tearing_solver_test.yaml", solver_registry().sections());
}

// The measures without the run's timings (the only ones that may differ
// between two runs of the same scene).
std::map<std::string, Measure> without_timings(std::map<std::string, Measure> measures) {
  for (const char* key : {"run_wall_s", "run_cpu_s", "cpu_s_per_simulated_s", "wall_s_per_simulated_s"}) {
    EXPECT_EQ(measures.erase(key), 1u) << key;
  }
  return measures;
}

TEST(TearingSolver, DeclaresItsParametersAndRunsDeterministically) {
  const auto compiled = solver_registry().get("tearing").compile(small_scene());
  ASSERT_EQ(compiled->parameters().size(), 3u);
  EXPECT_EQ(compiled->parameters()[0].name, "stiffness_scale");
  EXPECT_EQ(compiled->parameters()[1].name, "tear_strain");
  EXPECT_EQ(compiled->parameters()[2].name, "fibre_anisotropy");
  const repose::Run a = compiled->run(compiled->default_values(), {});
  const repose::Run b = compiled->run(compiled->default_values(), {});
  EXPECT_GT(a.measure("tear.length_m").value, 0.0);
  EXPECT_GE(a.measure("tear.tortuosity").value, 1.0);
  EXPECT_GT(a.measure("grip.peak_force_n").value, 0.0);
  EXPECT_EQ(a.measure("grip.peak_force_n").unit, "N");
  EXPECT_EQ(without_timings(a.measures), without_timings(b.measures));
  EXPECT_TRUE((a.field("displacement_z_m").heights() == b.field("displacement_z_m").heights()).all());
  EXPECT_EQ(a.field("torn_time_s").nx(), 15);
  EXPECT_EQ(a.field("displacement_z_m").nx(), 16);
  EXPECT_EQ(a.field("fibre_composite").nx(), 120);
}

TEST(TearingSolver, ReportsItsTimingsPerSimulatedSecond) {
  const auto compiled = solver_registry().get("tearing").compile(small_scene());
  const repose::Run run = compiled->run(compiled->default_values(), {});
  const double simulated = run.measure("simulated_time_s").value;
  // the whole duration (no stop depth), in whole steps
  EXPECT_GE(simulated, 0.002 - 1e-12);
  EXPECT_NEAR(simulated, run.measure("steps").value * run.measure("time_step_s").value, 1e-12);
  EXPECT_EQ(run.measure("run_cpu_s").value, run.cpu_s);
  EXPECT_EQ(run.measure("run_wall_s").value, run.wall_s);
  EXPECT_GT(run.cpu_s, 0.0);
  EXPECT_EQ(run.measure("run_cpu_s").unit, "s");
  EXPECT_DOUBLE_EQ(run.measure("cpu_s_per_simulated_s").value, run.cpu_s / simulated);
  EXPECT_DOUBLE_EQ(run.measure("wall_s_per_simulated_s").value, run.wall_s / simulated);
  EXPECT_EQ(run.measure("cpu_s_per_simulated_s").unit, "s/s");
}

TEST(TearingSolver, AStifferSheetTearsUnderMoreForce) {
  const auto compiled = solver_registry().get("tearing").compile(small_scene());
  std::vector<double> values = compiled->default_values();
  const double soft = compiled->run(values, {}).measure("grip.peak_force_n").value;
  values[0] *= 2.0;
  const double stiff = compiled->run(values, {}).measure("grip.peak_force_n").value;
  EXPECT_GT(stiff, 1.2 * soft);
}

TEST(TearingSolver, WritesItsPicturesWhenGivenAFolder) {
  const auto compiled = solver_registry().get("tearing").compile(small_scene());
  const test_support::TempDir temp;
  const std::filesystem::path& dir = temp.path;
  RunOptions options;
  options.output_dir = dir.string();
  const repose::Run run = compiled->run(compiled->default_values(), options);
  for (const std::string& file : run.files) EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
  EXPECT_NE(std::find(run.files.begin(), run.files.end(), "tear_edge.png"), run.files.end());
  EXPECT_NE(std::find(run.files.begin(), run.files.end(), "grip_force.csv"), run.files.end());
  std::ifstream csv(dir / "grip_force.csv");
  std::string header, first;
  std::getline(csv, header);
  EXPECT_EQ(header, "time_s,grip,force_x_n,force_y_n,force_z_n");
  EXPECT_TRUE(std::getline(csv, first) && !first.empty());
}

// A 3 x 1 cm strip on 2 mm cells in a tensile test, under the energy rule.
TEST(TearingSolver, RunsATensileTestAndDeclaresTheEnergyRulesParameter) {
  const Scene scene = load_scene_from_string(
      "name: t\nseed: 5\ntime: {step_s: 0.001, duration_s: 0.002}\n"
      "ground: {extent_m: [0.1, 0.1], resolution: [2, 2], initial_height: {kind: flat, height_m: 0}, material: sand}\n"
      "tearing:\n  width_m: 0.03\n  height_m: 0.01\n  cells_x: 15\n  notch_x_m: 0.015\n  tear_rule: energy\n  tear_energy_j_per_m: 0.2\n"
      "  tensile: {speed_m_per_s: 0.5}\n",
      "/tmp/tearing_solver_test.yaml", solver_registry().sections());
  const auto compiled = solver_registry().get("tearing").compile(scene);
  ASSERT_EQ(compiled->parameters().size(), 3u);
  EXPECT_EQ(compiled->parameters()[1].name, "tear_energy");
  EXPECT_EQ(compiled->parameters()[1].unit, "J/m");
  const repose::Run run = compiled->run(compiled->default_values(), {});
  EXPECT_EQ(run.measure("tensile.broke").value, 1.0);
  EXPECT_GT(run.measure("tensile.stiffness_n_per_m").value, 0.0);
  EXPECT_GT(run.measure("tensile.strength_n_per_m").value, 0.0);
  EXPECT_EQ(run.measure("tensile.strength_n_per_m").unit, "N/m");
  EXPECT_EQ(run.measure("run_cpu_s").value, run.cpu_s);
}

TEST(TearingSolver, RefusesValuesOutsideTheirIntervalAndScenesWithoutTheSection) {
  const auto compiled = solver_registry().get("tearing").compile(small_scene());
  std::vector<double> values = compiled->default_values();
  values[1] = 20.0;
  EXPECT_THROW(compiled->run(values, {}), InputError);
  Scene plain = small_scene();
  plain.sections.erase("tearing");
  std::string why;
  EXPECT_FALSE(solver_registry().get("tearing").can_run(plain, &why));
  EXPECT_NE(why.find("tearing"), std::string::npos);
}

}  // namespace
}  // namespace repose
