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
  // on an inclined bed the initial heap is not at rest: every cell holding
  // material starts remembered (on a level bed only objects start erosion)
  if (model.options.bed_slope_rad > 0.0) {
    const double* h = state.height.heights().data();
    for (std::int64_t c = 0; c < static_cast<std::int64_t>(model.grid.cell_count()); ++c) {
      if (h[c] > 0.0) state.erosion.touch(c);
    }
  }
  state.ledger.initial_m3 = state.height.volume_m3();
  return state;
}

}  // namespace repose
