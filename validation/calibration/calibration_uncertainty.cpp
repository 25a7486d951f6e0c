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

// The covariance (J^T J)^-1 of the kept blocks by ceres::Covariance, the
// others held constant while it is computed, before scaling by the residual
// variance; p x p, zero outside the kept rows and columns. False when Ceres
// finds the Jacobian rank-deficient.
bool unit_covariance(ceres::Problem& problem, const std::vector<double*>& blocks, const std::vector<std::size_t>& kept,
                     double min_reciprocal_condition, Eigen::MatrixXd* cov) {
  const auto p = static_cast<Eigen::Index>(blocks.size());
  std::vector<bool> is_kept(blocks.size(), false);
  for (const std::size_t a : kept) is_kept[a] = true;
  for (std::size_t c = 0; c < blocks.size(); ++c) {
    if (!is_kept[c]) problem.SetParameterBlockConstant(blocks[c]);
  }
  ceres::Covariance::Options options;
  options.algorithm_type = ceres::DENSE_SVD;
  options.min_reciprocal_condition_number = min_reciprocal_condition * min_reciprocal_condition;
  options.null_space_rank = 0;
  options.apply_loss_function = true;
  options.num_threads = 1;
  ceres::Covariance covariance(options);
  std::vector<std::pair<const double*, const double*>> pairs;
  for (const std::size_t a : kept) {
    for (const std::size_t b : kept) {
      if (a <= b) pairs.emplace_back(blocks[a], blocks[b]);
    }
  }
  const bool ok = covariance.Compute(pairs, &problem);
  for (double* block : blocks) problem.SetParameterBlockVariable(block);
  if (!ok) return false;
  *cov = Eigen::MatrixXd::Zero(p, p);
  for (const std::size_t a : kept) {
    for (const std::size_t b : kept) {
      double value = 0.0;
      covariance.GetCovarianceBlock(blocks[std::min(a, b)], blocks[std::max(a, b)], &value);
      (*cov)(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) = value;
    }
  }
  return true;
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
  Eigen::MatrixXd cov;
  if (!unit_covariance(problem, blocks, kept, min_reciprocal_condition, &cov)) {
    u.note += std::string(u.note.empty() ? "" : "; ") + "ceres::Covariance::Compute failed (rank-deficient Jacobian)";
    u.determined.assign(p, false);
    return u;
  }
  u.residual_variance = 2.0 * cost / static_cast<double>(n - kept.size());
  set_errors_and_correlation(cov * u.residual_variance, kept, &u);
  return u;
}

}  // namespace repose
