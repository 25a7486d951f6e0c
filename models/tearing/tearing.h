#pragma once
// Tearing as the seed paper does it (section 3.2): when a spring is stretched
// past the limit, every spring of its cell goes at once and the vertices
// stay. Every intact cell is judged on the same positions and all cells over
// the limit tear together, so the torn set does not depend on the order the
// cells are stored in (a cell's springs are its own, sheet_model.h). An edge
// shared by two cells has the same strain in both, so both tear.
//
// The limit is one strain for every spring, as in the seed (or, optionally,
// one set by an energy per unit tear length and the cell size: tear_limit.h;
// or springs that soften past a peak before the cell goes: cohesive_law.h);
// in a fibre image the soft cells between clumps stretch most and go first,
// which is what makes the tear follow the gaps between clumps.
//
// Departure from the seed, optional: SheetSpec::release_time_s > 0 lets a
// torn cell go gradually instead of at once (cell_release.h); tear_and_internal_forces
// (sheet_forces.h) starts it, the explicit integrator fades it.

#include <vector>

#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_params.h"
#include "models/tearing/sheet_state.h"

namespace repose {

// Intact cells with a spring strained past their limit (tear_limit.h), in cell order.
std::vector<int> overstretched_cells(const SheetModel& model, const SheetParams& params, const SheetState& state);

// Marks overstretched_cells torn at step `step_number`; returns how many.
int tear_overstretched_cells(const SheetModel& model, const SheetParams& params, int step_number, SheetState* state);

}  // namespace repose
