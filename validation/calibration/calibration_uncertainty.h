#pragma once
// The uncertainty of a fitted parameter vector, from the Jacobian J of the
// residuals at the optimum.
//
// First, which parameters the data determines: the columns of J are scaled by
// each parameter's bound range (so that the test does not depend on units),
// and while the smallest singular value of the scaled J falls below
// min_reciprocal_condition times the largest, the parameter with the largest
// share in that direction is marked undetermined and its column dropped (a
// zero column, a parameter that moves no observable within its finite-
// difference step, goes first; two parameters of which only a combination
// matters go both, one after the other, only if the rest stays deficient).
// Then (J^T J)^-1 of the determined parameters, from the SVD of their
// range-scaled columns (so that parameters in very different units do not
// make it ill-conditioned), scaled by the residual variance
// s^2 = 2 cost / (n - p) (n residuals, p determined parameters).

#include <string>
#include <vector>

#include <Eigen/Core>

namespace ceres {
class Problem;
}

namespace repose {

struct CalibrationUncertainty {
  std::vector<bool> determined;        // per free parameter
  std::vector<double> standard_error;  // per free parameter; NaN where undetermined
  Eigen::MatrixXd correlation;         // free x free; NaN rows/columns where undetermined
  Eigen::VectorXd scaled_singular_values;  // of the range-scaled Jacobian, descending
  double residual_variance = 0.0;      // s^2
  std::string note;                    // why something is undetermined, when it is
};

// blocks: the free parameters, one block of size 1 each, in order; ranges:
// their bound ranges (upper - lower); labels: their names for the note. cost: the final cost (0.5 sum rho(r^2)).
// Evaluates the problem's Jacobian at the blocks' current values (the loss
// function applied); changes no block.
CalibrationUncertainty estimate_uncertainty(ceres::Problem& problem, const std::vector<double*>& blocks,
                                            const std::vector<double>& ranges, const std::vector<std::string>& labels, double cost,
                                            double min_reciprocal_condition);

}  // namespace repose
