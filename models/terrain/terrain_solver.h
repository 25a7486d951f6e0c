#pragma once
// `--solver terrain`: terrain generation from key contours (models/terrain,
// seed paper 003) as a repose Solver. It reads the scene's `terrain:`
// section (terrain_section.h). Its one parameter is slope_deg (the ground's
// slope rising from the key contours; a fit may change it). A run returns
// the fields height_initial (the scene's initial ground) and height_final
// (the terrain mesh sampled at the centres of the scene's grid; cells
// outside the outermost key contours get their lowest height) and the
// measures triangle_count, contour_count, key_contour_count,
// summit_point_count, relief_m, min_height_m, max_height_m, element_count,
// elements_skipped_off_terrain and building_part_count. With an output
// folder it writes the files of terrain_outputs.h.
//
// Not here: the debris flow over the terrain (Bullet, ODE, LIGGGHTS) and
// breakable buildings belong to the rigid-body and DEM references.

#include "models/core/solver/solver.h"

namespace repose {

class TerrainSolver final : public Solver {
 public:
  std::string name() const override { return "terrain"; }
  std::string description() const override {
    return "terrain from key contours (models/terrain): straight skeleton, B-splines, Delaunay; height_final";
  }
  std::vector<SectionType> sections() const override;
  std::unique_ptr<CompiledSolver> compile(const Scene& scene) const override;
};

}  // namespace repose
