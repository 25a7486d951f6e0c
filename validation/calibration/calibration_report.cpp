#include "validation/calibration/calibration_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/io/npy_io.h"
#include "models/core/run/repository_path.h"
#include "validation/observables/calibration_observables.h"
#include "validation/observables/surface_change.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

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

// The series and measure observables (held mass at the stages of a scoop, the
// peak force on a wall): per time (one row for a measure) the reference's
// seeds and mean, the solver with the initial and fitted values.
void write_series_table(std::ostream& out, const CalibrationFit& fit) {
  bool any = false;
  for (const SceneError& e : fit.scenes) any = any || !e.series.empty();
  if (!any) return;
  out << "\n## Series and measures per scene (reference: the seeds' mean)\n\n"
         "Paired SE (beds: each): the standard error of the relative error that the number of beds leaves, from each "
         "bed's own error (the solver on a seed's bed against that seed).\n\n"
         "| scene | role | series | t (s) | seeds | reference | initial | fitted | fitted − reference | relative | paired SE |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const SceneError& e : fit.scenes) {
    for (const SeriesComparison& c : e.series) {
      const std::vector<double> error = c.fitted_relative_error(), paired = c.paired_standard_error();
      for (std::size_t k = 0; k < c.reference.size(); ++k) {
        std::string seeds;
        for (const auto& seed : c.seeds) seeds += (seeds.empty() ? "" : ", ") + fmt::format("{:.4g}", seed[k]);
        const std::string time = c.times_s.empty() ? "–" : fmt::format("{:.3g}", c.times_s[k]);
        const std::string name = c.unit.empty() ? c.series : fmt::format("{} ({})", c.series, c.unit);
        // a reference of zero (the bucket emptied) has no relative error: the difference says it
        const std::string relative = c.reference[k] != 0.0 ? fmt::format("{:+.1f} %", 100.0 * error[k]) : "–";
        const std::string se = k < paired.size() && std::isfinite(paired[k]) ? fmt::format("{:.1f} %", 100.0 * paired[k]) : "–";
        out << fmt::format("| {} | {} | {} | {} | {} | {:.4g} | {:.4g} | {:.4g} | {:+.3g} | {} | {} |\n",
                           e.name, role_name(e.fit), name, time, seeds, c.reference[k],
                           c.initial[k], c.fitted[k], c.fitted[k] - c.reference[k], relative, se);
      }
    }
  }
}

// A series' relative errors at its times, "+1.9 / -2.0 %" ("–" where the
// reference is 0: the bucket emptied).
std::string relative_errors(const SeriesComparison& c) {
  const std::vector<double> error = c.fitted_relative_error();
  std::string text;
  for (std::size_t k = 0; k < error.size(); ++k) {
    text += (k == 0 ? "" : " / ") + (c.reference[k] != 0.0 ? fmt::format("{:+.1f}", 100.0 * error[k]) : "–");
  }
  return text + " %";
}

// Each series' relative errors, "name: e1 / e2 ... %; ...", or "-" without any.
std::string series_errors(const std::vector<SeriesComparison>& series) {
  std::string text;
  for (const SeriesComparison& c : series) text += (text.empty() ? "" : "; ") + c.series + ": " + relative_errors(c);
  return text.empty() ? "-" : text;
}

// What each leave-one-scene-out fold predicts for the scenes it did not fit:
// the left-out scene and the held-out ones, their ground error and their
// series' relative errors (cross_validation.h).
void write_cross_validation_table(std::ostream& out, const CalibrationFit& fit) {
  if (fit.folds.empty()) return;
  out << "\n## Cross-validation: what each fold predicts\n\n"
         "Each fold is the fit without one fit scene; it predicts that scene and the held-out ones. Series: the "
         "relative error against the seeds' mean at each of the series' times. A fold of 0 iterations stopped at "
         "its start: it predicts with the initial values, not with a refit.\n\n"
         "| fit without | iterations | scene | role | RMSE of Δh (mm) | skill | series: relative error at each time |\n"
         "|---|---|---|---|---|---|---|\n";
  for (const CrossValidationFold& fold : fit.folds) {
    for (std::size_t k = 0; k < fold.scenes.size(); ++k) {
      const SceneError& e = fold.scenes[k];
      if (k != fold.left_out && e.fit) continue;
      out << fmt::format("| {} | {} | {} | {} | {} | {:.2f} | {} |\n", fold.scenes[fold.left_out].name,
                         fold.iterations, e.name,
                         k == fold.left_out ? "left out" : "held out", mm(e.scores_fitted.rmse_m),
                         e.scores_fitted.skill, series_errors(e.series));
    }
  }
}

// Which scenes ran the solver on each seed's own bed (calibration_spec.h: beds).
void write_beds_notes(std::ostream& out, const CalibrationProblem& problem) {
  for (const PreparedScene& s : problem.scenes()) {
    const double h = s.scene.ground.grid.cell_size_m;
    if (h != s.reference_cell_size_m) {
      out << fmt::format("\nScene {} (cell_size_m): the solver ran on {} mm cells; the reference's surfaces, on the "
                         "scene's {} mm cells, were averaged onto them, and its surface errors are on them.\n",
                         s.entry.name, h * 1e3, s.reference_cell_size_m * 1e3);
    }
    if (s.bed_count() == 1) continue;
    out << fmt::format("\nScene {} (beds: each): the solver ran on each of the {} seeds' own beds; its surfaces, series "
                       "and observables are the means over those runs.\n",
                       s.entry.name, s.bed_count());
  }
}

std::string ratio(double a, double b) { return b > 0.0 ? fmt::format("{:.2f}", a / b) : "-"; }

// The speed/accuracy ladder: each rung's time and error beside the yardstick's noise floor.
void write_ladder_table(std::ostream& out, const Ladder& l) {
  out << fmt::format("\n## Speed/accuracy ladder ({}; yardstick: {}; its noise floor {})\n\n"
                     "Series: the rung's relative error against the seeds' mean at each of the series' times.\n\n"
                     "| rung | wall time (s) | LIGGGHTS CPU time / this | RMSE of Δh (mm) | RMSE / noise floor | series |\n"
                     "|---|---|---|---|---|---|\n",
                     l.scene, l.yardstick, l.noise_floor_m ? mm(*l.noise_floor_m) + " mm" : "unknown (one seed)");
  for (const LadderRung& r : l.rungs) {
    out << fmt::format("| {} | {:.4g}{} | {} | {} | {} | {} |\n", r.label, r.wall_time_s,
                       r.cpu_time_s ? fmt::format(" (CPU {:.4g})", *r.cpu_time_s) : "",
                       r.liggghts_cpu_over_this ? fmt::format("{:.3g}", *r.liggghts_cpu_over_this) : "-", mm(r.rmse_m),
                       l.noise_floor_m ? ratio(r.rmse_m, *l.noise_floor_m) : "-", series_errors(r.series));
  }
  if (l.liggghts_over_ground_time) {
    out << fmt::format("\nLIGGGHTS (its finest grains) / {} (the scene's own cell size): {:.3g} by wall time, {:.3g} by "
                       "CPU time.\n",
                       l.own_rung, *l.liggghts_over_ground_time, l.liggghts_over_ground_cpu_time.value_or(0.0));
  }
}

// The table a report leads with: per scene, the reference's noise floor, the
// error of doing nothing, the fitted model's error, R² and skill, and for fit
// scenes the cross-validated (leave-one-scene-out) numbers.
void write_scene_table(std::ostream& out, const CalibrationFit& fit) {
  out << "## Per scene: error beside the reference's noise floor and doing nothing\n\n"
         "Δh = final − start surface, over each scene's RMSE region. Noise floor: each seed's Δh against the mean of the "
         "other seeds (what another DEM run scores). Skill = 1 − RMSE / RMSE of doing nothing. CV: leave-one-scene-out "
         "(the fit without this scene, scored on it).\n\n"
         "| scene | role | seeds | noise floor (mm) | noise R² | doing nothing (mm) | fitted (mm) | fitted / noise | R² | "
         "skill | R² defaults | CV (mm) | CV / noise | CV R² | CV skill |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const SceneError& e : fit.scenes) {
    const ChangeScores& f = e.scores_fitted;
    const double noise = e.noise ? e.noise->rmse_m : 0.0;
    const auto cv = e.cross_validated;
    out << fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {:.2f} | {:.2f} | {:.2f} | {} | {} | {} | {} |\n", e.name,
                       role_name(e.fit), e.noise ? std::to_string(e.noise->seeds) : "1", e.noise ? mm(noise) : "-",
                       e.noise ? fmt::format("{:.2f}", e.noise->r2) : "-", mm(f.rmse_nothing_m), mm(f.rmse_m),
                       ratio(f.rmse_m, noise), f.r2, f.skill, e.scores_initial_params.r2, cv ? mm(cv->rmse_m) : "-",
                       cv ? ratio(cv->rmse_m, noise) : "-", cv ? fmt::format("{:.2f}", cv->r2) : "-",
                       cv ? fmt::format("{:.2f}", cv->skill) : "-");
  }
  out << "\n| scene | depth ref / fitted (mm) | rim or heap height (mm) | its distance from the imprint (mm) | "
         "trench width (mm) | dug (cm³) | heaped (cm³) |\n|---|---|---|---|---|---|---|\n";
  const auto pair = [](double r, double m, double scale) { return fmt::format("{:.1f} / {:.1f}", r * scale, m * scale); };
  for (const SceneError& e : fit.scenes) {
    const ChangeFeatures& r = e.reference_features;
    const ChangeFeatures& m = e.fitted_features;
    out << fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", e.name, pair(r.depth_m, m.depth_m, 1e3),
                       pair(r.height_m, m.height_m, 1e3), pair(r.rim_distance_m, m.rim_distance_m, 1e3),
                       pair(r.trench_width_m, m.trench_width_m, 1e3), pair(r.dug_m3, m.dug_m3, 1e6),
                       pair(r.heaped_m3, m.heaped_m3, 1e6));
  }
  out << "\n";
}

}  // namespace

std::string calibrated_parameters_yaml(const CalibrationOutputs& o) {
  const CalibrationProblem& problem = o.problem;
  std::string text = fmt::format("# The parameters of solver {} calibrated by repose calibrate, in their units.\n",
                                 problem.spec().fitted_solver);
  text += fmt::format("# calibration: {} ({})\n# fit scenes:", problem.spec().name, repository_relative(problem.spec().source_path));
  for (const PreparedScene& s : problem.scenes()) {
    if (s.fit()) text += " " + s.entry.name;
  }
  text += fmt::format("\n# final cost {:.6g} (initial {:.6g}); git commit {}\n", o.fit.final_cost, o.fit.initial_cost,
                      o.git_commit);
  text += "# (a map a calibration's `heuristic:` reference reads)\n";
  for (std::size_t p = 0; p < problem.spec().parameters.size(); ++p) {
    const ParameterSpec& spec = problem.spec().parameters[p];
    const auto k = problem.free_index(p);
    std::string se = "fixed";
    if (k) {
      se = o.fit.uncertainty.determined[*k]
               ? fmt::format("+- {:.4g} {}", spec.in_file_units(o.fit.uncertainty.standard_error[*k]), spec.unit)
               : "undetermined by the data (the value is the fit's, not a measurement)";
    }
    // "{}" is the shortest text that reads back as the same double: a chaotic
    // reference (a Bullet flow) runs differently 1e-16 away from the fit.
    text += fmt::format("{}: {}  # {}\n", spec.label(), spec.in_file_units(o.fit.values[p]), se);
  }
  return text;
}

std::vector<std::string> write_calibrated_parameters(const CalibrationOutputs& o,
                                                     const std::function<std::string(const std::string&)>& path) {
  std::ofstream out;
  open_file(out, path("parameters.yaml"));
  out << calibrated_parameters_yaml(o);
  if (!out) throw InputError(path("parameters.yaml") + ": write failed");
  return {"parameters.yaml"};
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
      out << "distance_m,x_m,y_m,start_m,reference_m,heuristic_initial_m,heuristic_fitted_m,"
             "reference_seed_min_m,reference_seed_max_m\n";
      const ObservableSpec& line = lines[t];
      for (int i = 0; i < line.samples; ++i) {
        const double f = static_cast<double>(i) / (line.samples - 1);
        const Eigen::Vector2d p = line.from_m + f * (line.to_m - line.from_m);
        // the seeds' spread of the final surface, each seed's change on the common start
        double lo = s.reference_final.sample(p.x(), p.y()), hi = lo;
        for (std::size_t seed = 0; seed < s.seed_final.size(); ++seed) {
          const double h = s.initial.sample(p.x(), p.y()) + s.seed_final[seed].sample(p.x(), p.y()) -
                           s.seed_initial[seed].sample(p.x(), p.y());
          lo = std::min(lo, h);
          hi = std::max(hi, h);
        }
        out << fmt::format("{},{},{},{},{},{},{},{},{}\n", f * (line.to_m - line.from_m).norm(), p.x(), p.y(),
                           s.initial.sample(p.x(), p.y()), s.reference_final.sample(p.x(), p.y()),
                           e.heuristic_initial_params.sample(p.x(), p.y()), e.heuristic_fitted.sample(p.x(), p.y()), lo, hi);
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
  out << fmt::format("From `{}`; command `{}`; git commit {}.\n\n", repository_relative(problem.spec().source_path), o.command_line, o.git_commit);
  write_scene_table(out, fit);
  out << "## Parameters\n\n| parameter | initial | fitted | standard error | status | bounds |\n|---|---|---|---|---|---|\n";
  for (std::size_t p = 0; p < problem.spec().parameters.size(); ++p) {
    const ParameterSpec& spec = problem.spec().parameters[p];
    const auto k = problem.free_index(p);
    std::string se = "-", status = "fixed";
    if (k) {
      status = determination(fit, problem, *k);
      se = fit.uncertainty.determined[*k] ? fmt::format("{:.4g}", spec.in_file_units(fit.uncertainty.standard_error[*k]))
                                          : "undetermined";
      if (fit.values[p] <= spec.lower || fit.values[p] >= spec.upper) status += ", at a bound";
    }
    out << fmt::format("| {} | {:.4g} | {:.4g} | {} | {} | [{:.4g}, {:.4g}] |\n", spec.label(),
                       spec.in_file_units(fit.initial_values[p]), spec.in_file_units(fit.values[p]), se, status,
                       spec.in_file_units(spec.lower), spec.in_file_units(spec.upper));
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
  write_beds_notes(out, problem);
  write_series_table(out, fit);
  write_cross_validation_table(out, fit);
  if (o.ladder) write_ladder_table(out, *o.ladder);
  out << "\n## Figures\n\n";
  for (const std::string& f : figures) out << fmt::format("![{}]({})\n\n", f, f);
  if (!figure_note.empty()) out << figure_note << "\n";
  out << "\nEvery number is in `calibration.json`; the calibrated parameters are in `parameters.yaml`.\n";
  if (!out) throw InputError(path + ": write failed");
}

}  // namespace repose
