#include "models/tearing/sheet_state.h"

#include <algorithm>

namespace repose {

int SheetState::torn_count() const {
  return static_cast<int>(std::count_if(torn_step.begin(), torn_step.end(), [](int s) { return s >= 0; }));
}

SheetState make_sheet_state(const SheetModel& model) {
  SheetState s;
  s.positions = model.rest_positions;
  s.velocities = Eigen::Matrix3Xd::Zero(3, model.vertex_count());
  s.torn_step.assign(static_cast<std::size_t>(model.cell_count()), -1);
  s.releasing.assign(static_cast<std::size_t>(model.cell_count()), 0.0);
  if (model.spec.tear_rule == TearRule::kCohesive) s.softening.assign(6 * static_cast<std::size_t>(model.cell_count()), 0.0);
  for (const int c : model.notch_cells) s.torn_step[static_cast<std::size_t>(c)] = 0;
  s.grip_force_n = Eigen::Matrix3Xd::Zero(3, static_cast<Eigen::Index>(model.spec.grips.size()));
  return s;
}

}  // namespace repose
