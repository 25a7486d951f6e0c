// The sheet fitted to measured paper (issue 15, item 7): Ceres fits the
// tearing solver's stiffness_scale (E t), tear_strain and fibre_anisotropy
// so that the tensile test of an uncut strip (models/tearing/tensile_test.h)
// gives a paper grade's tensile stiffness and strength along (MD) and across
// (CD) the grain, then checks the ratio of tear work across/along the grain
// (the seed's twist tear) against the grade's Elmendorf tear ratio. The fit
// file (experiments/tearing_paper_fit.yaml) names the scenes, the published
// values and their source, the parameters' starts, bounds and
// central-difference steps.
//
// It reuses the calibration's machinery (validation/calibration): the
// central-difference cost over any evaluator (calibration_cost.h), Halton
// starts (halton.h) and the standard errors from the Jacobian
// (calibration_uncertainty.h, scaled by s^2 = 2 cost / (n - p)). Residuals
// are relative, (model - published) / published, one per measure, each the
// mean over the file's seeds.
//
//   build/bin/tearing_paper_fit experiments/tearing_paper_fit.yaml --out runs/tearing_paper_fit

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <thread>

#include <CLI/CLI.hpp>
#include <ceres/ceres.h>
#include <fmt/format.h>

#include "experiments/runner/scene_override.h"
#include "experiments/solvers/solver_registry.h"
#include "experiments/tearing/paper_fit_report.h"
#include "experiments/tearing/paper_fit_spec.h"
#include "experiments/tearing/tear_ratio.h"
#include "validation/calibration/calibration_cost.h"
#include "validation/calibration/calibration_fit.h"
#include "validation/calibration/calibration_uncertainty.h"
#include "validation/calibration/halton.h"

namespace {

using namespace repose;

// One compiled scene: a direction (grain angle) and a seed.
struct Case {
  std::string direction;  // "md" or "cd"
  std::shared_ptr<const CompiledSolver> solver;
};

std::vector<Case> compile_cases(const std::string& scene, const std::vector<int>& seeds, bool tensile,
                                const std::vector<SceneOverride>& fibre_overrides = {}) {
  const SolverRegistry& registry = solver_registry();
  std::vector<Case> cases;
  for (const char* direction : {"md", "cd"}) {
    for (const int seed : seeds) {
      // the tensile strip is pulled along x; the tear runs down y, so a tear
      // along the grain (MD tear) has its grain at 90 degrees
      const bool grain_along_x = tensile == (std::string(direction) == "md");
      std::vector<SceneOverride> overrides{{"seed", YAML::Node(seed)},
                                           {"tearing.fibres.grain_direction_deg", YAML::Node(grain_along_x ? 0 : 90)}};
      overrides.insert(overrides.end(), fibre_overrides.begin(), fibre_overrides.end());
      const Scene s = load_scene_with_overrides(scene, overrides, registry.sections());
      cases.push_back({direction, registry.get("tearing").compile(s)});
    }
  }
  return cases;
}

// Each measure of each run, by direction, in the order of the seeds.
SeedMeasures run_cases_by_seed(const std::vector<Case>& cases, const std::vector<double>& values,
                               const std::vector<std::string>& measures) {
  std::vector<Run> runs(cases.size());
  for (std::size_t k = 0; k < cases.size(); k += 2) {  // two at a time: the machine is shared
    std::vector<std::thread> threads;
    for (std::size_t j = k; j < std::min(k + 2, cases.size()); ++j) {
      threads.emplace_back([&, j] { runs[j] = cases[j].solver->run(values, RunOptions{}); });
    }
    for (std::thread& t : threads) t.join();
  }
  SeedMeasures by_seed;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    std::map<std::string, double> of_run;
    for (const std::string& m : measures) of_run[m] = runs[k].measure(m).value;
    by_seed[cases[k].direction].push_back(of_run);
  }
  return by_seed;
}

// Mean of each measure over the seeds of each direction: {md: {...}, cd: {...}}.
DirectionMeasures means_of(const SeedMeasures& by_seed) {
  DirectionMeasures mean;
  for (const auto& [direction, runs] : by_seed) {
    for (const auto& run : runs) {
      for (const auto& [m, v] : run) mean[direction][m] += v / static_cast<double>(runs.size());
    }
  }
  return mean;
}

const std::vector<std::string> kTensileMeasures{"tensile.stiffness_n_per_m", "tensile.strength_n_per_m",
                                                "tensile.strain_at_peak"};

const std::string kPerPath = "tear.fracture_energy_per_path_length_j_per_m";

// The sheet at parameter values x: the solver's three (stiffness_scale,
// tear_strain, fibre_anisotropy) and, when the file frees it, the fibre
// images' background_density, a scene setting (the scenes are compiled
// again for each value of it).
class PaperFit {
 public:
  explicit PaperFit(const PaperFitSpec& spec)
      : spec_(spec), tensile_(compile_cases(spec.tensile_scene, spec.seeds, true)) {}

  bool fits_tear_ratio() const { return spec_.parameters.size() == 4; }

  SeedMeasures tensile(const std::vector<double>& x) const {
    const std::vector<Case> cases =
        fits_tear_ratio() ? compile_cases(spec_.tensile_scene, spec_.seeds, true, fibres(x)) : tensile_;
    return run_cases_by_seed(cases, solver_values(x), kTensileMeasures);
  }

  SeedMeasures tear(const std::vector<double>& x, const std::vector<int>& seeds) const {
    return run_cases_by_seed(compile_cases(spec_.tear_scene, seeds, false, fibres(x)), solver_values(x),
                             {"tear.work_per_length_j_per_m", "tear.fracture_energy_per_length_j_per_m", kPerPath,
                              "tear.tortuosity"});
  }

  // Relative residuals: the four tensile values, and the tear ratio CD / MD
  // per path length on the fit's tear seeds when the file frees a fibre
  // setting to fit it with.
  std::vector<double> residuals(const std::vector<double>& x) const {
    DirectionMeasures m = means_of(tensile(x));
    std::vector<double> r{m["md"]["tensile.stiffness_n_per_m"] / spec_.md_stiffness_n_per_m - 1.0,
                          m["cd"]["tensile.stiffness_n_per_m"] / spec_.cd_stiffness_n_per_m - 1.0,
                          m["md"]["tensile.strength_n_per_m"] / spec_.md_strength_n_per_m - 1.0,
                          m["cd"]["tensile.strength_n_per_m"] / spec_.cd_strength_n_per_m - 1.0};
    if (fits_tear_ratio()) {
      r.push_back(tear_ratio_residual(tear_ratio_cd_over_md(tear(x, spec_.fit_tear_seeds), kPerPath),
                                      spec_.tear_cd_over_md));
    }
    return r;
  }

 private:
  static std::vector<double> solver_values(const std::vector<double>& x) { return {x[0], x[1], x[2]}; }
  std::vector<SceneOverride> fibres(const std::vector<double>& x) const {
    if (!fits_tear_ratio()) return {};
    return {{"tearing.fibres.background_density", YAML::Node(x[3])}};
  }

  const PaperFitSpec& spec_;
  std::vector<Case> tensile_;
};

std::vector<double> from_unit(const PaperFitSpec& spec, const std::vector<double>& u) {
  std::vector<double> x;
  for (std::size_t k = 0; k < u.size(); ++k) {
    x.push_back(spec.parameters[k].lower + u[k] * (spec.parameters[k].upper - spec.parameters[k].lower));
  }
  return x;
}

// One line per evaluated point on stderr (parameters, then residuals), so
// that a long fit stopped early still shows where it went.
void log_point(const std::vector<double>& x, const std::vector<double>& r) {
  std::string line = "point";
  for (const double v : x) line += fmt::format(" {:.6g}", v);
  line += " residuals";
  for (const double v : r) line += fmt::format(" {:+.5f}", v);
  std::fprintf(stderr, "%s\n", line.c_str());
  std::fflush(stderr);
}

// From u (unit coordinates, see main) to the best u of this start (calibration_fit.h).
CalibrationStart solve_from(const PaperFitSpec& spec, CalibrationCost* cost, const std::vector<double>& u) {
  return minimize_from(cost, nullptr, u, spec.max_iterations);
}

struct Fitted {
  std::vector<CalibrationStart> starts;
  std::size_t best = 0;
  std::vector<double> x;
  CalibrationUncertainty uncertainty;
};

// Ceres works on u in [0, 1]^p, x = lower + u (upper - lower): parameters
// of units as far apart as N/m and strain make J^T J too ill-conditioned
// for ceres::Covariance otherwise.
Fitted fit(const PaperFitSpec& spec, const PaperFit& sheet) {
  const CalibrationCost::Evaluator evaluate = [&](const std::vector<std::vector<double>>& points) {
    std::vector<std::vector<double>> r;
    for (const auto& u : points) {
      const std::vector<double> x = from_unit(spec, u);
      r.push_back(sheet.residuals(x));
      log_point(x, r.back());
    }
    return r;
  };
  std::vector<double> step, initial;
  for (const PaperFitParameter& p : spec.parameters) {
    step.push_back(p.step / (p.upper - p.lower));
    initial.push_back((p.initial - p.lower) / (p.upper - p.lower));
  }
  const std::size_t n = initial.size();
  CalibrationCost cost(evaluate, std::vector<double>(n, 0.0), std::vector<double>(n, 1.0), step,
                       sheet.fits_tear_ratio() ? 5 : 4);
  Fitted f;
  f.starts.push_back(solve_from(spec, &cost, initial));
  const Halton halton(static_cast<int>(n), 1);
  for (int s = 1; s < spec.starts; ++s) {
    f.starts.push_back(solve_from(spec, &cost, halton.point(static_cast<std::uint64_t>(s))));
  }
  for (std::size_t s = 1; s < f.starts.size(); ++s) f.best = f.starts[s].final_cost < f.starts[f.best].final_cost ? s : f.best;
  f.x = from_unit(spec, f.starts[f.best].final_free);
  std::vector<std::string> labels;
  for (const PaperFitParameter& p : spec.parameters) labels.push_back(p.name);
  // no loss; u's bounds are [0, 1], so the ranges are 1 (u is already scaled by the bounds)
  f.uncertainty = uncertainty_at(&cost, nullptr, f.starts[f.best].final_free, labels, f.starts[f.best].final_cost, 1e-3);
  for (std::size_t k = 0; k < n; ++k) f.uncertainty.standard_error[k] *= spec.parameters[k].upper - spec.parameters[k].lower;
  return f;
}

PaperFitResults results_of(const PaperFitSpec& spec, const PaperFit& sheet, const Fitted& f) {
  PaperFitResults results;
  results.fitted = f.x;
  results.uncertainty = f.uncertainty;
  results.final_cost = f.starts[f.best].final_cost;
  results.tensile = sheet.tensile(f.x);
  std::vector<double> x0;
  for (const PaperFitParameter& p : spec.parameters) x0.push_back(p.initial);
  results.unfitted = means_of(sheet.tensile(x0));
  if (!spec.tear_scene.empty()) results.tear = sheet.tear(f.x, spec.tear_seeds);
  return results;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fit the paper-tearing sheet to a paper grade's tensile stiffness and strength, MD and CD"};
  std::string file, out = "runs/tearing_paper_fit";
  app.add_option("file", file, "the fit file (experiments/tearing_paper_fit.yaml)")->required();
  app.add_option("--out", out, "output folder");
  CLI11_PARSE(app, argc, argv);
  try {
    const std::clock_t cpu_start = std::clock();  // the process: runs are on other threads
    const PaperFitSpec spec = load_paper_fit_spec(file);
    std::filesystem::create_directories(out);
    const PaperFit sheet(spec);
    const Fitted f = fit(spec, sheet);
    PaperFitResults results = results_of(spec, sheet, f);
    results.cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    write_paper_fit_report(spec, results, out);
    for (const CalibrationStart& s : f.starts) {
      std::printf("start: cost %.6g after %d iterations (%s)\n", s.final_cost, s.iterations, s.termination.c_str());
    }
    std::ifstream report(out + "/report.md");
    std::printf("%s", std::string(std::istreambuf_iterator<char>(report), {}).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tearing_paper_fit: %s\n", e.what());
    return 1;
  }
  return 0;
}
