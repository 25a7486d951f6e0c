#include "validation/calibration/calibration_report.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/io/json_writer.h"
#include "models/core/io/npy_io.h"
#include "validation/observables/calibration_observables.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

constexpr double kDeg = std::numbers::pi / 180.0;

// A parameter value in the file's units (degrees for the angle).
double in_file_units(const ParameterSpec& p, double si) {
  return p.field == ParameterSpec::Field::kReposeAngle ? si / kDeg : si;
}

// Position of parameter p among the free ones, if free.
std::optional<std::size_t> free_index(const CalibrationProblem& problem, std::size_t p) {
  for (std::size_t k = 0; k < problem.free().size(); ++k) {
    if (problem.free()[k] == p) return k;
  }
  return std::nullopt;
}

void open_file(std::ofstream& out, const std::string& path) {
  out.open(path, std::ios::binary);
  if (!out) throw InputError(path + ": cannot be written");
}

std::string role_name(bool fit) { return fit ? "fit" : "held_out"; }

std::string mm(double m) { return fmt::format("{:.2f}", m * 1e3); }

// The transects of a scene: its transect and furrow observables, else the middle row along x.
std::vector<ObservableSpec> transects_of(const PreparedScene& s) {
  std::vector<ObservableSpec> lines;
  for (const ObservableSpec& o : s.entry.observables) {
    if (o.kind == ObservableSpec::Kind::kTransect || o.kind == ObservableSpec::Kind::kFurrowArea) lines.push_back(o);
  }
  if (lines.empty()) {
    const Grid& g = s.scene.ground.grid;
    ObservableSpec o;
    o.kind = ObservableSpec::Kind::kTransect;
    const double y = g.origin_y_m + 0.5 * g.extent_y_m();
    o.from_m = {g.centre_x(0), y};
    o.to_m = {g.centre_x(g.nx - 1), y};
    o.samples = 4 * g.nx;
    lines.push_back(o);
  }
  return lines;
}

void write_ladder(JsonWriter& json, const Ladder& ladder) {
  json.begin_object();
  json.key("scene").string(ladder.scene);
  json.key("yardstick").string(ladder.yardstick);
  json.key("rungs").begin_array();
  for (const LadderRung& r : ladder.rungs) {
    json.begin_object();
    json.key("label").string(r.label);
    json.key("kind").string(r.kind);
    json.key("resolution_m").number(r.resolution_m);
    json.key("wall_time_s").number(r.wall_time_s);
    json.key("cpu_time_s");
    if (r.cpu_time_s) json.number(*r.cpu_time_s);
    else json.null();
    json.key("rmse_m").number(r.rmse_m);
    json.key("yardstick").boolean(r.yardstick);
    json.end_object();
  }
  json.end_array();
  json.key("liggghts_over_ground_wall_time");
  if (ladder.liggghts_over_ground_time) json.number(*ladder.liggghts_over_ground_time);
  else json.null();
  json.key("liggghts_cpu_over_ground_wall_time");
  if (ladder.liggghts_over_ground_cpu_time) json.number(*ladder.liggghts_over_ground_cpu_time);
  else json.null();
  json.end_object();
}

}  // namespace

std::vector<std::string> write_calibration_json(const CalibrationOutputs& o,
                                                const std::function<std::string(const std::string&)>& path) {
  const CalibrationProblem& problem = o.problem;
  const CalibrationFit& fit = o.fit;
  std::ofstream out;
  open_file(out, path("calibration.json"));
  JsonWriter json(out);
  json.begin_object();
  json.key("calibration").string(problem.spec().name);
  json.key("source").string(problem.spec().source_path);
  json.key("command_line").string(o.command_line);
  json.key("git_commit").string(o.git_commit);
  json.key("parameters").begin_array();
  for (std::size_t p = 0; p < problem.spec().parameters.size(); ++p) {
    const ParameterSpec& spec = problem.spec().parameters[p];
    const auto k = free_index(problem, p);
    json.begin_object();
    json.key("name").string(spec.label());
    json.key("material").string(spec.material);
    json.key("field").string(parameter_field_name(spec.field));
    json.key("value").number(in_file_units(spec, fit.values[p]));
    json.key("initial").number(in_file_units(spec, fit.initial_values[p]));
    json.key("bounds").begin_array().number(in_file_units(spec, spec.lower)).number(in_file_units(spec, spec.upper)).end_array();
    json.key("step").number(in_file_units(spec, spec.step));
    json.key("fixed").boolean(spec.fixed);
    json.key("standard_error");
    if (!k) json.null();
    else if (!fit.uncertainty.determined[*k]) json.string("undetermined");
    else json.number(in_file_units(spec, fit.uncertainty.standard_error[*k]));
    json.key("determination").string(k ? determination(fit, problem, *k) : "fixed");
    json.key("at_bound").boolean(k && (fit.values[p] <= spec.lower || fit.values[p] >= spec.upper));
    json.end_object();
  }
  json.end_array();
  json.key("correlation").begin_object();
  json.key("parameters").begin_array();
  for (const std::size_t p : problem.free()) json.string(problem.spec().parameters[p].label());
  json.end_array();
  json.key("matrix").begin_array();
  for (Eigen::Index a = 0; a < fit.uncertainty.correlation.rows(); ++a) {
    json.begin_array();
    for (Eigen::Index b = 0; b < fit.uncertainty.correlation.cols(); ++b) json.number(fit.uncertainty.correlation(a, b));
    json.end_array();
  }
  json.end_array();
  json.end_object();
  json.key("residual_variance").number(fit.uncertainty.residual_variance);
  json.key("covariance_note").string(fit.uncertainty.note);
  json.key("scaled_singular_values").begin_array();
  for (Eigen::Index k = 0; k < fit.uncertainty.scaled_singular_values.size(); ++k) json.number(fit.uncertainty.scaled_singular_values(k));
  json.end_array();
  const CalibrationStart& best = fit.starts[fit.best_start];
  json.key("initial_cost").number(fit.initial_cost);
  json.key("final_cost").number(fit.final_cost);
  json.key("residual_count").unsigned_integer(fit.residual_count);
  json.key("iterations").integer(best.iterations);
  json.key("termination").string(best.termination);
  json.key("wall_time_s").number(fit.wall_time_s);
  json.key("heuristic_runs").integer(fit.heuristic_runs);
  json.key("seed").unsigned_integer(problem.spec().solver.seed);
  json.key("best_start").unsigned_integer(fit.best_start);
  json.key("starts").begin_array();
  for (const CalibrationStart& s : fit.starts) {
    json.begin_object();
    json.key("initial").begin_array();
    for (std::size_t k = 0; k < s.initial_free.size(); ++k) {
      json.number(in_file_units(problem.spec().parameters[problem.free()[k]], s.initial_free[k]));
    }
    json.end_array();
    json.key("final").begin_array();
    for (std::size_t k = 0; k < s.final_free.size(); ++k) {
      json.number(in_file_units(problem.spec().parameters[problem.free()[k]], s.final_free[k]));
    }
    json.end_array();
    json.key("initial_cost").number(s.initial_cost);
    json.key("final_cost").number(s.final_cost);
    json.key("iterations").integer(s.iterations);
    json.key("termination").string(s.termination);
    json.key("cost_per_iteration").begin_array();
    for (const double c : s.cost_per_iteration) json.number(c);
    json.end_array();
    json.end_object();
  }
  json.end_array();
  json.key("scenes").begin_array();
  for (std::size_t k = 0; k < fit.scenes.size(); ++k) {
    const SceneError& e = fit.scenes[k];
    json.begin_object();
    json.key("name").string(e.name);
    json.key("role").string(role_name(e.fit));
    json.key("scene_path").string(problem.scenes()[k].entry.scene_path);
    json.key("rmse_initial_m").number(e.rmse_initial_m);
    json.key("rmse_fitted_m").number(e.rmse_fitted_m);
    json.key("grain_diameter_m").number(e.grain_diameter_m);
    json.key("rmse_fitted_over_grain_diameter");
    if (e.grain_diameter_m > 0.0) json.number(e.rmse_fitted_m / e.grain_diameter_m);
    else json.null();
    json.end_object();
  }
  json.end_array();
  json.key("ladder");
  if (o.ladder) write_ladder(json, *o.ladder);
  else json.null();
  json.end_object();
  out << "\n";
  if (!out) throw InputError(path("calibration.json") + ": write failed");
  return {"calibration.json"};
}

std::string calibrated_material_yaml(const CalibrationOutputs& o, const std::string& material) {
  const CalibrationProblem& problem = o.problem;
  Material m;
  for (const PreparedScene& s : problem.scenes()) {
    if (!s.fit()) continue;
    const GroundParams params = problem.params_for(s, o.fit.values);
    for (const Material& candidate : params.materials) {
      if (candidate.name == material) m = candidate;
    }
  }
  std::string text = fmt::format("# The {} material calibrated by repose calibrate (use it as a scene's ground.material).\n", material);
  text += fmt::format("# calibration: {} ({})\n", problem.spec().name, problem.spec().source_path);
  text += fmt::format("# fit scenes:");
  for (const PreparedScene& s : problem.scenes()) {
    if (s.fit()) text += " " + s.entry.name;
  }
  text += fmt::format("\n# final cost {:.6g} (initial {:.6g}); git commit {}\n", o.fit.final_cost, o.fit.initial_cost, o.git_commit);
  for (std::size_t k = 0; k < problem.free().size(); ++k) {
    const ParameterSpec& p = problem.spec().parameters[problem.free()[k]];
    if (p.material != material) continue;
    const std::string se = o.fit.uncertainty.determined[k]
                               ? fmt::format("+- {:.4g}", in_file_units(p, o.fit.uncertainty.standard_error[k]))
                               : "undetermined by the data (value is the fit's, not a measurement)";
    text += fmt::format("# {}: {}\n", parameter_field_name(p.field), se);
  }
  text += fmt::format("name: {}\nalpha: {}\nrepose_angle_deg: {:.15g}\nsigma: {}\nerosion_iterations: {}\n", material,
                      m.alpha, m.repose_angle_rad / kDeg, m.sigma, m.erosion_iterations);
  return text;
}

std::vector<std::string> write_calibrated_materials(const CalibrationOutputs& o,
                                                    const std::function<std::string(const std::string&)>& path) {
  std::vector<std::string> materials, names;
  for (const ParameterSpec& p : o.problem.spec().parameters) {
    if (std::find(materials.begin(), materials.end(), p.material) == materials.end()) materials.push_back(p.material);
  }
  for (std::size_t k = 0; k < materials.size(); ++k) {
    const std::string name = k == 0 ? "material.yaml" : "material_" + materials[k] + ".yaml";
    std::ofstream out;
    open_file(out, path(name));
    out << calibrated_material_yaml(o, materials[k]);
    if (!out) throw InputError(path(name) + ": write failed");
    names.push_back(name);
  }
  return names;
}

std::vector<std::string> write_calibration_figure_data(const CalibrationOutputs& o,
                                                       const std::function<std::string(const std::string&)>& path) {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < o.problem.scenes().size(); ++k) {
    const PreparedScene& s = o.problem.scenes()[k];
    const SceneError& e = o.fit.scenes[k];
    const std::string base = "data/" + s.entry.name;
    const std::vector<std::pair<std::string, const HeightField*>> maps = {
        {"_start.npy", &s.initial}, {"_reference.npy", &s.reference_final},
        {"_heuristic_initial.npy", &e.heuristic_initial_params}, {"_heuristic_fitted.npy", &e.heuristic_fitted}};
    for (const auto& [suffix, field] : maps) {
      write_npy_2d(path(base + suffix), field->heights());
      names.push_back(base + suffix);
    }
    const std::vector<ObservableSpec> lines = transects_of(s);
    for (std::size_t t = 0; t < lines.size(); ++t) {
      const std::string name = fmt::format("{}_transect_{}.csv", base, t);
      std::ofstream out;
      open_file(out, path(name));
      out << "distance_m,x_m,y_m,start_m,reference_m,heuristic_initial_m,heuristic_fitted_m\n";
      const ObservableSpec& line = lines[t];
      for (int i = 0; i < line.samples; ++i) {
        const double f = static_cast<double>(i) / (line.samples - 1);
        const Eigen::Vector2d p = line.from_m + f * (line.to_m - line.from_m);
        out << fmt::format("{},{},{},{},{},{},{}\n", f * (line.to_m - line.from_m).norm(), p.x(), p.y(),
                           s.initial.sample(p.x(), p.y()), s.reference_final.sample(p.x(), p.y()),
                           e.heuristic_initial_params.sample(p.x(), p.y()), e.heuristic_fitted.sample(p.x(), p.y()));
      }
      names.push_back(name);
    }
  }
  return names;
}

void write_calibration_report(const CalibrationOutputs& o, const std::vector<std::string>& figures,
                              const std::string& figure_note, const std::string& path) {
  const CalibrationProblem& problem = o.problem;
  const CalibrationFit& fit = o.fit;
  std::ofstream out;
  open_file(out, path);
  out << fmt::format("# Calibration: {}\n\n", problem.spec().name);
  out << fmt::format("From `{}`; command `{}`; git commit {}.\n\n", problem.spec().source_path, o.command_line, o.git_commit);
  out << "## Parameters\n\n| parameter | initial | fitted | standard error | status | bounds |\n|---|---|---|---|---|---|\n";
  for (std::size_t p = 0; p < problem.spec().parameters.size(); ++p) {
    const ParameterSpec& spec = problem.spec().parameters[p];
    const auto k = free_index(problem, p);
    std::string se = "-", status = "fixed";
    if (k) {
      status = determination(fit, problem, *k);
      se = fit.uncertainty.determined[*k] ? fmt::format("{:.4g}", in_file_units(spec, fit.uncertainty.standard_error[*k]))
                                          : "undetermined";
      if (fit.values[p] <= spec.lower || fit.values[p] >= spec.upper) status += ", at a bound";
    }
    out << fmt::format("| {} | {:.4g} | {:.4g} | {} | {} | [{:.4g}, {:.4g}] |\n", spec.label(),
                       in_file_units(spec, fit.initial_values[p]), in_file_units(spec, fit.values[p]), se, status,
                       in_file_units(spec, spec.lower), in_file_units(spec, spec.upper));
  }
  if (!fit.uncertainty.note.empty()) out << fmt::format("\nWhat the data does not determine: {}.\n", fit.uncertainty.note);
  const CalibrationStart& best = fit.starts[fit.best_start];
  out << fmt::format("\nCost {:.6g} -> {:.6g} over {} residuals; best of {} starts (start {}), {} iterations, {}. "
                     "{} heuristic runs in {:.1f} s.\n\n",
                     fit.initial_cost, fit.final_cost, fit.residual_count, fit.starts.size(), fit.best_start, best.iterations,
                     best.termination, fit.heuristic_runs, fit.wall_time_s);
  out << "## Surface RMSE per scene\n\n| scene | role | RMSE initial (mm) | RMSE fitted (mm) | grain diameter (mm) | fitted / grain diameter |\n|---|---|---|---|---|---|\n";
  for (const SceneError& e : fit.scenes) {
    out << fmt::format("| {} | {} | {} | {} | {} | {} |\n", e.name, role_name(e.fit), mm(e.rmse_initial_m), mm(e.rmse_fitted_m),
                       e.grain_diameter_m > 0 ? mm(e.grain_diameter_m) : "-",
                       e.grain_diameter_m > 0 ? fmt::format("{:.2f}", e.rmse_fitted_m / e.grain_diameter_m) : "-");
  }
  if (o.ladder) {
    const Ladder& l = *o.ladder;
    out << fmt::format("\n## Speed/accuracy ladder ({}; yardstick: {})\n\n| rung | wall time (s) | surface RMSE (mm) |\n|---|---|---|\n",
                       l.scene, l.yardstick);
    for (const LadderRung& r : l.rungs) {
      out << fmt::format("| {}{} | {:.4g}{} | {} |\n", r.label, r.yardstick ? " (yardstick)" : "", r.wall_time_s,
                         r.cpu_time_s ? fmt::format(" (CPU {:.4g})", *r.cpu_time_s) : "", mm(r.rmse_m));
    }
    if (l.liggghts_over_ground_time) {
      out << fmt::format("\nLIGGGHTS / ground model time at the scene's resolution: {:.3g} (wall), {:.3g} (LIGGGHTS CPU time "
                         "over ground wall time); target >= 1e4.\n",
                         *l.liggghts_over_ground_time, l.liggghts_over_ground_cpu_time.value_or(0.0));
    }
  }
  out << "\n## Figures\n\n";
  for (const std::string& f : figures) out << fmt::format("![{}]({})\n\n", f, f);
  if (!figure_note.empty()) out << figure_note << "\n";
  out << "\nEvery number is in `calibration.json`; the calibrated material is `material.yaml`.\n";
  if (!out) throw InputError(path + ": write failed");
}

}  // namespace repose
