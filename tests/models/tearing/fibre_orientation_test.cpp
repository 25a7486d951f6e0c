// The fibre orientation measured by the structure tensor: exact on stripes,
// and the drawn fibres follow the grain direction.
#include "models/tearing/fibre_orientation.h"

#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "models/tearing/fibre_image.h"

namespace repose {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Difference of two orientations (period pi), in [0, pi/2].
double orientation_gap(double a, double b) {
  const double d = std::fmod(std::abs(a - b), std::numbers::pi);
  return std::min(d, std::numbers::pi - d);
}

TEST(FibreOrientation, StripesAreMeasuredAlongTheirLength) {
  for (const double angle_deg : {0.0, 20.0, 45.0, 90.0, -70.0}) {
    const double a = angle_deg * kDeg;
    ArrayXXdR image(128, 128);
    for (int r = 0; r < 128; ++r) {
      for (int c = 0; c < 128; ++c) image(r, c) = std::sin(0.4 * (-c * std::sin(a) + r * std::cos(a)));
    }
    const FibreOrientation o = measure_fibre_orientation(image);
    EXPECT_LT(orientation_gap(o.angle_rad, a), 0.5 * kDeg) << angle_deg;
    EXPECT_GT(o.coherence, 0.95) << angle_deg;
  }
}

TEST(FibreOrientation, DrawnFibresFollowTheGrainDirection) {
  for (const double grain_deg : {0.0, 30.0, 90.0, -60.0}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      FibreOptions options;
      options.grain_direction_rad = grain_deg * kDeg;
      std::mt19937_64 rng(seed);
      const FibreImages images = draw_fibre_images(options, 0.05, 0.05, rng);
      const FibreOrientation o = measure_fibre_orientation(images.composite);
      EXPECT_LT(orientation_gap(o.angle_rad, options.grain_direction_rad), 4.0 * kDeg)
          << "grain " << grain_deg << " deg, seed " << seed << ": measured " << o.angle_rad / kDeg;
      EXPECT_GT(o.coherence, 0.3) << "grain " << grain_deg << " deg, seed " << seed;
    }
  }
}

TEST(FibreOrientation, NoSpreadIsMoreCoherentThanFullSpreadWhichHasNoDirection) {
  FibreOptions aligned, random;
  aligned.grain_spread_rad = 0.0;
  random.grain_spread_rad = std::numbers::pi / 2;
  std::mt19937_64 rng_a(9), rng_r(9);
  const double aligned_coherence = measure_fibre_orientation(draw_fibre_images(aligned, 0.05, 0.05, rng_a).composite).coherence;
  const double random_coherence = measure_fibre_orientation(draw_fibre_images(random, 0.05, 0.05, rng_r).composite).coherence;
  EXPECT_GT(aligned_coherence, 0.6);
  EXPECT_LT(random_coherence, 0.1);
}

}  // namespace
}  // namespace repose
