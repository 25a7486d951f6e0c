#include "experiments/runner/experiment.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/io/input_file.h"
#include "models/core/run/repository_path.h"
#include "models/core/config/yaml_reader.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

const IntRange kRepeat{1, 1000};
const std::vector<std::string> kRunKeys = {"name", "scene", "solver", "overrides"};

struct Context {
  std::string file;
  fs::path directory;
  const SolverRegistry& registry;
};

// A run name becomes a folder name: letters, digits, '_', '.', '-', not starting with '.'.
bool is_folder_name(const std::string& name) {
  if (name.empty() || name.front() == '.' || name.size() > 200) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.' || c == '-';
  });
}

// A swept value as part of a run name: its text, with other characters as '_'.
std::string name_part(const YAML::Node& value) {
  std::string text = value.IsScalar() ? value.Scalar() : YAML::Dump(value);
  for (char& c : text) {
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '.' && c != '-') c = '_';
  }
  return text;
}

std::string read_run_name(const YamlValue& value) {
  const std::string name = value.string();
  if (!is_folder_name(name)) value.fail("a run name of letters, digits, '_', '.', '-' (a folder name)");
  return name;
}

std::string read_scene_path(const Context& ctx, const YamlValue& value) {
  const fs::path p(value.string());
  const std::string path = (p.is_absolute() ? p : ctx.directory / p).lexically_normal().string();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    value.fail("a scene file (relative to the experiment file)",
               fmt::format("'{}', which does not exist or is not a file ({})", value.string(), path));
  }
  return path;
}

std::string read_solver(const Context& ctx, const YamlMap& map) {
  const auto value = map.get("solver");
  const std::vector<std::string> names = ctx.registry.names();
  if (!value) return names.front();
  return names[value->choice(names)];
}

// An override with where it came from, for messages.
struct LocatedOverride {
  SceneOverride override_;
  YamlValue source;
};

std::vector<LocatedOverride> read_overrides(const Context& ctx, const YamlMap& map) {
  std::vector<LocatedOverride> out;
  const auto value = map.get("overrides");
  if (!value) return out;
  if (!value->is_map()) value->fail("a map {dotted.scene.key: value, ...}");
  for (const auto& entry : value->node()) {
    const std::string key = entry.first.Scalar();
    out.push_back({{key, entry.second}, YamlValue(ctx.file, entry.second, value->path() + "." + key)});
  }
  return out;
}

std::vector<SceneOverride> plain_overrides(const std::vector<LocatedOverride>& overrides) {
  std::vector<SceneOverride> plain;
  for (const auto& o : overrides) plain.push_back(o.override_);
  return plain;
}

// Loads the run's scene with its overrides; an error names the experiment
// file (at the override to blame, or at the scene key), the override and the scene.
Scene load_run_scene(const std::string& scene_path, const std::vector<LocatedOverride>& overrides,
                     const YamlValue& scene_value, const SectionTypes& sections) {
  const std::vector<SceneOverride> plain = plain_overrides(overrides);
  try {
    return load_scene_with_overrides(scene_path, plain, sections);
  } catch (const InputError&) {
    // Only on failure: the first prefix of the overrides that fails names the override to blame.
    for (std::size_t k = 0; k <= plain.size(); ++k) {
      try {
        load_scene_with_overrides(scene_path, {plain.begin(), plain.begin() + static_cast<std::ptrdiff_t>(k)},
                                  sections);
      } catch (const InputError& e) {
        if (k == 0) scene_value.fail("a scene that loads", e.what());
        overrides[k - 1].source.fail(fmt::format("an override that scene {} accepts", scene_path), e.what());
      }
    }
    throw;
  }
}

// The run's solver must be able to run its scene (its sections present, the
// scene compiles), so that a bad experiment fails before anything runs.
void check_solver_runs(const Context& ctx, const ExperimentRun& run, const YamlMap& map) {
  const Solver& solver = ctx.registry.get(run.solver);
  std::string why;
  const YamlValue at = map.get("solver") ? *map.get("solver") : map.self();
  if (!solver.can_run(run.scene, &why)) at.fail(fmt::format("a solver that can run {}", run.scene_path), why);
  try {
    solver.compile(run.scene);
  } catch (const InputError& e) {
    at.fail(fmt::format("a solver that can run {}", run.scene_path), e.what());
  }
}

ExperimentRun read_run(const Context& ctx, const YamlValue& value) {
  const YamlMap map = value.map(kRunKeys);
  ExperimentRun run;
  run.name = read_run_name(map.required("name", "a run name"));
  const YamlValue scene_value = map.required("scene", "a scene file");
  run.scene_path = read_scene_path(ctx, scene_value);
  run.solver = read_solver(ctx, map);
  const auto overrides = read_overrides(ctx, map);
  run.overrides = plain_overrides(overrides);
  run.scene = load_run_scene(run.scene_path, overrides, scene_value, ctx.registry.sections());
  check_solver_runs(ctx, run, map);
  return run;
}

std::vector<ExperimentRun> read_sweep(const Context& ctx, const YamlValue& value) {
  std::vector<std::string> keys = kRunKeys;
  keys.push_back("sweep");
  const YamlMap map = value.map(keys);
  const std::string name = read_run_name(map.required("name", "a sweep name"));
  const YamlValue scene_value = map.required("scene", "a scene file");
  const std::string scene_path = read_scene_path(ctx, scene_value);
  const std::string solver = read_solver(ctx, map);
  const auto overrides = read_overrides(ctx, map);
  const YamlMap sweep = map.required("sweep", "a map {key: dotted.scene.key, values: [...]}").map({"key", "values"});
  const YamlValue key_value = sweep.required("key", "a dotted scene key");
  const std::string key = key_value.string();
  const YamlValue values = sweep.required("values", "a list of values");
  std::vector<ExperimentRun> runs;
  for (const YamlValue& v : values.list(1)) {
    ExperimentRun run;
    run.name = name + "_" + name_part(v.node());
    if (!is_folder_name(run.name)) v.fail("a value that makes a folder name", fmt::format("'{}'", run.name));
    run.scene_path = scene_path;
    run.solver = solver;
    auto located = overrides;
    located.push_back({{key, v.node()}, v});
    run.overrides = plain_overrides(located);
    run.scene = load_run_scene(scene_path, located, scene_value, ctx.registry.sections());
    check_solver_runs(ctx, run, map);
    runs.push_back(std::move(run));
  }
  return runs;
}

Experiment read_experiment(const Context& ctx, const YamlValue& root) {
  const std::vector<std::string> top = {"name", "description", "repeat", "runs", "sweeps", "measures", "plot"};
  if (!root.node().IsDefined() || root.node().IsNull()) {
    root.fail(fmt::format("a map with the keys {}", fmt::join(top, ", ")), "an empty document");
  }
  const YamlMap map = root.map(top);
  Experiment e;
  e.source_path = (ctx.directory / fs::path(ctx.file).filename()).string();
  e.name = map.string_or("name", fs::path(ctx.file).stem().string());
  e.description = map.string_or("description", "");
  e.repeat = static_cast<int>(map.integer_or("repeat", kRepeat, 1));
  if (auto runs = map.get("runs")) {
    for (const YamlValue& r : runs->list()) e.runs.push_back(read_run(ctx, r));
  }
  if (auto sweeps = map.get("sweeps")) {
    for (const YamlValue& s : sweeps->list()) {
      for (auto& run : read_sweep(ctx, s)) e.runs.push_back(std::move(run));
    }
  }
  if (e.runs.empty()) map.fail_missing("runs", "at least one run (in runs or sweeps)");
  std::set<std::string> names;
  for (const auto& run : e.runs) {
    if (!names.insert(run.name).second) {
      map.self().fail("run names that differ", fmt::format("the run name '{}' twice", run.name));
    }
  }
  if (auto measures = map.get("measures")) {
    for (const YamlValue& m : measures->list()) e.measures.push_back(m.string());
  }
  if (auto plot = map.get("plot")) {
    const fs::path p(plot->string());
    e.plot_path = (p.is_absolute() ? p : ctx.directory / p).lexically_normal().string();
    std::error_code ec;
    if (!fs::is_regular_file(e.plot_path, ec)) {
      plot->fail("a Python script (relative to the experiment file)",
                 fmt::format("'{}', which does not exist ({})", plot->string(), e.plot_path));
    }
  }
  return e;
}

}  // namespace

Experiment load_experiment_from_string(const std::string& yaml, const std::string& pretend_path,
                                       const SolverRegistry& registry) {
  REPOSE_DEMAND(!registry.solvers().empty());
  const Context ctx{pretend_path, fs::absolute(fs::path(pretend_path)).parent_path().lexically_normal(), registry};
  return read_experiment(ctx, parse_yaml(yaml, pretend_path));
}

Experiment load_experiment(const std::string& path, const SolverRegistry& registry) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": no such experiment file");
  return load_experiment_from_string(read_input_file(path, input_kind::kExperiment), path, registry);
}

std::string experiment_to_yaml(const Experiment& e) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << e.name;
  out << YAML::Key << "description" << YAML::Value << e.description;
  out << YAML::Key << "repeat" << YAML::Value << e.repeat;
  out << YAML::Key << "runs" << YAML::Value << YAML::BeginSeq;
  for (const ExperimentRun& run : e.runs) {
    out << YAML::BeginMap;
    out << YAML::Key << "name" << YAML::Value << run.name;
    out << YAML::Key << "scene" << YAML::Value << repository_relative(run.scene_path);
    out << YAML::Key << "solver" << YAML::Value << run.solver;
    out << YAML::Key << "overrides" << YAML::Value << YAML::BeginMap;
    for (const SceneOverride& o : run.overrides) out << YAML::Key << o.key << YAML::Value << o.value;
    out << YAML::EndMap << YAML::EndMap;
  }
  out << YAML::EndSeq;
  out << YAML::Key << "measures" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (const auto& m : e.measures) out << m;
  out << YAML::EndSeq;
  out << YAML::Key << "plot" << YAML::Value << repository_relative(e.plot_path);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace repose
