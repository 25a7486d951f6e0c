#include "models/terrain/terrain_scene.h"

#include <gtest/gtest.h>

#include <numbers>

#include "models/core/base/error.h"
#include "tests/models/terrain/terrain_fixtures.h"

namespace repose {
namespace {

TerrainScene hill_scene() {
  TerrainScene scene;
  scene.key_contours = {{"foot", test::circle_polygon(Point2(0, 0), 60.0, 40), 0.0},
                        {"top", test::circle_polygon(Point2(-10, 0), 15.0, 24), 25.0}};
  scene.options.slope_rad = 30.0 * std::numbers::pi / 180.0;
  scene.options.sample_spacing_m = 2.0;
  ElementSource src;
  src.region_m = test::rectangle_polygon(5, -10, 25, 10);
  src.layers = {{"debris", 0.8, 1, 0.6, 0.2}};
  scene.elements = src;
  scene.buildings = {{"house", test::rectangle_polygon(35, -5, 45, 5), 2, 3.0, 0.02}};
  return scene;
}

TEST(TerrainScene, GeneratesTerrainElementsAndBuildings) {
  const TerrainScenery s = generate_scenery(hill_scene());
  EXPECT_GT(s.terrain.summary.triangle_count, 100);
  EXPECT_GT(s.elements.elements.size(), 50u);
  EXPECT_EQ(s.building_parts.size(), 2u);  // a rectangle: one part per storey
  // no element reaches a building part (the region keeps its distance)
  for (const PlacedElement& e : s.elements.elements) {
    for (const BuildingPart& p : s.building_parts) {
      double gap = INFINITY;
      for (std::size_t i = 0; i < p.footprint_m.size(); ++i) {
        gap = std::min(gap, point_segment_distance_m(e.centre_m.head<2>(), p.footprint_m[i],
                                                     p.footprint_m[(i + 1) % p.footprint_m.size()]));
      }
      EXPECT_GT(gap, e.radius_m);
    }
  }
}

TEST(TerrainScene, OverlapsAreRefusedNamingBoth) {
  TerrainScene scene = hill_scene();
  scene.buildings.push_back({"shed", test::rectangle_polygon(40, 0, 48, 8), 1, 3.0, 0.0});
  try {
    scene.validate();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'house' and 'shed' overlap"), std::string::npos) << e.what();
  }
  scene = hill_scene();
  scene.buildings[0].polygon_m = test::rectangle_polygon(25.5, -5, 35, 5);  // 0.5 m from the elements
  EXPECT_THROW(scene.validate(), InputError);
}

}  // namespace
}  // namespace repose
