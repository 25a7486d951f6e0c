#pragma once
// `--solver snow`: the snow-cover heuristic (models/snow) as a repose Solver.
// Compiling builds the snow maps once (SnowModel); the parameters are
// repose_angle_deg (the snow angle of repose), spread_deg (the spread of
// the snowfall directions) and snowfall_scale (settled depth per depth of
// snowfall), the ones a fit changes. A run returns
//   fields:   snow_depth_final.<group> (m, per snow map, 0 outside its area),
//             snow_probability.<group> (1), and for a scene with a ground
//             group height_initial (the ground) and height_final (ground +
//             its snow);
//   measures: steps, unsettled_steps, stabilisation_passes,
//             snow.fallen_m3, snow.on_maps_m3, snow.left_scene_m3,
//             snow.imbalance_m3 (round-off), snow.volume_m3.<group>,
//             snow.max_depth_m.<group>, probability_wall_s, steps_wall_s;
//   files (with an output folder): snow_surface_<group>.obj (the runner
//             writes the fields as NAME.npy).

#include "models/core/solver/solver.h"

namespace repose {

class SnowSolver final : public Solver {
 public:
  std::string name() const override { return "snow"; }
  std::string description() const override {
    return "the snow-cover heuristic (models/snow): shadow-map snow probability, accumulation, stabilisation";
  }
  std::vector<SectionType> sections() const override;
  bool can_run(const Scene& scene, std::string* why) const override;
  std::unique_ptr<CompiledSolver> compile(const Scene& scene) const override;
};

}  // namespace repose
