#include "validation/liggghts/liggghts_motion.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "validation/liggghts/liggghts_script.h"

namespace repose {

long liggghts_steps(double time_s, double step_s) { return std::lround(time_s / step_s); }

Eigen::Vector3d position_at(const ObjectSpec& object, double t) {
  const auto& k = object.keyframes;
  REPOSE_DEMAND(!k.empty());
  if (t <= k.front().time_s) return k.front().pose.position_m;
  if (t >= k.back().time_s) return k.back().pose.position_m;
  for (std::size_t i = 0; i + 1 < k.size(); ++i) {
    if (t <= k[i + 1].time_s) {
      const double span = k[i + 1].time_s - k[i].time_s;
      const double a = span > 0 ? (t - k[i].time_s) / span : 1.0;
      return (1 - a) * k[i].pose.position_m + a * k[i + 1].pose.position_m;
    }
  }
  return k.back().pose.position_m;
}

bool rotates(const ObjectSpec& object) {
  const Eigen::Quaterniond q0 = object.keyframes.front().pose.orientation.normalized();
  for (const Keyframe& k : object.keyframes) {
    if (std::abs(std::abs(q0.dot(k.pose.orientation.normalized())) - 1.0) > 1e-12) return true;
  }
  return false;
}

Aabb swept_bounds(const ObjectSpec& object) {
  Aabb box;
  if (rotates(object)) {
    double reach = 0.0;
    for (Eigen::Index v = 0; v < object.body.V.rows(); ++v) reach = std::max(reach, object.body.V.row(v).norm());
    for (const Keyframe& key : object.keyframes) {
      box.extend(key.pose.position_m - Eigen::Vector3d::Constant(reach));
      box.extend(key.pose.position_m + Eigen::Vector3d::Constant(reach));
    }
    return box;
  }
  const Aabb body =
      bounding_box(transformed(object.body, Pose{Eigen::Vector3d::Zero(), object.keyframes.front().pose.orientation}));
  for (const Keyframe& key : object.keyframes) {
    box.extend(key.pose.position_m + body.min);
    box.extend(key.pose.position_m + body.max);
  }
  return box;
}

namespace {

// The constant-rate rotation carrying orientation a to b along the slerp
// (the shortest way): angle in [0, pi] about a unit world axis; angle 0 when they agree.
struct Turn {
  double angle_rad = 0.0;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
};

Turn turn_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  Eigen::Quaterniond d = b.normalized() * a.normalized().conjugate();
  if (d.w() < 0.0) d.coeffs() = -d.coeffs();
  const double s = d.vec().norm();
  Turn t;
  if (s <= 1e-15) return t;
  t.angle_rad = 2.0 * std::atan2(s, d.w());
  t.axis = d.vec() / s;
  return t;
}

// The times at which any object's velocity may change, within [0, duration].
std::vector<double> segment_times(const Scene& scene) {
  std::set<double> times = {0.0, scene.time.duration_s};
  for (const ObjectSpec& o : scene.objects) {
    for (const Keyframe& k : o.keyframes) {
      if (k.time_s > 0.0 && k.time_s < scene.time.duration_s) times.insert(k.time_s);
    }
  }
  return {times.begin(), times.end()};
}

// One object's move/mesh fixes for one segment: a linear velocity and, for a
// rotating object, a constant-rate rotation about the body origin's
// segment-start position. Returns their ids in the order they must be unfixed.
std::vector<std::string> write_segment_fixes(std::ostringstream& s, const ObjectSpec& o, std::size_t k,
                                             std::size_t seg, double t0, double t1, double span_s,
                                             const std::string& mesh_id) {
  const auto n = [](double v) { return liggghts_number(v); };
  const bool turning = rotates(o);
  const Pose a = turning ? o.pose_at(t0) : Pose{position_at(o, t0), Eigen::Quaterniond::Identity()};
  const Pose b = turning ? o.pose_at(t1) : Pose{position_at(o, t1), Eigen::Quaterniond::Identity()};
  const Eigen::Vector3d v = (b.position_m - a.position_m) / span_s;
  std::vector<std::string> fixes;
  if (!v.isZero(0.0)) {
    const std::string id = fmt::format("move{}_{}", k, seg);
    s << "fix " << id << " all move/mesh mesh " << mesh_id << " linear " << n(v.x()) << " " << n(v.y()) << " "
      << n(v.z()) << "\n";
    fixes.push_back(id);
  }
  const Turn turn = turning ? turn_between(a.orientation, b.orientation) : Turn{};
  if (turn.angle_rad > 0.0) {
    const std::string id = fmt::format("turn{}_{}", k, seg);
    const Eigen::Vector3d& p = a.position_m;
    s << "fix " << id << " all move/mesh mesh " << mesh_id << " rotate origin " << n(p.x()) << " " << n(p.y()) << " "
      << n(p.z()) << " axis " << n(turn.axis.x()) << " " << n(turn.axis.y()) << " " << n(turn.axis.z())
      << " period " << n(2.0 * std::numbers::pi * span_s / turn.angle_rad) << "\n";
    fixes.push_back(id);
  }
  return {fixes.rbegin(), fixes.rend()};
}

}  // namespace

// Keyframed motion: per object and segment a linear velocity and, for a
// rotating object, a constant-rate rotation (the slerp between keyframes)
// about the body origin. LIGGGHTS superposes move/mesh fixes on one mesh,
// each later one in the frame carried by the earlier ones: linear first,
// then rotate with its origin at the body origin's segment-start position
// (so the centre of rotation travels with the object); superposed fixes
// must be unfixed in reverse order. Checked against a real run in
// tests/validation/liggghts/rotating_mesh_test.cpp.
long write_motion(std::ostringstream& s, const Scene& scene, const DemSpec& dem,
                  const std::vector<std::string>& mesh_fix_ids) {
  REPOSE_DEMAND(mesh_fix_ids.size() == scene.objects.size());
  long total_steps = 0;
  const auto n = [](double v) { return liggghts_number(v); };
  const std::vector<double> times = segment_times(scene);
  for (std::size_t seg = 0; seg + 1 < times.size(); ++seg) {
    const long first = liggghts_steps(times[seg], dem.time_step_s);
    const long last = liggghts_steps(times[seg + 1], dem.time_step_s);
    if (last <= first) continue;
    const double span_s = static_cast<double>(last - first) * dem.time_step_s;
    std::vector<std::string> fixes;
    s << "# segment " << seg << ": t = " << n(times[seg]) << " .. " << n(times[seg + 1]) << " s\n";
    for (std::size_t k = 0; k < scene.objects.size(); ++k) {
      if (scene.objects[k].dynamic) continue;  // a free sphere: moved by LIGGGHTS itself (liggghts_free_body.h)
      const auto ids = write_segment_fixes(s, scene.objects[k], k, seg, times[seg], times[seg + 1], span_s,
                                           mesh_fix_ids[k]);
      fixes.insert(fixes.end(), ids.begin(), ids.end());
    }
    s << "run " << (last - first) << "\n";
    for (const std::string& id : fixes) s << "unfix " << id << "\n";
    total_steps = last;
  }
  return total_steps;
}

}  // namespace repose
