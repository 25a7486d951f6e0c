// Every experiments/scenes/snow_*.yaml and snowfall_*.yaml (the DEM
// snowfall references' scenes, which the snow calibrations run under the
// snow solver) loads with the registry's sections,
// compiles under the snow solver and runs (its first two steps: the whole
// runs are experiments), conserving snow.
#include <filesystem>

#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"
#include "models/core/config/scene_loader.h"
#include "models/snow/snow_solver.h"

namespace repose {
namespace {

TEST(ExperimentScenes, EverySnowSceneRunsAndConserves) {
  const std::filesystem::path dir = std::filesystem::path(REPOSE_SOURCE_DIR) / "experiments" / "scenes";
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    const bool snow = name.rfind("snow_", 0) == 0 || name.rfind("snowfall_", 0) == 0;
    if (!snow || entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(name);
    Scene scene = load_scene(entry.path().string(), solver_registry().sections());
    scene.time.duration_s = 2.0 * scene.time.step_s;
    const SnowSolver solver;
    std::string why;
    ASSERT_TRUE(solver.can_run(scene, &why)) << why;
    const auto compiled = solver.compile(scene);
    const repose::Run run = compiled->run(compiled->default_values(), RunOptions{});
    EXPECT_GT(run.measure("snow.fallen_m3").value, 0.0);
    EXPECT_NEAR(run.measure("snow.imbalance_m3").value, 0.0, 1e-12 * run.measure("snow.fallen_m3").value);
    EXPECT_TRUE(run.field("height_final").all_finite());
    ++count;
  }
  EXPECT_GE(count, 7);  // table, primitives, the snowfall tables, roofs and ridge
}

}  // namespace
}  // namespace repose
