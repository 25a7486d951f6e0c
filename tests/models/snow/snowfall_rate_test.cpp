#include "models/snow/snowfall_rate.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"

namespace repose {
namespace {

TEST(SnowfallRate, ConstantRateIntegratesToRateTimesDuration) {
  const SnowfallRate m(2e-3);
  EXPECT_DOUBLE_EQ(m.depth_between_m(0.0, 5.0), 1e-2);
  EXPECT_DOUBLE_EQ(m.depth_between_m(-3.0, -1.0), 4e-3);  // held before the first keyframe
}

TEST(SnowfallRate, KeyframedIntegralMatchesAFineMidpointSum) {
  const SnowfallRate m({{0.0, 0.0}, {2.0, 4e-3}, {3.0, 1e-3}});
  const double t0 = -0.5, t1 = 4.5;
  const int n = 200000;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) sum += m.rate_m_s(t0 + (k + 0.5) * (t1 - t0) / n) * (t1 - t0) / n;
  // exact: 0 before 0, 4e-3 on [0, 2], 2.5e-3 on [2, 3], 1.5e-3 after 3
  EXPECT_NEAR(m.depth_between_m(t0, t1), 4e-3 + 2.5e-3 + 1.5e-3, 1e-15);
  EXPECT_NEAR(sum, m.depth_between_m(t0, t1), 1e-9);
  // additive over a split inside a piece
  EXPECT_NEAR(m.depth_between_m(t0, 2.7) + m.depth_between_m(2.7, t1), m.depth_between_m(t0, t1), 1e-16);
}

TEST(SnowfallRate, RefusesBadKeyframesNamingThem) {
  EXPECT_THROW(SnowfallRate(std::vector<SnowfallKeyframe>{}), InputError);
  try {
    SnowfallRate({{0.0, 1e-3}, {0.0, 1e-3}});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("keyframes[1].time_s"), std::string::npos) << e.what();
  }
  try {
    SnowfallRate(-1.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("rate_m_s"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace repose
