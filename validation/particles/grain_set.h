#pragma once
// Spherical grains as arrays (libigl style):
//   position_m: #G by 3 centres (m)
//   radius_m:   #G radii (m)
//   velocity_m_s: #G by 3 velocities (m/s), or empty when the source has none
// The common input of the observables, whichever solver made the grains.

#include <Eigen/Core>

#include "models/core/geometry/triangle_mesh.h"

namespace repose {

struct GrainSet {
  MatrixX3dR position_m;
  Eigen::VectorXd radius_m;
  MatrixX3dR velocity_m_s = MatrixX3dR(0, 3);  // empty: not known (a dump without vx vy vz)

  Eigen::Index size() const { return position_m.rows(); }
};

}  // namespace repose
