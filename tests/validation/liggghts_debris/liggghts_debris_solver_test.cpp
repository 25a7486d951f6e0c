#include "validation/liggghts_debris/liggghts_debris_solver.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"
#include "models/core/config/scene_loader.h"

namespace repose {
namespace {

Scene shipped(const std::string& name) {
  const auto path = std::filesystem::path(REPOSE_SOURCE_DIR) / "experiments" / "scenes" / name;
  return load_scene(path.string(), solver_registry().sections());
}

TEST(LiggghtsDebrisSolver, RunsATerrainScenesDebrisAndStillADemScene) {
  const LiggghtsDebrisSolver solver;
  EXPECT_EQ(solver.name(), "liggghts");
  std::string why;
  for (const char* scene : {"terrain_debris.yaml", "dem_indent.yaml"}) {
    SCOPED_TRACE(scene);
    const Scene s = shipped(scene);
    ASSERT_TRUE(solver.can_run(s, &why)) << why;
    EXPECT_NE(solver.compile(s), nullptr);
  }
}

TEST(LiggghtsDebrisSolver, ASceneWithNeitherSectionIsRefusedSayingWhy) {
  const LiggghtsDebrisSolver solver;
  const Scene s = load_scene_from_string(
      "name: bare\ntime: {step_s: 0.1, duration_s: 1}\n"
      "ground: {extent_m: [1, 1], cell_size_m: 0.1, initial_height: {kind: flat, height_m: 0}, material: sand}\n",
      "bare.yaml", solver_registry().sections());
  std::string why;
  EXPECT_FALSE(solver.can_run(s, &why));
  EXPECT_NE(why.find("terrain"), std::string::npos) << why;
}

}  // namespace
}  // namespace repose
