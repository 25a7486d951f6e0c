#include "models/core/geometry/height_field.h"

#include <gtest/gtest.h>

#include <random>

namespace repose {
namespace {

HeightField random_field(const Grid& g, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  HeightField f(g);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) f.at(i, j) = u(rng);
  return f;
}

TEST(HeightField, VolumeIsSumTimesCellArea) {
  HeightField f(Grid{4, 3, 0.5, 0, 0}, 2.0);
  EXPECT_DOUBLE_EQ(f.volume_m3(), 12 * 2.0 * 0.25);
}

TEST(HeightField, BilinearSampleIsExactOnAPlane) {
  Grid g{8, 6, 0.1, -0.4, -0.3};
  HeightField f(g);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) f.at(i, j) = 0.5 + 2.0 * g.centre_x(i) - 1.0 * g.centre_y(j);
  for (double x : {-0.3, -0.01, 0.17, 0.3})
    for (double y : {-0.2, 0.0, 0.21})
      EXPECT_NEAR(f.sample(x, y), 0.5 + 2.0 * x - y, 1e-12) << x << "," << y;
}

TEST(HeightField, ConservativeResampleConservesVolumeDownAndUp) {
  Grid fine{64, 48, 0.01, 0, 0};
  const HeightField f = random_field(fine, 7);
  for (int factor : {2, 3, 4}) {
    Grid coarse = fine.coarsened(factor);
    const HeightField c = resample_conservative(f, coarse);
    EXPECT_NEAR(c.volume_m3(), f.volume_m3(), 1e-12 * f.volume_m3()) << factor;
    const HeightField back = resample_conservative(c, fine);
    // coarse cells reaching past the fine grid lose their outside part; factor 2, 4 divide evenly
    if (64 % factor == 0 && 48 % factor == 0) {
      EXPECT_NEAR(back.volume_m3(), f.volume_m3(), 1e-12 * f.volume_m3());
    }
  }
}

TEST(HeightField, ConservativeResampleOfConstantIsConstant) {
  HeightField f(Grid{10, 10, 0.1, 0, 0}, 3.0);
  const HeightField c = resample_conservative(f, Grid{7, 7, 1.0 / 7.0, 0, 0});
  EXPECT_NEAR((c.heights() - 3.0).abs().maxCoeff(), 0.0, 1e-12);
}

}  // namespace
}  // namespace repose
