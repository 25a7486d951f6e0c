// repose calibrate CALIB.yaml --out DIR [--force]: fit the ground model's
// parameters to reference runs (validation/calibration_*.h), check them on
// held-out scenes, measure the speed/accuracy ladder, and write the run
// folder atomically: calibration.json, material.yaml, report.md, figures,
// data/ and manifest.json. Progress lines go to stderr.
#include <cstdio>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "experiments/cli/commands.h"
#include "experiments/runner/manifest.h"
#include "experiments/runner/progress_printer.h"
#include "models/core/run/repository_path.h"
#include "models/core/run/build_info.h"
#include "models/core/run/output_directory.h"
#include "validation/calibration/calibration_figures.h"
#include "validation/calibration/calibration_fit.h"
#include "validation/calibration/calibration_ladder.h"
#include "validation/calibration/cross_validation.h"
#include "validation/calibration/calibration_loader.h"
#include "validation/calibration/calibration_problem.h"
#include "validation/calibration/calibration_report.h"

namespace repose::cli {
namespace {

struct CalibrateOptions {
  std::string calibration_path;
  std::string out_dir;
  bool force = false;
};

std::string joined_command_line(int argc, char** argv) {
  std::string text;
  for (const std::string& a : recorded_command_line({argv, argv + argc})) text += (text.empty() ? "" : " ") + a;
  return text;
}

void calibrate(const CalibrateOptions& options, int argc, char** argv, const SolverRegistry& registry) {
  Manifest manifest(argc, argv);
  manifest.set_solver("calibrate");
  // the calibration is loaded before anything is written: a bad file writes nothing
  CalibrationSpec spec;
  manifest.time_stage("load_calibration", [&] { spec = load_calibration(options.calibration_path); });
  ProgressPrinter progress;
  // every scene, reference and parameter is checked before the folder is made
  std::unique_ptr<CalibrationProblem> problem;
  manifest.time_stage("references", [&] {
    problem = std::make_unique<CalibrationProblem>(spec, registry, progress.callback());
  });
  OutputDirectory out = OutputDirectory::open(options.out_dir, options.force);
  CalibrationFit fit;
  manifest.time_stage("fit", [&] { fit = fit_calibration(*problem, progress.callback()); });
  if (problem->spec().solver.cross_validation) {
    manifest.time_stage("cross_validation", [&] { cross_validate(*problem, &fit, progress.callback()); });
  }
  std::optional<Ladder> ladder;
  if (problem->spec().ladder) {
    manifest.time_stage("ladder", [&] { ladder = measure_ladder(*problem, fit.values, progress.callback()); });
  }

  const CalibrationOutputs outputs{*problem, fit, ladder, joined_command_line(argc, argv), build_info().git_commit};
  const auto path = [&](const std::string& name) { return out.path(name); };
  std::vector<std::string> files;
  manifest.time_stage("write_results", [&] {
    for (const auto& group : {write_calibration_json(outputs, path), write_calibrated_parameters(outputs, path),
                              write_calibration_figure_data(outputs, path)}) {
      files.insert(files.end(), group.begin(), group.end());
    }
  });
  CalibrationFigures figures;
  manifest.time_stage("figures", [&] {
    progress.report(0.0, "figures (matplotlib)");
    figures = make_calibration_figures(out.temporary().string());
  });
  if (!figures.note.empty()) std::fprintf(stderr, "repose calibrate: %s\n", figures.note.c_str());
  manifest.time_stage("report", [&] { write_calibration_report(outputs, figures.names, figures.note, out.path("report.md")); });
  files.insert(files.end(), figures.names.begin(), figures.names.end());
  files.push_back("report.md");
  for (const std::string& f : files) manifest.add_file(f);
  manifest.set_results({{"calibration", repository_relative(problem->spec().source_path)},
                        {"solver", problem->spec().fitted_solver},
                        {"initial_cost", fit.initial_cost},
                        {"final_cost", fit.final_cost},
                        {"seed", problem->spec().solver.seed},
                        {"heuristic_runs", fit.heuristic_runs}});
  manifest.add_file("manifest.json");
  manifest.write(out.path("manifest.json"));
  out.commit();
  std::printf("wrote %s (report: %s/report.md)\n", out.target().string().c_str(), out.target().string().c_str());
}

}  // namespace

void add_calibrate_command(CLI::App& app, int argc, char** argv, const SolverRegistry& registry) {
  CLI::App* command = app.add_subcommand(
      "calibrate", "Fit a solver's parameters to reference runs and write a calibration folder (report.md first)");
  auto options = std::make_shared<CalibrateOptions>();
  command->add_option("calibration", options->calibration_path, "Calibration file (YAML)")->required();
  command->add_option("--out,-o", options->out_dir, "Folder to write (refused if not empty, unless --force)")->required();
  command->add_flag("--force", options->force, "Replace a non-empty folder (only once the new calibration succeeded)");
  command->callback([options, argc, argv, &registry] { calibrate(*options, argc, argv, registry); });
}

}  // namespace repose::cli
