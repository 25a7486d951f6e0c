#include "validation/calibration/calibration_uncertainty.h"

#include <cmath>
#include <limits>

#include <Eigen/SVD>
#include <ceres/ceres.h>
#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Eigen::MatrixXd dense_jacobian(ceres::Problem& problem, const std::vector<double*>& blocks, std::size_t* residuals) {
  ceres::Problem::EvaluateOptions options;
  options.parameter_blocks = blocks;
  options.apply_loss_function = true;
  ceres::CRSMatrix crs;
  double cost = 0.0;
  std::vector<double> r;
  REPOSE_DEMAND(problem.Evaluate(options, &cost, &r, nullptr, &crs));
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
  for (int row = 0; row < crs.num_rows; ++row) {
    for (int k = crs.rows[row]; k < crs.rows[row + 1]; ++k) j(row, crs.cols[k]) = crs.values[k];
  }
  *residuals = r.size();
  return j;
}

// Marks undetermined columns until the scaled Jacobian is well conditioned.
std::vector<bool> determined_columns(const Eigen::MatrixXd& scaled, const std::vector<std::string>& labels, double min_rcond,
                                     std::string* note,
                                     Eigen::VectorXd* singular_values) {
  const Eigen::Index p = scaled.cols();
  std::vector<bool> keep(static_cast<std::size_t>(p), true);
  Eigen::JacobiSVD<Eigen::MatrixXd> full(scaled, Eigen::ComputeThinV);
  *singular_values = full.singularValues();
  for (;;) {
    std::vector<Eigen::Index> cols;
    for (Eigen::Index c = 0; c < p; ++c) {
      if (keep[static_cast<std::size_t>(c)]) cols.push_back(c);
    }
    if (cols.empty()) return keep;
    Eigen::MatrixXd sub(scaled.rows(), static_cast<Eigen::Index>(cols.size()));
    for (std::size_t k = 0; k < cols.size(); ++k) sub.col(static_cast<Eigen::Index>(k)) = scaled.col(cols[k]);
    // full V: with fewer residuals than parameters the null-space directions are not in the thin V
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(sub, Eigen::ComputeFullV);
    const Eigen::VectorXd& s = svd.singularValues();
    const double largest = s.size() > 0 ? s(0) : 0.0;
    const Eigen::Index last = static_cast<Eigen::Index>(cols.size()) - 1;
    // more parameters than residuals also leaves directions free
    const double smallest = last < s.size() ? s(last) : 0.0;
    if (largest > 0.0 && smallest >= min_rcond * largest) return keep;
    Eigen::Index worst = 0;
    svd.matrixV().col(last).cwiseAbs().maxCoeff(&worst);
    keep[static_cast<std::size_t>(cols[static_cast<std::size_t>(worst)])] = false;
    *note += fmt::format("{}direction of singular value {:.3g} (largest {:.3g}) is mostly {}",
                         note->empty() ? "" : "; ", smallest, largest,
                         labels[static_cast<std::size_t>(cols[static_cast<std::size_t>(worst)])]);
  }
}

// The covariance (J^T J)^-1 of the kept columns before scaling by the
// residual variance; p x p, zero outside the kept rows and columns. From the
// range-scaled Jacobian's SVD (J S = U D V^T, S the ranges: (J^T J)^-1 =
// S V D^-2 V^T S), whose kept columns determined_columns found well
// conditioned. Not ceres::Covariance: it tests the conditioning of the
// unscaled J^T J, which parameters in very different units fail (a layer in
// metres beside an angle in degrees: its column is 10^3-10^4 times the
// other's) although every range-scaled direction is determined.
Eigen::MatrixXd unit_covariance(const Eigen::MatrixXd& scaled, const std::vector<double>& ranges,
                                const std::vector<std::size_t>& kept) {
  const auto at = [](std::size_t k) { return static_cast<Eigen::Index>(k); };
  Eigen::MatrixXd sub(scaled.rows(), at(kept.size()));
  for (std::size_t k = 0; k < kept.size(); ++k) sub.col(at(k)) = scaled.col(at(kept[k]));
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(sub, Eigen::ComputeThinV);
  const Eigen::VectorXd inverse_squares = svd.singularValues().array().square().inverse();
  const Eigen::MatrixXd scaled_cov = svd.matrixV() * inverse_squares.asDiagonal() * svd.matrixV().transpose();
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(scaled.cols(), scaled.cols());
  for (std::size_t a = 0; a < kept.size(); ++a) {
    for (std::size_t b = 0; b < kept.size(); ++b) {
      cov(at(kept[a]), at(kept[b])) = scaled_cov(at(a), at(b)) * ranges[kept[a]] * ranges[kept[b]];
    }
  }
  return cov;
}

// Standard errors and correlations of the kept parameters from their covariance.
void set_errors_and_correlation(const Eigen::MatrixXd& cov, const std::vector<std::size_t>& kept,
                                CalibrationUncertainty* u) {
  const auto at = [](std::size_t k) { return static_cast<Eigen::Index>(k); };
  for (const std::size_t a : kept) u->standard_error[a] = std::sqrt(std::max(0.0, cov(at(a), at(a))));
  for (const std::size_t a : kept) {
    for (const std::size_t b : kept) {
      const double d = u->standard_error[a] * u->standard_error[b];
      u->correlation(at(a), at(b)) = d > 0.0 ? cov(at(a), at(b)) / d : (a == b ? 1.0 : 0.0);
    }
  }
}

}  // namespace

CalibrationUncertainty estimate_uncertainty(ceres::Problem& problem, const std::vector<double*>& blocks,
                                            const std::vector<double>& ranges, const std::vector<std::string>& labels, double cost,
                                            double min_reciprocal_condition) {
  const std::size_t p = blocks.size();
  REPOSE_DEMAND(ranges.size() == p && labels.size() == p);
  CalibrationUncertainty u;
  std::size_t n = 0;
  const Eigen::MatrixXd j = dense_jacobian(problem, blocks, &n);
  Eigen::MatrixXd scaled = j;
  for (std::size_t c = 0; c < p; ++c) scaled.col(static_cast<Eigen::Index>(c)) *= ranges[c];
  u.determined = determined_columns(scaled, labels, min_reciprocal_condition, &u.note, &u.scaled_singular_values);
  u.standard_error.assign(p, kNaN);
  u.correlation = Eigen::MatrixXd::Constant(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(p), kNaN);

  std::vector<std::size_t> kept;
  for (std::size_t c = 0; c < p; ++c) {
    if (u.determined[c]) kept.push_back(c);
  }
  if (kept.empty()) return u;
  if (n <= kept.size()) {
    u.note += fmt::format("{}{} residuals for {} parameters: no residual variance to scale by", u.note.empty() ? "" : "; ",
                          n, kept.size());
    u.determined.assign(p, false);
    return u;
  }
  u.residual_variance = 2.0 * cost / static_cast<double>(n - kept.size());
  set_errors_and_correlation(unit_covariance(scaled, ranges, kept) * u.residual_variance, kept, &u);
  return u;
}

}  // namespace repose
