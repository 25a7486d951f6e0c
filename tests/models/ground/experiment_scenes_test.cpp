// Every experiments/scenes/ground_*.yaml loads, builds and runs with the
// ground model, conserving volume.
#include <filesystem>

#include <gtest/gtest.h>

#include "models/core/config/scene_loader.h"
#include "experiments/solvers/solver_registry.h"
#include "models/ground/simulate_ground.h"
#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

TEST(ExperimentScenes, EveryGroundSceneRunsAndBalances) {
  const std::filesystem::path dir = std::filesystem::path(REPOSE_SOURCE_DIR) / "experiments" / "scenes";
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("ground_", 0) != 0 || entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(name);
    const Scene scene = load_scene(entry.path().string(), solver_registry().sections());
    const GroundModel model = build_ground_model(scene);
    const GroundRun run = simulate_ground(scene, default_params(model));
    EXPECT_TRUE(run.final_height.all_finite());
    testing::expect_balanced(run.ledger, run.final_volume_m3);
    EXPECT_GT(run.contact_cells, 0);
    ++count;
  }
  EXPECT_GE(count, 13);  // drag x3, footprint x3, letters x3, wheel, multi drag, multires x2
}

}  // namespace
}  // namespace repose
