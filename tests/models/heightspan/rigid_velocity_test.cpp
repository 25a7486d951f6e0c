#include "models/heightspan/rigid_velocity.h"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace repose {
namespace {

Pose posed(const Eigen::Vector3d& position_m, double angle_rad, const Eigen::Vector3d& axis) {
  return {position_m, Eigen::Quaterniond(Eigen::AngleAxisd(angle_rad, axis.normalized()))};
}

TEST(RigidVelocity, ATranslationMovesEveryPointAlike) {
  const Pose from = posed({0.1, 0.2, 0.3}, 0.4, Eigen::Vector3d::UnitX());
  Pose to = from;
  to.position_m += Eigen::Vector3d(0.01, -0.02, 0.005);
  const RigidVelocity v = rigid_velocity(from, to, 0.5);
  EXPECT_EQ(v.angular_rad_s, Eigen::Vector3d::Zero());
  EXPECT_TRUE(v.at({3.0, -1.0, 7.0}).isApprox(Eigen::Vector3d(0.02, -0.04, 0.01), 1e-12));
}

TEST(RigidVelocity, ATurnInPlaceMovesAPointAtOmegaTimesItsRadius) {
  const Eigen::Vector3d centre(0.18, 0.05, 0.11);
  const RigidVelocity v = rigid_velocity(posed(centre, 0.0, Eigen::Vector3d::UnitY()),
                                         posed(centre, std::numbers::pi / 2, Eigen::Vector3d::UnitY()), 0.5);
  EXPECT_TRUE(v.angular_rad_s.isApprox(Eigen::Vector3d(0.0, std::numbers::pi, 0.0), 1e-12));
  EXPECT_EQ(v.at(centre), Eigen::Vector3d::Zero());
  // a point 4 cm along +x turning about +y heads down at pi x 0.04 m/s
  EXPECT_TRUE(v.at(centre + Eigen::Vector3d(0.04, 0.0, 0.0)).isApprox(Eigen::Vector3d(0.0, 0.0, -0.04 * std::numbers::pi),
                                                                       1e-12));
}

TEST(RigidVelocity, APointOfTheBodyMovesAsTheFiniteDifferenceOfItsPlacements) {
  const Eigen::Vector3d body_point(0.03, -0.02, 0.05);
  const Pose from = posed({0.1, 0.0, 0.2}, 0.7, Eigen::Vector3d(1.0, 2.0, -0.5));
  Pose to = from;
  to.position_m += Eigen::Vector3d(1e-5, 2e-5, -1e-5);
  to.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(1e-4, Eigen::Vector3d(-0.3, 1.0, 0.2).normalized())) *
                   from.orientation;
  const double dt_s = 1e-3;
  const Eigen::Vector3d start = from.orientation * body_point + from.position_m;
  const Eigen::Vector3d end = to.orientation * body_point + to.position_m;
  const Eigen::Vector3d difference = (end - start) / dt_s;
  EXPECT_LT((rigid_velocity(from, to, dt_s).at(end) - difference).norm(), 1e-4 * difference.norm());
}

TEST(RigidVelocity, TakesTheShorterWayRound) {
  const RigidVelocity v = rigid_velocity(posed({}, 0.0, Eigen::Vector3d::UnitZ()),
                                         posed({}, 350.0 * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ()), 1.0);
  EXPECT_TRUE(v.angular_rad_s.isApprox(Eigen::Vector3d(0.0, 0.0, -10.0 * std::numbers::pi / 180.0), 1e-12));
}

}  // namespace
}  // namespace repose
