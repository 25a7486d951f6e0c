// repose run SCENE.yaml --out DIR [--force] [--solver NAME]: build the
// initial state, run a solver, and write the run folder atomically.
#include <cstdio>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "experiments/cli/commands.h"
#include "experiments/runner/manifest.h"
#include "experiments/runner/progress_printer.h"
#include "experiments/runner/run_scene.h"
#include "models/core/run/output_directory.h"
#include "models/core/base/error.h"
#include "models/core/config/scene_loader.h"

namespace repose::cli {
namespace {

struct RunOptions {
  std::string scene_path;
  std::string out_dir;
  bool force = false;
  std::string solver;
};

void run(const RunOptions& options, int argc, char** argv, const SolverRegistry& registry) {
  Manifest manifest(argc, argv);
  // The scene is loaded before anything is written: a bad scene writes nothing.
  Scene scene;
  const Solver& solver = registry.get(options.solver);
  manifest.time_stage("load_scene", [&] { scene = load_scene(options.scene_path, registry.sections()); });
  std::string why;
  if (!solver.can_run(scene, &why)) throw InputError(fmt::format("{}: solver {}: {}", scene.source_path, solver.name(), why));
  OutputDirectory out = OutputDirectory::open(options.out_dir, options.force);
  ProgressPrinter progress;
  run_scene(scene, solver, out, manifest, progress.callback());
  out.commit();
  std::printf("wrote %s\n", out.target().string().c_str());
}

}  // namespace

void add_run_command(CLI::App& app, int argc, char** argv, const SolverRegistry& registry) {
  CLI::App* command = app.add_subcommand("run", "Run a scene and write a run folder (manifest.json, data, images)");
  auto options = std::make_shared<RunOptions>();
  options->solver = registry.names().front();
  command->add_option("scene", options->scene_path, "Scene file (YAML)")->required();
  command->add_option("--out,-o", options->out_dir, "Run folder to write (refused if not empty, unless --force)")
      ->required();
  command->add_flag("--force", options->force, "Replace a non-empty run folder (only once the new run succeeded)");
  std::string solver_help = "Solver:";
  for (const auto& solver : registry.solvers()) {
    solver_help += fmt::format(" {} ({});", solver->name(), solver->description());
  }
  command->add_option("--solver", options->solver, solver_help)
      ->check(CLI::IsMember(registry.names()))
      ->capture_default_str();
  command->callback([options, argc, argv, &registry] { run(*options, argc, argv, registry); });
}

}  // namespace repose::cli
