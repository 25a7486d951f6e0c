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
  // beds: each: the solver's fitted values on each seed's own bed (seed
  // order), per time, whose mean is `fitted`; empty on the mean bed.
  std::vector<std::vector<double>> fitted_per_bed;
  // (fitted - reference) / reference per time (0 where the reference is 0 and so is the fit)
  std::vector<double> fitted_relative_error() const;
  // The standard error of fitted_relative_error() that the finite number of
  // beds leaves (beds: each): each bed's (fitted - seed) / reference, the
  // solver paired with the seed on that seed's own bed, has that error as its
  // mean; its sample sd over sqrt(beds). NaN where the reference is 0; empty
  // without fitted_per_bed (fewer than two beds, or the mean bed).
  std::vector<double> paired_standard_error() const;
};

// One comparison per series, measure or heap_flank observable of the scene,
// in its order, from the solver's observed values (CalibrationProblem::observed)
// with the initial and the fitted parameters, and with beds: each the fitted
// values per bed (CalibrationProblem::observed_per_bed); units from the
// fitted run's series and measures.
std::vector<SeriesComparison> compare_series(const PreparedScene& scene, const std::vector<std::vector<double>>& initial,
                                             const std::vector<std::vector<double>>& fitted,
                                             const std::vector<std::vector<std::vector<double>>>& fitted_per_bed,
                                             const Run& fitted_run);

}  // namespace repose
