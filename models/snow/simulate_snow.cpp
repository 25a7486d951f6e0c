#include "models/snow/simulate_snow.h"

#include <chrono>

#include "models/snow/ray_cast_probability.h"
#include "models/snow/snow_step.h"

namespace repose {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

SnowRunSummary simulate_snow(const SnowModel& model, const SnowParams& params, SnowState* state,
                             const std::function<void(int step, const SnowState&)>& on_step) {
  validate(params);
  SnowRunSummary summary;
  auto start = std::chrono::steady_clock::now();
  const std::vector<Eigen::Vector3d> directions = snowfall_directions(model, params);
  summary.probability = model.options.probability == SnowOptions::Probability::kRayCast
                            ? snow_probability_ray_cast(model, directions)
                            : snow_probability_shadow_maps(model, directions);
  summary.probability_wall_s = seconds_since(start);
  *state = make_snow_state(model);
  start = std::chrono::steady_clock::now();
  const int steps = model.time.step_count();
  for (int k = 0; k < steps; ++k) {
    const SnowStepResult r = step_snow(model, params, summary.probability, state);
    ++summary.steps;
    summary.stabilisation_passes += r.stabilisation.passes;
    if (!r.stabilisation.settled) ++summary.unsettled_steps;
    if (on_step) on_step(k, *state);
  }
  summary.steps_wall_s = seconds_since(start);
  summary.imbalance_m3 = snow_imbalance_m3(*state, model.grid);
  return summary;
}

}  // namespace repose
