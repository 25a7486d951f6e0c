// repose check SCENE.yaml: load and validate a scene (every section a solver
// reads), compile it for every solver that can run it, and print its
// summary. So `run` refuses nothing that `check` accepted. Writes nothing.
#include <cstdio>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "experiments/cli/commands.h"
#include "models/core/config/scene_loader.h"

namespace repose::cli {

void add_check_command(CLI::App& app, const SolverRegistry& registry) {
  CLI::App* check = app.add_subcommand("check", "Validate a scene file and summarise it");
  auto scene_path = std::make_shared<std::string>();
  check->add_option("scene", *scene_path, "Scene file (YAML)")->required();
  check->callback([scene_path, &registry] {
    const Scene scene = load_scene(*scene_path, registry.sections());
    std::string summary = describe_scene(scene);
    for (const auto& solver : registry.solvers()) {
      std::string why;
      if (!solver->can_run(scene, &why)) {
        summary += fmt::format("solver {}: cannot run ({})\n", solver->name(), why);
        continue;
      }
      const auto compiled = solver->compile(scene);
      summary += fmt::format("solver {}: ready, {} parameter(s)\n", solver->name(), compiled->parameters().size());
    }
    std::fputs(summary.c_str(), stdout);
    if (!summary.ends_with('\n')) std::fputc('\n', stdout);
  });
}

}  // namespace repose::cli
