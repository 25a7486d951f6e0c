#pragma once
// A debris flow on generated terrain (validation/rigid/debris_setup.h) as
// LIGGGHTS input: the terrain mesh a granular mesh wall (terrain.stl), the
// plain a zplane wall at its height, the elements atoms read from
// elements.data (spec order: atom id = element index + 1) with their
// layers' density, each building part a fixed mesh wall of its own
// (part_<p>.stl, fix mesh/surface/stress part<p>: the force of the elements
// on it; one mesh per part, as the convex pieces of a storey share faces,
// which LIGGGHTS refuses within one mesh: it aborts without a message),
// their forces averaged over bins of force_interval_s into
// building_forces.txt (fix ave/time; 3 columns per part, spec order).
// Hertz with tangential history and cdt rolling friction.
//
// Atom types: 1 the walls (terrain, plain, buildings), 2.. one per distinct
// element material (friction, restitution, rolling mu_r). Pair values as
// debris_world.h states them for the rigid engines: between elements the
// mean of the two; element and wall the element's own; wall-wall (never in
// contact) the building's, restitution at least 0.1 (LIGGGHTS requires
// 0.05 < e <= 1; an element's below that is refused).
// Buildings are fixed here: they do not break or move (their joints are the
// rigid engines' business), so every run reports no part moved.

#include <string>
#include <vector>

#include "models/core/geometry/triangle_mesh.h"
#include "validation/liggghts_debris/liggghts_debris_options.h"
#include "validation/rigid/debris_setup.h"

namespace repose {

inline constexpr const char* kDebrisScriptFile = "debris.in";
inline constexpr const char* kDebrisDataFile = "elements.data";
inline constexpr const char* kDebrisForceFile = "building_forces.txt";
inline constexpr const char* kDebrisDumpDirectory = "dumps";  // dumps/dump.<step>.txt

struct DebrisMeshFile {
  std::string file_name;  // "terrain.stl", "part_<p>.stl"
  TriangleMesh mesh;
};

struct LiggghtsDebrisScript {
  std::string script;                // debris.in
  std::string data;                  // elements.data
  std::vector<DebrisMeshFile> meshes;
  long total_steps = 0;
  long dump_every_steps = 0;
  long force_every_steps = 0;
  int atom_types = 0;
};

// A part's prism as a closed triangle mesh in world coordinates, faces outward.
TriangleMesh part_mesh(const DebrisPart& part);

// Throws InputError for invalid options or a setup without elements.
LiggghtsDebrisScript liggghts_debris_script(const DebrisSetup& setup, double duration_s,
                                            const LiggghtsDebrisOptions& options);

// Writes the script, data and meshes (binary STL) into run_dir and creates its dump directory.
void write_liggghts_debris_inputs(const LiggghtsDebrisScript& script, const std::string& run_dir);

}  // namespace repose
