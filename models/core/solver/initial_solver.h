#pragma once
// `--solver initial`: the scene's initial state only (height_initial and
// height_final equal), no time stepping: the "doing nothing" every error is
// compared with.

#include "models/core/solver/solver.h"

namespace repose {

class InitialSolver final : public Solver {
 public:
  std::string name() const override { return "initial"; }
  std::string description() const override { return "the initial state only; no time stepping (doing nothing)"; }
  std::unique_ptr<CompiledSolver> compile(const Scene& scene) const override;
};

}  // namespace repose
