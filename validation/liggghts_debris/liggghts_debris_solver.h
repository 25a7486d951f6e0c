#pragma once
// `--solver liggghts` for every scene: LiggghtsSolver (validation/liggghts)
// for a scene with a dem: section, and for a scene with a terrain: section
// (elements, buildings) and no dem: section the debris flow in LIGGGHTS
// (liggghts_debris_run.h) with the rigid engines' fields, measures and files
// (validation/rigid/debris_solver.h), plus the LIGGGHTS inputs and log.
// It lives here, not in validation/liggghts, because the debris setup it
// shares with the rigid engines (validation/rigid) itself uses the LIGGGHTS
// library. No fittable parameters (a DEM run is the reference).

#include "models/core/solver/solver.h"
#include "validation/liggghts/liggghts_solver.h"

namespace repose {

class LiggghtsDebrisSolver final : public Solver {
 public:
  std::string name() const override { return dem_.name(); }
  std::string description() const override;
  std::vector<SectionType> sections() const override;
  bool can_run(const Scene& scene, std::string* why) const override;
  std::unique_ptr<CompiledSolver> compile(const Scene& scene) const override;

 private:
  LiggghtsSolver dem_;
};

}  // namespace repose
