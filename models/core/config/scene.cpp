#include "models/core/config/scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

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

double ObjectSpec::volume_m3() const {
  const double pi = std::numbers::pi;
  const double s = scale.prod();
  switch (shape) {
    case Shape::kSphere: return s * 4.0 / 3.0 * pi * radius_m * radius_m * radius_m;
    case Shape::kBox: return s * 8.0 * half_extents_m.prod();
    case Shape::kCylinder: return s * pi * radius_m * radius_m * 2.0 * half_height_m;
    case Shape::kCapsule:
      return s * (pi * radius_m * radius_m * 2.0 * half_height_m + 4.0 / 3.0 * pi * radius_m * radius_m * radius_m);
    case Shape::kMesh: break;
  }
  return signed_volume_m3(body);
}

double ObjectSpec::mass_kg() const {
  REPOSE_DEMAND(dynamic.has_value());
  return dynamic->mass_kg > 0.0 ? dynamic->mass_kg : dynamic->density_kg_m3 * volume_m3();
}

int TimeSpec::step_count() const {
  REPOSE_DEMAND(step_s > 0.0 && duration_s > 0.0);
  // a duration that is a whole number of steps up to round-off gives that number
  return static_cast<int>(std::ceil(duration_s / step_s - 1e-9));
}

}  // namespace repose
