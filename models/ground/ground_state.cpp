#include "models/ground/ground_state.h"

#include "models/core/base/error.h"
#include "models/ground/ground_model.h"

namespace repose {

GroundState make_ground_state(const GroundModel& model, HeightField initial) {
  REPOSE_DEMAND(initial.grid() == model.grid);
  REPOSE_DEMAND(initial.grid().cell_count() == 0 || initial.min_height_m() >= 0.0);
  GroundState state;
  state.height = std::move(initial);
  state.erosion = ErosionMemory(model.grid.cell_count(), model.options.erosion_memory_steps);
  for (const ObjectSpec& o : model.objects) state.previous_poses.push_back(o.pose_at(0.0));
  state.ledger.initial_m3 = state.height.volume_m3();
  return state;
}

}  // namespace repose
