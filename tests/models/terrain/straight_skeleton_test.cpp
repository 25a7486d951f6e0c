#include "models/terrain/straight_skeleton.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "models/terrain/edge_event.h"
#include "tests/models/terrain/terrain_fixtures.h"

namespace repose {
namespace {

double first_node_time_m(const StraightSkeleton& s) {
  double t = INFINITY;
  for (const SkeletonNode& n : s.nodes()) t = std::min(t, n.time_m);
  return t;
}

TEST(StraightSkeleton, RectangleClosedForm) {
  // a 6 x 2 rectangle: the ridge from (1, 1) to (5, 1), both nodes at t = 1
  const StraightSkeleton s(test::rectangle_polygon(0, 0, 6, 2));
  ASSERT_EQ(s.nodes().size(), 2u);
  for (const SkeletonNode& n : s.nodes()) {
    EXPECT_NEAR(n.time_m, 1.0, 1e-12);
    EXPECT_NEAR(n.point_m.y(), 1.0, 1e-12);
    EXPECT_NEAR(std::min(n.point_m.x(), 6.0 - n.point_m.x()), 1.0, 1e-12);
  }
  // eq. (1): the short edges vanish first, at the skeleton's first event
  EXPECT_NEAR(first_edge_event_distance_m(test::rectangle_polygon(0, 0, 6, 2)), first_node_time_m(s), 1e-12);
}

TEST(StraightSkeleton, LShapeEventsAtEquationOneDistance) {
  // arms of width 1: both arm ends vanish (edge events) and the reflex
  // corner meets the inner corner at t = 0.5, which eq. (1) predicts
  const Polygon2 l = test::l_polygon();
  const StraightSkeleton s(l);
  EXPECT_NEAR(first_node_time_m(s), first_edge_event_distance_m(l), 1e-12);
  EXPECT_NEAR(s.vanish_time_m(), 0.5, 1e-12);
  // shrunk by 0.25 it is an L of arm width 0.5 with area 2.5 - ... (closed form)
  const std::vector<Polygon2> shrunk = s.offset(0.25);
  ASSERT_EQ(shrunk.size(), 1u);
  // arms 0.5 wide: the long arm from x = 0.25 to 3.75, the short one up to y = 2.75
  const double expected = 3.5 * 0.5 + 0.5 * (2.75 - 0.75);
  EXPECT_NEAR(signed_area_m2(shrunk[0]), expected, 1e-9);
}

TEST(StraightSkeleton, ConvexPolygonsFirstEventIsEquationOne) {
  // no split events in a convex polygon, so the first skeleton node forms at
  // the smallest eq. (1) distance
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    std::mt19937_64 rng(seed);
    const Polygon2 p = test::random_convex_polygon(&rng, 5 + static_cast<int>(seed % 7));
    const StraightSkeleton s(p);
    EXPECT_NEAR(first_node_time_m(s), first_edge_event_distance_m(p), 1e-9) << "seed " << seed;
  }
}

TEST(StraightSkeleton, OffsetsLieInsideAtTheRightDistance) {
  std::mt19937_64 rng(7);
  const Polygon2 star = test::random_star_polygon(&rng, 10.0, 24);
  const StraightSkeleton s(star);
  for (double d : {0.5, 1.5, 3.0}) {
    for (const Polygon2& piece : s.offset(d)) {
      EXPECT_TRUE(nested_inside(piece, star));
      // every offset vertex is at least d from the boundary (1-Lipschitz roof), and
      // on it the nearest boundary edge is exactly d away
      double nearest = INFINITY;
      for (const Point2& v : piece) {
        double gap = INFINITY;
        for (std::size_t i = 0; i < star.size(); ++i) {
          gap = std::min(gap, point_segment_distance_m(v, star[i], star[(i + 1) % star.size()]));
        }
        EXPECT_GE(gap, d - 1e-9);
        nearest = std::min(nearest, gap);
      }
      EXPECT_NEAR(nearest, d, 1e-9);
    }
  }
}

TEST(StraightSkeleton, SplitEventGivesTwoPieces) {
  // a dumbbell: two 4 x 4 squares joined by a 1-wide neck; past 0.5 the neck is gone
  const Polygon2 dumbbell = {Point2(0, 0), Point2(4, 0), Point2(4, 1.5), Point2(6, 1.5), Point2(6, 0),
                             Point2(10, 0), Point2(10, 4), Point2(6, 4), Point2(6, 2.5), Point2(4, 2.5),
                             Point2(4, 4), Point2(0, 4)};
  const StraightSkeleton s(dumbbell);
  EXPECT_EQ(s.offset(0.25).size(), 1u);
  EXPECT_EQ(s.offset(1.0).size(), 2u);
  EXPECT_NEAR(s.vanish_time_m(), 2.0, 1e-12);
  EXPECT_TRUE(s.offset(2.5).empty());
}

}  // namespace
}  // namespace repose

namespace repose {
namespace {

TEST(StraightSkeleton, RoofTimeIsTheDistanceToTheNearestEdgeOfARectangle) {
  const StraightSkeleton s(test::rectangle_polygon(0, 0, 6, 2));
  EXPECT_NEAR(s.roof_time_m(Point2(3.0, 0.5)), 0.5, 1e-12);
  EXPECT_NEAR(s.roof_time_m(Point2(0.25, 1.0)), 0.25, 1e-12);
  EXPECT_NEAR(s.roof_time_m(Point2(5.5, 1.2)), 0.5, 1e-12);
  EXPECT_EQ(s.roof_time_m(Point2(7.0, 1.0)), 0.0);
}

TEST(StraightSkeleton, RoofTimeMatchesTheOffsets) {
  // a point on the polygon shrunk by d has roof time d
  std::mt19937_64 rng(11);
  const Polygon2 star = test::random_star_polygon(&rng, 10.0, 18);
  const StraightSkeleton s(star);
  for (double d : {0.4, 1.3, 2.2}) {
    for (const Polygon2& piece : s.offset(d)) {
      for (std::size_t i = 0; i < piece.size(); ++i) {
        const Point2 mid = 0.5 * (piece[i] + piece[(i + 1) % piece.size()]);
        EXPECT_NEAR(s.roof_time_m(mid), d, 1e-9);
      }
    }
  }
}

}  // namespace
}  // namespace repose
