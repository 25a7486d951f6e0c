#pragma once
// A scene run as a rigid-body reference (Bullet or ODE), from scene to the
// observables the LIGGGHTS reference gives (liggghts_reference.h), through
// the shared particle path (validation/particles):
//   1. the settled bed (rigid_bed_cache.h, cached);
//   2. the run: the settled grains, the ground box, the objects kinematic
//      along their keyframes, for the scene's duration at the engine's step;
//   3. the surface height of the initial and final grains, material per
//      area, the mass each object holds at the end.
// write_rigid_reference() writes them to a run folder:
//   height_initial.npy, height_final.npy, material_per_area_final.npy,
//   grains_initial.npy, grains_final.npy (#G by 4: x y z r), and
//   ENGINE_manifest.json (engine, version, every option used, grain count, steps,
//   particle-steps per CPU second, wall and CPU times, mass_held_kg, and
//   for a column scene its runout and pile flank angles, as LIGGGHTS writes them);
//   a scene with free bodies writes free_body_NAME.csv per body (trajectory
//   and contact force every step, free_body_track.h) and their rest in the
//   manifest's free_bodies;
//   a scene with keyframed objects writes held_mass.csv (the mass each one
//   holds in every frame, every dem.dump_interval_s: held_mass_series.h);
//   a column scene also writes runout.csv (the front every dem.dump_interval_s)
//   and, for a cylinder, pile_flank_angles.csv;
//   a scene with kinematic objects writes forces.csv (time_s and the force
//   on each, N, every step, as LIGGGHTS's), and a chute (dem.impact_window_m
//   > 0) chute_impact.csv and the manifest's chute (chute_impact.h).

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "models/core/geometry/height_field.h"
#include "validation/particles/column_collapse.h"
#include "validation/particles/free_body_track.h"
#include "validation/particles/grain_set.h"
#include "validation/particles/particle_observables.h"
#include "validation/particles/surface_height.h"
#include "validation/rigid/rigid_bed_cache.h"
#include "validation/rigid/rigid_engine.h"
#include "validation/rigid/rigid_setup.h"
#include "validation/rigid/rigid_simulation.h"

namespace repose {

struct RigidReferenceOptions {
  std::string cache_dir;  // empty: default_cache_dir() (liggghts_bed.h)
  SurfaceHeightOptions surface;
  ColumnCollapseOptions column;
  FlankAngleOptions flank;
};

struct RigidReferenceResult {
  std::string engine;
  std::string engine_version;
  std::string engine_options;             // key=value lines: every option of the engine's section used
  RigidBed bed;
  RigidPhaseSummary run;
  long grain_count = 0;
  double particle_steps_per_cpu_s = 0.0;  // of the run (after the bed)
  GrainSet grains_initial;                // the settled bed
  GrainSet grains_final;
  HeightField height_initial;
  HeightField height_final;
  HeightField material_per_area_final;    // grain volume per unit area (m)
  // Per object (scene order): its name and the mass (kg) of the grains it
  // holds at the end (mass_held_by_object_kg), the object at pose_at(duration).
  std::vector<std::pair<std::string, double>> mass_held_kg;
  HeldMassSeries held_mass;  // per keyframed object, per frame (every dem.dump_interval_s; held_mass_series.h)
  std::vector<FreeBodyTrack> free_bodies;  // per free body (scene order): a sample every step
  std::vector<FreeBodyRest> free_body_rests;
  std::optional<ColumnCollapse> column;  // a column scene: its runout
  std::optional<FlankAngles> pile;       // a cylinder column: the final pile's flank angles
  RigidForceTrack object_forces;         // the force on each kinematic object after every step
  std::optional<ChuteImpact> chute;      // a chute: the flow's impact on the wall (chute_impact.h)
};

// Throws InputError for options that break their rules and
// std::runtime_error when the bed or the run fails (unsettled, a grain lost).
RigidReferenceResult run_rigid_reference(const RigidEngine& engine, const RigidInputs& in,
                                         const RigidReferenceOptions& options = {});

// Writes the files listed above into run_dir (which must exist).
void write_rigid_reference(const RigidReferenceResult& result, const std::string& run_dir);

}  // namespace repose
