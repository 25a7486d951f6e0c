#pragma once
// The surface height field of a set of grains on a grid: over each cell, the
// top of the union of the spheres seen straight down at the cell centre,
//   h(i, j) = max over grains with |c_xy - p_xy| < r of  z + sqrt(r^2 - |c_xy - p_xy|^2),
// the same thing the heuristic's height field describes (material top above z = 0).
//
// Cells whose centre no grain covers: a centre in a gap between grains of a
// bed (at least gap_covered_fraction of its neighbours inside the grid, of
// up to 8, are covered) takes the lowest of its covered neighbours' tops,
// since the true surface in a gap lies below the grains around it; any other
// uncovered cell (beyond the edge of a pile, an empty floor) is bare floor,
// height 0. The rule looks at covered cells only (it is not iterated).
//
// With a probe (probe_radius_m = p > 0) the surface is where a sphere of
// radius p lowered onto the packing stops, less p: every grain counts as a
// sphere of radius r + p and
//   h = max over grains with |c_xy - p_xy| < r + p of z + sqrt((r + p)^2 - |c_xy - p_xy|^2) - p.
// A probe about a grain diameter across bridges the gaps between surface
// grains, so a cell's height is the packing's smooth surface rather than the
// top of whichever grain its centre happens to hit (the DEM's own noise at
// one grain per cell).

#include "models/core/geometry/grid.h"
#include "models/core/geometry/height_field.h"
#include "validation/particles/grain_set.h"

namespace repose {

struct SurfaceHeightOptions {
  // Points per cell and axis at which the top is taken (their maximum): 1 is
  // the cell centre (the definition above); n > 1 takes an n x n lattice of
  // points at the centres of n x n sub-cells, closer to the top over the whole
  // cell and less noisy when cells are about a grain across. An odd n
  // includes the centre, so it is never lower than n = 1.
  int samples_per_axis = 1;
  double gap_covered_fraction = 0.5;  // share of covered neighbours that makes an uncovered cell a gap; > 1: never
  double probe_radius_m = 0.0;        // 0: the tops of the grains themselves; > 0: the probe surface above
};

HeightField surface_height(const GrainSet& grains, const Grid& grid, const SurfaceHeightOptions& options = {});

}  // namespace repose
