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
#include <nlohmann/json.hpp>

#include "experiments/runner/manifest.h"
#include "experiments/runner/progress_printer.h"
#include "experiments/runner/run_scene.h"
#include "models/core/run/build_info.h"
#include "models/core/base/error.h"
#include "models/core/run/repository_path.h"
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
// returns the wall time and the solver's run.
std::pair<double, Run> run_once(const Experiment& experiment, const ExperimentRun& run, const Solver& solver,
                                const ExperimentOptions& options, OutputDirectory& out, bool keep) {
  const auto start = Clock::now();
  try {
    OutputDirectory run_out = OutputDirectory::open(out.path(run.name), true);
    cli::Manifest manifest(options.command_line);
    cli::ProgressPrinter printer;
    const ProgressFn quiet = [](double, std::string_view) {};
    Run result = cli::run_scene(run.scene, solver, run_out, manifest, options.solver_progress ? printer.callback() : quiet);
    if (keep) run_out.commit();
    return {seconds_since(start), std::move(result)};
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: run '{}' failed: {}", experiment.source_path, run.name, e.what()));
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("{}: run '{}' failed: {}", experiment.source_path, run.name, e.what()));
  }
}

ExperimentRunOutcome run_repeated(const Experiment& experiment, std::size_t index, const SolverRegistry& registry,
                                  const ExperimentOptions& options, OutputDirectory& out) {
  const ExperimentRun& run = experiment.runs[index];
  ExperimentRunOutcome outcome{run.name, run.solver, {}, 0.0, {}};
  std::vector<std::vector<double>> measure_values(experiment.measures.size());
  for (int r = 0; r < experiment.repeat; ++r) {
    log_line(options, fmt::format("[{}/{}] {}: scene {}, solver {}{}", index + 1, experiment.runs.size(), run.name,
                                  run.scene.name, run.solver,
                                  experiment.repeat > 1 ? fmt::format(", repeat {}/{}", r + 1, experiment.repeat)
                                                        : std::string()));
    const bool last = r + 1 == experiment.repeat;
    const auto [wall_s, result] = run_once(experiment, run, registry.get(run.solver), options, out, last);
    outcome.wall_s.push_back(wall_s);
    for (std::size_t m = 0; m < experiment.measures.size(); ++m) {
      const auto it = result.measures.find(experiment.measures[m]);
      if (it != result.measures.end() && std::isfinite(it->second.value)) measure_values[m].push_back(it->second.value);
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
      throw InputError(fmt::format("{}: measures: '{}' is a measure of no run (see run.measures in a run's "
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
  // REPOSE_EXE: this program, for a plot that renders with it (plots/debris_render3d.py)
  std::vector<std::string> env_text = {"MPLBACKEND=Agg", "REPOSE_EXE=" + fs::read_symlink("/proc/self/exe").string()};
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string_view entry(*e);
    if (entry.rfind("MPLBACKEND=", 0) != 0 && entry.rfind("REPOSE_EXE=", 0) != 0) env_text.emplace_back(*e);
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

nlohmann::json run_json(const ExperimentRun& run, const ExperimentRunOutcome& outcome, const Experiment& experiment) {
  nlohmann::json measures = nlohmann::json::object();
  for (std::size_t m = 0; m < experiment.measures.size(); ++m) {
    measures[experiment.measures[m]] = outcome.measures[m] ? nlohmann::json(*outcome.measures[m]) : nlohmann::json();
  }
  return {{"name", run.name},
          {"solver", run.solver},
          {"scene", repository_relative(run.scene_path)},
          {"scene_sha256", sha256_hex_of_file(run.scene_path)},
          {"seed", run.scene.seed},
          {"wall_s", outcome.wall_s},
          {"wall_s_median", outcome.wall_s_median},
          {"measures", measures}};
}

void write_experiment_manifest(const std::string& path, const Experiment& experiment, const ExperimentOptions& options,
                               const std::vector<ExperimentRunOutcome>& runs, const ManifestInputs& inputs) {
  nlohmann::json run_list = nlohmann::json::array();
  for (std::size_t k = 0; k < runs.size(); ++k) run_list.push_back(run_json(experiment.runs[k], runs[k], experiment));
  const nlohmann::json json = {
      {"format", "repose-experiment-manifest"},
      {"format_version", 2},
      {"start_time_utc", inputs.start_time_utc},
      {"command_line", cli::recorded_command_line(options.command_line)},
      {"experiment",
       {{"path", repository_relative(experiment.source_path)},
        {"sha256", sha256_hex_of_file(experiment.source_path)},
        {"name", experiment.name},
        {"description", experiment.description},
        {"repeat", experiment.repeat},
        {"resolved_yaml", experiment_to_yaml(experiment)}}},
      {"build", cli::build_json(build_info())},
      {"runs", run_list},
      {"total_wall_s", seconds_since(inputs.start)},
      {"files", inputs.files}};
  std::ofstream file(path, std::ios::binary);
  file << json.dump(2) << "\n";
  file.close();
  if (!file) throw std::runtime_error(path + ": writing the experiment manifest failed");
}

}  // namespace

ExperimentOutcome run_experiment(const Experiment& experiment, const SolverRegistry& registry,
                                 const ExperimentOptions& options) {
  ManifestInputs inputs{cli::utc_now_iso8601(), Clock::now(), {}};
  OutputDirectory out = OutputDirectory::open(options.out_dir, options.force);
  log_line(options, fmt::format("experiment {}: {} run(s){}", experiment.name, experiment.runs.size(),
                                experiment.repeat > 1 ? fmt::format(", each {} times", experiment.repeat) : ""));
  ExperimentOutcome outcome;
  for (std::size_t k = 0; k < experiment.runs.size(); ++k) {
    outcome.runs.push_back(run_repeated(experiment, k, registry, options, out));
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
