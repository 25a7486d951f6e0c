#pragma once
// Experiment files (YAML): which scenes, which solvers, which parameter
// sweeps, which measures and which plot. Paths are relative to the file.
//
//   name: ground_table1                # optional (default: the file name)
//   description: "..."                 # optional
//   repeat: 5                          # optional (default 1): run each run N times, record medians
//   runs:
//     - name: no_sweep                 # a folder name: letters, digits, _ . -
//       scene: scenes/ground_drag_sweep.yaml
//       solver: ground                 # a solver of the registry (default: its first, ground)
//       overrides: {ground_model.sweep: false}   # optional scene keys, see scene_override.h
//   sweeps:                            # optional: one run template, one key, several values
//     - name: cell                     # runs cell_0.004, cell_0.008, ...
//       scene: scenes/ground_multires_full.yaml
//       solver: ground
//       overrides: {...}               # optional, applied before the swept key
//       sweep: {key: ground.cell_size_m, values: [0.004, 0.008]}
//   measures: [step_wall_s_median, volume.imbalance_m3]   # optional: keys of each run's
//                                      # manifest results (dotted), columns of summary.csv
//   plot: plots/ground_table1.py       # optional: python3 script, run with the experiment folder
//
// Every error is one InputError line: FILE:LINE:COL: KEY.PATH: expected WHAT, got WHAT.
// Loading checks that every scene exists and loads with its overrides, so a
// bad experiment fails before anything runs.

#include <cstddef>
#include <string>
#include <vector>

#include "experiments/runner/scene_override.h"
#include "models/core/config/scene.h"
#include "models/core/solver/solver_registry.h"

namespace repose {

struct ExperimentRun {
  std::string name;
  std::string scene_path;   // resolved (absolute, normalised)
  std::string solver;
  std::vector<SceneOverride> overrides;
  Scene scene;              // the scene with its overrides, loaded and validated
};

struct Experiment {
  std::string source_path;  // the experiment file
  std::string name;
  std::string description;
  int repeat = 1;
  std::vector<ExperimentRun> runs;  // the runs, then every sweep expanded, in file order
  std::vector<std::string> measures;
  std::string plot_path;    // resolved, empty when none
};

// Runs may name the registry's solvers (the first is the default); every
// run's scene loads with the registry's sections and its solver can run it.
Experiment load_experiment(const std::string& path, const SolverRegistry& registry);
Experiment load_experiment_from_string(const std::string& yaml, const std::string& pretend_path,
                                       const SolverRegistry& registry);

// The resolved experiment (sweeps expanded; scene and plot paths relative
// to the repository when inside it, as a committed manifest must name them)
// as YAML, for the experiment manifest.
std::string experiment_to_yaml(const Experiment& experiment);

}  // namespace repose
