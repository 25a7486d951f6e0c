#pragma once
// `--solver ground`: the ground-deformation heuristic as a repose Solver.
// Compiling builds the GroundModel once; its parameters are each named
// material's alpha, repose angle and sigma ("sand.alpha",
// "sand.repose_angle_deg", "sand.sigma": a value applies to every region of
// that material). A run returns the fields height_initial and height_final
// (m) and the measures steps, step_wall_s_median, steps_wall_s_total,
// step_wall_s_mean, contact_cells_total, volume.* (the ledger, m^3) and
// streaks.<object>.* (streaks.h).

#include "models/core/solver/solver.h"

namespace repose {

class GroundSolver final : public Solver {
 public:
  std::string name() const override { return "ground"; }
  std::string description() const override {
    return "the ground-deformation heuristic (models/ground): height_final";
  }
  std::vector<SectionType> sections() const override;
  // Also false for a scene with a free body (ground_model.h).
  bool can_run(const Scene& scene, std::string* why) const override;
  std::unique_ptr<CompiledSolver> compile(const Scene& scene) const override;
};

}  // namespace repose
