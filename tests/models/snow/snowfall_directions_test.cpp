#include "models/snow/snowfall_directions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace repose {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(SnowfallDirections, ZeroSpreadGivesTheMainDirection) {
  std::mt19937_64 rng(3);
  const SnowfallDirection main{30 * kDeg, 45 * kDeg};
  for (const Eigen::Vector3d& d : draw_snowfall_directions(main, 0.0, 5, &rng)) {
    EXPECT_NEAR((d - travel_vector(main)).norm(), 0.0, 1e-15);
  }
}

TEST(SnowfallDirections, SameSeedSameBits) {
  std::mt19937_64 a(11), b(11);
  const auto da = draw_snowfall_directions({0.2, 1.0}, 0.3, 100, &a);
  const auto db = draw_snowfall_directions({0.2, 1.0}, 0.3, 100, &b);
  ASSERT_EQ(da.size(), 100u);
  for (std::size_t k = 0; k < da.size(); ++k) EXPECT_EQ(da[k], db[k]);
}

// The deviation angle is |(a, b)| with a, b ~ N(0, s^2): its mean square is
// 2 s^2, and the deviations are centred on the main direction.
TEST(SnowfallDirections, DeviationsFollowTheTwoDimensionalNormal) {
  const double spread = 5 * kDeg;
  const SnowfallDirection main{20 * kDeg, -60 * kDeg};
  const Eigen::Vector3d t = travel_vector(main);
  std::mt19937_64 rng(5);
  const int n = 20000;
  const auto dirs = draw_snowfall_directions(main, spread, n, &rng);
  double mean_square = 0.0;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& d : dirs) {
    const double angle = std::acos(std::clamp(d.dot(t), -1.0, 1.0));
    mean_square += angle * angle / n;
    mean += d / n;
  }
  EXPECT_NEAR(mean_square / (2 * spread * spread), 1.0, 0.03);  // 4 sigma of the estimate is ~0.03
  EXPECT_LT(std::acos(std::clamp(mean.normalized().dot(t), -1.0, 1.0)), 0.002);
}

TEST(SnowfallDirections, EveryDirectionFallsEvenForAHugeSpread) {
  std::mt19937_64 rng(7);
  for (double spread : {1.0, std::numbers::pi}) {
    for (const Eigen::Vector3d& d : draw_snowfall_directions({80 * kDeg, 0.0}, spread, 2000, &rng)) {
      ASSERT_TRUE(d.allFinite());
      EXPECT_NEAR(d.norm(), 1.0, 1e-12);
      EXPECT_GE(-d.z(), std::cos(kMaxFallTiltRad) - 1e-12);
    }
  }
}

}  // namespace
}  // namespace repose
