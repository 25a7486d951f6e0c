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

}  // namespace
}  // namespace repose
