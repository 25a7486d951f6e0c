#pragma once
// A scene run as a LIGGGHTS reference, from scene to observables:
//   1. the settled bed (liggghts_bed.h, cached) the run starts from;
//   2. the run script (objects as STL meshes, keyframed motion) run in run_dir;
//   3. observables written to run_dir:
//        height_initial.npy / .csv   surface of the settled bed (the heuristic's
//                                    initial height field for a compared run)
//        height_final.npy / .csv     surface after the run
//        material_per_area_final.npy grain volume per unit area (m)
//        forces.csv                  time_s and the force (N) on each object over time
//        liggghts_manifest.json      LIGGGHTS version, script sha256, grain count,
//                                    steps, particle-steps per second, wall and CPU times
//        bed_manifest.json           the settled bed's manifest (its cost)
//        free_body_NAME.csv          a free sphere's trajectory and contact force (free_body_track.h;
//                                    LIGGGHTS prints free_body_NAME.txt, liggghts_free_body.h)
//        held_mass.csv               time_s, <object>_mass_kg: the mass each keyframed object holds
//                                    at every dump (held_mass_series.h), when the scene has one
//   the manifest also holds free_bodies (each one's rest: depth, force, final state) and mass_held_kg: the mass of grains each object holds at the end
//   and for a scene that starts from a column (dem.initial: column):
//        runout.csv                  time_s, front_m: the deposit front over the dumps
//        pile_flank_angles.csv       cylinder and quarter columns: the final pile's flank angle per azimuth (degrees)
//   and for a chute (dem.impact_window_m > 0; chute_impact.h):
//        chute_impact.csv            per dump: the flow upstream of the wall, the force on it, p, Fr, p/(rho v^2)
// run_dir must exist and should be empty (the caller makes it atomic, e.g.
// with OutputDirectory); the run's own files (run.in, log.liggghts, dumps/) stay there.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "models/core/geometry/height_field.h"
#include <nlohmann/json.hpp>

#include "models/core/config/scene.h"
#include "validation/particles/chute_impact.h"
#include "validation/particles/column_collapse.h"
#include "validation/particles/free_body_track.h"
#include "validation/particles/held_mass_series.h"
#include "validation/liggghts/liggghts_bed.h"
#include "validation/liggghts/liggghts_neighbor_stats.h"
#include "validation/liggghts/liggghts_runner.h"
#include "validation/liggghts/liggghts_script.h"
#include "validation/particles/particle_observables.h"
#include "validation/particles/surface_height.h"

namespace repose {

struct LiggghtsReferenceOptions {
  BedOptions bed;                // cache directory, bed sizing, the settling run's options
  RunScriptOptions script;
  LiggghtsRunOptions run;        // executable, wall-clock limit, progress of the run itself
  SurfaceHeightOptions surface;
  ColumnCollapseOptions column;
  FlankAngleOptions flank;
};

struct LiggghtsReferenceResult {
  SettledBed bed;
  LiggghtsRunSummary run;
  long grain_count = 0;          // grains in the last dump
  long steps = 0;                // steps of the run (after the bed)
  double particle_steps_per_s = 0.0;
  std::string script_sha256;
  NeighborStats neighbor;        // list builds and dangerous builds of the run (liggghts_neighbor_stats.h)
  HeightField height_initial;    // surface of the settled bed on the scene's grid
  HeightField height_final;      // surface after the run
  HeightField material_per_area_final;  // grain volume per unit area (m), particle_observables.h
  std::optional<ColumnCollapse> column;  // a column scene: its runout
  std::optional<FlankAngles> pile;       // a cylinder column: the final pile's flank angles
  std::optional<ChuteImpact> chute;      // a chute: the flow's impact on the wall (chute_impact.h)
  // Per object (scene order): its name and the mass (kg) of the grains it
  // holds at the end of the run (mass_held_by_object_kg, observables.h), the
  // object at ObjectSpec::pose_at(scene duration), grains of the scene's density.
  std::vector<std::pair<std::string, double>> mass_held_kg;
  HeldMassSeries held_mass;                // per keyframed object, per dump (held_mass_series.h)
  std::vector<FreeBodyTrack> free_bodies;  // per free sphere (scene order)
  std::vector<FreeBodyRest> free_body_rests;
};

// Throws InputError for a scene that cannot run (no dem section, a time step
// too large) and LiggghtsRunError when a run fails.
LiggghtsReferenceResult run_liggghts_reference(const Scene& scene, const std::string& run_dir,
                                               const LiggghtsReferenceOptions& options = {});

// The run's results as one JSON object: LIGGGHTS version, script hash, bed
// cache key, grain count, steps, costs, and when present "column" and "pile"
// (angles in degrees, as in files), "chute" and "mass_held_kg": {"<object>": kg}.
// Written into liggghts_manifest.json; the solver turns its numbers into measures.
nlohmann::json liggghts_results_json(const LiggghtsReferenceResult& r);

}  // namespace repose
