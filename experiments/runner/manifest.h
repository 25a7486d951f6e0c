#pragma once
// The manifest of a run folder (manifest.json): what was run, from what, with
// what, and how long each stage took, so a result can be traced and redone.

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "models/core/run/build_info.h"
#include "models/core/io/json_writer.h"
#include "models/core/config/scene.h"

namespace repose::cli {

struct StageTime {
  std::string name;
  double wall_s = 0.0;
};

// Now, as 2026-11-21T07:30:00Z.
std::string utc_now_iso8601();

// The build as a JSON object: repose version, git commit, compiler, library versions.
void write_build_json(JsonWriter& json, const BuildInfo& build);

class Manifest {
 public:
  // Records the start time (UTC) and the command line.
  Manifest(int argc, char** argv);
  explicit Manifest(std::vector<std::string> command_line);

  // The scene: its file's SHA-256 and its resolved form (every default filled).
  void set_scene(const Scene& scene);
  void set_solver(const std::string& solver) { solver_ = solver; }
  // Runs one stage of the run and records its wall time.
  void time_stage(const std::string& name, const std::function<void()>& stage);
  // A file of the run folder, by its name inside the folder.
  void add_file(const std::string& name) { files_.push_back(name); }
  // The modules the scene built (e.g. "collision:cpu", "sweep", "erosion").
  void set_stages_built(std::vector<std::string> names) { stages_built_ = std::move(names); }
  // The solver's own results, written as the members of a "results" object.
  void set_results(std::function<void(JsonWriter&)> write_members) { results_ = std::move(write_members); }

  // The results as a JSON object ("{}" when the solver set none), for
  // experiment summaries.
  std::string results_json() const;

  // Writes the manifest as JSON (with the build information and the total wall time).
  void write(const std::string& path) const;

 private:
  std::vector<std::string> command_line_;
  std::string start_time_utc_;
  std::chrono::steady_clock::time_point start_;
  std::string scene_path_;
  std::string scene_sha256_;
  std::string scene_name_;
  std::string scene_yaml_;
  std::uint64_t seed_ = 0;
  std::string solver_;
  std::vector<StageTime> stages_;
  std::vector<std::string> files_;
  std::vector<std::string> stages_built_;
  std::function<void(JsonWriter&)> results_;
  BuildInfo build_;
};

}  // namespace repose::cli
