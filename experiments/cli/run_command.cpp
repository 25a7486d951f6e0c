// repose run SCENE.yaml --out DIR [--force] [--solver NAME] [--set KEY=VALUE ...]:
// build the initial state, run a solver, and write the run folder atomically.
// --set overrides a scene key before the scene is checked (scene_override.h),
// e.g. `--set seed=12` for another random bed of the same reference scene.
#include <cstdio>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "experiments/cli/commands.h"
#include "experiments/runner/manifest.h"
#include "experiments/runner/progress_printer.h"
#include "experiments/runner/run_scene.h"
#include "experiments/runner/scene_override.h"
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
  std::vector<std::string> sets;  // KEY=VALUE
};

// "KEY=VALUE" -> an override whose value is read as YAML (a number, a list, a string).
SceneOverride parse_set(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError(fmt::format("--set {}: expected KEY=VALUE, e.g. --set seed=12", text));
  }
  try {
    return SceneOverride{text.substr(0, eq), YAML::Load(text.substr(eq + 1))};
  } catch (const YAML::Exception& e) {
    throw InputError(fmt::format("--set {}: the value is not YAML: {}", text, e.msg));
  }
}

void run(const RunOptions& options, int argc, char** argv, const SolverRegistry& registry) {
  Manifest manifest(argc, argv);
  // The scene is loaded before anything is written: a bad scene writes nothing.
  Scene scene;
  const Solver& solver = registry.get(options.solver);
  std::vector<SceneOverride> overrides;
  for (const std::string& set : options.sets) overrides.push_back(parse_set(set));
  manifest.time_stage("load_scene",
                      [&] { scene = load_scene_with_overrides(options.scene_path, overrides, registry.sections()); });
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
  command->add_option("--set", options->sets, "Override a scene key before it is checked: KEY=VALUE (repeatable)");
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
