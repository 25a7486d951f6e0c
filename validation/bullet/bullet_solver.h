#pragma once
// `--solver bullet`: the scene's grains as rigid spheres in Bullet (validation/rigid/rigid_solver.h
// lists the fields, measures and parameters). Reads the dem section and the
// optional bullet: section.

#include "models/core/solver/solver.h"

namespace repose {

class BulletSolver final : public Solver {
 public:
  std::string name() const override { return "bullet"; }
  std::string description() const override;
  std::vector<SectionType> sections() const override;
  // Needs the dem section only (the bullet: section is optional).
  bool can_run(const Scene& scene, std::string* why) const override;
  std::unique_ptr<CompiledSolver> compile(const Scene& scene) const override;
  bool thread_safe() const override { return false; }  // Bullet's contact thresholds and margins are process-wide
};

}  // namespace repose
