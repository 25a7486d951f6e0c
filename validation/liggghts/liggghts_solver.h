#pragma once
// `--solver liggghts`: the scene as a LIGGGHTS DEM reference run
// (liggghts_reference.h), as a repose Solver. It reads the dem section. The
// settled bed's surface is the run's height_initial, so a heuristic compared
// with this run starts from the same ground. Fields: height_initial,
// height_final, material_per_area_final. Measures: grain_count, steps, costs
// (run_wall_s, run_cpu_s, bed_*), particle_steps_per_*; column.* and pile.*
// for a column scene; mass_held_kg.<object>. It declares no fittable
// parameters (a DEM run takes minutes). With no output folder it runs in a
// temporary one and removes it.

#include "models/core/solver/solver.h"

namespace repose {

class LiggghtsSolver final : public Solver {
 public:
  std::string name() const override { return "liggghts"; }
  std::string description() const override {
    return "the LIGGGHTS DEM reference (needs the scene's dem section): settled bed, run, observables";
  }
  std::vector<SectionType> sections() const override;
  // Needs the dem section; the liggghts: section is optional (defaults).
  bool can_run(const Scene& scene, std::string* why) const override;
  std::unique_ptr<CompiledSolver> compile(const Scene& scene) const override;
};

}  // namespace repose
