#include "models/terrain/building.h"

#include <gtest/gtest.h>

#include <numbers>

#include "models/core/base/error.h"
#include "models/terrain/terrain.h"
#include "tests/models/terrain/terrain_fixtures.h"

namespace repose {
namespace {

TerrainSurface hill() {
  TerrainOptions o;
  o.slope_rad = 20.0 * std::numbers::pi / 180.0;
  o.contour_interval_m = 1.0;
  o.sample_spacing_m = 2.0;
  return TerrainSurface(build_terrain({{"foot", test::circle_polygon(Point2(0, 0), 50.0, 40), 0.0}}, o).mesh);
}

TEST(Building, PartsTileTheFootprintPerStoreyAndStandOnTheGround) {
  const TerrainSurface surface = hill();
  Polygon2 l = test::l_polygon();
  for (Point2& p : l) p = p * 4.0 + Point2(10.0, -5.0);  // 16 x 12 m L on the flank
  const BuildingFootprint fp{"L house", l, 3, 3.0, 0.02};
  const std::vector<BuildingPart> parts = building_parts(fp, surface);
  ASSERT_EQ(parts.size(), 6u);  // two rectangles per storey
  const double base = highest_ground_m(surface, counter_clockwise(l)).value();
  double area_per_storey[3] = {0, 0, 0};
  for (const BuildingPart& p : parts) {
    area_per_storey[p.storey] += signed_area_m2(p.footprint_m);
    EXPECT_NEAR(p.bottom_m, base + 3.0 * p.storey, 1e-12);
    EXPECT_NEAR(p.top_m - p.bottom_m, 2.98, 1e-12);
  }
  for (double a : area_per_storey) EXPECT_NEAR(a, signed_area_m2(counter_clockwise(l)), 1e-9);
  // no corner of the footprint or mesh vertex under it is above the base
  for (const Point2& p : l) EXPECT_LE(surface.height_at(p).value(), base + 1e-12);
}

TEST(Building, HighestGroundIsExactOnAPiecewiseLinearSurface) {
  const TerrainSurface surface = hill();
  const Polygon2 square = test::rectangle_polygon(-5, -5, 5, 5);  // around the summit
  const double top = surface.mesh().V.col(2).maxCoeff();
  EXPECT_NEAR(highest_ground_m(surface, square).value(), top, 1e-9);
}

TEST(Building, PrismIsAClosedSolidOfTheRightVolume) {
  const Polygon2 r = test::rectangle_polygon(0, 0, 4, 3);
  const TriangleMesh m = prism_mesh(r, 1.0, 3.5);
  EXPECT_TRUE(is_closed_manifold(m));
  EXPECT_NEAR(signed_volume_m3(m), 4 * 3 * 2.5, 1e-12);
}

TEST(Building, TheRigidEnginesValuesAreCheckedNamingTheField) {
  BuildingFootprint b{"shed", test::rectangle_polygon(0, 0, 4, 3), 1, 3.0, 0.02};
  b.joint_break_force_n = 0.0;
  try {
    b.validate();
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("joint_break_force_n"), std::string::npos) << e.what();
  }
  b.joint_break_force_n = 1e6;
  b.bulk_density_kg_m3 = -1.0;
  EXPECT_THROW(b.validate(), InputError);
}

TEST(Building, FootprintOffTheTerrainIsRefused) {
  const TerrainSurface surface = hill();
  const BuildingFootprint fp{"far", test::rectangle_polygon(100, 100, 110, 110), 1, 3.0, 0.0};
  EXPECT_THROW(building_parts(fp, surface), InputError);
}

}  // namespace
}  // namespace repose
