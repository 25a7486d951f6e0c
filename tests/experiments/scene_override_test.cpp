#include "experiments/runner/scene_override.h"

#include <gtest/gtest.h>

#include <string>

#include "experiments/solvers/solver_registry.h"
#include "models/core/base/error.h"
#include "models/ground/ground_section.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

const char* const kScene = R"(time: {step_s: 0.1, duration_s: 0.2}
ground:
  extent_m: [0.4, 0.2]
  cell_size_m: 0.02
  initial_height: {kind: flat, height_m: 0.05}
objects:
  - name: ball
    shape: sphere
    radius_m: 0.03
    motion:
      - {time_s: 0, position_m: [0, 0, 0.08]}
      - {time_s: 0.2, position_m: [0.1, 0, 0.08]}
)";




TEST(SceneOverride, SetsNestedKeysListItemsAndCreatesMissingMaps) {
  YAML::Node root = YAML::Load("{time: {step_s: 0.1}, objects: [{name: a, motion: [{time_s: 0}, {time_s: 1}]}]}");
  apply_scene_override(root, {"time.step_s", YAML::Load("0.5")});
  apply_scene_override(root, {"objects[0].motion[1].time_s", YAML::Load("2")});
  apply_scene_override(root, {"ground_model.sweep", YAML::Load("false")});
  EXPECT_EQ(root["time"]["step_s"].as<double>(), 0.5);
  EXPECT_EQ(root["objects"][0]["motion"][1]["time_s"].as<double>(), 2.0);
  EXPECT_EQ(root["objects"][0]["motion"][0]["time_s"].as<double>(), 0.0);  // neighbours untouched
  EXPECT_EQ(root["objects"][0]["name"].as<std::string>(), "a");
  EXPECT_FALSE(root["ground_model"]["sweep"].as<bool>());
}

TEST(SceneOverride, RejectsPathsThatDoNotFitTheDocument) {
  YAML::Node root = YAML::Load("{time: {step_s: 0.1}, objects: [{name: a}]}");
  const auto message = [&](const std::string& key) {
    try {
      apply_scene_override(root, {key, YAML::Load("1")});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message("objects[3].name").find("the list has 1 item"), std::string::npos) << message("objects[3].name");
  EXPECT_NE(message("time.step_s.x").find("not a map"), std::string::npos);
  EXPECT_NE(message("time[0]").find("not a list"), std::string::npos);
  for (const char* bad : {"", "time..step_s", "time.", "objects[x]", "objects[]", "a b"}) {
    EXPECT_NE(message(bad).find("not a scene key path"), std::string::npos) << bad;
  }
}

TEST(SceneOverride, TheOverriddenSceneGoesThroughTheStrictLoader) {
  test_support::TempDir dir("repose_override");
  const std::string path = (dir.path / "scene.yaml").string();
  test_support::write_all(path, kScene);
  const Scene s = load_scene_with_overrides(path, {{"ground_model.substeps", YAML::Load("4")}},
                                            solver_registry().sections());
  EXPECT_EQ(ground_model_section(s).options.substeps, 4);
  // an override the section's rule refuses is refused with the scene file's line
  try {
    load_scene_with_overrides(path, {{"ground_model.substeps", YAML::Load("0")}}, solver_registry().sections());
    FAIL() << "substeps 0 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ground_model.substeps: expected an integer in [1, 10000], got 0"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(load_scene_with_overrides(path, {{"ground.colour", YAML::Load("red")}}, solver_registry().sections()),
               InputError);
}

}  // namespace
}  // namespace repose
