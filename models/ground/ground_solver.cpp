#include "models/ground/ground_solver.h"

#include <algorithm>
#include <numbers>
#include <numeric>

#include <fmt/format.h>

#include "models/core/base/cpu_time.h"
#include "models/core/config/fields.h"
#include "models/core/config/initial_height.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_section.h"
#include "models/ground/material_parameters.h"
#include "models/ground/simulate_ground.h"
#include "models/ground/streaks.h"
#include "models/ground/substep_count.h"

namespace repose {

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

void add_measures(Run& run, const GroundRun& g, const Scene& scene) {
  run.set("steps", g.steps, "count");
  run.set("step_wall_s_median", median(g.step_wall_s), "s");
  const double total = std::accumulate(g.step_wall_s.begin(), g.step_wall_s.end(), 0.0);
  run.set("steps_wall_s_total", total, "s");
  run.set("step_wall_s_mean", g.steps > 0 ? total / g.steps : 0.0, "s");
  run.set("contact_cells_total", static_cast<double>(g.contact_cells), "count");
  run.set("volume.initial_m3", g.ledger.initial_m3, "m^3");
  run.set("volume.final_m3", g.final_volume_m3, "m^3");
  run.set("volume.compressed_m3", g.ledger.compressed_m3, "m^3");
  run.set("volume.left_grid_m3", g.ledger.left_grid_m3, "m^3");
  run.set("volume.bedrock_m3", g.ledger.bedrock_m3, "m^3");
  run.set("volume.imbalance_m3", g.ledger.imbalance_m3(g.final_volume_m3), "m^3");
  // free bodies, under the particle engines' keys (free_bodies.NAME.*)
  for (const FreeBodyReport& b : g.free_bodies) {
    const std::string key = "free_bodies." + b.name + ".";
    run.set(key + "resting_depth_m", b.resting_depth_m, "m");
    run.set(key + "final_speed_m_s", b.final_speed_m_s, "m/s");
    run.set(key + "travel_m", b.travel_m, "m");
    run.set(key + "max_force_n", b.max_load_n, "N");
    run.set(key + "final_force_n", b.final_load_n, "N");
    run.set(key + "weight_n", b.weight_n, "N");
    run.set(key + "mass_kg", b.mass_kg, "kg");
    run.set(key + "bearing_sinkage_m", b.bearing_sinkage_m, "m");
  }
  // streaks along each moving object's path; ridges count above 5 % of a cell
  for (const ObjectSpec& object : scene.objects) {
    const StreakStats s =
        streaks_along_path(g.final_height, object, scene.time, 0.05 * g.final_height.grid().cell_size_m);
    if (s.samples == 0) continue;
    const std::string key = "streaks." + object.name + ".";
    run.set(key + "samples", s.samples, "count");
    run.set(key + "rms_m", s.rms_m, "m");
    run.set(key + "range_m", s.range_m, "m");
    run.set(key + "ridges", s.ridges, "count");
  }
}

class CompiledGround final : public CompiledSolver {
 public:
  explicit CompiledGround(const Scene& scene)
      : scene_(scene), model_(build_ground_model(scene)), initial_(make_initial_height(scene)), parameters_(model_) {
    check_counts(model_);  // substeps and coarse patches, so that `check` refuses what `run` would
  }

  const std::vector<ParameterInfo>& parameters() const override { return parameters_.infos(); }

  Run run(const std::vector<double>& values_si, const RunOptions& options) const override {
    check_values(parameters_.infos(), values_si, "ground");
    const Stopwatch clock;
    const GroundParams params = parameters_.params_for(model_, values_si);
    const GroundRun g = simulate_ground(model_, params, initial_, options.progress);
    Run run;
    run.solver = "ground";
    run.wall_s = clock.wall_s();
    run.cpu_s = clock.cpu_s();
    run.fields["height_initial"] = initial_;
    run.fields["height_final"] = g.final_height;
    run.stages = g.stages;
    add_measures(run, g, scene_);
    return run;
  }

 private:
  Scene scene_;
  GroundModel model_;
  HeightField initial_;
  MaterialParameters parameters_;
};

}  // namespace

std::vector<SectionType> GroundSolver::sections() const { return {ground_model_section_type()}; }

bool GroundSolver::can_run(const Scene& scene, std::string* why) const {
  return Solver::can_run(scene, why);
}

std::unique_ptr<CompiledSolver> GroundSolver::compile(const Scene& scene) const {
  return std::make_unique<CompiledGround>(scene);
}

}  // namespace repose
