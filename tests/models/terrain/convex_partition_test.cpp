#include "models/terrain/convex_partition.h"

#include <gtest/gtest.h>

#include <random>

#include "models/terrain/edge_event.h"
#include "tests/models/terrain/terrain_fixtures.h"

namespace repose {
namespace {

bool is_convex(const Polygon2& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (interior_angle_rad(p, i) > std::numbers::pi + 1e-12) return false;
  }
  return true;
}

// Area of the intersection of two convex counter-clockwise polygons (Sutherland-Hodgman).
double overlap_area_m2(const Polygon2& subject, const Polygon2& clip) {
  Polygon2 out = subject;
  for (std::size_t i = 0; i < clip.size() && !out.empty(); ++i) {
    const Point2 a = clip[i], b = clip[(i + 1) % clip.size()];
    auto side = [&](const Point2& p) { return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x()); };
    Polygon2 in = out;
    out.clear();
    for (std::size_t k = 0; k < in.size(); ++k) {
      const Point2 p = in[k], q = in[(k + 1) % in.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0) out.push_back(p);
      if ((sp >= 0) != (sq >= 0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
    }
  }
  return out.size() < 3 ? 0.0 : std::abs(signed_area_m2(out));
}

void expect_tiles(const Polygon2& footprint, const std::vector<Polygon2>& pieces, const std::string& what) {
  double area = 0.0;
  for (const Polygon2& p : pieces) {
    EXPECT_TRUE(is_convex(p)) << what;
    EXPECT_GT(signed_area_m2(p), 0.0) << what;
    area += signed_area_m2(p);
  }
  EXPECT_NEAR(area, signed_area_m2(footprint), 1e-9 * signed_area_m2(footprint)) << what;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    for (std::size_t j = i + 1; j < pieces.size(); ++j) {
      EXPECT_LT(overlap_area_m2(pieces[i], pieces[j]), 1e-9 * signed_area_m2(footprint)) << what;
    }
  }
}

TEST(ConvexPartition, LFootprintSplitsIntoTwoRectangles) {
  const Polygon2 l = test::l_polygon();
  const std::vector<Polygon2> pieces = convex_partition(l);
  EXPECT_EQ(pieces.size(), 2u);
  for (const Polygon2& p : pieces) EXPECT_EQ(p.size(), 4u);
  expect_tiles(l, pieces, "L");
}

TEST(ConvexPartition, ConvexFootprintStaysWhole) {
  const Polygon2 r = test::rectangle_polygon(0, 0, 12, 8);
  EXPECT_EQ(convex_partition(r).size(), 1u);
}

TEST(ConvexPartition, RandomConcaveFootprintsAreTiled) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    std::mt19937_64 rng(seed);
    const Polygon2 star = counter_clockwise(test::random_star_polygon(&rng, 15.0, 12));
    expect_tiles(star, convex_partition(star), "seed " + std::to_string(seed));
  }
}

TEST(ConvexPartition, LargeFootprintUsesTheApproximation) {
  std::mt19937_64 rng(5);
  const Polygon2 star = counter_clockwise(test::random_star_polygon(&rng, 15.0, 80));
  ASSERT_GT(star.size(), kOptimalPartitionMaxVertices);
  expect_tiles(star, convex_partition(star), "80-gon");
}

}  // namespace
}  // namespace repose
