// repose experiment EXP.yaml --out DIR [--force]: run every run of an
// experiment file, then its summary, manifest and figures, atomically.
#include <cstdio>
#include <memory>
#include <string>

#include "experiments/cli/commands.h"
#include "experiments/runner/experiment.h"
#include "experiments/runner/run_experiment.h"

namespace repose::cli {
namespace {

struct ExperimentCommandOptions {
  std::string experiment_path;
  std::string out_dir;
  bool force = false;
};

void run(const ExperimentCommandOptions& options, int argc, char** argv, const SolverRegistry& registry) {
  // The whole experiment (every scene, every override) is checked before anything runs.
  const Experiment experiment = load_experiment(options.experiment_path, registry);
  ExperimentOptions run_options;
  run_options.out_dir = options.out_dir;
  run_options.force = options.force;
  run_options.command_line.assign(argv, argv + argc);
  const ExperimentOutcome outcome = run_experiment(experiment, registry, run_options);
  std::printf("wrote %s\n", outcome.folder.c_str());
}

}  // namespace

void add_experiment_command(CLI::App& app, int argc, char** argv, const SolverRegistry& registry) {
  CLI::App* command = app.add_subcommand(
      "experiment", "Run an experiment file: its runs (each a run folder), summary.csv, manifest.json and figures");
  auto options = std::make_shared<ExperimentCommandOptions>();
  command->add_option("experiment", options->experiment_path, "Experiment file (YAML)")->required();
  command->add_option("--out,-o", options->out_dir, "Folder to write (refused if not empty, unless --force)")
      ->required();
  command->add_flag("--force", options->force, "Replace a non-empty folder (only once the new experiment succeeded)");
  command->callback([options, argc, argv, &registry] { run(*options, argc, argv, registry); });
}

}  // namespace repose::cli
