#include "models/tearing/cell_release.h"

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "models/core/base/error.h"
#include "models/tearing/sheet_forces.h"

namespace repose {

namespace {

// The bending terms' hold lost by moving state's holds to `next`, times
// their energy at full strength, the mean over x0 and the state's
// positions (J).
double released_bending_energy_j(const SheetModel& model, const SpringConstants& k, const std::vector<double>& next,
                                 const Eigen::Matrix3Xd& x0, SheetState* state) {
  SheetState after_holds;  // only torn_step and releasing are read by bending_hold
  after_holds.torn_step = state->torn_step;
  after_holds.releasing = next;
  double released = 0.0;
  for (const BendingTerm& t : model.bending) {
    const double before = bending_hold(t, *state);
    if (before == 0.0) continue;
    const double lost = before - bending_hold(t, after_holds);
    if (lost != 0.0) {
      released += lost * 0.5 * (bending_term_energy_j(k, t, x0) + bending_term_energy_j(k, t, state->positions));
    }
  }
  return released;
}

}  // namespace

int release_torn_cells(const SheetModel& model, const SheetParams& params, double time_step_s,
                       const Eigen::Matrix3Xd& step_start_positions, SheetState* state) {
  const double release_s = model.spec.release_time_s;
  if (release_s == 0.0) return 0;
  REPOSE_DEMAND(state->releasing.size() == static_cast<std::size_t>(model.cell_count()) &&
                step_start_positions.cols() == state->positions.cols());
  const double fall = time_step_s / release_s;
  std::vector<double> next = state->releasing;
  bool any = false;
  for (double& r : next) {
    if (r > 0.0) {
      r = std::max(0.0, r - fall);
      any = true;
    }
  }
  if (!any) return 0;
  const SpringConstants k = spring_constants(model, params);
  int still = 0;
  for (int c = 0; c < model.cell_count(); ++c) {
    const std::size_t i = static_cast<std::size_t>(c);
    const double lost = state->releasing[i] - next[i];
    if (lost == 0.0) continue;
    const Eigen::Matrix3Xd& x0 = step_start_positions;
    const Eigen::Matrix3Xd& x1 = state->positions;
    state->torn_energy_j +=
        lost * 0.5 * (cell_springs_energy_j(model, k, x0, c) + cell_springs_energy_j(model, k, x1, c));
    state->torn_twist_energy_j +=
        lost * 0.5 * (cell_twist_energy_j(model, k, x0, c) + cell_twist_energy_j(model, k, x1, c));
    if (next[i] > 0.0) ++still;
  }
  state->torn_bending_energy_j += released_bending_energy_j(model, k, next, step_start_positions, state);
  state->releasing = std::move(next);
  return still;
}

}  // namespace repose
