#pragma once
// Snowfall directions (the snow paper, 2.2.2): falling snow does not move in
// straight lines, so the probability that snow reaches a point is taken over
// many directions drawn from a 2-D normal distribution around the main
// direction.
//
// Parametrisation (the paper does not give one): a direction is the unit
// vector snow travels along. The main direction is tilted by tilt_rad from
// straight down towards the azimuth azimuth_rad (from +x towards +y). A draw
// takes two independent normal angles (a, b) ~ N(0, spread^2) along the two
// unit vectors perpendicular to the main direction (towards more tilt, and
// horizontal) and rotates the main direction by the angle |(a, b)| about the
// axis perpendicular to (a, b): the 2-D normal lives in the tangent plane of
// the sphere of directions, so spread is an angle whatever the main direction.
//
// Departure: a draw travelling upwards or nearly horizontally (more than
// kMaxFallTiltRad from straight down) cannot bring snow from above and is
// drawn again (rejection), so a very large spread tends to a distribution
// over the lower hemisphere instead of wrapping round the sphere.
//
// Determinism: the normals come from Box-Muller over the raw 64-bit output of
// the generator passed in, not std::normal_distribution, whose algorithm
// differs between standard libraries: same seed, same bits, everywhere.

#include <random>
#include <vector>

#include <Eigen/Core>

namespace repose {

inline constexpr double kMaxFallTiltRad = 1.4835298641951802;  // 85 deg

struct SnowfallDirection {
  double tilt_rad = 0.0;     // from straight down, [0, pi/2)
  double azimuth_rad = 0.0;  // towards which snow drifts, from +x towards +y
};

// The unit vector snow travels along (z < 0).
Eigen::Vector3d travel_vector(const SnowfallDirection& direction);

// `count` directions around `main` (tilt <= kMaxFallTiltRad), spread_rad >= 0.
// spread 0 gives `count` copies of the main direction.
std::vector<Eigen::Vector3d> draw_snowfall_directions(const SnowfallDirection& main, double spread_rad, int count,
                                                      std::mt19937_64* rng);

}  // namespace repose
