#include "validation/calibration/calibration_cost.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "models/core/base/error.h"

namespace repose {

namespace {

constexpr std::size_t kMemoryLimit = 4096;  // points remembered before the memory is emptied

}  // namespace

CalibrationCost::CalibrationCost(const CalibrationProblem& problem)
    : evaluate_([&problem](const std::vector<std::vector<double>>& points) { return problem.fit_residuals(points); }) {
  for (const std::size_t p : problem.free()) {
    const ParameterSpec& spec = problem.spec().parameters[p];
    lower_.push_back(spec.lower);
    upper_.push_back(spec.upper);
    step_.push_back(spec.step);
    mutable_parameter_block_sizes()->push_back(1);
  }
  set_num_residuals(static_cast<int>(problem.fit_residual_count()));
}

CalibrationCost::CalibrationCost(Evaluator evaluate, std::vector<double> lower, std::vector<double> upper,
                                 std::vector<double> step, int residual_count)
    : evaluate_(std::move(evaluate)), lower_(std::move(lower)), upper_(std::move(upper)), step_(std::move(step)) {
  REPOSE_DEMAND(lower_.size() == upper_.size() && step_.size() == lower_.size() && residual_count > 0);
  for (std::size_t k = 0; k < lower_.size(); ++k) mutable_parameter_block_sizes()->push_back(1);
  set_num_residuals(residual_count);
}

std::vector<std::vector<double>> CalibrationCost::residuals_at(const std::vector<std::vector<double>>& points) const {
  std::lock_guard lock(mutex_);
  std::vector<std::vector<double>> missing;
  for (const auto& p : points) {
    if (!memory_.count(p) && std::find(missing.begin(), missing.end(), p) == missing.end()) missing.push_back(p);
  }
  const std::vector<std::vector<double>> computed = evaluate_(missing);
  if (memory_.size() + missing.size() > kMemoryLimit) memory_.clear();
  for (std::size_t k = 0; k < missing.size(); ++k) memory_[missing[k]] = computed[k];
  std::vector<std::vector<double>> out;
  for (const auto& p : points) {
    const auto it = memory_.find(p);
    if (it != memory_.end()) {
      out.push_back(it->second);
    } else {  // emptied just now
      out.push_back(computed[static_cast<std::size_t>(std::find(missing.begin(), missing.end(), p) - missing.begin())]);
    }
  }
  return out;
}

bool CalibrationCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const std::size_t p = step_.size();
  std::vector<double> x(p);
  for (std::size_t k = 0; k < p; ++k) x[k] = std::clamp(parameters[k][0], lower_[k], upper_[k]);
  // the point itself, then (x - h, x + h) for every parameter whose derivative is asked for
  std::vector<std::vector<double>> points{x};
  std::vector<std::size_t> wanted;
  std::vector<double> width;
  for (std::size_t k = 0; jacobians != nullptr && k < p; ++k) {
    if (jacobians[k] == nullptr) continue;
    std::vector<double> below = x, above = x;
    below[k] = std::max(lower_[k], x[k] - step_[k]);
    above[k] = std::min(upper_[k], x[k] + step_[k]);
    wanted.push_back(k);
    width.push_back(above[k] - below[k]);
    points.push_back(below);
    points.push_back(above);
  }
  const std::vector<std::vector<double>> r = residuals_at(points);
  const std::size_t n = r[0].size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(r[0][i])) return false;
    residuals[i] = r[0][i];
  }
  for (std::size_t w = 0; w < wanted.size(); ++w) {
    const std::vector<double>& below = r[1 + 2 * w];
    const std::vector<double>& above = r[2 + 2 * w];
    REPOSE_DEMAND(width[w] > 0.0);
    for (std::size_t i = 0; i < n; ++i) jacobians[wanted[w]][i] = (above[i] - below[i]) / width[w];
  }
  return true;
}

}  // namespace repose
