#pragma once
// The solvers `repose run --solver NAME` can dispatch to. A solver turns the
// scene and its initial state into results written into the run folder; the
// run command has already written the initial state (height_initial.npy/.png)
// and writes the manifest after the solver returns.
//
// To add a solver (the ground model, LIGGGHTS, ...): add an entry in
// solvers.cpp. Record each long stage with context.manifest.time_stage and
// each file with context.manifest.add_file; report progress through
// context.progress.

#include <functional>
#include <string>
#include <vector>

#include "experiments/runner/manifest.h"
#include "models/core/geometry/height_field.h"
#include "models/core/run/output_directory.h"
#include "models/core/base/progress.h"
#include "models/core/config/scene.h"

namespace repose::cli {

struct RunContext {
  const Scene& scene;
  const HeightField& initial_height;
  OutputDirectory& out;
  Manifest& manifest;
  ProgressFn progress;
};

struct Solver {
  std::string name;
  std::string description;
  std::function<void(RunContext&)> run;
};

// models/ground, with the scene's own materials as parameters (ground_solver.cpp).
void run_ground_solver(RunContext& context);

// validation/liggghts/liggghts_reference.h (liggghts_solver.cpp).
void run_liggghts_solver(RunContext& context);

// Every solver, by name; the first is the default.
const std::vector<Solver>& solvers();
std::vector<std::string> solver_names();
const Solver& find_solver(const std::string& name);  // REPOSE_DEMAND: a listed name

}  // namespace repose::cli
