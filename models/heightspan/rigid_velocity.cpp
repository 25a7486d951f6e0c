#include "models/heightspan/rigid_velocity.h"

#include <Eigen/Geometry>

#include "models/core/base/error.h"

namespace repose {

RigidVelocity rigid_velocity(const Pose& from, const Pose& to, double dt_s) {
  REPOSE_DEMAND(dt_s > 0.0);
  // AngleAxis of a quaternion takes the shorter way round: its angle is in [0, pi]
  const Eigen::AngleAxisd turn(to.orientation * from.orientation.conjugate());
  return {(to.position_m - from.position_m) / dt_s, turn.axis() * (turn.angle() / dt_s), to.position_m};
}

}  // namespace repose
