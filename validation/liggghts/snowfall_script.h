#pragma once
// The LIGGGHTS script of the cohesive DEM snowfall reference
// (dem.initial: snowfall): grains rain onto the scene's objects and settle,
// the particle counterpart of the snow model (models/snow), whose depth maps
// the settled grains are turned into (snowfall_reference.h).
//
//   Box: the ground grid's extent, periodic in x and y (open ground gets
//     the same snow everywhere, whatever the directions), the floor z = 0
//     (the scene's ground must be flat at 0), the top above the insertion layer.
//   Objects: every scene object at its t = 0 pose, an STL mesh made a
//     granular wall of the floor's material (the snow maps' surfaces).
//   Snowfall: options.stream_count insertion streams (`fix
//     insert/rate/region`), each along one direction drawn from the snow
//     section's distribution (snowfall_stream_directions), in a layer over
//     the whole grid above the highest object, entering at fall_speed_m_s
//     over insert_time_s, staggered so that no two streams insert on one step.
//     The grain count fills the snow section's open-ground depth (its
//     snowfall rate integrated over the scene's duration) at packing_fraction.
//   Terminal speed: no `fix gravity`; `fix addforce` applies m g downwards
//     only to grains slower than fall_speed_m_s, so falling snow keeps its
//     straight line and dropping snow is capped at the same speed.
//   Cohesion: dem.cohesion_energy_density_j_m3 (sjkr) between grains; none
//     with the floor and the objects.
//   Then: the run continues until every grain has had time to land, then
//   settles in chunks until the kinetic energy falls below
//   dem.settle_kinetic_energy_j (REPOSE_FAILURE after max_settle_time_s),
//   and dumps the grains to snow.dump.
// Units: LIGGGHTS "units si". Deterministic text (liggghts_script.h).

#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/core/config/scene.h"
#include "validation/liggghts/liggghts_script.h"
#include "validation/liggghts/snowfall_section.h"

namespace repose {

inline constexpr const char* kSnowfallDumpFile = "snow.dump";

// The streams' directions (unit vectors snow travels along, z < 0): draws
// from the snow section's distribution (snowfall_directions.h) with a
// generator seeded from scene_seed (a stream of its own, not the heuristic's
// shadow-map directions).
std::vector<Eigen::Vector3d> snowfall_stream_directions(const Scene& scene, int count);

struct SnowfallPlan {
  DemDomain domain;
  long grain_count = 0;          // grains rained in all
  double open_depth_m = 0.0;     // the snow section's depth on open ground
  double layer_bottom_m = 0.0;   // insertion layer (z)
  double layer_top_m = 0.0;
  long insert_every_steps = 0;   // per stream
  long insert_steps = 0;         // steps while grains enter
  long landing_steps = 0;        // then, until the last grain has landed
  long settle_chunk_steps = 0;   // kinetic energy checked this often
  long max_settle_chunks = 0;
  long max_steps() const { return insert_steps + landing_steps + settle_chunk_steps * max_settle_chunks + 1; }
};

struct SnowfallScript {
  std::string text;
  std::vector<LiggghtsMeshFile> meshes;  // to be written next to the script (STL)
  SnowfallPlan plan;
  std::vector<Eigen::Vector3d> directions;  // per stream
};

// Requires dem (initial: snowfall), a snow: section, a ground flat at 0 and
// static objects; InputError naming the key otherwise, or when the grain
// count exceeds max_grain_count.
SnowfallScript snowfall_script(const Scene& scene, long max_grain_count = 100000);

}  // namespace repose
