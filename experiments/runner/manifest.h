#pragma once
// The manifest of a run folder (manifest.json): what was run, from what, with
// what, and how long each stage took, so a result can be traced and redone.
// Paths inside the repository are recorded relative to it.

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/core/config/scene.h"
#include "models/core/run/build_info.h"
#include "models/core/solver/run.h"

namespace repose::cli {

struct StageTime {
  std::string name;
  double wall_s = 0.0;
};

// Now, as 2026-11-21T07:30:00Z.
std::string utc_now_iso8601();

// The command line as manifests record it: absolute paths inside the
// repository made relative (committed manifests must not hold the machine's
// paths), the program as its name.
std::vector<std::string> recorded_command_line(std::vector<std::string> arguments);

// The build as a JSON object: repose version, git commit, compiler, library versions.
nlohmann::json build_json(const BuildInfo& build);

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
  // The solver's run: its modules built, its results (measures as nested
  // objects, details) and the run itself (measures with units, timings).
  void set_run(const Run& run);
  // Results of a command that is not one solver run (calibrate).
  void set_results(nlohmann::json results) { results_ = std::move(results); }
  const nlohmann::json& results() const { return results_; }

  // Writes the manifest as JSON (with the build information and the total
  // wall time). Only files that exist in the manifest's folder are listed.
  void write(const std::string& path) const;

 private:
  std::vector<std::string> command_line_;
  std::string start_time_utc_;
  std::chrono::steady_clock::time_point start_;
  nlohmann::json scene_ = nlohmann::json::object();
  std::string solver_;
  std::vector<StageTime> stages_;
  std::vector<std::string> files_;
  std::vector<std::string> stages_built_;
  nlohmann::json results_ = nlohmann::json::object();
  nlohmann::json run_ = nlohmann::json::object();
  BuildInfo build_;
};

}  // namespace repose::cli
