#pragma once
// The two phases of a rigid-body reference run, written once for every
// engine (rigid_world.h): settling a bed until its kinetic energy falls
// below a threshold, and moving the objects along their keyframes for the
// scene's duration. Both count steps and measure wall and CPU time.

#include <string>
#include <vector>

#include "models/core/config/scene.h"
#include "validation/particles/grain_set.h"
#include "validation/particles/held_mass_series.h"
#include "validation/rigid/rigid_world.h"

namespace repose {

struct RigidPhaseSummary {
  long steps = 0;
  double simulated_s = 0.0;
  double kinetic_energy_j = 0.0;  // at the end
  bool settled = false;           // settling: the threshold was reached
  double wall_time_s = 0.0;
  double cpu_time_s = 0.0;        // of this process
};

// Steps until the kinetic energy, checked every check_interval_s, is below
// threshold_j, or max_time_s has passed (settled = false then).
RigidPhaseSummary settle(RigidWorld& world, double threshold_j, double check_interval_s, double max_time_s);

// A frame of the run: the grains at a time (held_mass_series.h).
using RigidFrame = GrainFrame;

// The objects moved along keyframes (dynamic unset) and the free bodies, each in scene order.
std::vector<ObjectSpec> kinematic_objects(const std::vector<ObjectSpec>& objects);
std::vector<ObjectSpec> free_body_objects(const std::vector<ObjectSpec>& objects);

// The force on each kinematic object (scene order) after every step.
struct RigidForceTrack {
  std::vector<std::string> names;  // the objects' (set by the caller, for files)
  std::vector<double> time_s;
  std::vector<std::vector<Eigen::Vector3d>> force_n;  // per sample, per object
};

// What a run records besides its summary (each optional).
struct RigidRecording {
  double frame_interval_s = 0.0;          // grains every this (to the nearest step) and at the end
  std::vector<RigidFrame>* frames = nullptr;
  std::vector<FreeBodyTrack>* free_bodies = nullptr;  // started tracks (free_body_track.h): a sample every step
  RigidForceTrack* object_forces = nullptr;           // a sample every step
  double gravity_m_s2 = 9.81;             // for the free bodies' contact force
};

// Steps ceil(duration_s / time step) times; before each step the kinematic
// objects (the world's, in order) are placed at ObjectSpec::pose_at(end of
// that step).
RigidPhaseSummary run_motion(RigidWorld& world, const std::vector<ObjectSpec>& objects, double duration_s,
                             const RigidRecording& recording = {});

// The grains that left the ground box (centre beyond a side wall or below
// the floor by more than its radius) or are not finite; empty when none.
std::vector<long> lost_grains(const GrainSet& grains, const RigidBounds& bounds);

// Throws std::runtime_error "ENGINE: PHASE lost N of M grains (first: grain G at (x, y, z))"
// when any grain is lost: material is never lost silently.
void demand_no_grain_lost(const GrainSet& grains, const RigidBounds& bounds, const std::string& engine,
                          const std::string& phase);

// CPU time of this process (s).
double process_cpu_time_s();

}  // namespace repose
