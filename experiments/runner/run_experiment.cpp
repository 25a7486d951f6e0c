#include "experiments/runner/run_experiment.h"

#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "experiments/runner/manifest.h"
#include "experiments/runner/progress_printer.h"
#include "experiments/runner/run_scene.h"
#include "models/core/run/build_info.h"
#include "models/core/base/error.h"
#include "models/core/io/json_writer.h"
#include "models/core/run/output_directory.h"
#include "models/core/base/sha256.h"

extern char** environ;

namespace repose {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double median(std::vector<double> values) {
  REPOSE_DEMAND(!values.empty());
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

void log_line(const ExperimentOptions& options, const std::string& line) {
  if (options.log == nullptr) return;
  std::fprintf(options.log, "%s\n", line.c_str());
  std::fflush(options.log);
}

// One repeat of one run into DIR/RUN_NAME (committed only when `keep`);
// returns the wall time and the solver's results as JSON.
std::pair<double, std::string> run_once(const Experiment& experiment, const ExperimentRun& run,
                                        const ExperimentOptions& options, OutputDirectory& out, bool keep) {
  const auto start = Clock::now();
  try {
    OutputDirectory run_out = OutputDirectory::open(out.path(run.name), true);
    cli::Manifest manifest(options.command_line);
    cli::ProgressPrinter printer;
    const ProgressFn quiet = [](double, std::string_view) {};
    cli::run_scene(run.scene, run.solver, run_out, manifest, options.solver_progress ? printer.callback() : quiet);
    if (keep) run_out.commit();
    return {seconds_since(start), manifest.results_json()};
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: run '{}' failed: {}", experiment.source_path, run.name, e.what()));
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("{}: run '{}' failed: {}", experiment.source_path, run.name, e.what()));
  }
}

ExperimentRunOutcome run_repeated(const Experiment& experiment, std::size_t index, const ExperimentOptions& options,
                                  OutputDirectory& out) {
  const ExperimentRun& run = experiment.runs[index];
  ExperimentRunOutcome outcome{run.name, run.solver, {}, 0.0, {}};
  std::vector<std::vector<double>> measure_values(experiment.measures.size());
  for (int r = 0; r < experiment.repeat; ++r) {
    log_line(options, fmt::format("[{}/{}] {}: scene {}, solver {}{}", index + 1, experiment.runs.size(), run.name,
                                  run.scene.name, run.solver,
                                  experiment.repeat > 1 ? fmt::format(", repeat {}/{}", r + 1, experiment.repeat)
                                                        : std::string()));
    const bool last = r + 1 == experiment.repeat;
    const auto [wall_s, results] = run_once(experiment, run, options, out, last);
    outcome.wall_s.push_back(wall_s);
    for (std::size_t m = 0; m < experiment.measures.size(); ++m) {
      if (auto value = json_number_at(results, experiment.measures[m])) measure_values[m].push_back(*value);
    }
  }
  outcome.wall_s_median = median(outcome.wall_s);
  for (const auto& values : measure_values) {
    outcome.measures.push_back(values.empty() ? std::nullopt : std::optional<double>(median(values)));
  }
  log_line(options, fmt::format("[{}/{}] {}: done in {:.3f} s (median of {})", index + 1, experiment.runs.size(),
                                run.name, outcome.wall_s_median, outcome.wall_s.size()));
  return outcome;
}

// A measure that no run has is a typo in the experiment, not a result.
void check_measures_found(const Experiment& experiment, const std::vector<ExperimentRunOutcome>& runs) {
  for (std::size_t m = 0; m < experiment.measures.size(); ++m) {
    const bool found = std::any_of(runs.begin(), runs.end(), [&](const auto& r) { return r.measures[m].has_value(); });
    if (!found) {
      throw InputError(fmt::format("{}: measures: '{}' is a number in no run's results (see results in a run's "
                                   "manifest.json)",
                                   experiment.source_path, experiment.measures[m]));
    }
  }
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

void write_summary_csv(const std::string& path, const Experiment& experiment,
                       const std::vector<ExperimentRunOutcome>& runs) {
  std::ofstream file(path, std::ios::binary);
  file << "name,solver,wall_s";
  for (const auto& m : experiment.measures) file << ',' << csv_field(m);
  file << '\n';
  for (const auto& run : runs) {
    file << csv_field(run.name) << ',' << run.solver << ',' << fmt::format("{}", run.wall_s_median);
    for (const auto& value : run.measures) file << ',' << (value ? fmt::format("{}", *value) : std::string());
    file << '\n';
  }
  file.close();
  if (!file) throw std::runtime_error(path + ": writing the summary failed");
}

// Runs the plot script on the (not yet committed) experiment folder.
void run_plot(const Experiment& experiment, const ExperimentOptions& options, const std::string& folder) {
  std::vector<std::string> args = {options.python, experiment.plot_path, folder};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_text = {"MPLBACKEND=Agg"};
  for (char** e = environ; *e != nullptr; ++e) {
    if (std::string_view(*e).rfind("MPLBACKEND=", 0) != 0) env_text.emplace_back(*e);
  }
  std::vector<char*> envp;
  for (auto& e : env_text) envp.push_back(e.data());
  envp.push_back(nullptr);
  log_line(options, fmt::format("plot: {} {}", options.python, experiment.plot_path));
  pid_t pid = 0;
  if (::posix_spawn(&pid, options.python.c_str(), nullptr, nullptr, argv.data(), envp.data()) != 0) {
    throw std::runtime_error(fmt::format("{}: plot: cannot start {}", experiment.source_path, options.python));
  }
  int status = 0;
  if (::waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error(fmt::format("{}: plot: {} failed (exit status {})", experiment.source_path,
                                         experiment.plot_path, WIFEXITED(status) ? WEXITSTATUS(status) : -1));
  }
}

// The files of the folder (relative paths), run folders excluded.
std::vector<std::string> top_files(const fs::path& folder, const Experiment& experiment) {
  std::set<std::string> run_names;
  for (const auto& run : experiment.runs) run_names.insert(run.name);
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    const std::string relative = fs::relative(entry.path(), folder).generic_string();
    if (run_names.count(relative.substr(0, relative.find('/'))) == 0) files.push_back(relative);
  }
  std::sort(files.begin(), files.end());
  return files;
}

struct ManifestInputs {
  std::string start_time_utc;
  Clock::time_point start;
  std::vector<std::string> files;
};

void write_experiment_manifest(const std::string& path, const Experiment& experiment, const ExperimentOptions& options,
                               const std::vector<ExperimentRunOutcome>& runs, const ManifestInputs& inputs) {
  const BuildInfo build = build_info();
  std::ofstream file(path, std::ios::binary);
  JsonWriter json(file);
  json.begin_object();
  json.key("format").string("repose-experiment-manifest");
  json.key("format_version").integer(1);
  json.key("start_time_utc").string(inputs.start_time_utc);
  json.key("command_line").begin_array();
  for (const auto& argument : options.command_line) json.string(argument);
  json.end_array();
  json.key("experiment").begin_object();
  json.key("path").string(experiment.source_path);
  json.key("sha256").string(sha256_hex_of_file(experiment.source_path));
  json.key("name").string(experiment.name);
  json.key("description").string(experiment.description);
  json.key("repeat").integer(experiment.repeat);
  json.key("resolved_yaml").string(experiment_to_yaml(experiment));
  json.end_object();
  json.key("build");
  cli::write_build_json(json, build);
  json.key("runs").begin_array();
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const ExperimentRun& run = experiment.runs[k];
    json.begin_object();
    json.key("name").string(run.name);
    json.key("solver").string(run.solver);
    json.key("scene").string(run.scene_path);
    json.key("scene_sha256").string(sha256_hex_of_file(run.scene_path));
    json.key("seed").unsigned_integer(run.scene.seed);
    json.key("wall_s").begin_array();
    for (double t : runs[k].wall_s) json.number(t);
    json.end_array();
    json.key("wall_s_median").number(runs[k].wall_s_median);
    json.key("measures").begin_object();
    for (std::size_t m = 0; m < experiment.measures.size(); ++m) {
      json.key(experiment.measures[m]);
      if (runs[k].measures[m]) json.number(*runs[k].measures[m]); else json.null();
    }
    json.end_object();
    json.end_object();
  }
  json.end_array();
  json.key("total_wall_s").number(seconds_since(inputs.start));
  json.key("files").begin_array();
  for (const auto& name : inputs.files) json.string(name);
  json.end_array();
  json.end_object();
  file.close();
  if (!file) throw std::runtime_error(path + ": writing the experiment manifest failed");
}

}  // namespace

std::optional<double> json_number_at(const std::string& json_object, const std::string& dotted_key) {
  // JSON is YAML (flow style), so yaml-cpp reads it.
  YAML::Node node;
  try {
    node = YAML::Load(json_object);
  } catch (const YAML::Exception&) {
    return std::nullopt;
  }
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = dotted_key.find('.', start);
    const std::string key = dotted_key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (!node.IsMap() || !node[key]) return std::nullopt;
    node.reset(node[key]);
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  if (!node.IsScalar()) return std::nullopt;
  try {
    const double value = node.as<double>();
    return std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
  } catch (const YAML::Exception&) {
    return std::nullopt;
  }
}

ExperimentOutcome run_experiment(const Experiment& experiment, const ExperimentOptions& options) {
  ManifestInputs inputs{cli::utc_now_iso8601(), Clock::now(), {}};
  OutputDirectory out = OutputDirectory::open(options.out_dir, options.force);
  log_line(options, fmt::format("experiment {}: {} run(s){}", experiment.name, experiment.runs.size(),
                                experiment.repeat > 1 ? fmt::format(", each {} times", experiment.repeat) : ""));
  ExperimentOutcome outcome;
  for (std::size_t k = 0; k < experiment.runs.size(); ++k) {
    outcome.runs.push_back(run_repeated(experiment, k, options, out));
  }
  check_measures_found(experiment, outcome.runs);
  write_summary_csv(out.path("summary.csv"), experiment, outcome.runs);
  if (!experiment.plot_path.empty()) run_plot(experiment, options, out.temporary().string());
  inputs.files = top_files(out.temporary(), experiment);
  inputs.files.push_back("manifest.json");
  write_experiment_manifest(out.path("manifest.json"), experiment, options, outcome.runs, inputs);
  out.commit();
  outcome.folder = out.target().string();
  return outcome;
}

}  // namespace repose
