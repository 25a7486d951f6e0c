#include "validation/calibration/reference_cost.h"

#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "models/core/base/error.h"
#include "models/core/io/input_file.h"
#include "models/core/solver/run.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

std::optional<nlohmann::json> read_json(const fs::path& path) {
  if (!fs::exists(path)) return std::nullopt;
  const std::string text = read_input_file(path.string(), input_kind::kRunRecord);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: not valid JSON: {}", path.string(), e.what()));
  }
}

}  // namespace

std::optional<RunCost> read_run_cost(const std::string& folder) {
  try {
    // a LIGGGHTS run's own record: the run (after the settled bed)
    if (const auto liggghts = read_json(fs::path(folder) / "liggghts_manifest.json")) {
      return RunCost{liggghts->at("wall_time_s").get<double>(), liggghts->at("cpu_time_s").get<double>()};
    }
    if (const auto manifest = read_json(fs::path(folder) / "manifest.json"); manifest && manifest->contains("run")) {
      const Run run = manifest->at("run").get<Run>();
      return RunCost{run.wall_s, run.cpu_s};
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: a run record without its cost ({})", folder, e.what()));
  }
  return std::nullopt;
}

std::map<std::string, double> read_run_measures(const std::string& folder) {
  std::map<std::string, double> out;
  try {
    const auto manifest = read_json(fs::path(folder) / "manifest.json");
    if (!manifest || !manifest->contains("run")) return out;
    for (const auto& [name, measure] : manifest->at("run").get<Run>().measures) out[name] = measure.value;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: a run record without its measures ({})", folder, e.what()));
  }
  return out;
}

std::string read_run_engine(const std::string& folder) {
  if (fs::exists(fs::path(folder) / "liggghts_manifest.json")) return "liggghts";
  const fs::path path = fs::path(folder) / "manifest.json";
  const auto manifest = read_json(path);
  if (!manifest || !manifest->contains("solver") || !manifest->at("solver").is_string()) {
    throw InputError(path.string() + ": a run manifest naming its solver");
  }
  return manifest->at("solver").get<std::string>();
}

}  // namespace repose
