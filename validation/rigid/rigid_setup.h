#pragma once
// A scene's grains, ground box and objects as a rigid-body world
// (rigid_world.h): the same grain count, radius distribution and material
// as the LIGGGHTS bed of the scene, so that the three references start from
// comparable beds.
//
// The LIGGGHTS bed inserts grains at random into a region and lets them
// fall; here they start on a loose cubic lattice (every random draw from the
// scene seed: each grain's radius, a jitter smaller than the gaps so no two
// grains overlap) and fall the same way. Settling happens without the
// objects (as for LIGGGHTS), which join for the run.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "models/core/config/scene.h"
#include "models/core/geometry/grid.h"
#include "validation/particles/chute_impact.h"
#include "validation/particles/column_geometry.h"
#include "validation/particles/dem_section.h"
#include "validation/particles/grain_set.h"
#include "validation/rigid/rigid_options.h"
#include "validation/rigid/rigid_world.h"

namespace repose {

// The parts of a scene a rigid reference reads: the dem section and the
// common scene (grid, objects, time, seed); nothing of other sections.
struct RigidInputs {
  DemSpec dem;
  Grid grid;
  std::vector<ObjectSpec> objects;
  TimeSpec time;
  std::uint64_t seed = 0;
  std::optional<ColumnGeometry> column;  // dem.initial: column
  std::optional<ChuteGeometry> chute;    // dem.impact_window_m > 0: the wall and window (chute_impact.h)
};

// Throws InputError naming `solver` for a scene without a dem section, or a
// column that does not fit the grid (column_geometry.h).
RigidInputs rigid_inputs(const Scene& scene, const std::string& solver);

// Grains that fill the grid area up to dem.bed_depth_m (a column: its
// footprint up to column_height_m) at packing_fraction (the LIGGGHTS bed's count).
long rigid_grain_count(const RigidInputs& in, const RigidOptions& options);

// The grains before settling: a loose lattice over the grid (a column: over
// its footprint, inside the gate), from the floor up, radii drawn from
// grain_radii_m(dem) (liggghts_script.h). Throws InputError when the region
// is narrower than one grain.
GrainSet grain_lattice(const RigidInputs& in, const RigidOptions& options);

// The world to settle: the lattice in the ground box (a column: behind its
// gate, a wall at x = gate_x_m for a slot, a ring of 32 boxes around a
// cylinder, removed at t = 0 as in LIGGGHTS), no objects.
RigidWorldSpec settling_world(const RigidInputs& in, const RigidOptions& options);
// The world of the run: settled grains, the ground box (high enough for
// the objects), the objects kinematic, gravity tilted on a chute (the bed
// settles under gravity along -z, as LIGGGHTS's does).
RigidWorldSpec run_world(const RigidInputs& in, const GrainSet& settled);

}  // namespace repose
