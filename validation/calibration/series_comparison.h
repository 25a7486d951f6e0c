#pragma once
// A series observable (observable_spec.h, kind series: the mass a bucket
// holds at the stages of a scoop) compared at its times, or a measure
// observable (kind measure: the peak force on a wall) as one value, between
// the reference's seeds and the calibrated solver (also a heap_flank
// observable, as one value named "heap_flank" in rad) with the initial and the
// fitted parameters, for the report and calibration.json.

#include <string>
#include <vector>

#include "models/core/solver/run.h"
#include "validation/calibration/calibration_problem.h"

namespace repose {

struct SeriesComparison {
  std::string series;                      // "mass_held_kg.bucket", or the measure's name
  std::string unit;                        // of the solver's series or measure ("kg"), "" when unknown
  std::vector<double> times_s;             // empty for a measure (one value)
  std::vector<std::vector<double>> seeds;  // per reference seed, per time
  std::vector<double> reference;           // the seeds' mean, per time
  std::vector<double> initial, fitted;     // the solver's, per time
  // (fitted - reference) / reference per time (0 where the reference is 0 and so is the fit)
  std::vector<double> fitted_relative_error() const;
};

// One comparison per series, measure or heap_flank observable of the scene,
// in its order, from the solver's observed values (CalibrationProblem::observed)
// with the initial and the fitted parameters; units from the fitted run's series and measures.
std::vector<SeriesComparison> compare_series(const PreparedScene& scene, const std::vector<std::vector<double>>& initial,
                                             const std::vector<std::vector<double>>& fitted, const Run& fitted_run);

}  // namespace repose
