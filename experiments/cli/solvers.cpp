#include "experiments/cli/solvers.h"

#include "models/core/base/error.h"

namespace repose::cli {

const std::vector<Solver>& solvers() {
  static const std::vector<Solver> table = {
      {"ground", "the ground-deformation heuristic (models/ground): height_final.npy/.png", run_ground_solver},
      {"liggghts", "the LIGGGHTS DEM reference (needs the scene's dem section): settled bed, run, observables",
       run_liggghts_solver},
      {"initial", "the initial state only (height_initial.npy and .png); no time stepping",
       [](RunContext&) {}},
  };
  return table;
}

std::vector<std::string> solver_names() {
  std::vector<std::string> names;
  for (const auto& solver : solvers()) names.push_back(solver.name);
  return names;
}

const Solver& find_solver(const std::string& name) {
  for (const auto& solver : solvers()) {
    if (solver.name == name) return solver;
  }
  REPOSE_DEMAND(false && "the command line checks solver names");
  return solvers().front();
}

}  // namespace repose::cli
