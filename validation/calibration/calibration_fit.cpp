#include "validation/calibration/calibration_fit.h"

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <utility>

#include <ceres/ceres.h>
#include <fmt/format.h>

#include "models/core/base/error.h"
#include "validation/calibration/calibration_cost.h"
#include "validation/observables/calibration_observables.h"
#include "validation/calibration/halton.h"

namespace repose {

namespace {

// Reports each iteration as progress through the starts.
class ProgressCallback : public ceres::IterationCallback {
 public:
  ProgressCallback(const ProgressFn& progress, std::size_t start, std::size_t starts, int max_iterations)
      : progress_(progress), start_(start), starts_(starts), max_iterations_(max_iterations) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    const double fraction = (static_cast<double>(start_) + std::min(1.0, static_cast<double>(s.iteration) / max_iterations_)) /
                            static_cast<double>(starts_);
    report(progress_, fraction, fmt::format("fit: start {}/{}, iteration {}, cost {:.6g}", start_ + 1, starts_, s.iteration, s.cost));
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const ProgressFn& progress_;
  std::size_t start_, starts_;
  int max_iterations_;
};

ceres::LossFunction* make_loss(const CalibrationSolverSpec& solver) {
  switch (solver.loss) {
    case CalibrationSolverSpec::Loss::kNone: return nullptr;
    case CalibrationSolverSpec::Loss::kHuber: return new ceres::HuberLoss(solver.loss_scale);
    case CalibrationSolverSpec::Loss::kCauchy: return new ceres::CauchyLoss(solver.loss_scale);
  }
  return nullptr;
}

// A problem over one block per free parameter, bounded; the cost and the loss are owned by the caller.
struct BoundedProblem {
  std::unique_ptr<ceres::Problem> problem;
  std::vector<double> x;  // the blocks' storage
  std::vector<double*> blocks;
};

BoundedProblem make_problem(CalibrationCost* cost, ceres::LossFunction* loss, const std::vector<double>& start) {
  REPOSE_DEMAND(cost->lower().size() == start.size());
  BoundedProblem b;
  ceres::Problem::Options options;
  options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  b.problem = std::make_unique<ceres::Problem>(options);
  b.x = start;
  for (double& v : b.x) b.blocks.push_back(&v);
  b.problem->AddResidualBlock(cost, loss, b.blocks);
  for (std::size_t k = 0; k < b.blocks.size(); ++k) {
    b.problem->SetParameterLowerBound(b.blocks[k], 0, cost->lower()[k]);
    b.problem->SetParameterUpperBound(b.blocks[k], 0, cost->upper()[k]);
  }
  return b;
}

std::vector<std::vector<double>> start_points(const CalibrationProblem& problem) {
  const CalibrationSolverSpec& solver = problem.spec().solver;
  std::vector<std::vector<double>> starts{problem.free_of(problem.initial_values())};
  const Halton halton(static_cast<int>(problem.free().size()), solver.seed);
  for (int s = 1; s < solver.starts; ++s) {
    const std::vector<double> u = halton.point(static_cast<std::uint64_t>(s));
    std::vector<double> x;
    for (std::size_t k = 0; k < u.size(); ++k) {
      const ParameterSpec& p = problem.spec().parameters[problem.free()[k]];
      x.push_back(p.lower + u[k] * (p.upper - p.lower));
    }
    starts.push_back(x);
  }
  return starts;
}

// Every parameter ended within kStalledFractionOfStep of its step of where it started.
bool stalled(const CalibrationStart& s, const std::vector<double>& steps) {
  for (std::size_t k = 0; k < steps.size(); ++k) {
    if (std::abs(s.final_free[k] - s.initial_free[k]) >= kStalledFractionOfStep * steps[k]) return false;
  }
  return true;
}

}  // namespace

CalibrationStart solve_or_retry_damped(const std::function<CalibrationStart(double first_radius)>& solve,
                                       const std::vector<double>& steps) {
  CalibrationStart first = solve(kFirstTrustRegionRadius);
  if (!std::isfinite(first.final_cost) || !stalled(first, steps)) return first;
  CalibrationStart damped = solve(kDampedTrustRegionRadius);
  if (damped.final_cost < first.final_cost) {
    damped.termination = fmt::format("{} (retried with a damped first step: the first solve stalled after {} iterations, {})",
                                     damped.termination, first.iterations, first.termination);
    return damped;
  }
  first.termination += " (a retry with a damped first step did no better)";
  return first;
}

CalibrationStart minimize_from(CalibrationCost* cost, ceres::LossFunction* loss, const std::vector<double>& start,
                               int max_iterations, ceres::IterationCallback* callback) {
  const auto solve = [&](double first_radius) {
    BoundedProblem b = make_problem(cost, loss, start);
    ceres::Solver::Options options;
    options.minimizer_type = ceres::TRUST_REGION;
    options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    options.linear_solver_type = ceres::DENSE_QR;
    options.initial_trust_region_radius = first_radius;
    options.max_num_iterations = max_iterations;
    options.num_threads = 1;  // the heuristic runs are parallel inside the cost
    options.logging_type = ceres::SILENT;
    options.minimizer_progress_to_stdout = false;
    if (callback != nullptr) options.callbacks.push_back(callback);
    ceres::Solver::Summary summary;
    ceres::Solve(options, b.problem.get(), &summary);
    CalibrationStart s;
    s.initial_free = start;
    s.final_free = b.x;
    s.initial_cost = summary.initial_cost;
    s.final_cost = summary.final_cost;
    s.iterations = static_cast<int>(summary.iterations.size()) - 1;
    s.termination = fmt::format("{}: {}", ceres::TerminationTypeToString(summary.termination_type), summary.message);
    for (const ceres::IterationSummary& it : summary.iterations) s.cost_per_iteration.push_back(it.cost);
    if (summary.termination_type == ceres::FAILURE || !std::isfinite(s.final_cost)) {
      s.final_cost = std::numeric_limits<double>::infinity();
    }
    return s;
  };
  return solve_or_retry_damped(solve, cost->steps());
}

CalibrationUncertainty uncertainty_at(CalibrationCost* cost, ceres::LossFunction* loss, const std::vector<double>& at,
                                      const std::vector<std::string>& labels, double final_cost,
                                      double min_reciprocal_condition) {
  BoundedProblem b = make_problem(cost, loss, at);
  std::vector<double> ranges;
  for (std::size_t k = 0; k < at.size(); ++k) ranges.push_back(cost->upper()[k] - cost->lower()[k]);
  return estimate_uncertainty(*b.problem, b.blocks, ranges, labels, final_cost, min_reciprocal_condition);
}

namespace {

CalibrationStart solve_from(const CalibrationProblem& calibration, CalibrationCost* cost, const std::vector<double>& start,
                            std::size_t index, const ProgressFn& progress) {
  const int max_iterations = calibration.spec().solver.max_iterations;
  ProgressCallback callback(progress, index, static_cast<std::size_t>(calibration.spec().solver.starts), max_iterations);
  const std::unique_ptr<ceres::LossFunction> loss(make_loss(calibration.spec().solver));
  return minimize_from(cost, loss.get(), start, max_iterations, &callback);
}

}  // namespace

CalibrationFit fit_calibration(const CalibrationProblem& problem, const ProgressFn& progress) {
  const auto clock_start = std::chrono::steady_clock::now();
  CalibrationFit fit;
  fit.initial_values = problem.initial_values();
  fit.residual_count = problem.fit_residual_count();
  CalibrationCost cost(problem);
  for (const std::vector<double>& start : start_points(problem)) {
    fit.starts.push_back(solve_from(problem, &cost, start, fit.starts.size(), progress));
    if (fit.starts.back().final_cost < fit.starts[fit.best_start].final_cost) fit.best_start = fit.starts.size() - 1;
  }
  const CalibrationStart& best = fit.starts[fit.best_start];
  if (!std::isfinite(best.final_cost)) throw InputError(problem.spec().source_path + ": every start of the fit failed: " + best.termination);
  fit.initial_cost = fit.starts[0].initial_cost;
  fit.final_cost = best.final_cost;
  fit.values = problem.with_free(best.final_free);

  report(progress, 1.0, "covariance at the optimum");
  std::vector<std::string> labels;
  for (const std::size_t p : problem.free()) labels.push_back(problem.spec().parameters[p].label());
  const std::unique_ptr<ceres::LossFunction> loss(make_loss(problem.spec().solver));
  fit.uncertainty = uncertainty_at(&cost, loss.get(), best.final_free, labels, best.final_cost,
                                   problem.spec().solver.min_reciprocal_condition);

  for (const PreparedScene& scene : problem.scenes()) {
    fit.scenes.push_back(scene_error(problem, scene, fit.initial_values, fit.values));
  }
  fit.heuristic_runs = problem.runs();
  fit.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return fit;
}

SceneError scene_error(const CalibrationProblem& problem, const PreparedScene& scene, const std::vector<double>& initial_values,
                       const std::vector<double>& fitted_values) {
  const auto& region = scene.entry.rmse_region;
  SceneError e;
  e.name = scene.entry.name;
  e.fit = scene.fit();
  e.grain_diameter_m = scene.grain_diameter_m;
  const std::vector<Run> initial = problem.runs(scene, initial_values), fitted = problem.runs(scene, fitted_values);
  e.heuristic_initial_params = problem.mean_final(scene, initial);  // the entry's field, as the fit compares
  e.heuristic_fitted = problem.mean_final(scene, fitted);
  const auto fitted_per_bed = problem.observed_per_bed(scene, fitted);
  e.series = compare_series(scene, problem.observed(scene, initial), CalibrationProblem::mean_over_beds(fitted_per_bed),
                            fitted_per_bed, fitted.front());
  e.rmse_initial_m = surface_rmse_m(e.heuristic_initial_params, scene.reference_final, region);
  e.rmse_fitted_m = surface_rmse_m(e.heuristic_fitted, scene.reference_final, region);
  e.scores_initial_params = score_change(scene.initial, e.heuristic_initial_params, scene.reference_final, region);
  e.scores_fitted = score_change(scene.initial, e.heuristic_fitted, scene.reference_final, region);
  e.noise = noise_floor(scene.seed_initial, scene.seed_final, region);
  e.reference_features = change_features(scene.initial, scene.reference_final, region);
  e.fitted_features = change_features(scene.initial, e.heuristic_fitted, region);
  return e;
}

std::string determination(const CalibrationFit& fit, const CalibrationProblem& problem, std::size_t k) {
  if (!fit.uncertainty.determined[k]) return "undetermined";
  const ParameterSpec& p = problem.spec().parameters[problem.free()[k]];
  return fit.uncertainty.standard_error[k] > 0.25 * (p.upper - p.lower) ? "poorly determined" : "determined";
}

}  // namespace repose
