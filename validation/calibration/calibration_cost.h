#pragma once
// The Ceres cost of a calibration: all residuals of the fit scenes as one
// residual block over the free parameters, one parameter block of size 1
// each (so that ceres::Covariance can hold undetermined ones constant).
//
// The heuristic is not smooth in its parameters (erosion thresholds, integer
// passes, cells that do or do not touch an object), so derivatives are
// central differences with a wide, absolute step per parameter (the
// calibration file's `step`), evaluated at x - h and x + h, cut at the bounds
// (one-sided there). All the points one Evaluate needs are run together, in
// parallel (CalibrationProblem::fit_residuals). Residual vectors of points
// already run are remembered, since Ceres evaluates a point's residuals and
// later its Jacobian; results are bit-identical either way.

#include <functional>
#include <map>
#include <mutex>
#include <vector>

#include <ceres/cost_function.h>

#include "validation/calibration/calibration_problem.h"

namespace repose {

class CalibrationCost : public ceres::CostFunction {
 public:
  // Residuals at each of several points (free parameter values), in order.
  using Evaluator = std::function<std::vector<std::vector<double>>(const std::vector<std::vector<double>>&)>;

  // problem must outlive the cost.
  explicit CalibrationCost(const CalibrationProblem& problem);
  // Any residuals of p = lower.size() parameters with their bounds and
  // central-difference half-widths (e.g. the measures of solver runs
  // against published values: experiments/tearing/tearing_paper_fit.cpp).
  CalibrationCost(Evaluator evaluate, std::vector<double> lower, std::vector<double> upper, std::vector<double> step,
                  int residual_count);

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

  // Each parameter's bounds and central-difference half-width.
  const std::vector<double>& lower() const { return lower_; }
  const std::vector<double>& upper() const { return upper_; }
  const std::vector<double>& steps() const { return step_; }

  // Residuals at free parameter values, through the memory.
  std::vector<std::vector<double>> residuals_at(const std::vector<std::vector<double>>& points) const;

 private:
  Evaluator evaluate_;
  std::vector<double> lower_, upper_, step_;
  mutable std::mutex mutex_;
  mutable std::map<std::vector<double>, std::vector<double>> memory_;
};

}  // namespace repose
