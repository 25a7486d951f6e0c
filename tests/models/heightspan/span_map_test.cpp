#include "models/heightspan/span_map.h"

#include <gtest/gtest.h>

#include "heightspan_fixtures.h"

namespace repose {
namespace {

Grid grid(int n, double h, double origin) { return Grid{n, n, h, origin, origin}; }

double solid_volume_m3(const SpanMap& map) {
  double v = 0.0;
  for (const Span& s : map.spans) v += s.top_m - s.bottom_m;
  return v * map.grid.cell_area_m2();
}

TEST(SpanMap, BoxGivesOneSpanPerCoveredCell) {
  // a 2 x 2 x 1 cm box centred at (0, 0, 0.05) on 1 mm cells: 20 x 20 cells, no edge on a centre
  const TriangleMesh box = transformed(make_box({0.01, 0.01, 0.005}), Pose{{0, 0, 0.05}, Eigen::Quaterniond::Identity()});
  const SpanMap map = peel_spans(box, grid(40, 0.001, -0.02));
  int covered = 0;
  for (std::int64_t c = 0; c < 1600; ++c) {
    ASSERT_LE(map.count(c), 1);
    if (map.count(c) == 0) continue;
    ++covered;
    EXPECT_NEAR(map.begin(c)[0].bottom_m, 0.045, 1e-12);
    EXPECT_NEAR(map.begin(c)[0].top_m, 0.055, 1e-12);
  }
  EXPECT_EQ(covered, 400);
}

TEST(SpanMap, CentresOnSharedEdgesAreCountedOnce) {
  // box edges and its triangles' diagonals pass through cell centres: every
  // column must still close (one span, right height), never two or a half
  const TriangleMesh box = make_box({0.0105, 0.0105, 0.01});
  const SpanMap map = peel_spans(box, grid(42, 0.001, -0.021));
  for (std::int64_t c = 0; c < 42 * 42; ++c) {
    ASSERT_LE(map.count(c), 1) << c;
    if (map.count(c) == 1) {
      EXPECT_NEAR(map.begin(c)[0].top_m - map.begin(c)[0].bottom_m, 0.02, 1e-12) << c;
    }
  }
}

TEST(SpanMap, StackedBodiesGiveOrderedSpansAndOverlapsMerge) {
  const TriangleMesh low = make_box({0.01, 0.01, 0.005});
  const TriangleMesh high = transformed(make_box({0.01, 0.01, 0.005}), Pose{{0, 0, 0.03}, Eigen::Quaterniond::Identity()});
  const TriangleMesh overlapping = transformed(make_box({0.005, 0.005, 0.005}), Pose{{0, 0, 0.004}, Eigen::Quaterniond::Identity()});
  const SpanMap map = peel_spans(merged(merged(low, high), overlapping), grid(10, 0.004, -0.02));
  const std::int64_t centre = 5 * 10 + 5;
  ASSERT_EQ(map.count(centre), 2);
  EXPECT_NEAR(map.begin(centre)[0].bottom_m, -0.005, 1e-12);
  EXPECT_NEAR(map.begin(centre)[0].top_m, 0.009, 1e-12);  // the overlapping box reaches higher
  EXPECT_NEAR(map.begin(centre)[1].bottom_m, 0.025, 1e-12);
  EXPECT_NEAR(map.begin(centre)[1].top_m, 0.035, 1e-12);
}

TEST(SpanMap, SphereVolumeConvergesUnderRefinement) {
  const TriangleMesh sphere = make_sphere(0.02, 64);
  const double exact = signed_volume_m3(sphere);
  auto error = [&](int n) {
    return std::abs(solid_volume_m3(peel_spans(sphere, grid(n, 0.05 / n, -0.025))) - exact) / exact;
  };
  const double coarse = error(8), fine = error(64);
  EXPECT_LT(fine, coarse);
  EXPECT_LT(fine, 0.002);
}

TEST(SpanMap, BucketFloorAndWallsAreSpansAndItsCavityIsOpen) {
  const SpanMap map = peel_spans(testing::bucket_mesh(), grid(40, 0.0025, -0.05));
  int i, j;
  ASSERT_TRUE(map.cell_at(0.0, 0.0, &i, &j));
  const std::int64_t centre = map.cell(i, j);
  ASSERT_EQ(map.count(centre), 1);
  EXPECT_NEAR(map.begin(centre)[0].bottom_m, -0.025, 1e-12);
  EXPECT_NEAR(map.begin(centre)[0].top_m, -0.020, 1e-12);  // the floor, 5 mm thick
  ASSERT_TRUE(map.cell_at(0.0385, 0.0, &i, &j));
  const std::int64_t wall = map.cell(i, j);
  ASSERT_EQ(map.count(wall), 1);
  EXPECT_NEAR(map.begin(wall)[0].top_m, 0.025, 1e-12);  // the rim
  EXPECT_NEAR(solid_volume_m3(map), signed_volume_m3(testing::bucket_mesh()), 0.05 * signed_volume_m3(testing::bucket_mesh()));
}

TEST(SpanMap, SpanUnderAndOverflow) {
  SpanMap map;
  map.grid = Grid{1, 1, 0.01, 0, 0};
  map.first = {0, 2};
  map.spans = {{0.0, 0.01, 0.0}, {0.02, 0.03, 0.0}};
  EXPECT_EQ(span_under(map, 0, -0.01), -1);
  EXPECT_EQ(span_under(map, 0, 0.005), 0);   // inside the lower
  EXPECT_EQ(span_under(map, 0, 0.015), 0);   // on it
  EXPECT_EQ(span_under(map, 0, 0.025), 1);
  map.spans[0].material_m = 0.015;           // reaches 5 mm into the upper span
  EXPECT_NEAR(push_overflow_up(&map, 0), 0.005, 1e-15);
  EXPECT_NEAR(map.spans[0].level_m(), 0.02, 1e-15);
  EXPECT_NEAR(map.spans[1].material_m, 0.005, 1e-15);
  EXPECT_NEAR(map.material_m3(), 0.015 * 1e-4, 1e-18);
}

}  // namespace
}  // namespace repose
