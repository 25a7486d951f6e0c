#pragma once
// The speed/accuracy ladder of a calibrated scene: each rung is a way to
// compute the scene's surface change, as (time, RMSE of its change Δh
// against the yardstick's). The yardstick is the scene's own reference (the
// mean of its seeds), drawn with its noise floor (seed-to-seed, as a band):
// no rung is placed at a made-up error. Rungs:
//   - the calibrated ground model at each listed cell size (the reference's
//     initial surface resampled onto that grid, the result back onto the
//     yardstick's grid: area-weighted when finer, bilinear when coarser);
//   - the multi-resolution ground model at the scene's cell size (every
//     object on the coarse grid, coarse_factor as listed);
//   - each LIGGGHTS run of the ladder, its cost from its manifest; a run that
//     is one of the reference's seeds is compared with the other seeds' mean.
// Each rung also carries its series (the held mass at the scene's series
// times) beside the reference's: a rung can match the ground and still
// hold the wrong mass.
// The heuristic's time is the fastest of timing_repeats runs.

#include <optional>
#include <string>
#include <vector>

#include "models/core/base/progress.h"
#include "validation/calibration/calibration_problem.h"
#include "validation/calibration/series_comparison.h"

namespace repose {

struct LadderRung {
  std::string label;        // "ground 4 mm", "ground multires 4/8 mm", "LIGGGHTS d = 4 mm", "Bullet d = 3 mm"
  std::string kind;         // "ground", "ground-multires", or the engine: "liggghts", "bullet", "ode"
  double resolution_m = 0.0;  // cell size, or grain diameter for a particle engine
  double wall_time_s = 0.0;
  std::optional<double> cpu_time_s;  // a particle engine's run; a heuristic's calling thread
  double rmse_m = 0.0;      // RMSE of Δh against the yardstick's (rmse region of the scene)
  // The finest LIGGGHTS run's CPU time over this rung's: how much faster this
  // rung is than the reference (none without a LIGGGHTS rung or a CPU time).
  std::optional<double> liggghts_cpu_over_this;
  // The scene's series observables (the mass a bucket holds) on this rung:
  // `fitted` holds the rung's values, `seeds` and `reference` the seeds' and
  // their mean (the other seeds' for a run that is one of them); none where
  // the rung's run has no such series.
  std::vector<SeriesComparison> series;
};

struct Ladder {
  std::string scene;
  std::string yardstick;    // label of the yardstick
  std::optional<double> noise_floor_m;  // the yardstick's seed-to-seed noise (2 or more seeds)
  std::vector<LadderRung> rungs;
  std::string own_rung;  // label of the calibrated solver's rung at the scene's own cell size
  // The finest LIGGGHTS run's wall time over the calibrated solver's at the scene's own cell size (own_rung).
  std::optional<double> liggghts_over_ground_time;
  std::optional<double> liggghts_over_ground_cpu_time;  // their CPU times, the same way
};

// values: every parameter of the calibration (the fitted ones).
Ladder measure_ladder(const CalibrationProblem& problem, const std::vector<double>& values, const ProgressFn& progress = {});

}  // namespace repose
