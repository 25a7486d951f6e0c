#include "experiments/runner/manifest.h"

#include <ctime>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/base/sha256.h"
#include "models/core/config/scene_loader.h"
#include "models/core/run/repository_path.h"

namespace repose::cli {
namespace {

namespace fs = std::filesystem;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

nlohmann::json build_json(const BuildInfo& build) {
  nlohmann::json libraries = nlohmann::json::object();
  for (const auto& library : build.libraries) libraries[library.name] = library.version;
  return {{"repose_version", REPOSE_VERSION}, {"git_commit", build.git_commit}, {"git_dirty", build.git_dirty},
          {"compiler", build.compiler},       {"build_type", build.build_type}, {"libraries", libraries}};
}

Manifest::Manifest(int argc, char** argv) : Manifest(std::vector<std::string>(argv, argv + argc)) {}

std::vector<std::string> recorded_command_line(std::vector<std::string> arguments) {
  for (std::size_t k = 0; k < arguments.size(); ++k) {
    if (k == 0) arguments[k] = fs::path(arguments[k]).filename().string();
    else if (!arguments[k].empty() && arguments[k].front() == '/') arguments[k] = repository_relative(arguments[k]);
  }
  return arguments;
}

Manifest::Manifest(std::vector<std::string> command_line)
    : command_line_(recorded_command_line(std::move(command_line))),
      start_time_utc_(utc_now_iso8601()),
      start_(std::chrono::steady_clock::now()),
      build_(build_info()) {}

namespace {

// The resolved scene with every path inside the repository written relative
// to it (mesh and contour files resolve to absolute paths when loaded, and
// manifests under data/ are committed).
std::string repository_relative_yaml(const Scene& scene) {
  std::string text = scene_to_yaml(scene);
  const std::string root = repository_root() + "/";
  for (std::size_t at = text.find(root); at != std::string::npos; at = text.find(root, at)) text.erase(at, root.size());
  return text;
}

}  // namespace

void Manifest::set_scene(const Scene& scene) {
  scene_ = {{"path", repository_relative(scene.source_path)},
            {"sha256", sha256_hex_of_file(scene.source_path)},
            {"name", scene.name},
            {"seed", scene.seed},
            {"resolved_yaml", repository_relative_yaml(scene)}};
}

void Manifest::time_stage(const std::string& name, const std::function<void()>& stage) {
  const auto start = std::chrono::steady_clock::now();
  stage();
  stages_.push_back({name, seconds_since(start)});
}

void Manifest::set_run(const Run& run) {
  stages_built_ = run.stages;
  results_ = results_json(run);
  run_ = run;
}

void Manifest::write(const std::string& path) const {
  const fs::path folder = fs::path(path).parent_path();
  nlohmann::json stages = nlohmann::json::array();
  for (const auto& stage : stages_) stages.push_back({{"name", stage.name}, {"wall_s", stage.wall_s}});
  nlohmann::json files = nlohmann::json::array();
  for (const auto& name : files_) {
    if (name == fs::path(path).filename() || fs::exists(folder / name)) files.push_back(name);
  }
  const nlohmann::json json = {{"format", "repose-run-manifest"},
                               {"format_version", 2},
                               {"start_time_utc", start_time_utc_},
                               {"command_line", command_line_},
                               {"solver", solver_},
                               {"scene", scene_},
                               {"build", build_json(build_)},
                               {"stages", stages},
                               {"stages_built", stages_built_},
                               {"results", results_},
                               {"run", run_},
                               {"total_wall_s", seconds_since(start_)},
                               {"files", files}};
  std::ofstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error(fmt::format("{}: cannot write the manifest", path));
  file << json.dump(2) << "\n";
  file.close();
  if (!file) throw std::runtime_error(fmt::format("{}: writing the manifest failed", path));
}

}  // namespace repose::cli
