#pragma once
// Streaks: the ridges a fast drag leaves without sweeping (the ground paper,
// 3.3, Table 1). Without sweeping, an object moving several cells per frame
// is pressed in at separate poses, and the furrow floor between two imprints
// stays higher than at them; sweeping (or substeps) makes the floor even.
//
// Measured on the final surface along the object's horizontal path: the
// positions at the ends of the time steps, joined by straight segments and
// sampled every half cell (bilinear). The first and last moving segments are
// left out, where the furrow starts and ends. Statistics of that profile:
// its RMS about its mean, its range, and its ridges (local maxima that rise
// more than `min_prominence_m` above the lowest point on either side before
// a higher one).

#include "models/core/geometry/height_field.h"
#include "models/core/config/scene.h"

namespace repose {

struct StreakStats {
  int samples = 0;       // 0: the object does not move horizontally over the grid for 3+ steps
  double rms_m = 0.0;    // RMS of the profile about its mean
  double range_m = 0.0;  // highest minus lowest sample
  int ridges = 0;
};

StreakStats streaks_along_path(const HeightField& final_height, const ObjectSpec& object, const TimeSpec& time,
                               double min_prominence_m);

// The profile itself (heights along the path), as streaks_along_path samples it.
std::vector<double> height_along_path(const HeightField& final_height, const ObjectSpec& object, const TimeSpec& time);

}  // namespace repose
