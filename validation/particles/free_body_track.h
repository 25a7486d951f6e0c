#pragma once
// A free body's run (models/core/config/dynamic_body.h) as every particle
// reference reports it: its trajectory (pose and velocities over time), the
// force the grains and walls put on it, and where it came to rest.
//
// The contact force is what the body's momentum says: F = m dv/dt + m g z
// (z up), the total force minus its weight, from the velocity change over
// each sample interval. It is exact for an engine that integrates velocity
// explicitly over the step (Bullet, ODE, LIGGGHTS' nve/sphere) when samples
// are one step apart, and the mean force over the interval otherwise.
//
// The resting depth is how far the body's lowest point lies below the
// settled bed's surface at the body's final (x, y): the initial surface
// height there minus the lowest vertex of its body at its final pose
// (negative when it rests on top of grains heaped above the surface).

#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "models/core/config/scene.h"
#include "models/core/geometry/height_field.h"

namespace repose {

struct FreeBodyState {
  Pose pose;
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity_rad_s = Eigen::Vector3d::Zero();
};

struct FreeBodySample {
  double time_s = 0.0;
  FreeBodyState state;
  Eigen::Vector3d contact_force_n = Eigen::Vector3d::Zero();  // mean over the interval that ends here
};

struct FreeBodyTrack {
  std::string name;
  double mass_kg = 0.0;
  std::vector<FreeBodySample> samples;  // the first at t = 0 (its initial state, no force)
};

// One track per free body of `bodies` (objects with dynamic set, in order).
std::vector<FreeBodyTrack> start_free_body_tracks(const std::vector<ObjectSpec>& bodies);

// Appends a sample per body at time_s; the contact force from the velocity
// change since the previous sample, with gravity g (m/s^2) along -z.
void record_free_bodies(std::vector<FreeBodyTrack>& tracks, double time_s, const std::vector<FreeBodyState>& states,
                        double gravity_m_s2);

struct FreeBodyRest {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  // final
  double bottom_z_m = 0.0;          // the body's lowest point at its final pose
  double surface_z_m = 0.0;         // the initial surface under its final (x, y)
  double resting_depth_m = 0.0;     // surface_z_m - bottom_z_m
  double final_speed_m_s = 0.0;
  Eigen::Vector3d resting_force_n = Eigen::Vector3d::Zero();  // mean contact force over the last window_s
  double weight_n = 0.0;            // m g, what resting_force_n.z() balances at rest
  double max_force_n = 0.0;         // the largest contact force magnitude of any sample (the impact)
};

// The body's rest from its track (at least one sample).
FreeBodyRest free_body_rest(const ObjectSpec& body, const FreeBodyTrack& track, const HeightField& surface_initial,
                            double gravity_m_s2, double window_s);

// time_s, x_m, y_m, z_m, qw, qx, qy, qz, vx_m_s, vy_m_s, vz_m_s, wx_rad_s,
// wy_rad_s, wz_rad_s, fx_n, fy_n, fz_n: one row per sample.
void write_free_body_csv(const std::string& path, const FreeBodyTrack& track);

// {"NAME": {mass_kg, resting_depth_m, bottom_z_m, surface_z_m, final_position_m,
// final_speed_m_s, resting_force_n, weight_n, max_force_n, trajectory}} for the manifests.
nlohmann::json free_bodies_json(const std::vector<FreeBodyTrack>& tracks, const std::vector<FreeBodyRest>& rests);

}  // namespace repose
