#include "models/tearing/tear_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/fields.h"
#include "models/tearing/explicit_integrator.h"
#include "models/tearing/implicit_integrator.h"
#include "models/tearing/sheet_forces.h"
#include "models/tearing/stable_time_step.h"

namespace repose {

void TearRunOptions::validate() const {
  if (!(std::isfinite(duration_s) && duration_s > 0.0)) {
    throw FieldError("duration_s", "a duration > 0 s", fmt::format("{}", duration_s));
  }
  const double most = integrator == Integrator::kExplicit ? 1.0 : 1000.0;
  if (!(time_step_fraction > 0.0 && time_step_fraction <= most)) {
    throw FieldError("time_step_fraction", fmt::format("a number in (0, {}] for this integrator", most),
                     fmt::format("{}", time_step_fraction));
  }
  if (!(std::isfinite(stop_at_depth_m) && stop_at_depth_m >= 0.0)) {
    throw FieldError("stop_at_depth_m", "a depth >= 0 m", fmt::format("{}", stop_at_depth_m));
  }
  for (std::size_t k = 0; k < snapshot_times_s.size(); ++k) {
    const double t = snapshot_times_s[k];
    if (!(std::isfinite(t) && t >= 0.0 && (k == 0 || t >= snapshot_times_s[k - 1]))) {
      throw FieldError("snapshot_times_s", "ascending times >= 0 s", fmt::format("{} (entry {})", t, k));
    }
  }
  implicit_solver.validate();
}

namespace {

// A sample of TearTrRun::grip_force_n: the mean force over the steps since
// the last one (so that the series sums to the grips' work exactly).
void sample_grip_force(Eigen::Matrix3Xd* impulse, TearRun* run) {
  const double since_s = run->state.time_s - (run->force_time_s.empty() ? 0.0 : run->force_time_s.back());
  run->force_time_s.push_back(run->state.time_s);
  run->grip_force_n.push_back(*impulse / since_s);
  impulse->resize(3, 0);
}

template <class Integrator>
void pull(const SheetModel& model, const TearRunOptions& options, const ProgressFn& progress, Integrator* integrator,
          TearRun* run) {
  const long steps = static_cast<long>(std::ceil(options.duration_s / run->time_step_s));
  const long check_every = std::max(1L, steps / 200);
  const long sample_every = std::max(1L, steps / 1000);
  Eigen::Matrix3Xd impulse;  // sum of dt x the grips' force since the last sample
  for (long s = 0; s < steps; ++s) {
    const int torn = integrator->step(&run->state);
    for (Eigen::Index g = 0; g < run->state.grip_force_n.cols(); ++g) {
      run->peak_grip_force_n = std::max(run->peak_grip_force_n, run->state.grip_force_n.col(g).norm());
    }
    impulse = impulse.size() == 0 ? Eigen::Matrix3Xd(run->time_step_s * run->state.grip_force_n)
                                  : Eigen::Matrix3Xd(impulse + run->time_step_s * run->state.grip_force_n);
    if ((s + 1) % sample_every == 0) sample_grip_force(&impulse, run);
    while (run->snapshots.size() < options.snapshot_times_s.size() &&
           run->state.time_s >= options.snapshot_times_s[run->snapshots.size()]) {
      run->snapshots.push_back(run->state);
    }
    if (s % check_every == 0) report(progress, static_cast<double>(s) / static_cast<double>(steps), "tearing");
    // the tear deepens only on a step that tears a cell: judged on every
    // such step (and the first, for a notch already deep enough), the run
    // stops on the step the depth is reached, whatever the mesh (judged
    // every 1/200 of the duration, it ran on by up to 0.15 ms at the seed's
    // 4 m/s, ~2 % of the grips' work at 100 cells: TearRun tests)
    if (options.stop_at_depth_m > 0.0 && (torn > 0 || s == 0) &&
        measure_tear_path(model, run->state).depth_m >= options.stop_at_depth_m) {
      break;
    }
  }
  if (impulse.size() > 0) sample_grip_force(&impulse, run);
}

}  // namespace

EnergyLedger energy_ledger(const SheetModel& model, const SheetParams& params, const SheetState& state) {
  EnergyLedger e;
  e.stored = elastic_energy(model, params, state);
  e.stored_j = e.stored.total_j();
  const Eigen::Vector3d& g = model.spec.gravity_m_per_s2;
  for (int v = 0; v < model.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) {
      if (model.held_axes[static_cast<std::size_t>(v)] & (1u << a)) continue;
      const double m = model.mass_kg[v], speed = state.velocities(a, v);
      e.kinetic_j += 0.5 * m * speed * speed;
      e.gravity_j += m * g[a] * (state.positions(a, v) - model.rest_positions(a, v));
    }
  }
  e.damping_j = state.damping_loss_j;
  e.fracture_j = state.torn_energy_j;
  e.softening_j = state.softening_energy_j;
  e.torn_twist_j = state.torn_twist_energy_j;
  e.torn_bending_j = state.torn_bending_energy_j;
  e.residual_j = state.grip_work_j + e.gravity_j - e.stored_j - e.kinetic_j - e.damping_j - e.fracture_j -
                 e.torn_twist_j - e.torn_bending_j;
  return e;
}

TearRun run_tear(const SheetModel& model, const SheetParams& params, const TearRunOptions& options,
                 const ProgressFn& progress) {
  options.validate();
  params.validate();
  const auto start = std::chrono::steady_clock::now();
  TearRun run;
  run.stable_time_step_s = stable_time_step_s(model, params);
  run.time_step_s = options.time_step_fraction * run.stable_time_step_s;
  run.state = make_sheet_state(model);
  if (options.integrator == TearRunOptions::Integrator::kExplicit) {
    ExplicitIntegrator integrator(model, params, run.time_step_s);
    pull(model, options, progress, &integrator, &run);
  } else {
    ImplicitIntegrator integrator(model, params, run.time_step_s, options.implicit_solver);
    pull(model, options, progress, &integrator, &run);
  }
  REPOSE_DEMAND(run.state.positions.allFinite());
  run.steps = run.state.steps;
  run.path = measure_tear_path(model, run.state);
  run.grip_work_j = run.state.grip_work_j;
  run.ledger = energy_ledger(model, params, run.state);
  // the notch is not torn by the pull: take it off when the tear holds it
  const bool from_notch = !model.notch_cells.empty() && run.path.holds_notch;
  const double notch_depth_m = from_notch ? static_cast<double>(model.notch_cells.size()) * model.cell_size_m : 0.0;
  run.tear_length_m = std::max(0.0, run.path.depth_m - notch_depth_m);
  if (run.tear_length_m > 0.0) {
    run.work_per_tear_length_j_per_m = run.grip_work_j / run.tear_length_m;
    run.fracture_energy_per_tear_length_j_per_m = run.state.torn_energy_j / run.tear_length_m;
    run.fracture_energy_per_path_length_j_per_m =
        run.fracture_energy_per_tear_length_j_per_m / std::max(1.0, run.path.tortuosity);
  }
  run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace repose
