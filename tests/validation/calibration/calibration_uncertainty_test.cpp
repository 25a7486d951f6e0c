// The uncertainty of a linear least-squares fit is known in closed form:
// for residuals r = a + b x - y, Cov(a, b) = s^2 (X^T X)^-1 with
// s^2 = SSR / (n - p). estimate_uncertainty must reproduce it, also with
// parameters in very different units, and mark a parameter that moves no
// residual undetermined.
#include "validation/calibration/calibration_uncertainty.h"

#include <gtest/gtest.h>

#include <ceres/ceres.h>
#include <Eigen/Dense>

#include <cmath>
#include <random>

namespace repose {
namespace {

struct LinePoint {
  double x, y;
  template <class T>
  bool operator()(const T* const a, const T* const b, const T* const unused, T* r) const {
    r[0] = *a + *b * x - y + T(0.0) * *unused;
    return true;
  }
};

struct Fit {
  std::vector<double> x, y;
  double a = 0.0, b = 0.0, c = 0.0;
  ceres::Problem problem;
  double cost = 0.0;
};

void solve(Fit& fit) {
  for (std::size_t i = 0; i < fit.x.size(); ++i) {
    fit.problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<LinePoint, 1, 1, 1, 1>(new LinePoint{fit.x[i], fit.y[i]}), nullptr, &fit.a,
        &fit.b, &fit.c);
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.function_tolerance = options.gradient_tolerance = options.parameter_tolerance = 1e-15;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &fit.problem, &summary);
  fit.cost = summary.final_cost;
}

TEST(CalibrationUncertainty, ALinearFitHasItsClosedFormStandardErrors) {
  Fit fit;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.1);
  for (int i = 0; i < 40; ++i) {
    fit.x.push_back(0.25 * i);
    fit.y.push_back(1.5 + 0.8 * fit.x.back() + noise(rng));
  }
  solve(fit);
  fit.problem.SetParameterBlockConstant(&fit.c);  // not a parameter of this fit
  const CalibrationUncertainty u = estimate_uncertainty(fit.problem, {&fit.a, &fit.b}, {10.0, 10.0}, {"a", "b"},
                                                        fit.cost, 1e-6);
  // closed form (the unused parameter held constant: it enters no residual)
  Eigen::MatrixXd X(fit.x.size(), 2);
  Eigen::VectorXd y(fit.x.size());
  for (std::size_t i = 0; i < fit.x.size(); ++i) {
    X(static_cast<Eigen::Index>(i), 0) = 1.0;
    X(static_cast<Eigen::Index>(i), 1) = fit.x[i];
    y(static_cast<Eigen::Index>(i)) = fit.y[i];
  }
  const Eigen::Vector2d beta = (X.transpose() * X).ldlt().solve(X.transpose() * y);
  const double s2 = (X * beta - y).squaredNorm() / static_cast<double>(fit.x.size() - 2);
  const Eigen::Matrix2d cov = s2 * (X.transpose() * X).inverse();
  ASSERT_TRUE(u.determined[0] && u.determined[1]);
  EXPECT_NEAR(fit.a, beta(0), 1e-9);
  EXPECT_NEAR(u.residual_variance, s2, 1e-12);
  EXPECT_NEAR(u.standard_error[0], std::sqrt(cov(0, 0)), 1e-9);
  EXPECT_NEAR(u.standard_error[1], std::sqrt(cov(1, 1)), 1e-9);
  EXPECT_NEAR(u.correlation(0, 1), cov(0, 1) / std::sqrt(cov(0, 0) * cov(1, 1)), 1e-9);
}

TEST(CalibrationUncertainty, ParametersInVeryDifferentUnitsKeepTheirClosedFormStandardErrors) {
  // the slope per 10^-4 of x: its column of J is 10^-4 the intercept's, so that the unscaled J^T J's reciprocal
  // condition (about 10^-9) is below the 10^-6 the scaled test's 10^-3 allows, while over their ranges (10 and
  // 10^5) both are well determined
  Fit fit;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 0.1);
  for (int i = 0; i < 40; ++i) {
    fit.x.push_back(2.5e-5 * i);
    fit.y.push_back(1.5 + 8e3 * fit.x.back() + noise(rng));
  }
  solve(fit);
  fit.problem.SetParameterBlockConstant(&fit.c);
  const CalibrationUncertainty u = estimate_uncertainty(fit.problem, {&fit.a, &fit.b}, {10.0, 1e5}, {"a", "b"},
                                                        fit.cost, 1e-3);
  Eigen::MatrixXd X(fit.x.size(), 2);
  for (std::size_t i = 0; i < fit.x.size(); ++i) X.row(static_cast<Eigen::Index>(i)) << 1.0, fit.x[i];
  const Eigen::Matrix2d cov = u.residual_variance * (X.transpose() * X).inverse();
  ASSERT_TRUE(u.determined[0] && u.determined[1]) << u.note;
  EXPECT_NEAR(u.standard_error[0] / std::sqrt(cov(0, 0)), 1.0, 1e-9);
  EXPECT_NEAR(u.standard_error[1] / std::sqrt(cov(1, 1)), 1.0, 1e-9);
  EXPECT_NEAR(u.correlation(0, 1), cov(0, 1) / std::sqrt(cov(0, 0) * cov(1, 1)), 1e-9);
}

TEST(CalibrationUncertainty, AParameterThatMovesNoResidualIsUndetermined) {
  Fit fit;
  for (int i = 0; i < 10; ++i) {
    fit.x.push_back(i);
    fit.y.push_back(2.0 - 0.5 * i + (i % 2 ? 0.01 : -0.01));
  }
  solve(fit);
  const CalibrationUncertainty u = estimate_uncertainty(fit.problem, {&fit.a, &fit.b, &fit.c}, {1.0, 1.0, 1.0},
                                                        {"a", "b", "c"}, fit.cost, 1e-6);
  EXPECT_TRUE(u.determined[0]);
  EXPECT_TRUE(u.determined[1]);
  EXPECT_FALSE(u.determined[2]);
  EXPECT_TRUE(std::isnan(u.standard_error[2]));
  EXPECT_NE(u.note.find("c"), std::string::npos) << u.note;
}

}  // namespace
}  // namespace repose
