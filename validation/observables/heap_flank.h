#pragma once
// The flank angle of a heap on a height field, measured the way
// experiments/heightspan/dump_flank.py measures the heap a scoop dumps
// (issue 12), so the calibration can fit what that script reports:
//   1. the heights above base_height_m are passed through a 3 x 3 median
//      (a cell near the grid's edge: over its neighbours inside the grid; an
//      even count takes the mean of the two middle values): it leaves a
//      plane flank as it is but drops a one-cell spike (the height-span
//      model's last particles dripping off a tipped bucket's edge stack in
//      one cell), which would otherwise be taken for the peak;
//   2. the peak is the highest cell whose centre lies in peak_region (the
//      first in row-major order among equals);
//   3. from the peak's cell centre, ray_count rays evenly spaced in azimuth
//      sample the field (bilinear between cell centres) every half cell out to
//      reach_m, stopping where a sample would need a cell outside the grid;
//   4. along each ray the samples between lower_fraction and upper_fraction
//      of the peak's height are fitted by a least-squares line; a ray with
//      fewer than min_samples of them is left out;
//   5. the flank is atan(-slope), averaged over the rays; 0 without any
//      (no ray at all when the peak is not above the base).
// SI units, radians. Unlike pile_flank_angles (validation/particles) the
// centre is found, not given, and the rays have a reach.

#include <optional>
#include <vector>

#include "models/core/geometry/height_field.h"
#include "validation/observables/observable_spec.h"

namespace repose {

struct HeapFlankOptions {
  double base_height_m = 0.0;          // heights are measured above this level (m)
  std::optional<CalibrationRegion> peak_region;  // where the peak is looked for (default: the whole grid)
  double reach_m = 0.1;                // rays sample out to (not including) this distance (m), > 0
  int ray_count = 16;                  // >= 1
  double lower_fraction = 0.2;         // flank band, fractions of the peak's height, 0 <= lower < upper
  double upper_fraction = 0.8;
  int min_samples = 3;                 // >= 2
  void validate() const;               // InputError naming the field
};

struct HeapFlank {
  double peak_height_m = 0.0;         // above base_height_m, after the median
  std::vector<double> angle_rad;      // per ray with a flank
  double mean_rad = 0.0;              // 0 when no ray has a flank (no heap)
};

// The 3 x 3 median of each cell of h (step 1 above).
HeightField median3(const HeightField& h);

HeapFlank heap_flank(const HeightField& height, const HeapFlankOptions& options = {});

}  // namespace repose
