#pragma once
// How well a model's surface change Δh = final − initial matches a
// reference's, judged against two yardsticks (issue 10):
//   - doing nothing (Δh = 0): skill = 1 − RMSE_model / RMSE_nothing, so 0 is
//     no better than leaving the ground as it was and 1 is exact;
//   - the reference's own seed-to-seed noise: runs of the same scene on
//     different random beds (seeds) differ by their grains alone, and no
//     model can be expected to come closer to one run than another run does.
//     The noise floor is taken leave-one-seed-out: each seed's Δh against
//     the mean Δh of the others, i.e. how a second DEM run would score.
// And scalar features a reader can check by eye on a map: volume dug and
// heaped, the deepest and highest point of Δh and where they are, their
// distance (the rim's or heap's distance from the imprint's centre), the trench's
// width across its deepest point.
// All over the cells of a region (calibration_observables.h cells_in).

#include <optional>
#include <vector>

#include "models/core/geometry/height_field.h"
#include "validation/observables/observable_spec.h"

namespace repose {

struct ChangeScores {
  double rmse_m = 0.0;          // RMSE of Δh_model − Δh_reference
  double rmse_nothing_m = 0.0;  // RMSE of Δh_reference (the model Δh = 0)
  double r2 = 0.0;              // 1 − SS_res / SS_tot of Δh (SS_tot about the reference's mean Δh)
  double skill = 0.0;           // 1 − rmse / rmse_nothing
};

// model and reference start from the same initial surface.
ChangeScores score_change(const HeightField& initial, const HeightField& model_final, const HeightField& reference_final,
                          const std::optional<CalibrationRegion>& region);

struct NoiseFloor {
  int seeds = 0;
  double rmse_m = 0.0;       // mean over seeds of the RMSE of its Δh against the others' mean Δh
  double r2 = 0.0;           // mean over seeds of the same comparison's R²
  double pair_rmse_m = 0.0;  // mean over pairs of seeds of the RMSE between their Δh
};

// From each seed's initial and final surface (same grid); nothing with fewer than 2 seeds.
std::optional<NoiseFloor> noise_floor(const std::vector<HeightField>& initial, const std::vector<HeightField>& final_height,
                                      const std::optional<CalibrationRegion>& region);

struct ChangeFeatures {
  double dug_m3 = 0.0;          // volume below the initial surface (positive)
  double heaped_m3 = 0.0;       // volume above it
  double depth_m = 0.0;         // −min Δh (0 when nothing is dug)
  double depth_x_m = 0.0, depth_y_m = 0.0;    // the imprint's centre: depth-weighted centroid of the cells dug deeper than depth/2
  double height_m = 0.0;        // max Δh (0 when nothing is heaped)
  double height_x_m = 0.0, height_y_m = 0.0;  // centre of the highest cell
  double rim_distance_m = 0.0;  // from the deepest to the highest cell
  // Through the imprint's centre: the extent of the cells dug deeper than
  // half the depth along the row or the column, whichever is narrower (a
  // trench's width, an imprint's diameter).
  double trench_width_m = 0.0;
};

ChangeFeatures change_features(const HeightField& initial, const HeightField& final_height,
                               const std::optional<CalibrationRegion>& region);

// Mean of fields on one grid (at least one).
HeightField mean_field(const std::vector<HeightField>& fields);

}  // namespace repose
