#include "models/snow/snow_step.h"

#include <algorithm>

#include "models/core/base/error.h"

namespace repose {

void accumulate_snow(const SnowProbability& probability, double depth_m, const Grid& grid, SnowState* state) {
  REPOSE_DEMAND(probability.per_map.size() == state->depth_m.size() && depth_m >= 0.0);
  double fallen = 0.0;
  for (std::size_t m = 0; m < state->depth_m.size(); ++m) {
    const ArrayXXdR added = probability.per_map[m] * depth_m;
    state->depth_m[m] += added;
    fallen += added.sum();
  }
  state->ledger.fallen_m3 += fallen * grid.cell_area_m2();
}

SnowStepResult step_snow(const SnowModel& model, const SnowParams& params, const SnowProbability& probability,
                         SnowState* state) {
  const double t0 = state->time_s;
  const double t1 = std::min(t0 + model.time.step_s, model.time.duration_s);
  SnowStepResult result;
  result.snowfall_depth_m = params.snowfall_scale * model.options.snowfall.depth_between_m(t0, std::max(t0, t1));
  accumulate_snow(probability, result.snowfall_depth_m, model.grid, state);
  result.stabilisation = stabilise(model, params, state);
  state->time_s = std::max(t0, t1);
  return result;
}

}  // namespace repose
