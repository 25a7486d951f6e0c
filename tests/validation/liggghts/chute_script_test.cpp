// The scripts of a chute scene (dem.slope_deg, dem.impact_window_m): the
// block settled level, gravity tilted down the slope in the run, the wall a mesh whose force
// is on the thermo line, velocities in the dumps; a level scene's scripts
// keep their text (gravity along -z, no velocities); slopes and windows
// outside their rules are refused naming the field.

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/validation/liggghts/chute_test_scene.h"
#include "tests/validation/liggghts/dem_test_scene.h"
#include "validation/liggghts/liggghts_script.h"

namespace repose {
namespace {

bool has(const std::string& text, const std::string& line) { return text.find(line) != std::string::npos; }

TEST(ChuteScript, GravityTiltsDownTheSlopeInTheRunAfterALevelSettling) {
  const Scene scene = testing::chute_scene(30.0);
  const double a = 30.0 * std::numbers::pi / 180.0;
  const std::string gravity = "fix gravity all gravity 9.81 vector " + liggghts_number(std::sin(a)) + " 0 " +
                              liggghts_number(-std::cos(a)) + "\n";
  EXPECT_TRUE(has(bed_script(scene), "fix gravity all gravity 9.81 vector 0 0 -1\n")) << bed_script(scene);
  // every slope settles the same bed
  EXPECT_EQ(bed_script(scene), bed_script(testing::chute_scene(45.0)));
  const RunScript run = run_script(scene);
  EXPECT_TRUE(has(run.text, gravity));
  // the floor stays the plane z = 0, rough (type 2)
  EXPECT_TRUE(has(run.text, "fix wall_floor all wall/gran model hertz tangential history rolling_friction cdt "
                            "primitive type 2 zplane 0\n"));
}

TEST(ChuteScript, WallIsAMeshWithItsForceOnTheThermoLineAndDumpsCarryVelocities) {
  const RunScript run = run_script(testing::chute_scene(35.0));
  ASSERT_EQ(run.meshes.size(), 1u);
  EXPECT_EQ(run.meshes[0].fix_id, "obj0");
  EXPECT_TRUE(has(run.text, "fix obj0 all mesh/surface/stress file object_0.stl type 1 stress on\n"));
  EXPECT_TRUE(has(run.text, "thermo_style custom step atoms ke f_obj0[1] f_obj0[2] f_obj0[3]\n"));
  EXPECT_TRUE(has(run.text, "custom 500 dumps/dump.*.txt id type x y z radius vx vy vz\n")) << run.text;
  // the gate is gone in the run: grains are released at t = 0
  EXPECT_FALSE(has(run.text, "fix gate"));
  EXPECT_TRUE(has(bed_script(testing::chute_scene(35.0)), "fix gate all wall/gran"));
}

TEST(ChuteScript, LevelScenesKeepTheirScriptText) {
  const Scene scene = testing::small_dem_scene(true);
  EXPECT_TRUE(has(bed_script(scene), "fix gravity all gravity 9.81 vector 0 0 -1\n"));
  const RunScript run = run_script(scene);
  EXPECT_TRUE(has(run.text, "fix gravity all gravity 9.81 vector 0 0 -1\n"));
  EXPECT_TRUE(has(run.text, "id type x y z radius\n"));
  EXPECT_FALSE(has(run.text, "vx vy vz"));
}

std::string refusal(const std::string& yaml) {
  try {
    load_scene_from_string(yaml, "tiny_chute.yaml", solver_registry().sections());
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(ChuteScript, SlopeAndWindowOutsideTheirRulesAreRefusedNamingTheField) {
  EXPECT_TRUE(has(refusal(testing::chute_scene_yaml(80.0)), "slope_deg")) << refusal(testing::chute_scene_yaml(80.0));
  EXPECT_TRUE(has(refusal(testing::chute_scene_yaml(-5.0)), "slope_deg"));
  EXPECT_TRUE(has(refusal(testing::chute_scene_yaml(30.0, -0.01)), "impact_window_m"));
  // a window reaching past the chute's top end
  EXPECT_TRUE(has(refusal(testing::chute_scene_yaml(30.0, 0.3)), "impact window")) << refusal(testing::chute_scene_yaml(30.0, 0.3));
  // a window but no wall
  std::string no_wall = testing::chute_scene_yaml(30.0);
  const auto begin = no_wall.find("objects:"), end = no_wall.find("dem:");
  no_wall.erase(begin, end - begin);
  EXPECT_TRUE(has(refusal(no_wall), "first object")) << refusal(no_wall);
}

}  // namespace
}  // namespace repose
