#pragma once
// The solvers a program knows, by name, and the scene sections they read.
// The command line, the experiment runner and calibration all take one; the
// list of repose's solvers is experiments/solvers/solver_registry.cpp.

#include <memory>
#include <string>
#include <vector>

#include "models/core/config/scene_section.h"
#include "models/core/solver/solver.h"

namespace repose {

class SolverRegistry {
 public:
  // Adds a solver and the sections it reads (a section several solvers
  // share is kept once, by key). REPOSE_DEMAND: names and keys unique.
  SolverRegistry& add(std::shared_ptr<const Solver> solver);

  const std::vector<std::shared_ptr<const Solver>>& solvers() const { return solvers_; }
  std::vector<std::string> names() const;
  const Solver* find(const std::string& name) const;  // nullptr when unknown
  // The solver, or InputError naming the known ones.
  const Solver& get(const std::string& name) const;
  const std::vector<SectionType>& sections() const { return sections_; }

 private:
  std::vector<std::shared_ptr<const Solver>> solvers_;
  std::vector<SectionType> sections_;
};

}  // namespace repose
