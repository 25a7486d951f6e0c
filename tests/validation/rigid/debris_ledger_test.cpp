#include "validation/rigid/debris_ledger.h"

#include <gtest/gtest.h>

namespace repose {
namespace {

std::vector<DebrisJoint> two_joints() {
  std::vector<DebrisJoint> joints(2);
  joints[0].break_force_n = 100.0;
  joints[1].break_force_n = 1000.0;
  return joints;
}

TEST(DebrisLedger, AJointBreaksAboveItsForceReportingItThenNothing) {
  DebrisLedger ledger(two_joints(), 1);
  ledger.begin_step();
  EXPECT_FALSE(ledger.record_joint(0, 100.0));  // at the threshold: holds
  EXPECT_FALSE(ledger.record_joint(1, 500.0));
  ledger.begin_step();
  EXPECT_TRUE(ledger.record_joint(0, 150.0));
  EXPECT_FALSE(ledger.record_joint(1, 150.0));
  EXPECT_EQ(ledger.joint_forces_n()[0], 150.0);  // the force that broke it
  EXPECT_EQ(ledger.joints_broken(), (std::vector<bool>{true, false}));
  ledger.begin_step();
  EXPECT_EQ(ledger.joint_forces_n()[0], 0.0);
  EXPECT_TRUE(ledger.broken(0));
}

TEST(DebrisLedger, PartForcesAddUpWithinAStepAndStartOverEachStep) {
  DebrisLedger ledger({}, 2);
  ledger.begin_step();
  ledger.add_part_force(1, Eigen::Vector3d(1, 2, 3));
  ledger.add_part_force(1, Eigen::Vector3d(1, 0, -3));
  EXPECT_EQ(ledger.part_forces_n()[1], Eigen::Vector3d(2, 2, 0));
  EXPECT_EQ(ledger.part_forces_n()[0], Eigen::Vector3d::Zero());
  ledger.begin_step();
  EXPECT_EQ(ledger.part_forces_n()[1], Eigen::Vector3d::Zero());
}

}  // namespace
}  // namespace repose
