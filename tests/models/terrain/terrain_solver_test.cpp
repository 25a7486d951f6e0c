#include "models/terrain/terrain_solver.h"

#include <gtest/gtest.h>

#include <cmath>

#include "experiments/solvers/solver_registry.h"
#include "models/core/base/error.h"
#include "models/core/config/scene_loader.h"
#include "models/terrain/terrain_section.h"

namespace repose {
namespace {

// A cone: key contours at r = 40 m (0 m) and r = 20 m (20 tan 30 deg m) on a 100 m grid.
const char* const kScene = R"(time: {step_s: 1, duration_s: 1}
ground:
  extent_m: [100, 100]
  cell_size_m: 2
  origin_m: [-50, -50]
  initial_height: {kind: flat, height_m: 0}
terrain:
  key_contours:
    - {name: foot, height_m: 0, points_m: [[40, 0], [28.284271247461902, 28.284271247461902], [0, 40], [-28.284271247461902, 28.284271247461902], [-40, 0], [-28.284271247461902, -28.284271247461902], [0, -40], [28.284271247461902, -28.284271247461902]]}
  contour_interval_m: 1
  slope_deg: 30
  sample_spacing_m: 1
)";

Scene load(const std::string& yaml) { return load_scene_from_string(yaml, "/tmp/terrain_scene.yaml", solver_registry().sections()); }

TEST(TerrainSolver, RunsFromTheRegistryOnTheScenesGrid) {
  const Scene scene = load(kScene);
  const Solver& solver = solver_registry().get("terrain");
  std::string why;
  ASSERT_TRUE(solver.can_run(scene, &why)) << why;
  const auto compiled = solver.compile(scene);
  ASSERT_EQ(compiled->parameters().size(), 1u);
  EXPECT_EQ(compiled->parameters()[0].name, "slope_deg");
  const repose::Run run = compiled->run(compiled->default_values(), RunOptions{});
  const HeightField& h = run.field("height_final");
  EXPECT_EQ(h.grid(), scene.ground.grid);
  // an octagon of apothem 40 cos(22.5 deg) rises at 30 deg to its centre
  const double apex = 40.0 * std::cos(M_PI / 8) * std::tan(M_PI / 6);
  EXPECT_NEAR(run.measure("max_height_m").value, apex, 1e-9);
  EXPECT_NEAR(run.measure("relief_m").value, apex, 1e-9);
  EXPECT_GT(run.measure("triangle_count").value, 100);
  EXPECT_EQ(run.measure("key_contour_count").value, 1);
  EXPECT_NEAR(h.max_height_m(), apex, 0.05 * apex);  // cell centres miss the apex a little
  EXPECT_EQ(h.at(0, 0), 0.0);                          // outside the foot: the plain
  EXPECT_EQ(run.field("height_initial").max_height_m(), 0.0);
}

TEST(TerrainSolver, SlopeParameterChangesTheTerrain) {
  const auto compiled = solver_registry().get("terrain").compile(load(kScene));
  const repose::Run gentle = compiled->run({20.0 * M_PI / 180.0}, RunOptions{});
  const repose::Run steep = compiled->run({40.0 * M_PI / 180.0}, RunOptions{});
  EXPECT_NEAR(steep.measure("max_height_m").value / gentle.measure("max_height_m").value,
              std::tan(40.0 * M_PI / 180.0) / std::tan(20.0 * M_PI / 180.0), 1e-9);
  EXPECT_THROW(compiled->run({95.0 * M_PI / 180.0}, RunOptions{}), InputError);
}

TEST(TerrainSolver, SectionWritesBackToAnEqualSection) {
  const Scene scene = load(kScene);
  YAML::Emitter out;
  scene.section<TerrainSection>()->write_yaml(out);
  const YamlValue again = parse_yaml(out.c_str(), "written.yaml");
  const TerrainScene back = read_terrain_section(again);
  const TerrainScene& first = terrain_section(scene).scene;
  ASSERT_EQ(back.key_contours.size(), first.key_contours.size());
  EXPECT_EQ(back.key_contours[0].polygon_m, first.key_contours[0].polygon_m);
  EXPECT_EQ(back.options.slope_rad, first.options.slope_rad);
  EXPECT_EQ(back.options.sample_spacing_m, first.options.sample_spacing_m);
}

TEST(TerrainSolver, BadSectionIsRefusedAtTheKey) {
  std::string bad = kScene;
  bad.replace(bad.find("slope_deg: 30"), 13, "slope_deg: 95");
  try {
    load(bad);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("terrain.slope_deg"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace repose

namespace repose {
namespace {

// The random bed follows the scene's top-level seed (which `--set seed=N`
// and an experiment's seed sweep change), and the section writes the
// spread and jitter back.
TEST(TerrainSolver, TheScenesSeedDrawsTheElementsBed) {
  const std::string elements = R"(  elements:
    region_m: [[-10, -10], [10, -10], [10, 10], [-10, 10]]
    radius_spread: 0.2
    position_jitter: 1
    layers: [{radius_m: 0.5}]
)";
  const Scene one = load(std::string("seed: 1\n") + kScene + elements);
  const Scene two = load(std::string("seed: 2\n") + kScene + elements);
  ASSERT_TRUE(terrain_section(two).scene.elements.has_value());
  EXPECT_EQ(terrain_section(one).scene.elements->seed, 1u);
  EXPECT_EQ(terrain_section(two).scene.elements->seed, 2u);
  const TerrainScenery a = generate_scenery(terrain_section(one).scene);
  const TerrainScenery b = generate_scenery(terrain_section(two).scene);
  ASSERT_GT(a.elements.elements.size(), 100u);
  EXPECT_NE(a.elements.elements[0].radius_m, b.elements.elements[0].radius_m);
  YAML::Emitter out;
  two.section<TerrainSection>()->write_yaml(out);
  const TerrainScene back = read_terrain_section(parse_yaml(out.c_str(), "written.yaml"));
  ASSERT_TRUE(back.elements.has_value());
  EXPECT_EQ(back.elements->radius_spread, 0.2);
  EXPECT_EQ(back.elements->position_jitter, 1.0);
}

}  // namespace
}  // namespace repose
