#pragma once
// A debris flow run in a rigid-body engine (debris_world.h) and its
// observables, written once for every engine:
//   - the front: the front_quantile of the elements' positions along the
//     downhill direction at the source (debris_setup.h), from the source's
//     centre, in every frame; its speed by central differences (ends: one-sided);
//   - the runout: the front's final position less its initial one;
//   - the deposit: the elements' surface (validation/particles/surface_height.h)
//     less the terrain, never negative, taken on a grid fine enough to see
//     the elements (cells at most half the smallest radius, at most 8 times
//     finer) and averaged onto the grid of setup.scenery.terrain.height_field;
//   - per building: parts moved (displacement of the centre above
//     moved_threshold_m), the largest displacement, joints broken, and the
//     largest joint force seen (the first step's: the static load);
//   - per building the force of the elements on it over time: the vector sum
//     of the contact forces on its parts (DebrisWorld::part_element_forces_n),
//     averaged over bins of force_interval_s (the impulse in the bin / its
//     length, as a DEM's time average of a wall force), its magnitude per
//     bin, the largest (peak) and the impulse (the magnitudes times the bin lengths).

#include <string>
#include <vector>

#include "models/core/geometry/height_field.h"
#include "validation/particles/grain_set.h"
#include "validation/particles/surface_height.h"
#include "validation/rigid/debris_setup.h"
#include "validation/rigid/debris_world.h"

namespace repose {

struct DebrisRunOptions {
  double frame_interval_s = 0.0;     // frames every this (to the nearest step) and at the end; 0: duration / 20
  double moved_threshold_m = 0.05;   // a part moved when its centre moved farther
  double front_quantile = 0.98;      // in (0, 1]: 1 is the farthest element (a single bouncing rock)
  double force_interval_s = 0.05;    // > 0: the building forces' bins (to the nearest step, at least one)
  SurfaceHeightOptions surface;      // the deposit's surface
  void validate() const;             // InputError naming the field
};

struct DebrisFrame {
  double time_s = 0.0;
  GrainSet elements;
  std::vector<Pose> parts;
  int joints_broken = 0;
  double front_m = 0.0;
  double front_speed_m_s = 0.0;      // set after the run
  double mean_speed_m_s = 0.0;       // of the elements
};

struct BuildingOutcome {
  std::string name;
  int parts = 0;
  int parts_moved = 0;
  double max_displacement_m = 0.0;
  int joints = 0;
  int joints_broken = 0;
  double static_joint_force_n = 0.0;  // the largest joint force after the first step
  std::vector<double> force_n;        // the elements' force on it, per bin of DebrisRunResult::force_time_s
  double peak_force_n = 0.0;
  double impulse_n_s = 0.0;
};

struct DebrisRunResult {
  std::vector<DebrisFrame> frames;
  double runout_m = 0.0;
  double peak_front_speed_m_s = 0.0;
  HeightField deposit;               // on the terrain's grid (m)
  std::vector<BuildingOutcome> buildings;
  std::vector<double> force_time_s;  // the end of each force bin
  long steps = 0;
  double simulated_s = 0.0;
  double wall_time_s = 0.0;
  double cpu_time_s = 0.0;
  double cpu_s_per_simulated_s() const { return simulated_s > 0.0 ? cpu_time_s / simulated_s : 0.0; }
};

// The front (m): the quantile of (p_xy - centre) . direction over the elements.
double debris_front_m(const GrainSet& elements, const Eigen::Vector2d& centre_m, const Eigen::Vector2d& direction,
                      double quantile);

// Steps ceil(duration_s / time step) times. Throws std::runtime_error when an
// element's position becomes non-finite.
DebrisRunResult run_debris(DebrisWorld& world, const DebrisSetup& setup, double duration_s,
                           const DebrisRunOptions& options = {});

// A frame from an engine's state (the front and mean speed computed; the
// front speed set by finish_debris_result). Throws std::runtime_error when
// an element's position is non-finite.
DebrisFrame debris_frame(double t, GrainSet elements, std::vector<Pose> parts, int joints_broken,
                         const DebrisSetup& setup, double quantile);

// Completes a result whose frames, buildings (with their force series) and
// force_time_s are set: front speeds, runout, peak front speed, deposit,
// each building's peak force and impulse. For an engine that is not a
// DebrisWorld (a DEM run from its dumps) as run_debris does it for one.
void finish_debris_result(const DebrisSetup& setup, const SurfaceHeightOptions& surface, DebrisRunResult& r);

// Writes into run_dir (which must exist): terrain.obj, front.csv
// (time_s, front_m, front_speed_m_s, mean_speed_m_s, joints_broken),
// buildings.csv, building_forces.csv (time_s, then one column per
// building: the elements' force on it, N), deposit.npy, parts.json (each part's hull and building),
// frames/elements_NNN.npy (#E by 4: x y z r) and frames/parts_NNN.npy
// (#P by 7: x y z qw qx qy qz), and returns the files written (relative).
std::vector<std::string> write_debris_run(const DebrisRunResult& result, const DebrisSetup& setup,
                                          const std::string& run_dir);

}  // namespace repose
