#pragma once
// The fit of a calibration: Levenberg-Marquardt (Ceres) on the weighted
// residuals of all fit scenes, bounds enforced by Ceres, an optional robust
// loss, from several starts (the file's initial values, then points of a
// seeded Halton sequence spread over the bounds); the start that ends with
// the lowest cost wins (the earliest on a tie). Then the uncertainty of the
// winner (calibration_uncertainty.h) and each scene's surface RMSE with the
// initial and the fitted parameters, fit and held-out scenes alike.
// Deterministic: the same file and seed give bit-identical results, whatever
// the thread count.

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <ceres/ceres.h>

#include "models/core/base/progress.h"
#include "validation/calibration/calibration_cost.h"
#include "validation/calibration/calibration_problem.h"
#include "validation/calibration/calibration_uncertainty.h"
#include "validation/calibration/series_comparison.h"
#include "validation/observables/surface_change.h"

namespace repose {

struct CalibrationStart {
  std::vector<double> initial_free;  // free parameter values it started from
  std::vector<double> final_free;
  double initial_cost = 0.0;
  double final_cost = 0.0;
  int iterations = 0;
  std::string termination;           // Ceres's termination type and message
  std::vector<double> cost_per_iteration;  // iteration 0 is the start
};

// Ceres' first trust region, in Jacobi-scaled units, and the damped one a
// solve that stalled is retried with. Ceres' own (1e4) makes the first step
// all but Gauss-Newton's. Ceres projects a step that leaves the box onto it,
// and from a start on a bound (a fraction started at 1) that step can point
// so far out of the box that what the projection leaves is below the
// parameter tolerance: the solve stops at or next to its start (both
// leave-one-depth-out folds of experiments/heightspan_scoop_fit.yaml did:
// 0 and 1 iterations, every parameter within 6 % of its derivative step of
// the start). A radius of 1 damps the first step towards the gradient, which
// moves the parameters along the bound too. Only the retry uses it: a solve
// that moves keeps Ceres' own.
constexpr double kFirstTrustRegionRadius = 1.0e4;
constexpr double kDampedTrustRegionRadius = 1.0;
// A solve stalled when every parameter ended within this fraction of its
// derivative step (the scale the cost is resolved on) of where it started.
constexpr double kStalledFractionOfStep = 0.1;

// solve(kFirstTrustRegionRadius), or, when that stalled (without failing),
// also solve(kDampedTrustRegionRadius): the one of lower cost, its
// termination saying a retry was made. `steps`: each parameter's derivative step.
CalibrationStart solve_or_retry_damped(const std::function<CalibrationStart(double first_radius)>& solve,
                                       const std::vector<double>& steps);

// Levenberg-Marquardt (Ceres, dense QR) on `cost` (within its bounds) from
// `start`, retried damped when it stalls (solve_or_retry_damped); `loss` may
// be null, not owned; `callback` (may be null) sees every iteration. A failed
// solve ends at an infinite cost.
CalibrationStart minimize_from(CalibrationCost* cost, ceres::LossFunction* loss, const std::vector<double>& start,
                               int max_iterations, ceres::IterationCallback* callback = nullptr);

// The uncertainty (calibration_uncertainty.h) of `cost`'s parameters at
// `at`, where the fit ended at `final_cost`, each parameter's range taken
// from the cost's bounds; `loss` as in minimize_from; labels name the
// parameters in the note.
CalibrationUncertainty uncertainty_at(CalibrationCost* cost, ceres::LossFunction* loss, const std::vector<double>& at,
                                      const std::vector<std::string>& labels, double final_cost,
                                      double min_reciprocal_condition);

struct SceneError {
  std::string name;
  bool fit = true;                   // false: held out
  double rmse_initial_m = 0.0;       // surface RMSE (rmse region) with the initial parameters
  double rmse_fitted_m = 0.0;        // ... with the fitted ones
  double grain_diameter_m = 0.0;     // 0 without a dem section
  HeightField heuristic_initial_params;  // final surfaces, for the figures
  HeightField heuristic_fitted;
  // Δh against the reference's (mean over seeds), beside doing nothing (surface_change.h)
  ChangeScores scores_initial_params, scores_fitted;
  std::optional<NoiseFloor> noise;       // the reference's seed-to-seed noise (2 or more seeds)
  ChangeFeatures reference_features, fitted_features;
  // Fit scenes, when there are two or more: the fit on the other fit scenes
  // (leave one scene out), scored here (cross_validation.h; the fold's
  // values and its series are in CalibrationFit::folds).
  std::optional<ChangeScores> cross_validated;
  std::vector<SeriesComparison> series;  // its series observables (series_comparison.h)
};

// One leave-one-scene-out fold (cross_validation.h): the fit without one fit
// scene, and every scene's errors at the fold's values. The left-out scene's
// and the held-out scenes' are predictions: their series' `fitted` are what
// the fold predicts (a scoop's held mass at each stage).
// A fold whose fit stopped at its start (0 iterations) predicts with the
// initial values: it says nothing about the fit.
struct CrossValidationFold {
  std::size_t left_out = 0;        // index into the calibration's scenes
  std::vector<double> values;      // every parameter (SI) of the fold's fit
  int iterations = 0;              // of the fold's best start
  std::string termination;         // ... and why it stopped (Ceres)
  std::vector<SceneError> scenes;  // in the calibration's order
};

struct CalibrationFit {
  std::vector<double> initial_values;  // every parameter (SI)
  std::vector<double> values;          // every parameter, fitted (fixed ones unchanged)
  std::vector<CalibrationStart> starts;
  std::size_t best_start = 0;
  double initial_cost = 0.0;           // at the initial values
  double final_cost = 0.0;
  std::size_t residual_count = 0;
  CalibrationUncertainty uncertainty;  // over the free parameters
  std::vector<SceneError> scenes;      // in the calibration's order
  std::vector<CrossValidationFold> folds;  // empty unless cross-validated (cross_validation.h)
  long long heuristic_runs = 0;
  double wall_time_s = 0.0;
};

CalibrationFit fit_calibration(const CalibrationProblem& problem, const ProgressFn& progress = {});

// A scene's errors with the initial and the fitted parameters.
SceneError scene_error(const CalibrationProblem& problem, const PreparedScene& scene, const std::vector<double>& initial_values,
                       const std::vector<double>& fitted_values);

// "determined", "poorly determined" (a standard error above a quarter of the
// bound range) or "undetermined", for free parameter k.
std::string determination(const CalibrationFit& fit, const CalibrationProblem& problem, std::size_t k);

}  // namespace repose
