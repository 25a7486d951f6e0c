#include "models/snow/snowfall_rate.h"

#include <cmath>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

SnowfallRate::SnowfallRate(double rate_m_s) : SnowfallRate(std::vector<SnowfallKeyframe>{{0.0, rate_m_s}}) {}

SnowfallRate::SnowfallRate(std::vector<SnowfallKeyframe> keyframes) : keyframes_(std::move(keyframes)) {
  if (keyframes_.empty()) throw InputError("snowfall rate: at least one keyframe is needed");
  for (std::size_t k = 0; k < keyframes_.size(); ++k) {
    const SnowfallKeyframe& f = keyframes_[k];
    if (!(std::isfinite(f.rate_m_s) && f.rate_m_s >= 0.0)) {
      throw InputError(fmt::format("snowfall rate: keyframes[{}].rate_m_s = {} is outside [0, inf)", k, f.rate_m_s));
    }
    if (!std::isfinite(f.time_s)) throw InputError(fmt::format("snowfall rate: keyframes[{}].time_s is not finite", k));
    if (k > 0 && !(f.time_s > keyframes_[k - 1].time_s)) {
      throw InputError(fmt::format("snowfall rate: keyframes[{}].time_s = {} does not increase", k, f.time_s));
    }
  }
}

double SnowfallRate::rate_m_s(double time_s) const {
  if (time_s <= keyframes_.front().time_s) return keyframes_.front().rate_m_s;
  if (time_s >= keyframes_.back().time_s) return keyframes_.back().rate_m_s;
  std::size_t k = 1;
  while (keyframes_[k].time_s < time_s) ++k;
  const SnowfallKeyframe& a = keyframes_[k - 1];
  const SnowfallKeyframe& b = keyframes_[k];
  const double u = (time_s - a.time_s) / (b.time_s - a.time_s);
  return a.rate_m_s + u * (b.rate_m_s - a.rate_m_s);
}

double SnowfallRate::cumulative_m(double time_s) const {
  const double t_first = keyframes_.front().time_s;
  if (time_s <= t_first) return (time_s - t_first) * keyframes_.front().rate_m_s;
  double sum = 0.0;
  for (std::size_t k = 1; k < keyframes_.size(); ++k) {
    const SnowfallKeyframe& a = keyframes_[k - 1];
    const SnowfallKeyframe& b = keyframes_[k];
    if (time_s <= a.time_s) return sum;
    const double t_end = std::min(time_s, b.time_s);
    sum += 0.5 * (a.rate_m_s + rate_m_s(t_end)) * (t_end - a.time_s);
  }
  if (time_s > keyframes_.back().time_s) sum += (time_s - keyframes_.back().time_s) * keyframes_.back().rate_m_s;
  return sum;
}

double SnowfallRate::depth_between_m(double t0_s, double t1_s) const {
  REPOSE_DEMAND(t0_s <= t1_s);
  return std::max(0.0, cumulative_m(t1_s) - cumulative_m(t0_s));
}

}  // namespace repose
