#pragma once
// Leave-one-scene-out cross-validation of a calibration: for each fit scene
// (when there are two or more), the same fit (starts, bounds, loss) on the
// other fit scenes alone, its parameters then scored on the scene it did not
// see. A fit that only reproduces what it was fitted to shows here: the
// cross-validated error of a scene is what the calibrated model predicts for
// a scene like it, and beside the in-sample error it says whether the fit
// predicts. Held-out scenes stay held out of every fold.

#include "models/core/base/progress.h"
#include "validation/calibration/calibration_fit.h"
#include "validation/calibration/calibration_problem.h"

namespace repose {

// Fills fit->scenes[k].cross_validated for every fit scene k and appends its
// fold to fit->folds (the fold's values, and every scene's errors at them:
// the left-out and held-out scenes' series as the fold predicts them); leaves
// them empty when the calibration has fewer than two fit scenes. Returns the
// number of folds run.
int cross_validate(const CalibrationProblem& problem, CalibrationFit* fit, const ProgressFn& progress = {});

}  // namespace repose
