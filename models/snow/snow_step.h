#pragma once
// One time step of the snow model (the snow paper 2.3 and 2.4): snowfall
// S_a += P_a * (integral of M over the step) on every map cell (eq. 1 over
// one step, exact for the piecewise-linear M), then stabilisation with
// falling between maps (stabilisation.h).

#include "models/snow/snow_model.h"
#include "models/snow/snow_params.h"
#include "models/snow/snow_probability.h"
#include "models/snow/snow_state.h"
#include "models/snow/stabilisation.h"

namespace repose {

// Adds probability * depth_m to every map and the fallen volume to the ledger.
void accumulate_snow(const SnowProbability& probability, double depth_m, const Grid& grid, SnowState* state);

struct SnowStepResult {
  double snowfall_depth_m = 0.0;  // integral of M over the step
  StabilisationResult stabilisation;
};

// Advances state->time_s by the model's step (the last step ends at the duration).
SnowStepResult step_snow(const SnowModel& model, const SnowParams& params, const SnowProbability& probability,
                         SnowState* state);

}  // namespace repose
