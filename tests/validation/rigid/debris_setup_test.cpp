#include "validation/rigid/debris_setup.h"

#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "models/core/base/error.h"
#include "models/terrain/terrain_surface.h"
#include "tests/validation/rigid/debris_test_world.h"

namespace repose {
namespace {

// A valley floor at 0 m around a hill at 20 m; elements on the north flank
// (two layers), a house at its foot.
TerrainScene flank_scene() {
  TerrainScene s;
  s.key_contours = {{"valley", {{-60, -60}, {60, -60}, {60, 60}, {-60, 60}}, 0.0},
                    {"hill", {{-20, -20}, {20, -20}, {20, 0}, {-20, 0}}, 20.0}};
  s.options.slope_rad = 25.0 * std::numbers::pi / 180.0;
  s.options.contour_interval_m = 2.0;
  s.options.sample_spacing_m = 2.0;
  ElementSource e;
  e.region_m = {{-8, 10}, {8, 10}, {8, 18}, {-8, 18}};
  e.layers = {{"rock", 0.6, 1, 0.7, 0.1, 2600.0, 0.4}, {"soil", 0.4, 2, 0.5, 0.2, 2000.0, 0.3}};
  s.elements = e;
  s.buildings = {{"house", {{-5, 35}, {5, 35}, {5, 42}, {-5, 42}}, 2, 3.0, 0.02}};
  return s;
}

TEST(DebrisSetup, ElementsNeverOverlapAndRestOnOrAboveTheTerrainAtStart) {
  const DebrisSetup setup = debris_setup(flank_scene(), {});
  ASSERT_GT(setup.spec.elements.size(), 100u);
  EXPECT_GT(min_element_clearance_m(setup.spec.elements), 0.0);
  const TerrainSurface surface(setup.spec.terrain);
  for (const DebrisElement& e : setup.spec.elements) {
    const double ground = surface.height_at(Point2(e.centre_m.x(), e.centre_m.y())).value();
    EXPECT_GE(e.centre_m.z() - e.radius_m, ground - 1e-9);  // the sphere's bottom point is not under the ground
  }
}

TEST(DebrisSetup, LayersGiveTheirValuesAndTheFlowRunsDownhill) {
  const TerrainScene scene = flank_scene();
  const DebrisSetup setup = debris_setup(scene, {}, 2.0);
  for (const DebrisElement& e : setup.spec.elements) {
    const ElementLayer& l = scene.elements->layers[e.radius_m == 0.6 ? 0 : 1];
    EXPECT_EQ(e.friction, l.friction);
    EXPECT_EQ(e.restitution, l.restitution);
    EXPECT_EQ(e.density_kg_m3, l.density_kg_m3);
    EXPECT_EQ(e.rolling_friction, 2.0 * l.rolling_friction);  // scaled
  }
  // the source lies north of the hill: downhill is +y
  EXPECT_GT(setup.flow_direction.y(), 0.9);
  EXPECT_DOUBLE_EQ(setup.spec.plain_height_m, 0.0);
}

TEST(DebrisSetup, AnLHouseHasGroundSideAndStoreyJointsAndItsMass) {
  const DebrisSetup setup = test_support::house_on_flat_ground(1.0e6);
  ASSERT_EQ(setup.spec.parts.size(), 4u);  // two convex pieces, two storeys
  int ground = 0, side = 0, storey = 0;
  for (const DebrisJoint& j : setup.spec.joints) {
    const bool vertical = j.b >= 0 && std::abs(setup.spec.parts[static_cast<std::size_t>(j.a)].centre_m.z() -
                                               setup.spec.parts[static_cast<std::size_t>(j.b)].centre_m.z()) > 1.0;
    (j.b < 0 ? ground : vertical ? storey : side) += 1;
    EXPECT_EQ(j.break_force_n, 1.0e6);
  }
  EXPECT_EQ(ground, 2);
  EXPECT_EQ(side, 2);
  EXPECT_EQ(storey, 2);
  double mass = 0.0;
  for (const DebrisPart& p : setup.spec.parts) {
    mass += p.mass_kg;
    EXPECT_GE(p.centre_m.z() - p.half_extents_m.z(), kPartClearanceM - 1e-12);  // clear of the ground
  }
  EXPECT_NEAR(mass, 300.0 * 33.0 * 2.98 * 2, 1e-6 * mass);
}

TEST(DebrisSetup, ASceneWithoutElementsIsRefusedNamingTheKey) {
  TerrainScene s = flank_scene();
  s.elements.reset();
  try {
    debris_setup(s, {});
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("terrain: elements"), std::string::npos) << e.what();
  }
}

TEST(DebrisSetup, ABadJointThresholdIsRefusedNamingTheKey) {
  TerrainScene s = flank_scene();
  s.buildings[0].joint_break_force_n = -1.0;
  try {
    debris_setup(s, {});
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("joint_break_force_n"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace repose
