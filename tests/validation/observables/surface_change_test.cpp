#include "validation/observables/surface_change.h"

#include <cmath>

#include <gtest/gtest.h>

namespace repose {
namespace {

const Grid kGrid{20, 16, 0.005, 0.0, 0.0};

// A flat surface at 2 cm with an imprint of `depth` within `radius` of
// (x0, y0) and a ring heaped by `rim` just outside it.
HeightField imprinted(double x0, double y0, double radius, double depth, double rim) {
  HeightField f(kGrid, 0.02);
  for (int j = 0; j < kGrid.ny; ++j) {
    for (int i = 0; i < kGrid.nx; ++i) {
      const double d = std::hypot(kGrid.centre_x(i) - x0, kGrid.centre_y(j) - y0);
      if (d < radius) f.at(i, j) -= depth;
      else if (d < radius + 0.01) f.at(i, j) += rim;
    }
  }
  return f;
}

TEST(SurfaceChange, ScoresAgainstDoingNothingAndAnExactModel) {
  const HeightField initial(kGrid, 0.02);
  const HeightField reference = imprinted(0.05, 0.04, 0.015, 0.004, 0.001);
  const ChangeScores exact = score_change(initial, reference, reference, std::nullopt);
  EXPECT_EQ(exact.rmse_m, 0.0);
  EXPECT_EQ(exact.r2, 1.0);
  EXPECT_EQ(exact.skill, 1.0);
  const ChangeScores nothing = score_change(initial, initial, reference, std::nullopt);
  EXPECT_DOUBLE_EQ(nothing.rmse_m, nothing.rmse_nothing_m);
  EXPECT_NEAR(nothing.skill, 0.0, 1e-15);
  EXPECT_LT(nothing.r2, 0.0);  // Δh = 0 misses even the mean change
  // half the change: RMSE is half of doing nothing's, skill 1/2
  HeightField half = initial;
  half.heights() = 0.5 * (initial.heights() + reference.heights());
  const ChangeScores h = score_change(initial, half, reference, std::nullopt);
  EXPECT_NEAR(h.rmse_m, 0.5 * h.rmse_nothing_m, 1e-15);
  EXPECT_NEAR(h.skill, 0.5, 1e-12);
  EXPECT_GT(h.r2, 0.0);
  EXPECT_LT(h.r2, 1.0);
}

// Two seeds whose Δh are a common change ± e: each differs from the other
// (the mean of the others when there are two) by 2e everywhere.
TEST(SurfaceChange, NoiseFloorOfTwoSeedsIsTheirDifference) {
  const double e = 0.0003;
  const HeightField initial(kGrid, 0.02);
  HeightField a = imprinted(0.05, 0.04, 0.015, 0.004, 0.001), b = a;
  a.heights() += e;
  b.heights() -= e;
  const auto floor = noise_floor({initial, initial}, {a, b}, std::nullopt);
  ASSERT_TRUE(floor.has_value());
  EXPECT_EQ(floor->seeds, 2);
  EXPECT_NEAR(floor->rmse_m, 2 * e, 1e-15);
  EXPECT_NEAR(floor->pair_rmse_m, 2 * e, 1e-15);
  EXPECT_LT(floor->r2, 1.0);
  EXPECT_FALSE(noise_floor({initial}, {a}, std::nullopt).has_value());
  // identical seeds: no noise at all
  const auto same = noise_floor({initial, initial, initial}, {a, a, a}, std::nullopt);
  EXPECT_EQ(same->rmse_m, 0.0);
  EXPECT_EQ(same->r2, 1.0);
}

TEST(SurfaceChange, FeaturesOfAnImprintAndItsRim) {
  const double x0 = 0.0525, y0 = 0.0375, radius = 0.0125, depth = 0.004, rim = 0.001;
  const HeightField initial(kGrid, 0.02);
  const HeightField f = imprinted(x0, y0, radius, depth, rim);
  const ChangeFeatures c = change_features(initial, f, std::nullopt);
  EXPECT_NEAR(c.depth_m, depth, 1e-15);
  EXPECT_NEAR(c.height_m, rim, 1e-15);
  EXPECT_LT(std::hypot(c.depth_x_m - x0, c.depth_y_m - y0), radius);
  EXPECT_GT(c.rim_distance_m, radius - kGrid.cell_size_m);
  // 5 cells (centres within 12.5 mm of the centre along an axis) across
  EXPECT_NEAR(c.trench_width_m, 5 * kGrid.cell_size_m, 1e-12);
  // volumes: the cells' count times their change
  double dug = 0, heaped = 0;
  for (int j = 0; j < kGrid.ny; ++j) {
    for (int i = 0; i < kGrid.nx; ++i) {
      const double dh = f.at(i, j) - 0.02;
      (dh < 0 ? dug : heaped) += std::abs(dh) * kGrid.cell_size_m * kGrid.cell_size_m;
    }
  }
  EXPECT_NEAR(c.dug_m3, dug, 1e-18);
  EXPECT_NEAR(c.heaped_m3, heaped, 1e-18);
  EXPECT_GT(c.dug_m3, 0.0);
  // nothing changed: no depth, no width
  const ChangeFeatures none = change_features(initial, initial, std::nullopt);
  EXPECT_EQ(none.depth_m, 0.0);
  EXPECT_EQ(none.trench_width_m, 0.0);
}

TEST(SurfaceChange, MeanFieldAveragesCellByCell) {
  HeightField a(kGrid, 0.01), b(kGrid, 0.03);
  b.at(3, 4) = 0.05;
  const HeightField m = mean_field({a, b});
  EXPECT_DOUBLE_EQ(m.at(0, 0), 0.02);
  EXPECT_DOUBLE_EQ(m.at(3, 4), 0.03);
}

}  // namespace
}  // namespace repose
