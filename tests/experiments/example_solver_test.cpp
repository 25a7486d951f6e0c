// The example solver (example_solver.h) joins repose by one registration
// line and runs through `repose run`, `repose experiment` and `repose
// calibrate`, the commands called in-process over the extended registry; a
// synthetic-recovery fit recovers its parameter.
#include "tests/experiments/example_solver.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "experiments/cli/commands.h"
#include "experiments/solvers/solver_registry.h"
#include "models/core/io/npy_io.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;
using test_support::TempDirTest;
using test_support::read_all;
using test_support::write_all;

const SolverRegistry& registry_with_example() {
  static const SolverRegistry registry = [] {
    SolverRegistry r = solver_registry();
    r.add(std::make_shared<example::ExampleSolver>());  // the one registration line
    return r;
  }();
  return registry;
}

int repose_cli(const std::vector<std::string>& arguments) {
  std::vector<std::string> args = {"repose"};
  args.insert(args.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  return cli::run_cli(static_cast<int>(argv.size()), argv.data(), registry_with_example());
}

const char* const kScene = R"(time: {step_s: 0.1, duration_s: 0.1}
ground:
  extent_m: [0.1, 0.1]
  cell_size_m: 0.01
  initial_height: {kind: noise, mean_m: 0.01, amplitude_m: 0.005, correlation_m: 0.02}
settle: {depth_m: 0.004}
)";

class ExampleSolverTest : public TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    write_all(path("scene.yaml"), kScene);
  }
};

TEST_F(ExampleSolverTest, RunsThroughReposeRun) {
  ASSERT_EQ(repose_cli({"run", path("scene.yaml"), "--solver", "example", "--out", path("run")}), 0);
  const ArrayXXdR before = read_npy_2d(path("run/height_initial.npy"));
  const ArrayXXdR after = read_npy_2d(path("run/height_final.npy"));
  EXPECT_NEAR((before - after).maxCoeff(), 0.004, 1e-15);
  EXPECT_GE(after.minCoeff(), 0.0);
  const nlohmann::json manifest = nlohmann::json::parse(read_all(path("run/manifest.json")));
  EXPECT_EQ(manifest.at("solver"), "example");
  EXPECT_NEAR(manifest.at("results").at("mean_drop_m").get<double>(), (before - after).mean(), 1e-15);
  EXPECT_NE(manifest.at("scene").at("resolved_yaml").get<std::string>().find("settle"), std::string::npos);
}

TEST_F(ExampleSolverTest, CheckValidatesItsSectionAndNamesTheKey) {
  write_all(path("bad.yaml"), std::string(kScene).replace(std::string(kScene).find("0.004"), 5, "0.5"));
  ASSERT_EQ(repose_cli({"check", path("scene.yaml")}), 0);
  EXPECT_EQ(repose_cli({"check", path("bad.yaml")}), 2);  // settle.depth_m: expected a depth in [0, 0.1] m
}

TEST_F(ExampleSolverTest, RunsThroughReposeExperiment) {
  write_all(path("exp.yaml"), "runs:\n  - {name: a, scene: scene.yaml, solver: example}\n"
                              "sweeps:\n  - {name: d, scene: scene.yaml, solver: example, "
                              "sweep: {key: settle.depth_m, values: [0.001, 0.002]}}\n"
                              "measures: [mean_drop_m]\n");
  ASSERT_EQ(repose_cli({"experiment", path("exp.yaml"), "--out", path("exp")}), 0);
  const std::string summary = read_all(path("exp/summary.csv"));
  EXPECT_NE(summary.find("mean_drop_m"), std::string::npos) << summary;
  EXPECT_NE(summary.find("d_0.002,example"), std::string::npos) << summary;
}

TEST_F(ExampleSolverTest, CalibrateRecoversItsParameter) {
  write_all(path("calib.yaml"), "scenes:\n  - scene: scene.yaml\n    reference: {heuristic: {example.depth_m: 0.0037}}\n"
                                "    observables: [{kind: height_field}]\n"
                                "parameters: [{name: example.depth_m, initial: 0.01, bounds: [0, 0.05], step: 0.001}]\n"
                                "solver: {starts: 1, max_iterations: 20}\n");
  ASSERT_EQ(repose_cli({"calibrate", path("calib.yaml"), "--out", path("calib")}), 0);
  const YAML::Node fitted = YAML::LoadFile(path("calib/parameters.yaml"));
  EXPECT_NEAR(fitted["example.depth_m"].as<double>(), 0.0037, 1e-6);
}

}  // namespace
}  // namespace repose
