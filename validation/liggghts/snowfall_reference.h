#pragma once
// The cohesive DEM snowfall reference from scene to snow depth maps: writes
// the snowfall script (snowfall_script.h) and the objects' STL meshes into
// run_dir, runs LIGGGHTS there, checks that every grain rained is in the
// final dump (none lost, none failed to enter), and turns the settled grains
// into the snow model's depth maps (grain_snow_depth.h, on the snow maps the
// heuristic builds from the same scene). The Run holds
//   fields:   snow_depth_final.<group> (m), height_initial (the flat ground),
//             height_final (ground + its snow, for a scene with a ground
//             group), material_per_area_final (grain volume per area, m);
//   measures: grain_count, steps, run_wall_s, run_cpu_s, particle_steps_per_cpu_s,
//             snow.open_depth_m (the snow section's depth the grain count
//             was sized for), snow.volume_m3.<group> (grain volume on each
//             map's surface, m^3), snow.max_depth_m.<group>;
//   details:  liggghts_version, script_sha256.
// It also writes liggghts_manifest.json (version, script hash, grain count,
// steps, wall and CPU time: what calibration reads for a reference's cost).

#include <string>

#include "models/core/config/scene.h"
#include "models/core/solver/run.h"
#include "validation/liggghts/liggghts_runner.h"

namespace repose {

// Throws InputError for a scene the script refuses, LiggghtsRunError when
// the run fails or loses grains.
Run run_liggghts_snowfall(const Scene& scene, const std::string& run_dir, const LiggghtsRunOptions& options = {});

}  // namespace repose
