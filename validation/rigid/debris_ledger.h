#pragma once
// What every debris world (debris_world.h) keeps the same way, whatever its
// engine: the joints' state (each step's force, the rule that breaks a
// joint) and the contact force the elements put on each part.
//
// A joint breaks in the step whose force exceeds its break_force_n: that
// step reports the force that broke it, later steps 0 (the engine removes
// or disables it when record() says so).

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "validation/rigid/debris_world.h"

namespace repose {

// The mass (kg) of a spherical element.
inline double element_mass_kg(const DebrisElement& e) {
  return e.density_kg_m3 * 4.0 / 3.0 * M_PI * e.radius_m * e.radius_m * e.radius_m;
}

class DebrisLedger {
 public:
  DebrisLedger(const std::vector<DebrisJoint>& joints, std::size_t part_count);

  // Starts a step: every joint's force and every part's element force back to 0.
  void begin_step();
  // Joint k (not broken) carried force_n in this step; true when it breaks now.
  bool record_joint(std::size_t k, double force_n);
  // Adds an element's contact force on part p in this step.
  void add_part_force(std::size_t p, const Eigen::Vector3d& force_n) { part_force_n_.at(p) += force_n; }

  bool broken(std::size_t k) const { return broken_.at(k); }
  const std::vector<bool>& joints_broken() const { return broken_; }
  const std::vector<double>& joint_forces_n() const { return joint_force_n_; }
  const std::vector<Eigen::Vector3d>& part_forces_n() const { return part_force_n_; }

 private:
  std::vector<double> break_force_n_;
  std::vector<bool> broken_;
  std::vector<double> joint_force_n_;
  std::vector<Eigen::Vector3d> part_force_n_;
};

}  // namespace repose
