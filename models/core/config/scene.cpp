#include "models/core/config/scene.h"

#include <algorithm>
#include <cmath>

#include "models/core/base/error.h"

namespace repose {

Pose ObjectSpec::pose_at(double time_s) const {
  REPOSE_DEMAND(!keyframes.empty());
  if (time_s <= keyframes.front().time_s) return keyframes.front().pose;
  if (time_s >= keyframes.back().time_s) return keyframes.back().pose;
  // the first keyframe later than t; the one before it starts the segment
  const auto next = std::upper_bound(keyframes.begin(), keyframes.end(), time_s,
                                     [](double t, const Keyframe& k) { return t < k.time_s; });
  const Keyframe& b = *next;
  const Keyframe& a = *(next - 1);
  const double u = (time_s - a.time_s) / (b.time_s - a.time_s);
  Pose p;
  p.position_m = (1.0 - u) * a.pose.position_m + u * b.pose.position_m;
  p.orientation = a.pose.orientation.slerp(u, b.pose.orientation).normalized();
  return p;
}

int TimeSpec::step_count() const {
  REPOSE_DEMAND(step_s > 0.0 && duration_s > 0.0);
  // a duration that is a whole number of steps up to round-off gives that number
  return static_cast<int>(std::ceil(duration_s / step_s - 1e-9));
}

}  // namespace repose
