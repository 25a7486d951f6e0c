#include "models/terrain/terrain_solver.h"

#include <numbers>

#include "models/core/base/cpu_time.h"
#include "models/core/config/fields.h"
#include "models/core/config/initial_height.h"
#include "models/core/config/scene.h"
#include "models/terrain/terrain_outputs.h"
#include "models/terrain/terrain_section.h"
#include "models/terrain/terrain_surface.h"

namespace repose {

namespace {

void add_measures(Run& run, const TerrainScenery& s) {
  const TerrainSummary& t = s.terrain.summary;
  run.set("triangle_count", t.triangle_count, "count");
  run.set("contour_count", t.contour_count, "count");
  run.set("key_contour_count", t.key_contour_count, "count");
  run.set("summit_point_count", t.summit_point_count, "count");
  run.set("relief_m", t.relief_m(), "m");
  run.set("min_height_m", t.min_height_m, "m");
  run.set("max_height_m", t.max_height_m, "m");
  run.set("element_count", static_cast<double>(s.elements.elements.size()), "count");
  run.set("elements_skipped_off_terrain", s.elements.skipped_off_terrain, "count");
  run.set("building_part_count", static_cast<double>(s.building_parts.size()), "count");
}

class CompiledTerrain final : public CompiledSolver {
 public:
  explicit CompiledTerrain(const Scene& scene)
      : terrain_(terrain_section(scene).scene), initial_(make_initial_height(scene)), grid_(scene.ground.grid) {
    parameters_.push_back({"slope_deg", "deg", kRadPerDeg, 1e-6 * kRadPerDeg, 89.9 * kRadPerDeg,
                           terrain_.options.slope_rad, "slope of the ground rising inward from the key contours"});
  }

  const std::vector<ParameterInfo>& parameters() const override { return parameters_; }

  Run run(const std::vector<double>& values_si, const RunOptions& options) const override {
    check_values(parameters_, values_si, "terrain");
    const Stopwatch clock;
    TerrainScene scene = terrain_;
    scene.options.slope_rad = values_si[0];
    TerrainScenery scenery = generate_scenery(scene);
    double plain_m = scenery.terrain.summary.max_height_m;
    for (int r : scenery.terrain.nesting.roots) plain_m = std::min(plain_m, scenery.terrain.keys[r].height_m);
    // on the scene's grid, so that every solver's height_final compares cell by cell
    scenery.terrain.height_field = sample_height_field(TerrainSurface(scenery.terrain.mesh), grid_, plain_m);
    Run run;
    run.solver = "terrain";
    run.wall_s = clock.wall_s();
    run.cpu_s = clock.cpu_s();
    run.fields["height_initial"] = initial_;
    run.fields["height_final"] = scenery.terrain.height_field;
    run.stages = {"straight_skeleton", "bspline_smoothing", "constrained_delaunay"};
    if (scene.elements) run.stages.push_back("element_layers");
    if (!scene.buildings.empty()) run.stages.push_back("building_parts");
    add_measures(run, scenery);
    if (!options.output_dir.empty()) {
      run.files = write_terrain_outputs(options.output_dir, scenery.terrain, scenery.elements.elements,
                                        scenery.building_parts);
    }
    return run;
  }

 private:
  TerrainScene terrain_;
  HeightField initial_;
  Grid grid_;
  std::vector<ParameterInfo> parameters_;
};

}  // namespace

std::vector<SectionType> TerrainSolver::sections() const { return {terrain_section_type()}; }

std::unique_ptr<CompiledSolver> TerrainSolver::compile(const Scene& scene) const {
  auto compiled = std::make_unique<CompiledTerrain>(scene);
  // build once so that `repose check` refuses what a run would
  compiled->run(compiled->default_values(), RunOptions{});
  return compiled;
}

}  // namespace repose
