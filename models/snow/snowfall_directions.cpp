#include "models/snow/snowfall_directions.h"

#include <cmath>
#include <numbers>

#include "models/core/base/error.h"

namespace repose {

namespace {

// Uniform in (0, 1) from the top 53 bits, never 0 (log(0) in Box-Muller).
double uniform_open(std::mt19937_64* rng) {
  return (static_cast<double>((*rng)() >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

// Two independent standard normals (Box-Muller).
Eigen::Vector2d standard_normal_pair(std::mt19937_64* rng) {
  const double r = std::sqrt(-2.0 * std::log(uniform_open(rng)));
  const double phi = 2.0 * std::numbers::pi * uniform_open(rng);
  return {r * std::cos(phi), r * std::sin(phi)};
}

}  // namespace

Eigen::Vector3d travel_vector(const SnowfallDirection& d) {
  return {std::sin(d.tilt_rad) * std::cos(d.azimuth_rad), std::sin(d.tilt_rad) * std::sin(d.azimuth_rad),
          -std::cos(d.tilt_rad)};
}

std::vector<Eigen::Vector3d> draw_snowfall_directions(const SnowfallDirection& main, double spread_rad, int count,
                                                      std::mt19937_64* rng) {
  REPOSE_DEMAND(count >= 0 && spread_rad >= 0.0 && main.tilt_rad >= 0.0 && main.tilt_rad <= kMaxFallTiltRad);
  const Eigen::Vector3d t = travel_vector(main);
  // orthonormal to t for every tilt: d t / d tilt, and the horizontal perpendicular
  const Eigen::Vector3d e1(std::cos(main.tilt_rad) * std::cos(main.azimuth_rad),
                           std::cos(main.tilt_rad) * std::sin(main.azimuth_rad), std::sin(main.tilt_rad));
  const Eigen::Vector3d e2(-std::sin(main.azimuth_rad), std::cos(main.azimuth_rad), 0.0);
  const double min_fall = std::cos(kMaxFallTiltRad);
  std::vector<Eigen::Vector3d> out;
  out.reserve(static_cast<std::size_t>(count));
  // acceptance is at least ~1/3 for any spread; the cap only guards the loop
  const long long max_draws = 1000LL * count + 1000;
  for (long long draws = 0; static_cast<int>(out.size()) < count; ++draws) {
    REPOSE_DEMAND(draws < max_draws);
    const Eigen::Vector2d ab = spread_rad * standard_normal_pair(rng);
    const double angle = ab.norm();
    Eigen::Vector3d d = t;
    if (angle > 0.0) d = std::cos(angle) * t + std::sin(angle) * (ab.x() * e1 + ab.y() * e2) / angle;
    if (-d.z() >= min_fall) out.push_back(d.normalized());
  }
  return out;
}

}  // namespace repose
