#pragma once
// Scene -> LIGGGHTS input script text. Two scripts per compared run:
//   bed script: grains inserted over the ground grid up to the bed depth and
//     settled until the kinetic energy falls below the scene's threshold;
//     writes bed.restart and bed.dump (liggghts_bed.h caches them).
//   run script: reads bed.restart, adds the scene's objects as STL meshes
//     made granular walls, moves them along their keyframes and dumps grains.
// The text is deterministic: the same scene and options give the same bytes
// (numbers are printed round-trip exact), so its hash can key a cache.
// Units: LIGGGHTS "units si", the same SI units as the scene.

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/core/config/scene.h"
#include "models/core/geometry/triangle_mesh.h"

#include "validation/particles/column_geometry.h"
#include "validation/particles/dem_section.h"

namespace repose {

// LIGGGHTS random seeds must be primes > 10000. Returns `count` distinct
// primes derived from the scene seed (splitmix64 then the next prime).
std::vector<std::uint64_t> liggghts_seeds(std::uint64_t scene_seed, int count);

// The discrete radius distribution standing in for a uniform one of
// relative half-width radius_spread: 1 radius when the spread is 0, else 5
// evenly spaced radii r*(1-s) .. r*(1+s), equal in number.
std::vector<double> grain_radii_m(const DemSpec& dem);
// Mean grain volume of that distribution (m^3).
double mean_grain_volume_m3(const DemSpec& dem);

// A box (m). The walls: x and y the ground grid's extent, the floor z = 0.
struct DemDomain {
  double x_min_m = 0, x_max_m = 0, y_min_m = 0, y_max_m = 0, z_min_m = 0, z_max_m = 0;
};

// The column of grains a run starts from when dem.initial is column
// (scene.h): where it stands and where the gate removed at t = 0 was.

struct BedScriptOptions {
  double packing_fraction = 0.6;         // settled packing assumed to size the grain count
  double insert_volume_fraction = 0.3;   // grains are inserted this loosely (then fall)
  double max_settle_time_s = 5.0;        // give up settling after this (the run fails)
  double settle_check_interval_s = 0.02; // kinetic energy checked this often
  double thermo_interval_s = 0.01;       // thermo lines (progress) this often
  long max_grain_count = 100000;         // refuse larger beds (about 0.2 us per grain-step: hours)
};

// Grain count that fills the grid area up to dem.bed_depth_m (a column: its
// footprint up to column_height_m) at packing_fraction.
long bed_grain_count(const Scene& scene, const BedScriptOptions& options);
// The settling box: the grid's extent, z from 0 to the insertion height plus
// a margin. A column is inserted inside its gate (slot: a plane x = gate_x_m;
// cylinder: a zcylinder wall), which the run script leaves out: the gate is
// removed at t = 0, instantly.
DemDomain bed_domain(const Scene& scene, const BedScriptOptions& options);
// Steps of the settling loop at most (for progress).
long bed_max_steps(const Scene& scene, const BedScriptOptions& options);

// Marker lines the scripts print (runner treats REPOSE_FAILURE as a failure).
inline constexpr const char* kSettledMarker = "REPOSE_SETTLED";
inline constexpr const char* kFailureMarker = "REPOSE_FAILURE";
inline constexpr const char* kCompleteMarker = "REPOSE_COMPLETE";  // printed last, only on success

// File names used by the scripts, relative to the run directory.
inline constexpr const char* kBedRestartFile = "bed.restart";
inline constexpr const char* kBedDumpFile = "bed.dump";
inline constexpr const char* kDumpDirectory = "dumps";  // run dumps: dumps/dump.<step>.txt

// The loop a bed or snowfall script settles its grains with: run in chunks
// of chunk_steps until the kinetic energy falls below
// dem.settle_kinetic_energy_j (after `chunks` chunks: a failure line naming
// `what`), then settled_commands (write the restart, dump the grains).
struct SettleLoop {
  long chunk_steps = 1;
  long chunks = 1;
  std::string what;             // "bed", "snow": what did not settle
  double max_settle_time_s = 0; // named in the failure line
  std::string settled_commands;
};
void write_settle_loop(std::ostringstream& s, const DemSpec& dem, const SettleLoop& loop);

// Requires scene.dem (InputError otherwise) and checks it (check_dem_spec).
// A chute's block (dem.slope_deg > 0) settles under gravity along -z, so
// every slope of a sweep shares one cached bed; its run tilts gravity at
// t = 0, when the gate goes.
std::string bed_script(const Scene& scene, const BedScriptOptions& options = {});

// One object as the run script sees it: its STL file name (relative to the
// run directory) and the mesh to write there, placed at its time-0 pose.
struct LiggghtsMeshFile {
  std::string file_name;  // "object_<k>.stl"
  std::string fix_id;     // "obj<k>": thermo columns f_obj<k>[1..3] are the force on it (N)
  TriangleMesh mesh;      // world coordinates at t = 0
};

struct RunScriptOptions {
  double thermo_interval_s = 0.001;  // thermo lines (progress, forces on meshes) this often
  double top_margin_m = 0.0;         // extra room above the highest object (0: 4 grain diameters)
};

struct RunScript {
  std::string text;
  std::vector<LiggghtsMeshFile> meshes;  // to be written (binary STL) next to the script
  DemDomain domain;  // the walls: the grid's extent, the floor at z = 0, up to above every object
  DemDomain box;     // the simulation box: the walls' extent grown in x and y to hold every object's motion
  long total_steps = 0;       // steps after reset_timestep 0 (for progress)
  long dump_interval_steps = 0;
};

// Requires scene.dem. The box reaches above the highest object (and on a
// chute, dem.slope_deg > 0, above the highest splash up the wall at its foot:
// 1.5 (settled height + grid length * tan slope)). Objects move as ObjectSpec::pose_at says, per segment
// between consecutive keyframe times of any object: a `fix move/mesh linear`
// (the body origin's velocity) and, where the orientation changes, a
// `fix move/mesh rotate` superposed on it (constant rate about the slerp's
// axis through the body origin), so the mesh ends each segment at the
// keyframed pose. Reads kBedRestartFile from the run directory.
RunScript run_script(const Scene& scene, const RunScriptOptions& options = {});

// The grains' materials, contact law (with sjkr cohesion when
// dem.cohesion_energy_density_j_m3 > 0; none with walls) and time step: the
// commands every script gives once the box exists (no gravity, no walls).
std::string liggghts_contact_commands(const DemSpec& dem);
// The grain-wall contact law of `fix wall/gran` (the grains' own, no cohesion).
std::string liggghts_wall_model(const DemSpec& dem);

// Round-trip exact, locale-independent number text ("%.17g" trimmed by std::to_chars).
std::string liggghts_number(double v);

}  // namespace repose
