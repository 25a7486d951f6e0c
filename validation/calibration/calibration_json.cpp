// calibration.json: every number of a calibration (calibration_report.h).
#include <fstream>

#include <nlohmann/json.hpp>

#include "models/core/base/error.h"
#include "models/core/run/repository_path.h"
#include "validation/calibration/calibration_report.h"

namespace repose {

namespace {

using nlohmann::json;

json optional_number(const std::optional<double>& x) { return x ? json(*x) : json(); }

json scores_json(const ChangeScores& s) {
  return {{"rmse_m", s.rmse_m}, {"rmse_nothing_m", s.rmse_nothing_m}, {"r2", s.r2}, {"skill", s.skill}};
}

json features_json(const ChangeFeatures& f) {
  return {{"dug_m3", f.dug_m3},           {"heaped_m3", f.heaped_m3},     {"depth_m", f.depth_m},
          {"depth_xy_m", {f.depth_x_m, f.depth_y_m}}, {"height_m", f.height_m},
          {"height_xy_m", {f.height_x_m, f.height_y_m}}, {"rim_distance_m", f.rim_distance_m},
          {"trench_width_m", f.trench_width_m}};
}

json noise_json(const std::optional<NoiseFloor>& n) {
  if (!n) return json();
  return {{"seeds", n->seeds}, {"rmse_m", n->rmse_m}, {"r2", n->r2}, {"pair_rmse_m", n->pair_rmse_m}};
}

json series_json(const std::vector<SeriesComparison>& series) {
  json out = json::array();
  for (const SeriesComparison& c : series) {
    out.push_back({{"name", c.series}, {"unit", c.unit}, {"times_s", c.times_s}, {"seeds", c.seeds},
                   {"reference", c.reference}, {"initial", c.initial}, {"fitted", c.fitted},
                   {"fitted_relative_error", c.fitted_relative_error()}, {"fitted_per_bed", c.fitted_per_bed},
                   {"paired_standard_error", c.paired_standard_error()}});
  }
  return out;
}

json ladder_json(const Ladder& ladder) {
  json rungs = json::array();
  for (const LadderRung& r : ladder.rungs) {
    rungs.push_back({{"label", r.label}, {"kind", r.kind}, {"resolution_m", r.resolution_m},
                     {"wall_time_s", r.wall_time_s}, {"cpu_time_s", optional_number(r.cpu_time_s)},
                     {"liggghts_cpu_over_this", optional_number(r.liggghts_cpu_over_this)}, {"rmse_m", r.rmse_m},
                     {"series", series_json(r.series)}});
  }
  return {{"scene", ladder.scene},
          {"yardstick", ladder.yardstick},
          {"noise_floor_m", optional_number(ladder.noise_floor_m)},
          {"rungs", rungs},
          {"own_rung", ladder.own_rung},
          {"liggghts_over_ground_wall_time", optional_number(ladder.liggghts_over_ground_time)},
          {"liggghts_over_ground_cpu_time", optional_number(ladder.liggghts_over_ground_cpu_time)}};
}

json parameter_json(const CalibrationProblem& problem, const CalibrationFit& fit, std::size_t p) {
  const ParameterSpec& spec = problem.spec().parameters[p];
  const auto k = problem.free_index(p);
  json se;
  if (k) se = fit.uncertainty.determined[*k] ? json(spec.in_file_units(fit.uncertainty.standard_error[*k])) : json("undetermined");
  return {{"name", spec.label()},
          {"solver", spec.solver},
          {"parameter", spec.name},
          {"unit", spec.unit},
          {"value", spec.in_file_units(fit.values[p])},
          {"initial", spec.in_file_units(fit.initial_values[p])},
          {"bounds", {spec.in_file_units(spec.lower), spec.in_file_units(spec.upper)}},
          {"step", spec.in_file_units(spec.step)},
          {"fixed", spec.fixed},
          {"standard_error", se},
          {"determination", k ? determination(fit, problem, *k) : "fixed"},
          {"at_bound", k.has_value() && (fit.values[p] <= spec.lower || fit.values[p] >= spec.upper)}};
}

json starts_json(const CalibrationProblem& problem, const CalibrationFit& fit) {
  json starts = json::array();
  for (const CalibrationStart& s : fit.starts) {
    json initial = json::array(), final = json::array();
    for (std::size_t k = 0; k < s.initial_free.size(); ++k) {
      const ParameterSpec& spec = problem.spec().parameters[problem.free()[k]];
      initial.push_back(spec.in_file_units(s.initial_free[k]));
      final.push_back(spec.in_file_units(s.final_free[k]));
    }
    starts.push_back({{"initial", initial}, {"final", final}, {"initial_cost", s.initial_cost},
                      {"final_cost", s.final_cost}, {"iterations", s.iterations}, {"termination", s.termination},
                      {"cost_per_iteration", s.cost_per_iteration}});
  }
  return starts;
}

json folders_json(const ReferenceSpec& r) {
  json folders = json::array();
  for (const std::string& d : r.directories) folders.push_back(repository_relative(d));
  return folders;
}

// Per fold: the left-out scene, the fold's parameter values in their units,
// its scores there, and what it predicts for every scene it did not fit (the
// left-out one and the held-out ones): ground scores and series.
json cross_validation_json(const CalibrationProblem& problem, const CalibrationFit& fit) {
  json folds = json::array();
  for (const CrossValidationFold& fold : fit.folds) {
    json values = json::object();
    for (std::size_t p = 0; p < problem.spec().parameters.size(); ++p) {
      const ParameterSpec& spec = problem.spec().parameters[p];
      values[spec.label()] = spec.in_file_units(fold.values[p]);
    }
    json predicted = json::array();
    for (std::size_t k = 0; k < fold.scenes.size(); ++k) {
      const SceneError& e = fold.scenes[k];
      if (k != fold.left_out && e.fit) continue;
      predicted.push_back({{"name", e.name}, {"role", k == fold.left_out ? "left_out" : "held_out"},
                           {"scores", scores_json(e.scores_fitted)}, {"series", series_json(e.series)}});
    }
    folds.push_back({{"left_out", fold.scenes[fold.left_out].name}, {"values", values},
                     {"iterations", fold.iterations}, {"termination", fold.termination},
                     {"scores", scores_json(fold.scenes[fold.left_out].scores_fitted)}, {"predicted", predicted}});
  }
  return folds;
}

json scenes_json(const CalibrationProblem& problem, const CalibrationFit& fit) {
  json scenes = json::array();
  for (std::size_t k = 0; k < fit.scenes.size(); ++k) {
    const SceneError& e = fit.scenes[k];
    scenes.push_back({{"name", e.name},
                      {"role", e.fit ? "fit" : "held_out"},
                      {"beds", problem.scenes()[k].bed_count() > 1 ? "each" : "mean"},
                      {"scene_path", repository_relative(problem.scenes()[k].entry.scene_path)},
                      {"rmse_initial_m", e.rmse_initial_m},
                      {"rmse_fitted_m", e.rmse_fitted_m},
                      {"grain_diameter_m", e.grain_diameter_m},
                      {"rmse_fitted_over_grain_diameter",
                       e.grain_diameter_m > 0.0 ? json(e.rmse_fitted_m / e.grain_diameter_m) : json()},
                      {"reference_folders", folders_json(problem.scenes()[k].entry.reference)},
                      {"scores_initial", scores_json(e.scores_initial_params)},
                      {"scores_fitted", scores_json(e.scores_fitted)},
                      {"noise_floor", noise_json(e.noise)},
                      {"fitted_over_noise", e.noise && e.noise->rmse_m > 0 ? json(e.scores_fitted.rmse_m / e.noise->rmse_m) : json()},
                      {"cross_validated", e.cross_validated ? scores_json(*e.cross_validated) : json()},
                      {"cross_validated_over_noise", e.cross_validated && e.noise && e.noise->rmse_m > 0
                                                         ? json(e.cross_validated->rmse_m / e.noise->rmse_m)
                                                         : json()},
                      {"features", {{"reference", features_json(e.reference_features)},
                                    {"fitted", features_json(e.fitted_features)}}},
                      {"series", series_json(e.series)}});
  }
  return scenes;
}

json correlation_json(const CalibrationProblem& problem, const CalibrationFit& fit) {
  json names = json::array(), matrix = json::array();
  for (const std::size_t p : problem.free()) names.push_back(problem.spec().parameters[p].label());
  for (Eigen::Index a = 0; a < fit.uncertainty.correlation.rows(); ++a) {
    json row = json::array();
    for (Eigen::Index b = 0; b < fit.uncertainty.correlation.cols(); ++b) row.push_back(fit.uncertainty.correlation(a, b));
    matrix.push_back(row);
  }
  return {{"parameters", names}, {"matrix", matrix}};
}

}  // namespace

std::vector<std::string> write_calibration_json(const CalibrationOutputs& o,
                                                const std::function<std::string(const std::string&)>& path) {
  const CalibrationProblem& problem = o.problem;
  const CalibrationFit& fit = o.fit;
  json parameters = json::array();
  for (std::size_t p = 0; p < problem.spec().parameters.size(); ++p) parameters.push_back(parameter_json(problem, fit, p));
  json singular = json::array();
  for (Eigen::Index k = 0; k < fit.uncertainty.scaled_singular_values.size(); ++k) {
    singular.push_back(fit.uncertainty.scaled_singular_values(k));
  }
  const CalibrationStart& best = fit.starts[fit.best_start];
  const json document = {{"calibration", problem.spec().name},
                         {"source", repository_relative(problem.spec().source_path)},
                         {"solver", problem.spec().fitted_solver},
                         {"command_line", o.command_line},
                         {"git_commit", o.git_commit},
                         {"parameters", parameters},
                         {"correlation", correlation_json(problem, fit)},
                         {"residual_variance", fit.uncertainty.residual_variance},
                         {"covariance_note", fit.uncertainty.note},
                         {"scaled_singular_values", singular},
                         {"initial_cost", fit.initial_cost},
                         {"final_cost", fit.final_cost},
                         {"residual_count", fit.residual_count},
                         {"iterations", best.iterations},
                         {"termination", best.termination},
                         {"wall_time_s", fit.wall_time_s},
                         {"heuristic_runs", fit.heuristic_runs},
                         {"seed", problem.spec().solver.seed},
                         {"best_start", fit.best_start},
                         {"starts", starts_json(problem, fit)},
                         {"scenes", scenes_json(problem, fit)},
                         {"cross_validation", cross_validation_json(problem, fit)},
                         {"ladder", o.ladder ? ladder_json(*o.ladder) : json()}};
  std::ofstream out(path("calibration.json"), std::ios::binary);
  out << document.dump(2) << "\n";
  if (!out) throw InputError(path("calibration.json") + ": write failed");
  return {"calibration.json"};
}

}  // namespace repose
