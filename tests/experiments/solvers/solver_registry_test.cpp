// The registry of repose's solvers: every solver has a unique name, and
// every DEM scene that ships (experiments/scenes/*.yaml with a dem: section)
// compiles for each particle reference, LIGGGHTS, Bullet and ODE (issue 11:
// `repose run SCENE --solver bullet|ode` on every DEM scene).
#include "experiments/solvers/solver_registry.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
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

// The shipped debris scene with another seed and a short duration.
Scene debris_scene(int seed, const std::string& duration_s) {
  const std::filesystem::path path =
      std::filesystem::path(REPOSE_SOURCE_DIR) / "experiments" / "scenes" / "terrain_debris.yaml";
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"\nseed: 1\n", "\nseed: " + std::to_string(seed) + "\n"},
                                 {"duration_s: 8.0", "duration_s: " + duration_s}}) {
    const std::size_t at = yaml.find(from);
    if (at == std::string::npos) throw std::runtime_error("terrain_debris.yaml has no '" + from + "'");
    yaml.replace(at, from.size(), to);
  }
  return load_scene_from_string(yaml, path.string(), solver_registry().sections());
}

// The debris references' yardstick is their seed-to-seed noise: each engine
// must run the bed the seed draws (experiments/terrain_debris.yaml). The
// elements as the engine starts them (height_initial) and where it leaves
// them after 0.1 s (height_final, from the engine's own state) differ
// between seeds 1 and 2, and the same seed gives the same start.
TEST(SolverRegistry, TheSeedChangesTheDebrisBedInEveryEngine) {
  for (const char* engine : {"bullet", "ode", "liggghts"}) {
    SCOPED_TRACE(engine);
    const Solver& solver = solver_registry().get(engine);
    std::vector<repose::Run> runs;
    for (int seed : {1, 2, 1}) {
      const auto compiled = solver.compile(debris_scene(seed, "0.1"));
      runs.push_back(compiled->run(compiled->default_values(), RunOptions{}));
    }
    const auto differ = [](const HeightField& a, const HeightField& b) {
      return (a.heights() - b.heights()).abs().maxCoeff();
    };
    EXPECT_GT(differ(runs[0].field("height_initial"), runs[1].field("height_initial")), 0.05);
    EXPECT_GT(differ(runs[0].field("height_final"), runs[1].field("height_final")), 0.05);
    EXPECT_EQ(differ(runs[0].field("height_initial"), runs[2].field("height_initial")), 0.0);
    EXPECT_GT(runs[0].measure("element_count").value, 700);
  }
}

}  // namespace
}  // namespace repose
