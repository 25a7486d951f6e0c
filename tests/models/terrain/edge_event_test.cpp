#include "models/terrain/edge_event.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/models/terrain/terrain_fixtures.h"

namespace repose {
namespace {

TEST(EdgeEvent, InteriorAnglesOfAnLSumToThepolygonRule) {
  const Polygon2 l = test::l_polygon();
  double sum = 0.0;
  for (std::size_t i = 0; i < l.size(); ++i) sum += interior_angle_rad(l, i);
  EXPECT_NEAR(sum, (l.size() - 2) * std::numbers::pi, 1e-12);
  EXPECT_NEAR(interior_angle_rad(l, 3), 1.5 * std::numbers::pi, 1e-12);  // the reflex corner (1, 1)
}

TEST(EdgeEvent, RectangleEdgesVanishAtHalfTheirNeighboursLength) {
  // each end is 90 deg: cot 45 + cot 45 = 2, so e_d = L / 2
  const Polygon2 r = test::rectangle_polygon(0, 0, 6, 2);
  EXPECT_NEAR(edge_vanish_distance_m(r, 0), 3.0, 1e-12);
  EXPECT_NEAR(edge_vanish_distance_m(r, 1), 1.0, 1e-12);
  EXPECT_NEAR(first_edge_event_distance_m(r), 1.0, 1e-12);
}

TEST(EdgeEvent, TriangleEdgesAllVanishAtTheInradius) {
  // a = r (cot(B/2) + cot(C/2)) for every side: the paper's eq. (1) is the inradius
  const Polygon2 t = {Point2(0, 0), Point2(4, 0), Point2(1, 3)};
  const double a = 4.0, b = std::hypot(3.0, 3.0), c = std::hypot(1.0, 3.0);
  const double s = 0.5 * (a + b + c);
  const double inradius = std::abs(signed_area_m2(t)) / s;
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(edge_vanish_distance_m(t, i), inradius, 1e-12);
}

TEST(EdgeEvent, EdgeNextToAReflexCornerGrows) {
  // the edge (4,1)-(1,1) of the L: 0.5*90 + 0.5*270 = 180 deg, the bisectors never meet
  const Polygon2 l = test::l_polygon();
  EXPECT_TRUE(std::isinf(edge_vanish_distance_m(l, 2)));
  EXPECT_NEAR(edge_vanish_distance_m(l, 1), 0.5, 1e-12);  // the end of the long arm
  EXPECT_NEAR(edge_vanish_distance_m(l, 0), 2.0, 1e-12);  // 4 / 2
}

}  // namespace
}  // namespace repose
