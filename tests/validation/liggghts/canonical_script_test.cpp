// The canonical LIGGGHTS runs under data/ were made by this code: the run
// script generated now for each scene is byte for byte the one the run
// recorded (data/NAME/run.in), so the committed references still describe
// the scenes that experiments/scenes/NAME.yaml say.
#include <gtest/gtest.h>

#include <filesystem>

#include "experiments/solvers/solver_registry.h"
#include "models/core/config/scene_loader.h"
#include "tests/support/temp_dir.h"
#include "validation/liggghts/liggghts_script.h"
#include "validation/liggghts/snowfall_script.h"
#include "validation/particles/dem_section.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

TEST(CanonicalData, EachRunScriptIsTheOneTheCodeGeneratesForItsScene) {
  const fs::path data = fs::path(REPOSE_SOURCE_DIR) / "data";
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(data)) {
    if (!fs::is_regular_file(entry.path() / "run.in")) continue;
    const std::string name = entry.path().filename().string();
    SCOPED_TRACE(name);
    const fs::path scene = fs::path(REPOSE_SOURCE_DIR) / "experiments" / "scenes" / (name + ".yaml");
    ASSERT_TRUE(fs::exists(scene)) << scene;
    const std::string text = run_script(load_scene(scene.string(), solver_registry().sections())).text;
    EXPECT_EQ(text, test_support::read_all(entry.path() / "run.in"));
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

// The snowfall references (data/snowfall_SCENE_cC/seedN, made with --set
// seed=N --set dem.cohesion_energy_density_j_m3=C and, when cohesive,
// dem.settle_kinetic_energy_j=3e-6: scripts/make-canonical-data.sh) hold the
// script the code generates now.
TEST(CanonicalData, EachSnowfallScriptIsTheOneTheCodeGeneratesForItsSceneSeedAndCohesion) {
  const fs::path data = fs::path(REPOSE_SOURCE_DIR) / "data";
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(data)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with("snowfall_")) continue;
    const std::size_t c = name.rfind("_c");
    ASSERT_NE(c, std::string::npos) << name;
    const fs::path scene_path = fs::path(REPOSE_SOURCE_DIR) / "experiments" / "scenes" / (name.substr(0, c) + ".yaml");
    const double cohesion = std::stod(name.substr(c + 2));
    for (const auto& seed_dir : fs::directory_iterator(entry.path())) {
      SCOPED_TRACE(seed_dir.path().string());
      ASSERT_TRUE(fs::is_regular_file(seed_dir.path() / "snowfall.in"));
      Scene scene = load_scene(scene_path.string(), solver_registry().sections());
      scene.seed = std::stoull(seed_dir.path().filename().string().substr(4));
      scene = with_dem_changed(std::move(scene), [&](DemSpec& d) {
        d.cohesion_energy_density_j_m3 = cohesion;
        if (cohesion > 0) d.settle_kinetic_energy_j = 3e-6;
      });
      EXPECT_EQ(snowfall_script(scene).text, test_support::read_all(seed_dir.path() / "snowfall.in"));
      ++checked;
    }
  }
  EXPECT_GE(checked, 6);
}

}  // namespace
}  // namespace repose
