#pragma once
// Scratch of ground erosion (erosion.h) kept in the ground state between
// steps, so that a pass allocates nothing and never clears the whole grid.
// Derived data only: no result depends on it.

#include <array>
#include <cstdint>
#include <vector>

namespace repose {

// One pass's move of material between neighbouring cells (erosion.cpp).
struct ErosionFlux {
  std::int64_t from, to;
  double amount;
  double ceiling_m;  // over `to` (+inf: no object), found where its coordinates are known
};

struct ErosionScratch {
  // Per cell, m of height: what a pass sends into a cell under an object;
  // all 0 between passes (erosion.cpp, cap_inflow). Sized to the grid when first used.
  std::vector<double> inflow_m;
  // A pass's fluxes, and the remembered cells' (i, j) (erode() fills them
  // afresh every call): kept only so that their capacity is.
  std::vector<ErosionFlux> fluxes;
  std::vector<std::array<int, 3>> ij;  // (i, j, 1 where all four neighbours are on the grid)
  // A pass's pairs over the smallest limit: (index in the memory's cells, direction).
  std::vector<std::array<std::int32_t, 2>> candidates;
};

}  // namespace repose
