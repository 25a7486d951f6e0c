#pragma once
// The snowfall rate M(t) of the snow paper's eq. (1), S_a(T) = integral_0^T
// P_a M(t) dt: the depth of snow per second (m/s) that falls on open,
// unshadowed ground (P = 1). Constant (one keyframe) or keyframed: linear
// between keyframes, held at the first and last value outside them.

#include <vector>

namespace repose {

struct SnowfallKeyframe {
  double time_s = 0.0;
  double rate_m_s = 0.0;  // >= 0
};

class SnowfallRate {
 public:
  // A constant rate.
  explicit SnowfallRate(double rate_m_s = 0.0);
  // Keyframes with strictly increasing times and rates >= 0 (InputError
  // otherwise, naming the keyframe); at least one.
  explicit SnowfallRate(std::vector<SnowfallKeyframe> keyframes);

  double rate_m_s(double time_s) const;
  // Exact integral of M over [t0, t1] (m), t0 <= t1: the rate is piecewise
  // linear, so each piece is a trapezoid.
  double depth_between_m(double t0_s, double t1_s) const;
  const std::vector<SnowfallKeyframe>& keyframes() const { return keyframes_; }

 private:
  // integral of M from the first keyframe's time to t (negative before it)
  double cumulative_m(double time_s) const;

  std::vector<SnowfallKeyframe> keyframes_;
};

}  // namespace repose
