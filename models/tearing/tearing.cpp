#include "models/tearing/tearing.h"

#include "models/tearing/sheet_forces.h"

namespace repose {

std::vector<int> overstretched_cells(const SheetModel& model, const SheetParams& params, const SheetState& state) {
  std::vector<int> cells;
  for (int c = 0; c < model.cell_count(); ++c) {
    if (state.intact(c) && cell_overstretched(model, params, state, c)) cells.push_back(c);
  }
  return cells;
}

int tear_overstretched_cells(const SheetModel& model, const SheetParams& params, int step_number, SheetState* state) {
  const std::vector<int> cells = overstretched_cells(model, params, *state);
  for (const int c : cells) state->torn_step[static_cast<std::size_t>(c)] = step_number;
  return static_cast<int>(cells.size());
}

}  // namespace repose
