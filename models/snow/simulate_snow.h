#pragma once
// A whole snow run: the probability once, from the shadow maps or by ray
// casting (options.probability; the paper holds P constant while
// animating), then time.step_count() steps of snowfall and stabilisation,
// with timings and the conservation check.

#include <functional>

#include "models/snow/snow_model.h"
#include "models/snow/snow_params.h"
#include "models/snow/snow_probability.h"
#include "models/snow/snow_state.h"

namespace repose {

struct SnowRunSummary {
  SnowProbability probability;
  int steps = 0;
  int unsettled_steps = 0;         // steps whose stabilisation hit max_stabilisation_passes
  long long stabilisation_passes = 0;
  double probability_wall_s = 0.0;
  double steps_wall_s = 0.0;
  double imbalance_m3 = 0.0;       // snow_imbalance_m3 at the end: round-off
};

// Validates params; runs from a fresh state into *state. on_step, if set, is
// called after every step (for frames of an animation).
SnowRunSummary simulate_snow(const SnowModel& model, const SnowParams& params, SnowState* state,
                             const std::function<void(int step, const SnowState&)>& on_step = {});

}  // namespace repose
