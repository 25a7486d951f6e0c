// The registry of repose's solvers: every solver has a unique name, and
// every DEM scene that ships (experiments/scenes/*.yaml with a dem: section)
// compiles for each particle reference, LIGGGHTS, Bullet and ODE (issue 11:
// `repose run SCENE --solver bullet|ode` on every DEM scene).
#include "experiments/solvers/solver_registry.h"

#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/core/config/scene_loader.h"
#include "validation/particles/dem_section.h"

namespace repose {
namespace {

TEST(SolverRegistry, NamesAreUniqueAndIncludeTheThreeParticleEngines) {
  const std::vector<std::string> names = solver_registry().names();
  const std::set<std::string> unique(names.begin(), names.end());
  EXPECT_EQ(unique.size(), names.size());
  for (const char* engine : {"ground", "liggghts", "bullet", "ode"}) EXPECT_TRUE(unique.count(engine)) << engine;
}

TEST(SolverRegistry, EveryShippedDemSceneCompilesForEachParticleEngine) {
  const SolverRegistry& registry = solver_registry();
  const std::filesystem::path dir = std::filesystem::path(REPOSE_SOURCE_DIR) / "experiments" / "scenes";
  int dem_scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".yaml") continue;
    const Scene scene = load_scene(entry.path().string(), registry.sections());
    std::string why;
    if (dem_of(scene) == nullptr) continue;  // no dem: section (liggghts also runs a terrain: section's debris)
    ASSERT_TRUE(registry.get("liggghts").can_run(scene, &why)) << why;
    ++dem_scenes;
    // the snowfall reference is LIGGGHTS only: the rigid engines refuse it in one line naming the key
    const bool liggghts_only = dem_of(scene)->initial == DemSpec::Initial::kSnowfall;
    for (const char* engine : {"bullet", "ode"}) {
      SCOPED_TRACE(entry.path().filename().string() + " --solver " + engine);
      const Solver& solver = registry.get(engine);
      if (liggghts_only) {
        try {
          solver.compile(scene);
          ADD_FAILURE() << "a snowfall scene was accepted";
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("dem: initial"), std::string::npos) << e.what();
        }
        continue;
      }
      ASSERT_TRUE(solver.can_run(scene, &why)) << why;
      EXPECT_NE(solver.compile(scene), nullptr);
    }
  }
  EXPECT_GE(dem_scenes, 17);  // dem_* (8), ref_* (8), heightspan_scoop
}

}  // namespace
}  // namespace repose
