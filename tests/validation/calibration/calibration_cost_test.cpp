// The calibration's cost over any evaluator: residuals at the point, central
// differences of the given half-width inside the bounds (one-sided at a
// bound), and every point run once.
#include "validation/calibration/calibration_cost.h"

#include <gtest/gtest.h>

namespace repose {
namespace {

TEST(CalibrationCost, CentralDifferencesOfAnyEvaluatorAreExactForAQuadraticAndOneSidedAtABound) {
  int runs = 0;
  // r = (x0^2 + 3 x1, 2 - x1)
  const CalibrationCost::Evaluator evaluate = [&runs](const std::vector<std::vector<double>>& points) {
    std::vector<std::vector<double>> out;
    for (const auto& p : points) {
      ++runs;
      out.push_back({p[0] * p[0] + 3.0 * p[1], 2.0 - p[1]});
    }
    return out;
  };
  const CalibrationCost cost(evaluate, {-10.0, 0.0}, {10.0, 1.0}, {0.5, 0.25}, 2);
  const double x0 = 2.0, x1 = 1.0;  // x1 at its upper bound
  const double* parameters[2] = {&x0, &x1};
  double residuals[2], j0[2], j1[2];
  double* jacobians[2] = {j0, j1};
  ASSERT_TRUE(cost.Evaluate(parameters, residuals, jacobians));
  EXPECT_DOUBLE_EQ(residuals[0], 7.0);
  EXPECT_DOUBLE_EQ(residuals[1], 1.0);
  EXPECT_DOUBLE_EQ(j0[0], 4.0);  // central difference of x^2 is exact
  EXPECT_DOUBLE_EQ(j0[1], 0.0);
  EXPECT_DOUBLE_EQ(j1[0], 3.0);  // (x1 - 0.25, x1): one-sided, exact for a linear term
  EXPECT_DOUBLE_EQ(j1[1], -1.0);
  EXPECT_EQ(runs, 4);  // x, x0 -+ h, x1 - h: x1 + h is cut to x itself
  ASSERT_TRUE(cost.Evaluate(parameters, residuals, nullptr));
  EXPECT_EQ(runs, 4);  // remembered
}

}  // namespace
}  // namespace repose
