// repose check SCENE.yaml: load and validate a scene, print its summary. Writes nothing.
#include <cstdio>
#include <memory>
#include <string>

#include "experiments/cli/commands.h"
#include "models/core/config/scene_loader.h"

namespace repose::cli {

void add_check_command(CLI::App& app) {
  CLI::App* check = app.add_subcommand("check", "Validate a scene file and summarise it");
  auto scene_path = std::make_shared<std::string>();
  check->add_option("scene", *scene_path, "Scene file (YAML)")->required();
  check->callback([scene_path] {
    const Scene scene = load_scene(*scene_path);
    const std::string summary = describe_scene(scene);
    std::fputs(summary.c_str(), stdout);
    if (!summary.ends_with('\n')) std::fputc('\n', stdout);
  });
}

}  // namespace repose::cli
