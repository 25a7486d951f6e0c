#pragma once
// The implicit integrator's springs by vertex pair (implicit_integrator.h):
// a cell edge shared by two cells is one spring of each (sheet_forces.h's
// cell_springs), the same pair and rest length, so its stiffness blocks are
// the same matrix times each constant. A link assembles them once with the
// sum of its intact cells' constants: 160,400 links for the 240,000
// springs of a 200 x 200 sheet, a third of the springs' assembly spared.

#include <array>
#include <vector>

#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_state.h"

namespace repose {

struct SpringLink {
  int a = 0, b = 0;
  double rest_length_m = 0.0;
  // the block index (the integrator's for_each_block_place) of its first
  // spring's four blocks, whose vertex order (a, b) it keeps
  int first = 0;
  // its springs' cells and constants (N/m); cell[1] -1 for one spring
  std::array<int, 2> cell = {-1, -1};
  std::array<double, 2> constant = {0.0, 0.0};

  // The sum of the constants of its intact cells' springs (0: none acts).
  double constant_in(const SheetState& state) const {
    double k = state.intact(cell[0]) ? constant[0] : 0.0;
    if (cell[1] >= 0 && state.intact(cell[1])) k += constant[1];
    return k;
  }
};

// The links of every cell's springs in the order of their first spring
// (cell by cell); spring_constant per spring 6 c + k (cell c's spring k).
// A pair is never shared by more than two springs, and its springs share
// a rest length (REPOSE_DEMAND).
std::vector<SpringLink> spring_links(const SheetModel& model, const std::vector<double>& spring_constant);

}  // namespace repose
