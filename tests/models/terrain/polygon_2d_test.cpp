#include "models/terrain/polygon_2d.h"

#include <gtest/gtest.h>

#include "tests/models/terrain/terrain_fixtures.h"

namespace repose {
namespace {

TEST(Polygon2d, AreaAndOrientation) {
  const Polygon2 square = test::rectangle_polygon(0, 0, 2, 3);
  EXPECT_DOUBLE_EQ(signed_area_m2(square), 6.0);
  Polygon2 reversed(square.rbegin(), square.rend());
  EXPECT_DOUBLE_EQ(signed_area_m2(reversed), -6.0);
  EXPECT_DOUBLE_EQ(signed_area_m2(counter_clockwise(reversed)), 6.0);
}

TEST(Polygon2d, ContainsPointInConcavePolygon) {
  const Polygon2 l = test::l_polygon();
  EXPECT_TRUE(contains_point(l, Point2(0.5, 2.5)));
  EXPECT_TRUE(contains_point(l, Point2(3.5, 0.5)));
  EXPECT_FALSE(contains_point(l, Point2(2.0, 2.0)));  // in the notch
  EXPECT_FALSE(contains_point(l, Point2(-1.0, 0.5)));
}

TEST(Polygon2d, SimpleAndSelfIntersecting) {
  EXPECT_TRUE(is_simple(test::l_polygon()));
  const Polygon2 bow_tie = {Point2(0, 0), Point2(1, 1), Point2(1, 0), Point2(0, 1)};
  EXPECT_FALSE(is_simple(bow_tie));
  const Polygon2 repeated = {Point2(0, 0), Point2(1, 0), Point2(1, 0), Point2(0, 1)};
  EXPECT_FALSE(is_simple(repeated));
}

TEST(Polygon2d, DistanceAndNesting) {
  const Polygon2 outer = test::rectangle_polygon(0, 0, 10, 10);
  const Polygon2 inner = test::rectangle_polygon(2, 3, 5, 6);
  EXPECT_DOUBLE_EQ(boundary_distance_m(outer, inner), 2.0);
  EXPECT_TRUE(nested_inside(inner, outer));
  EXPECT_FALSE(nested_inside(outer, inner));
  const Polygon2 straddling = test::rectangle_polygon(8, 8, 12, 12);
  EXPECT_TRUE(boundaries_cross(outer, straddling));
  EXPECT_DOUBLE_EQ(boundary_distance_m(outer, straddling), 0.0);
}

TEST(Polygon2d, DensifiedKeepsCornersAndArea) {
  const Polygon2 l = test::l_polygon();
  const Polygon2 dense = densified(l, 0.3);
  EXPECT_NEAR(signed_area_m2(dense), signed_area_m2(l), 1e-12);
  for (const Point2& corner : l) {
    EXPECT_NE(std::find(dense.begin(), dense.end(), corner), dense.end());
  }
  for (std::size_t i = 0; i < dense.size(); ++i) {
    EXPECT_LE((dense[(i + 1) % dense.size()] - dense[i]).norm(), 0.3 + 1e-12);
  }
}

}  // namespace
}  // namespace repose
