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
#include "validation/calibration/calibration_uncertainty.h"
#include "validation/calibration/halton.h"

namespace {

using namespace repose;

// One compiled scene: a direction (grain angle) and a seed.
struct Case {
  std::string direction;  // "md" or "cd"
  std::shared_ptr<const CompiledSolver> solver;
};

std::vector<Case> compile_cases(const std::string& scene, const std::vector<int>& seeds, bool tensile) {
  const SolverRegistry& registry = solver_registry();
  std::vector<Case> cases;
  for (const char* direction : {"md", "cd"}) {
    for (const int seed : seeds) {
      // the tensile strip is pulled along x; the tear runs down y, so a tear
      // along the grain (MD tear) has its grain at 90 degrees
      const bool grain_along_x = tensile == (std::string(direction) == "md");
      std::vector<SceneOverride> overrides{{"seed", YAML::Node(seed)},
                                           {"tearing.fibres.grain_direction_deg", YAML::Node(grain_along_x ? 0 : 90)}};
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

DirectionMeasures run_cases(const std::vector<Case>& cases, const std::vector<double>& values,
                            const std::vector<std::string>& measures) {
  return means_of(run_cases_by_seed(cases, values, measures));
}

const std::vector<std::string> kTensileMeasures{"tensile.stiffness_n_per_m", "tensile.strength_n_per_m",
                                                "tensile.strain_at_peak"};

std::vector<double> residuals(const PaperFitSpec& spec, const std::vector<Case>& cases, const std::vector<double>& x) {
  auto m = run_cases(cases, x, kTensileMeasures);
  return {m["md"]["tensile.stiffness_n_per_m"] / spec.md_stiffness_n_per_m - 1.0,
          m["cd"]["tensile.stiffness_n_per_m"] / spec.cd_stiffness_n_per_m - 1.0,
          m["md"]["tensile.strength_n_per_m"] / spec.md_strength_n_per_m - 1.0,
          m["cd"]["tensile.strength_n_per_m"] / spec.cd_strength_n_per_m - 1.0};
}

std::vector<double> from_unit(const PaperFitSpec& spec, const std::vector<double>& u) {
  std::vector<double> x;
  for (std::size_t k = 0; k < u.size(); ++k) {
    x.push_back(spec.parameters[k].lower + u[k] * (spec.parameters[k].upper - spec.parameters[k].lower));
  }
  return x;
}

struct Start {
  std::vector<double> x;
  double cost = 0.0;
  int iterations = 0;
  std::string termination;
};

// From u (unit coordinates, see main) to the best u of this start.
Start solve_from(const PaperFitSpec& spec, CalibrationCost* cost, std::vector<double> x) {
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  std::vector<double*> blocks;
  for (double& v : x) blocks.push_back(&v);
  problem.AddResidualBlock(cost, nullptr, blocks);
  for (std::size_t k = 0; k < x.size(); ++k) {
    problem.SetParameterLowerBound(blocks[k], 0, 0.0);
    problem.SetParameterUpperBound(blocks[k], 0, 1.0);
  }
  ceres::Solver::Options options;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = spec.max_iterations;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  return {x, summary.final_cost, static_cast<int>(summary.iterations.size()) - 1,
          ceres::TerminationTypeToString(summary.termination_type)};
}

// The uncertainty at x, on a problem of its own (ceres::Covariance needs one).
CalibrationUncertainty uncertainty_at(const PaperFitSpec& spec, CalibrationCost* cost, std::vector<double> x,
                                      double final_cost) {
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  std::vector<double*> blocks;
  std::vector<double> ranges;
  std::vector<std::string> labels;
  for (double& v : x) blocks.push_back(&v);
  problem.AddResidualBlock(cost, nullptr, blocks);
  for (const PaperFitParameter& p : spec.parameters) {
    ranges.push_back(1.0);  // u is already scaled by the bounds
    labels.push_back(p.name);
  }
  return estimate_uncertainty(problem, blocks, ranges, labels, final_cost, 1e-3);
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
    const std::vector<Case> tensile = compile_cases(spec.tensile_scene, spec.seeds, true);
    // Ceres works on u in [0, 1]^3, x = lower + u (upper - lower): parameters
    // of units as far apart as N/m and strain make J^T J too ill-conditioned
    // for ceres::Covariance otherwise.
    const CalibrationCost::Evaluator evaluate = [&](const std::vector<std::vector<double>>& points) {
      std::vector<std::vector<double>> r;
      for (const auto& u : points) r.push_back(residuals(spec, tensile, from_unit(spec, u)));
      return r;
    };
    std::vector<double> step, initial;
    for (const PaperFitParameter& p : spec.parameters) {
      step.push_back(p.step / (p.upper - p.lower));
      initial.push_back((p.initial - p.lower) / (p.upper - p.lower));
    }
    CalibrationCost cost(evaluate, std::vector<double>(3, 0.0), std::vector<double>(3, 1.0), step, 4);
    std::vector<Start> starts{solve_from(spec, &cost, initial)};
    const Halton halton(static_cast<int>(initial.size()), 1);
    for (int s = 1; s < spec.starts; ++s) starts.push_back(solve_from(spec, &cost, halton.point(static_cast<std::uint64_t>(s))));
    std::size_t best = 0;
    for (std::size_t s = 1; s < starts.size(); ++s) best = starts[s].cost < starts[best].cost ? s : best;
    const std::vector<double> x = from_unit(spec, starts[best].x);
    CalibrationUncertainty u = uncertainty_at(spec, &cost, starts[best].x, starts[best].cost);
    for (std::size_t k = 0; k < 3; ++k) u.standard_error[k] *= spec.parameters[k].upper - spec.parameters[k].lower;
    PaperFitResults results;
    results.fitted = x;
    results.uncertainty = u;
    results.final_cost = starts[best].cost;
    results.tensile = run_cases_by_seed(tensile, x, kTensileMeasures);
    std::vector<double> x0;
    for (const PaperFitParameter& p : spec.parameters) x0.push_back(p.initial);
    results.unfitted = run_cases(tensile, x0, kTensileMeasures);
    if (!spec.tear_scene.empty()) {
      results.tear = run_cases_by_seed(compile_cases(spec.tear_scene, spec.tear_seeds, false), x,
                                       {"tear.work_per_length_j_per_m", "tear.fracture_energy_per_length_j_per_m",
                                        "tear.fracture_energy_per_path_length_j_per_m", "tear.tortuosity"});
    }
    results.cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    write_paper_fit_report(spec, results, out);
    for (const Start& s : starts) {
      std::printf("start: cost %.6g after %d iterations (%s)\n", s.cost, s.iterations, s.termination.c_str());
    }
    std::ifstream report(out + "/report.md");
    std::printf("%s", std::string(std::istreambuf_iterator<char>(report), {}).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tearing_paper_fit: %s\n", e.what());
    return 1;
  }
  return 0;
}
