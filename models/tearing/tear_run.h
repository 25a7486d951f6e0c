#pragma once
// A tear run: the sheet pulled by its grips with either integrator for a
// given time, what the grips felt, and the tear it made.

#include <vector>

#include <Eigen/Core>

#include "models/core/base/progress.h"
#include "models/tearing/implicit_integrator.h"
#include "models/tearing/sheet_forces.h"
#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_params.h"
#include "models/tearing/sheet_state.h"
#include "models/tearing/tear_path.h"

namespace repose {

struct TearRunOptions {
  enum class Integrator { kExplicit, kImplicit };
  Integrator integrator = Integrator::kExplicit;
  double duration_s = 0.02;
  // The step as a fraction of the explicit stable limit: in (0, 1] for the
  // explicit integrator, (0, 1000] for the implicit one.
  double time_step_fraction = 0.9;
  // Stop at the end of the first step whose tear reaches this depth below
  // the top edge (m); 0: run the whole duration.
  double stop_at_depth_m = 0.0;
  // Times (s, ascending, >= 0) at which to keep a copy of the sheet's state
  // (TearRun::snapshots), for figures over time; not read from scenes.
  std::vector<double> snapshot_times_s;
  // The implicit integrator's linear solver (implicit_integrator.h); not
  // read from scenes: the benchmark compares preconditioners over whole tears.
  ImplicitSolverOptions implicit_solver;

  void validate() const;  // throws FieldError (an InputError) naming the field
};

// Where the grips' work went by the end of a run (J): the sheet starts at
// rest in its rest shape, so
//   grip work + gravity's work = stored + kinetic + damping + fracture + torn twist + torn bending + residual,
// the residual being the integrator's own energy error (first order in the
// step through a softening tear: cohesive_law_test.cpp) plus what the
// ledger does not itemise (the dashpots of stiffness_damping_s; the
// bending terms snapped cells take out are torn bending). Kinetic energy and gravity's work
// are over the free degrees of freedom (the grips move the held ones and
// carry their weight). damping_j is 0 for the implicit integrator, whose
// damping then sits in the residual.
struct EnergyLedger {
  double stored_j = 0.0;     // elastic, intact springs, acting bending and twist terms
  ElasticEnergy stored;      // stored_j by kind (its total_j() is stored_j)
  double kinetic_j = 0.0;    // free degrees of freedom
  double gravity_j = 0.0;    // work gravity did on them
  double damping_j = 0.0;    // SheetState::damping_loss_j
  double fracture_j = 0.0;   // SheetState::torn_energy_j
  double softening_j = 0.0;  // SheetState::softening_energy_j, a part of fracture_j (tear_rule cohesive)
  double torn_twist_j = 0.0;  // SheetState::torn_twist_energy_j
  double torn_bending_j = 0.0;  // SheetState::torn_bending_energy_j
  double residual_j = 0.0;
};

EnergyLedger energy_ledger(const SheetModel& model, const SheetParams& params, const SheetState& state);

struct TearRun {
  SheetState state;
  TearPath path;
  double time_step_s = 0.0;
  double stable_time_step_s = 0.0;  // of the explicit integrator
  long steps = 0;
  // Largest force (N) any grip exerted along its held axes over the run.
  double peak_grip_force_n = 0.0;
  double grip_work_j = 0.0;
  // How far the tear ran below the notch (m): path.depth_m minus the notch.
  double tear_length_m = 0.0;
  // grip_work_j / tear_length_m (J/m), elastic energy still stored included;
  // 0 when the sheet did not tear.
  double work_per_tear_length_j_per_m = 0.0;
  // state.torn_energy_j / tear_length_m (J/m): the energy the torn cells
  // held when they tore, per unit tear length, i.e. the part of the work
  // the tear rule dissipates (under the energy rule a fixed fraction of
  // tear_energy_j_per_m, whatever the mesh); 0 when the sheet did not tear.
  double fracture_energy_per_tear_length_j_per_m = 0.0;
  // The same energy per unit length of the tortuous torn path,
  // state.torn_energy_j / (tear_length_m x path.tortuosity) (J/m): a tear
  // that wanders tears more cells per unit depth; this is the energy per
  // unit length of what tore. 0 when the sheet did not tear.
  double fracture_energy_per_path_length_j_per_m = 0.0;
  // The grips' forces over time: a sample every max(1, steps / 1000) steps
  // of the duration and one at the last step run, each its end time (s) and
  // every grip's force on the sheet's held vertices (N, 3 x grips,
  // SheetState::grip_force_n) averaged over the steps since the previous
  // sample, so that sum (interval x force . grip velocity) is grip_work_j
  // (instantaneous samples alias the explicit sheet's fast force ripple:
  // 7 % off the work in TearRun tests).
  std::vector<double> force_time_s;
  std::vector<Eigen::Matrix3Xd> grip_force_n;
  // The state at the end of the first step reaching each of
  // options.snapshot_times_s that the run reached (a run stopped early by
  // stop_at_depth_m has fewer).
  std::vector<SheetState> snapshots;
  EnergyLedger ledger;  // at the end of the run
  double wall_seconds = 0.0;
};

// progress, when given, hears the fraction of the duration done.
TearRun run_tear(const SheetModel& model, const SheetParams& params, const TearRunOptions& options,
                 const ProgressFn& progress = {});

}  // namespace repose
