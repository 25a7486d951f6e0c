#include "experiments/runner/manifest.h"

#include <ctime>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/io/json_writer.h"
#include "models/core/config/scene_loader.h"
#include "models/core/base/sha256.h"

namespace repose::cli {
namespace {

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

void write_build_json(JsonWriter& json, const BuildInfo& build) {
  json.begin_object();
  json.key("repose_version").string(REPOSE_VERSION);
  json.key("git_commit").string(build.git_commit);
  json.key("git_dirty").boolean(build.git_dirty);
  json.key("compiler").string(build.compiler);
  json.key("build_type").string(build.build_type);
  json.key("libraries").begin_object();
  for (const auto& library : build.libraries) json.key(library.name).string(library.version);
  json.end_object();
  json.end_object();
}

Manifest::Manifest(int argc, char** argv) : Manifest(std::vector<std::string>(argv, argv + argc)) {}

Manifest::Manifest(std::vector<std::string> command_line)
    : command_line_(std::move(command_line)),
      start_time_utc_(utc_now_iso8601()),
      start_(std::chrono::steady_clock::now()) {
  build_ = build_info();
}

std::string Manifest::results_json() const {
  std::ostringstream text;
  JsonWriter json(text);
  json.begin_object();
  if (results_) results_(json);
  json.end_object();
  return text.str();
}

void Manifest::set_scene(const Scene& scene) {
  scene_path_ = scene.source_path;
  scene_sha256_ = sha256_hex_of_file(scene.source_path);
  scene_name_ = scene.name;
  scene_yaml_ = scene_to_yaml(scene);
  seed_ = scene.seed;
}

void Manifest::time_stage(const std::string& name, const std::function<void()>& stage) {
  const auto start = std::chrono::steady_clock::now();
  stage();
  stages_.push_back({name, seconds_since(start)});
}

void Manifest::write(const std::string& path) const {
  std::ofstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error(fmt::format("{}: cannot write the manifest", path));
  JsonWriter json(file);
  json.begin_object();
  json.key("format").string("repose-run-manifest");
  json.key("format_version").integer(1);
  json.key("start_time_utc").string(start_time_utc_);
  json.key("command_line").begin_array();
  for (const auto& argument : command_line_) json.string(argument);
  json.end_array();
  json.key("solver").string(solver_);

  json.key("scene").begin_object();
  json.key("path").string(scene_path_);
  json.key("sha256").string(scene_sha256_);
  json.key("name").string(scene_name_);
  json.key("seed").unsigned_integer(seed_);
  json.key("resolved_yaml").string(scene_yaml_);
  json.end_object();

  json.key("build");
  write_build_json(json, build_);

  json.key("stages").begin_array();
  for (const auto& stage : stages_) {
    json.begin_object().key("name").string(stage.name).key("wall_s").number(stage.wall_s).end_object();
  }
  json.end_array();
  json.key("stages_built").begin_array();
  for (const auto& name : stages_built_) json.string(name);
  json.end_array();
  json.key("results").begin_object();
  if (results_) results_(json);
  json.end_object();
  json.key("total_wall_s").number(seconds_since(start_));
  json.key("files").begin_array();
  for (const auto& name : files_) json.string(name);
  json.end_array();
  json.end_object();
  file.close();
  if (!file) throw std::runtime_error(fmt::format("{}: writing the manifest failed", path));
}

}  // namespace repose::cli
