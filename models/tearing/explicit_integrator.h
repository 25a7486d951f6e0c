#pragma once
// Semi-implicit (symplectic) Euler for the sheet, with tearing (the seed
// paper's section 3.2). Each step n:
//   1. tear: every intact cell with a spring stretched past tear_strain at
//      x_n loses all its springs; all such cells tear together, decided on
//      the same positions, so the result does not depend on the order cells
//      are stored (tearing.h);
//      with SheetSpec::release_time_s > 0 the torn cells let go gradually
//      instead: f below takes them at their holds, which fall by
//      dt / release_time_s after step 3 (cell_release.h);
//   2. v_{n+1} = (v_n + dt (f(x_n, v_n) / m + g)) / (1 + damping dt), f the
//      elastic forces and the springs' dashpots (SheetSpec::stiffness_damping_s);
//   3. x_{n+1} = x_n + dt v_{n+1};
// held axes of gripped vertices follow their grip instead, and the force the
// grip needs to do so is recorded (SheetState::grip_force_n).
// Without damping, gravity or grips the scheme conserves linear and angular
// momentum exactly (pairwise central and rotation-invariant forces), and
// its energy oscillates without drift below the stable step.

#include <Eigen/Core>

#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_params.h"
#include "models/tearing/sheet_state.h"

namespace repose {

class ExplicitIntegrator {
 public:
  // Refuses (InputError naming time_step_s) a step above
  // stable_time_step_s(model, params) or not positive. model and params
  // must outlive the integrator.
  ExplicitIntegrator(const SheetModel& model, const SheetParams& params, double time_step_s);

  double time_step_s() const { return dt_; }
  double stable_time_step_s() const { return stable_dt_; }

  // One step; returns the number of cells torn in it.
  int step(SheetState* state);

 private:
  const SheetModel& model_;
  const SheetParams& params_;
  double dt_ = 0.0;
  double stable_dt_ = 0.0;
  Eigen::Matrix3Xd forces_;
  Eigen::Matrix3Xd step_start_positions_;  // x_n, kept only with release_time_s > 0
};

}  // namespace repose
