#pragma once
// What a run of the sheet changes: vertex positions and velocities, which
// cells are torn and when, the time, and what the grips feel.

#include <vector>

#include <Eigen/Core>

#include "models/tearing/sheet_model.h"

namespace repose {

struct SheetState {
  Eigen::Matrix3Xd positions;   // 3 x vertex_count (m)
  Eigen::Matrix3Xd velocities;  // 3 x vertex_count (m/s)
  // Per cell: -1 while intact, 0 for the notch cut before the run, n >= 1
  // when it tore at the start of step n.
  std::vector<int> torn_step;
  // Per cell, for torn cells still letting go (SheetSpec::release_time_s):
  // the fraction of its springs, dashpots, twist term and bending share it
  // still holds, in (0, 1]; 0 for every other cell (empty: all 0). hold()
  // below is the one reading of it.
  std::vector<double> releasing;
  // Per spring of each cell (6 per cell, cell_springs' order), under
  // tear_rule cohesive (cohesive_law.h): the largest strain it has reached
  // past its peak, 0 while it never has (empty under the other rules).
  std::vector<double> softening;
  long steps = 0;
  double time_s = 0.0;
  // 3 x grip count: the force each grip exerts on the sheet along its held
  // axes (N) during the last step, and the work the grips have done (J).
  Eigen::Matrix3Xd grip_force_n;
  double grip_work_j = 0.0;
  // The elastic energy (J) the springs of each cell held at the moment it
  // tore, summed over the run (the notch excluded): the energy the tear
  // itself took out of the sheet, apart from what the grips put into the
  // flaps' motion, drag and the strain still stored (tear_run.h); under
  // tear_rule cohesive also the work its softening springs dissipated.
  double torn_energy_j = 0.0;
  // The part of torn_energy_j the softening springs of tear_rule cohesive
  // dissipated before their cells tore (cohesive_law.h; 0 under the others).
  double softening_energy_j = 0.0;
  // The energy (J) the twist terms of those cells held when they tore
  // (SheetSpec::twist_stiffness; 0 without): lost with the cell, not
  // counted as fracture energy (sheet_model.h).
  double torn_twist_energy_j = 0.0;
  // The energy (J) the bending terms held when their cells let go: under
  // the seed's snap, what each term held at the step its last holding
  // cell tore (sheet_forces.h); with SheetSpec::release_time_s > 0, what
  // they gave up as the cells faded (cell_release.h).
  double torn_bending_energy_j = 0.0;
  // The kinetic energy (J) the mass-proportional damping (damping_per_s) has
  // taken from the free vertices, summed over the run; the explicit
  // integrator keeps it (the implicit one leaves it 0: its damping is inside
  // the solve). For the energy ledger (tear_run.h).
  double damping_loss_j = 0.0;

  bool intact(int cell) const { return torn_step[static_cast<std::size_t>(cell)] < 0; }
  // How much of its springs cell holds: 1 intact, 0 torn and let go, in
  // between while a torn cell is released.
  double hold(int cell) const {
    if (intact(cell)) return 1.0;
    return releasing.empty() ? 0.0 : releasing[static_cast<std::size_t>(cell)];
  }
  int torn_count() const;
};

// The sheet at rest in its rest shape, the notch cut.
SheetState make_sheet_state(const SheetModel& model);

}  // namespace repose
