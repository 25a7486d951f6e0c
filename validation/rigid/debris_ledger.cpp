#include "validation/rigid/debris_ledger.h"

#include "models/core/base/error.h"

namespace repose {

DebrisLedger::DebrisLedger(const std::vector<DebrisJoint>& joints, std::size_t part_count)
    : broken_(joints.size(), false), joint_force_n_(joints.size(), 0.0),
      part_force_n_(part_count, Eigen::Vector3d::Zero()) {
  for (const DebrisJoint& j : joints) break_force_n_.push_back(j.break_force_n);
}

void DebrisLedger::begin_step() {
  std::fill(joint_force_n_.begin(), joint_force_n_.end(), 0.0);
  std::fill(part_force_n_.begin(), part_force_n_.end(), Eigen::Vector3d::Zero());
}

bool DebrisLedger::record_joint(std::size_t k, double force_n) {
  REPOSE_DEMAND(!broken_.at(k));
  joint_force_n_[k] = force_n;
  if (force_n > break_force_n_[k]) broken_[k] = true;
  return broken_[k];
}

}  // namespace repose
