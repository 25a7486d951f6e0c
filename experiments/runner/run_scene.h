#pragma once
// One scene run into a run folder, shared by `repose run` and the experiment
// runner: the solver compiled and run with the scene's own parameter values,
// every field it produced written as NAME.npy (and height fields as
// NAME.png), and manifest.json last. The caller opens and commits the folder.

#include "experiments/runner/manifest.h"
#include "models/core/base/progress.h"
#include "models/core/config/scene.h"
#include "models/core/run/output_directory.h"
#include "models/core/solver/solver.h"

namespace repose::cli {

// The manifest gets the scene, the solver, the stage times and the run.
Run run_scene(const Scene& scene, const Solver& solver, OutputDirectory& out, Manifest& manifest,
              const ProgressFn& progress);

}  // namespace repose::cli
