#pragma once
// Free bodies on the ground model (issue 11, item 4): ODE moves each object
// with `dynamic:` over the ground's height field, and the ground model
// deforms the field under it, so a dropped or rolling body sinks and leaves
// its track (the interactive use the ground paper was written for).
//
// Each ground step (model.time.step_s): ODE steps the bodies over the field
// as the last ground step left it (a dHeightfield geom reading, in place,
// the field at cell corners, each the lowest cell sharing it: see
// free_body_drive.cpp), recording the mean vertical force the
// field exerts on each body (dJointFeedback of its contacts) and the
// kinetic energy of the downward speed with which it met the field; the
// bearing rule (bearing_sinkage.h) turns the load (at most the weight) into
// the sinkage below the undisturbed (initial) surface that Bekker's law
// gives, and an impact's energy into the depth where the ground's work has
// taken it up (impact_sinkage_m); a body that sits
// shallower is moved down by the difference in ODE (quasi-statically: its
// velocity is kept) and the ground step is given the body's pose from the
// step's start to that pressed pose, so the heuristic compresses and
// displaces the material it now intersects; then ODE's field is refreshed
// from the ground's. The heuristic alone never lowers the field under a body
// resting on it (a by-hand program measured this before the bearing rule
// existed: an ODE-held box ended within 0.7 mm of the surface at any load),
// so without bearing (law: off) a body rests on the field and leaves no
// imprint; the ground yields only where the bearing rule presses.
//
// A body's dynamic.torque_n_m is added in ODE before every ODE step: a wheel
// (a cylinder, axis horizontal) under a torque drives itself over the field
// on the contacts' Coulomb friction, sinking to its load's bearing depth
// under way and leaving its rut.
//
// Shapes: ODE's sphere, box, cylinder (axis z) and capsule, with the
// scene's scale where the primitive stays one (as validation/rigid does);
// meshes are refused (ODE's triangle mesh against a height field is not
// used here). Deterministic: QuickStep's random reordering is seeded per
// drive (set before and read back after each ODE step).

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/core/geometry/height_field.h"

namespace repose {

struct GroundModel;
struct GroundState;

// One free body at the end of a run.
struct FreeBodyReport {
  std::string name;
  double mass_kg = 0.0;
  double weight_n = 0.0;
  double resting_depth_m = 0.0;    // lowest point below the initial surface at the body's centre (>0: sunk)
  double final_speed_m_s = 0.0;
  double travel_m = 0.0;           // horizontal distance from the initial position to the final one
  double final_load_n = 0.0;       // mean vertical force of the field on the body over the last step
  double max_load_n = 0.0;         // largest step-mean force (the impact's)
  double bearing_sinkage_m = 0.0;  // Bekker's static sinkage for the last step's load (at most the weight)
  Eigen::Vector3d final_position_m = Eigen::Vector3d::Zero();
};

// True when the model has an object with `dynamic:`.
bool has_free_bodies(const GroundModel& model);

// Throws InputError naming the first free body ODE cannot drive over the
// field here (a mesh, a non-uniformly scaled primitive); nothing when there
// is no free body.
void check_free_bodies(const GroundModel& model, const std::string& source_path);

class FreeBodyDrive {
 public:
  // ODE's world with the model's free bodies at their initial poses and
  // velocities, over `initial` (also the undisturbed surface for sinkage).
  // The model must outlive the drive. Throws as check_free_bodies.
  FreeBodyDrive(const GroundModel& model, const HeightField& initial);
  ~FreeBodyDrive();
  FreeBodyDrive(const FreeBodyDrive&) = delete;
  FreeBodyDrive& operator=(const FreeBodyDrive&) = delete;

  // ODE over the step that `state` is at, then the bearing press; sets each
  // free object's keyframes in *driven (a copy of the model) from its pose at
  // the step's start (state.previous_poses) to its pose at the step's end.
  void advance(const GroundState& state, GroundModel* driven);
  // ODE's field from the ground's, after the ground step.
  void refresh_field(const HeightField& ground);
  std::vector<FreeBodyReport> reports() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace repose
