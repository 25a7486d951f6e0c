#include "validation/calibration/halton.h"

#include <vector>

#include <gtest/gtest.h>

namespace repose {
namespace {

TEST(Halton, RadicalInverseMirrorsTheDigits) {
  EXPECT_DOUBLE_EQ(radical_inverse(1, 2), 0.5);
  EXPECT_DOUBLE_EQ(radical_inverse(3, 2), 0.75);   // 11b -> 0.11b
  EXPECT_DOUBLE_EQ(radical_inverse(6, 2), 0.375);  // 110b -> 0.011b
  EXPECT_DOUBLE_EQ(radical_inverse(1, 3), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(radical_inverse(5, 3), 2.0 / 3.0 + 1.0 / 9.0);  // 12 in base 3 -> 0.21
}

TEST(Halton, SameSeedSamePointsOtherSeedOtherPoints) {
  const Halton a(3, 42), b(3, 42), c(3, 43);
  for (std::uint64_t i = 1; i < 20; ++i) {
    EXPECT_EQ(a.point(i), b.point(i));
    EXPECT_NE(a.point(i), c.point(i));
    for (const double u : a.point(i)) {
      EXPECT_GE(u, 0.0);
      EXPECT_LT(u, 1.0);
    }
  }
}

// Low discrepancy: 64 points put between 2 and 6 into each of 16 equal
// intervals of every axis (4 expected); the shift keeps that property.
TEST(Halton, PointsAreSpreadEvenly) {
  for (const std::uint64_t seed : {1u, 7u, 99u}) {
    const Halton h(2, seed);
    std::vector<std::vector<int>> counts(2, std::vector<int>(16, 0));
    for (std::uint64_t i = 1; i <= 64; ++i) {
      const auto p = h.point(i);
      for (int d = 0; d < 2; ++d) ++counts[d][static_cast<int>(p[d] * 16)];
    }
    for (const auto& axis : counts) {
      for (const int n : axis) {
        EXPECT_GE(n, 2);
        EXPECT_LE(n, 6);
      }
    }
  }
}

}  // namespace
}  // namespace repose
