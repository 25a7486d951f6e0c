#pragma once
// The velocity of every point of a held object over one substep, which the
// material it lets go of keeps (span_motion.h, span_erosion.h): a bucket
// tipped in place turns, and the sand leaving its lip moves with the lip,
// not with the bucket's (still) centre. The pose turns about its position
// (x_world = orientation * x_body + position), so a point p moves at
// linear + angular x (p - centre).

#include <Eigen/Core>

#include "models/core/geometry/triangle_mesh.h"

namespace repose {

struct RigidVelocity {
  Eigen::Vector3d linear_m_s = Eigen::Vector3d::Zero();     // of the pose's position
  Eigen::Vector3d angular_rad_s = Eigen::Vector3d::Zero();  // about it
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();       // the pose's position at the substep's end

  Eigen::Vector3d at(const Eigen::Vector3d& point_m) const {
    return linear_m_s + angular_rad_s.cross(point_m - centre_m);
  }
};

// The constant velocity that takes `from` to `to` in dt_s (> 0): the
// shortest turn between the orientations, at a constant rate.
RigidVelocity rigid_velocity(const Pose& from, const Pose& to, double dt_s);

}  // namespace repose
