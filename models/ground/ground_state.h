#pragma once
// What the ground model changes while it runs (as MuJoCo's mjData): the
// height field, the cells that keep eroding, where each object was at the
// end of the last step, and the volume ledger.

#include <vector>

#include "models/core/geometry/height_field.h"
#include "models/core/geometry/triangle_mesh.h"
#include "models/ground/erosion_memory.h"
#include "models/ground/erosion_scratch.h"
#include "models/ground/swept_mesh.h"
#include "models/ground/volume_ledger.h"

namespace repose {

struct GroundModel;

struct GroundState {
  HeightField height;
  ErosionMemory erosion;
  std::vector<Pose> previous_poses;  // one per model object, at time_s
  // Per model object (or none yet): what the vertical sweep of its body
  // keeps from step to step. Derived data only: the results do not depend on it.
  std::vector<VerticalSweepCache> sweep_caches;
  // Scratch of erosion kept between steps (erosion.h). Derived data only.
  ErosionScratch erosion_scratch;
  VolumeLedger ledger;
  double time_s = 0.0;
  int step_index = 0;
};

// The state at time 0: the given initial heights (on the model's grid), the
// objects at their poses at time 0, an empty erosion memory. Heights are
// material above the base (displacement.h): the initial ones must be >= 0
// (the scene loader refuses others), and the model keeps them so.
GroundState make_ground_state(const GroundModel& model, HeightField initial);

}  // namespace repose
