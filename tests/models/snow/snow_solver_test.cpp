#include "models/snow/snow_solver.h"

#include <gtest/gtest.h>

#include "models/core/config/scene_loader.h"
#include "models/snow/snow_section.h"

namespace repose {
namespace {

const char* const kScene = R"(
name: snow_solver
seed: 3
time: {step_s: 1.0, duration_s: 5.0}
ground:
  extent_m: [0.2, 0.2]
  cell_size_m: 0.01
  initial_height: {kind: flat, height_m: 0.01}
objects:
  - {name: top, shape: box, half_extents_m: [0.04, 0.04, 0.005], motion: [{time_s: 0, position_m: [0, 0, 0.05]}]}
snow:
  groups: [{name: ground, ground: true}, {name: table, objects: [top]}]
  direction_count: 8
  snowfall_rate_m_s: 0.002
)";

TEST(SnowSolver, RunsASceneAndReportsFieldsAndMeasures) {
  const SnowSolver solver;
  const Scene scene = load_scene_from_string(kScene, "/tmp/snow_solver.yaml", solver.sections());
  std::string why;
  ASSERT_TRUE(solver.can_run(scene, &why)) << why;
  const auto compiled = solver.compile(scene);
  ASSERT_EQ(compiled->parameters().size(), 4u);
  EXPECT_EQ(compiled->parameters()[0].name, "repose_angle_deg");
  EXPECT_EQ(compiled->parameters()[1].name, "spread_deg");
  EXPECT_EQ(compiled->parameters()[2].name, "snowfall_scale");
  EXPECT_EQ(compiled->parameters()[3].name, "edge_hold_m");
  const repose::Run run = compiled->run(compiled->default_values(), RunOptions{});
  EXPECT_EQ(run.solver, "snow");
  const ArrayXXdR& ground = run.field("height_initial").heights();
  const ArrayXXdR& snow = run.field("snow_depth_final.ground").heights();
  EXPECT_TRUE((run.field("height_final").heights() == ground + snow).all());
  EXPECT_GT(run.field("snow_depth_final.table").heights().maxCoeff(), 0.0);
  EXPECT_EQ(run.measure("steps").value, 5.0);
  EXPECT_NEAR(run.measure("snow.imbalance_m3").value, 0.0, 1e-12 * run.measure("snow.fallen_m3").value);
  EXPECT_NEAR(run.measure("snow.on_maps_m3").value,
              run.measure("snow.volume_m3.ground").value + run.measure("snow.volume_m3.table").value, 1e-15);
  // the same values give the same bits
  const repose::Run again = compiled->run(compiled->default_values(), RunOptions{});
  EXPECT_TRUE((again.field("snow_depth_final.ground").heights() == snow).all());
}

TEST(SnowSolver, CannotRunASceneWithoutASnowSection) {
  const SnowSolver solver;
  std::string text = kScene;
  text = text.substr(0, text.find("snow:\n"));
  const Scene scene = load_scene_from_string(text, "/tmp/no_snow.yaml", solver.sections());
  std::string why;
  EXPECT_FALSE(solver.can_run(scene, &why));
  EXPECT_NE(why.find("snow"), std::string::npos);
}

}  // namespace
}  // namespace repose
