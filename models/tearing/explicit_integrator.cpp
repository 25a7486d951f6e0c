#include "models/tearing/explicit_integrator.h"

#include <cmath>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/tearing/cell_release.h"
#include "models/tearing/sheet_forces.h"
#include "models/tearing/stable_time_step.h"

namespace repose {

ExplicitIntegrator::ExplicitIntegrator(const SheetModel& model, const SheetParams& params, double time_step_s)
    : model_(model), params_(params), dt_(time_step_s), stable_dt_(repose::stable_time_step_s(model, params)) {
  if (!(std::isfinite(time_step_s) && time_step_s > 0.0)) {
    throw InputError(fmt::format("tearing: time_step_s = {} must be > 0", time_step_s));
  }
  if (time_step_s > stable_dt_) {
    throw InputError(fmt::format(
        "tearing: time_step_s = {:.4g} s is above the explicit integrator's stable limit {:.4g} s (2 / w_max from "
        "the stiffest spring and lightest vertex); lower it, or lower stiffness_n_per_m, or coarsen the mesh",
        time_step_s, stable_dt_));
  }
}

int ExplicitIntegrator::step(SheetState* state) {
  REPOSE_DEMAND(state->positions.cols() == model_.vertex_count());
  const int torn = tear_and_internal_forces(model_, params_, static_cast<int>(state->steps + 1), state, &forces_);
  if (model_.spec.release_time_s > 0.0) step_start_positions_ = state->positions;
  const double t_next = state->time_s + dt_;
  const double damping = 1.0 / (1.0 + model_.spec.damping_per_s * dt_);
  const Eigen::Vector3d& g = model_.spec.gravity_m_per_s2;
  state->grip_force_n.setZero();
  for (int v = 0; v < model_.vertex_count(); ++v) {
    const double m = model_.mass_kg[v];
    const int grip = model_.grip_of_vertex[static_cast<std::size_t>(v)];
    for (int a = 0; a < 3; ++a) {
      if (model_.held_axes[static_cast<std::size_t>(v)] & (1u << a)) {
        const double speed = model_.spec.grips[static_cast<std::size_t>(grip)].velocity_m_per_s[a];
        state->grip_force_n(a, grip) -= forces_(a, v) + m * g[a];
        state->velocities(a, v) = speed;
        state->positions(a, v) = model_.rest_positions(a, v) + speed * t_next;
      } else {
        const double undamped = state->velocities(a, v) + dt_ * (forces_(a, v) / m + g[a]);
        state->damping_loss_j += 0.5 * m * undamped * undamped * (1.0 - damping * damping);
        state->velocities(a, v) = undamped * damping;
        state->positions(a, v) += dt_ * state->velocities(a, v);
      }
    }
  }
  for (std::size_t k = 0; k < model_.spec.grips.size(); ++k) {
    state->grip_work_j += dt_ * state->grip_force_n.col(static_cast<Eigen::Index>(k)).dot(
                                    model_.spec.grips[k].velocity_m_per_s);
  }
  // the holds fall after the move, their energy booked over x_n .. x_{n+1}
  release_torn_cells(model_, params_, dt_, step_start_positions_, state);
  state->time_s = t_next;
  ++state->steps;
  return torn;
}

}  // namespace repose
