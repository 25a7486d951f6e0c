#pragma once
// `--solver ode`: the scene's grains as rigid spheres in ODE (validation/rigid/rigid_solver.h
// lists the fields, measures and parameters). Reads the dem section and the
// optional ode: section.

#include "models/core/solver/solver.h"

namespace repose {

class OdeSolver final : public Solver {
 public:
  std::string name() const override { return "ode"; }
  std::string description() const override;
  std::vector<SectionType> sections() const override;
  // Needs the dem section only (the ode: section is optional).
  bool can_run(const Scene& scene, std::string* why) const override;
  std::unique_ptr<CompiledSolver> compile(const Scene& scene) const override;
  bool thread_safe() const override { return false; }  // ODE's random seed is process-wide
};

}  // namespace repose
