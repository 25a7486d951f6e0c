#pragma once
// One scene run into a run folder, shared by `repose run` and the experiment
// runner: the initial state (height_initial.npy/.png), the solver's results,
// and manifest.json. The caller opens and commits the folder.

#include <string>

#include "experiments/runner/manifest.h"
#include "models/core/run/output_directory.h"
#include "models/core/base/progress.h"
#include "models/core/config/scene.h"

namespace repose::cli {

// Runs `solver` (a name from solvers()) on `scene` and writes everything into
// `out`, manifest.json last. The manifest gets the scene, the solver and the
// stage times; its results are the solver's.
void run_scene(const Scene& scene, const std::string& solver, OutputDirectory& out, Manifest& manifest,
               const ProgressFn& progress);

}  // namespace repose::cli
