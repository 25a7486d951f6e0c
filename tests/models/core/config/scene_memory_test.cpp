// A scene whose run would need more memory than the budget is refused when
// it is loaded, with the estimate and the budget in one line.
#include <gtest/gtest.h>

#include <string>

#include "experiments/solvers/solver_registry.h"
#include "models/core/base/error.h"
#include "models/core/base/memory_budget.h"
#include "models/core/config/scene_loader.h"

namespace repose {
namespace {

std::string scene_with(int spheres) {
  std::string text = "time: {step_s: 0.1, duration_s: 0.1}\nground:\n  extent_m: [1, 1]\n  cell_size_m: 0.01\n"
                     "  initial_height: {kind: flat, height_m: 0.05}\nobjects:\n";
  for (int k = 0; k < spheres; ++k) {
    text += "  - {shape: sphere, radius_m: 0.01, motion: [{time_s: 0, position_m: [0, 0, 0.1]}]}\n";
  }
  return text;
}

class SceneMemory : public ::testing::Test {
 protected:
  void TearDown() override { set_memory_budget_bytes(std::nullopt); }
};

TEST_F(SceneMemory, ManySpheresAreRefusedAboveTheBudgetNamingTheEstimate) {
  set_memory_budget_bytes(64ull << 20);  // 64 MB
  EXPECT_NO_THROW(load_scene_from_string(scene_with(2), "/tmp/few.yaml", solver_registry().sections()));
  try {
    load_scene_from_string(scene_with(400), "/tmp/many.yaml", solver_registry().sections());
    FAIL() << "400 spheres of ~2000 triangles fitted in 64 MB";
  } catch (const InputError& e) {
    const std::string message = e.what();
    // refused while the bodies are made, before all 400 are
    EXPECT_NE(message.find("/tmp/many.yaml: the scene (100 x 100 cells, "), std::string::npos) << message;
    EXPECT_EQ(message.find("400 objects"), std::string::npos) << message;
    EXPECT_NE(message.find("memory budget"), std::string::npos) << message;
  }
}

TEST_F(SceneMemory, AGridBeyondTheBudgetIsRefusedBeforeItIsMade) {
  set_memory_budget_bytes(16ull << 20);  // 16 MB: 1000^2 cells x 8 grids x 8 bytes is 61 MB
  const std::string text = "time: {step_s: 0.1, duration_s: 0.1}\nground:\n  extent_m: [1, 1]\n  cell_size_m: 0.001\n"
                           "  initial_height: {kind: flat, height_m: 0.05}\n";
  EXPECT_THROW(load_scene_from_string(text, "/tmp/grid.yaml", solver_registry().sections()), InputError);
}

}  // namespace
}  // namespace repose
