#pragma once
// A torn cell let go gradually (SheetSpec::release_time_s > 0) instead of
// the seed's snap: its springs, dashpots, twist term and its share in the
// bending terms fade linearly from full strength, at the step it tears, to
// nothing release_time_s later (SheetState::releasing, read through
// SheetState::hold). The energy the cell gives up as it fades is booked
// where the snap books it whole: springs to SheetState::torn_energy_j
// (fracture), twist to torn_twist_energy_j, and the bending terms' to
// torn_bending_energy_j, so the energy ledger (tear_run.h) still closes.

#include <Eigen/Core>

#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_params.h"
#include "models/tearing/sheet_state.h"

namespace repose {

// Lowers every releasing cell's hold by time_step_s / release_time_s (to no
// less than 0), booking the hold lost x the full-strength energy, the mean
// of its values at step_start_positions and at the state's positions (the
// trapezoid rule over the step: booked at either end alone, a fade of ten
// steps left 2 % of the grips' work in the ledger's residual). Call once a
// step, after the step's forces were taken at the old holds and the
// positions moved (explicit_integrator.h). Does nothing when
// release_time_s is 0. Returns how many cells are still releasing.
int release_torn_cells(const SheetModel& model, const SheetParams& params, double time_step_s,
                       const Eigen::Matrix3Xd& step_start_positions, SheetState* state);

}  // namespace repose
