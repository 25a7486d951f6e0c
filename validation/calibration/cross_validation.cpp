#include "validation/calibration/cross_validation.h"

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

int cross_validate(const CalibrationProblem& problem, CalibrationFit* fit, const ProgressFn& progress) {
  REPOSE_DEMAND(fit->scenes.size() == problem.scenes().size());
  std::vector<std::size_t> fit_scenes;
  for (std::size_t k = 0; k < problem.scenes().size(); ++k) {
    if (problem.scenes()[k].fit()) fit_scenes.push_back(k);
  }
  if (fit_scenes.size() < 2) return 0;
  int folds = 0;
  for (const std::size_t k : fit_scenes) {
    const PreparedScene& left_out = problem.scenes()[k];
    report(progress, static_cast<double>(folds) / fit_scenes.size(),
           fmt::format("cross-validation: fit without {}", left_out.entry.name));
    const CalibrationProblem fold = problem.holding_out(left_out.entry.name);
    const CalibrationFit fold_fit = fit_calibration(fold, {});
    fit->scenes[k].cross_validated = fold_fit.scenes[k].scores_fitted;
    const CalibrationStart& best = fold_fit.starts[fold_fit.best_start];
    fit->folds.push_back({k, fold_fit.values, best.iterations, best.termination, fold_fit.scenes});
    ++folds;
  }
  report(progress, 1.0, "cross-validation done");
  return folds;
}

}  // namespace repose
