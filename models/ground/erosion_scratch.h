#pragma once
// Scratch of ground erosion (erosion.h) kept in the ground state between
// steps, so that a pass allocates nothing and never clears the whole grid.
// Derived data only: no result depends on it.

#include <vector>

namespace repose {

struct ErosionScratch {
  // Per cell, m of height: what a pass sends into a cell under an object;
  // all 0 between passes (erosion.cpp, cap_inflow). Sized to the grid when first used.
  std::vector<double> inflow_m;
};

}  // namespace repose
