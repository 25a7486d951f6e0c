#pragma once
// A free body: an object that is not moved along keyframes but falls,
// strikes and comes to rest under gravity and the grains' forces (or, in
// the ground model, its height field's: models/ground/free_body_drive.h).
// The particle references (validation/bullet, validation/ode,
// validation/liggghts) and the ground model move it; a scene object has
// either `motion:` (keyframes) or `dynamic:`, never both.
//
//   objects:
//     - {name: ball, shape: sphere, radius_m: 0.01,
//        dynamic: {density_kg_m3: 7800, position_m: [0, 0, 0.05], velocity_m_s: [0, 0, -1]}}
//     - {name: wheel, shape: cylinder, radius_m: 0.1, half_height_m: 0.05,
//        dynamic: {mass_kg: 5, position_m: [0, 0, 0.2], orientation_deg: [90, 0, 0], torque_n_m: [0, 2, 0]}}
//
// Its mass is mass_kg or density_kg_m3 times the body's volume (exact for
// the primitives, the closed mesh's volume for a mesh); its contacts use the
// dem section's friction, restitution and rolling friction.

#include <Eigen/Core>

#include "models/core/config/fields.h"

namespace repose {

struct DynamicBody {
  double mass_kg = 0.0;         // the body's mass; 0: from density_kg_m3 (give exactly one)
  double density_kg_m3 = 0.0;   // mass per volume of the body; 0: mass_kg is given
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();          // initial position of the body origin (required)
  Eigen::Vector3d orientation_deg = Eigen::Vector3d::Zero();     // initial roll, pitch, yaw (as keyframes)
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();        // initial linear velocity
  Eigen::Vector3d angular_velocity_rad_s = Eigen::Vector3d::Zero();  // initial angular velocity (world axes)
  // a constant torque about the body's centre of mass (world axes) applied
  // at every step: drives a wheel. The rigid-body engines and the ground
  // model's ODE drive apply it; LIGGGHTS refuses a non-zero one.
  Eigen::Vector3d torque_n_m = Eigen::Vector3d::Zero();
};

inline constexpr double kMaxBodySpeed_m_s = 1.0e3;
inline constexpr double kMaxBodyTorque_n_m = 1.0e6;

template <class V>
void dynamic_body_fields(V& v, DynamicBody& d) {
  v.number("mass_kg", d.mass_kg, Range::non_negative());
  v.number("density_kg_m3", d.density_kg_m3, Range::non_negative());
  v.vec3("position_m", d.position_m, Range::closed(-1.0e6, 1.0e6));
  v.vec3("orientation_deg", d.orientation_deg, Range::closed(-3600.0, 3600.0));
  v.vec3("velocity_m_s", d.velocity_m_s, Range::closed(-kMaxBodySpeed_m_s, kMaxBodySpeed_m_s));
  v.vec3("angular_velocity_rad_s", d.angular_velocity_rad_s, Range::closed(-1.0e4, 1.0e4));
  v.vec3("torque_n_m", d.torque_n_m, Range::closed(-kMaxBodyTorque_n_m, kMaxBodyTorque_n_m));
}

inline const auto kDynamicBodyFields = [](auto& v, DynamicBody& x) { dynamic_body_fields(v, x); };

// Throws FieldError naming the field: exactly one of mass_kg and
// density_kg_m3 is given (> 0), every value finite.
void validate(const DynamicBody& body);

}  // namespace repose
