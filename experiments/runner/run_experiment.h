#pragma once
// Runs an experiment (experiment.h) into one folder, atomically:
//
//   DIR/RUN_NAME/      the run folder of each run, as `repose run` writes it
//   DIR/summary.csv    one row per run: name, solver, wall_s (median over
//                      repeats), then each measure of the runs (Run::measures,
//                      median over repeats)
//   DIR/manifest.json  the experiment file's SHA-256, the resolved experiment,
//                      the build (git commit, library versions), per-run
//                      scenes, seeds and wall times, and the file list
//   DIR/...            the figures the plot script wrote
//
// A run, a measure or the plot that fails fails the experiment with a message
// naming it, and DIR is left as it was. A progress line per run goes to `log`.

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "experiments/runner/experiment.h"

namespace repose {

struct ExperimentOptions {
  std::string out_dir;
  bool force = false;                       // replace a non-empty DIR (once the experiment succeeded)
  std::vector<std::string> command_line;    // recorded in the manifests
  std::string python = "/usr/bin/python3";  // runs the plot script, with MPLBACKEND=Agg
  std::FILE* log = stderr;                  // one line per run; nullptr: quiet
  bool solver_progress = true;              // the solvers' own progress lines on stderr
};

struct ExperimentRunOutcome {
  std::string name;
  std::string solver;
  std::vector<double> wall_s;   // one per repeat
  double wall_s_median = 0.0;
  std::vector<std::optional<double>> measures;  // median per measure; empty when the run has no such result
};

struct ExperimentOutcome {
  std::string folder;  // the committed DIR
  std::vector<ExperimentRunOutcome> runs;
};

ExperimentOutcome run_experiment(const Experiment& experiment, const SolverRegistry& registry,
                                 const ExperimentOptions& options);


}  // namespace repose
