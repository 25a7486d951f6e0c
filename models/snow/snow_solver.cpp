#include "models/snow/snow_solver.h"

#include <filesystem>
#include <numbers>

#include "models/core/base/cpu_time.h"
#include "models/core/base/error.h"
#include "models/core/io/mesh_io.h"
#include "models/snow/simulate_snow.h"
#include "models/snow/snow_model.h"
#include "models/snow/snow_picture_series.h"
#include "models/snow/snow_section.h"
#include "models/snow/snow_surface_mesh.h"

namespace repose {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

void add_measures(Run& run, const SnowModel& model, const SnowState& state, const SnowRunSummary& s) {
  const Grid& g = model.grid;
  run.set("steps", s.steps, "count");
  run.set("unsettled_steps", s.unsettled_steps, "count");
  run.set("stabilisation_passes", static_cast<double>(s.stabilisation_passes), "count");
  run.set("probability_wall_s", s.probability_wall_s, "s");
  run.set("steps_wall_s", s.steps_wall_s, "s");
  run.set("snow.fallen_m3", state.ledger.fallen_m3, "m^3");
  run.set("snow.on_maps_m3", snow_on_maps_m3(state, g), "m^3");
  run.set("snow.left_scene_m3", state.ledger.left_scene_m3, "m^3");
  run.set("snow.imbalance_m3", s.imbalance_m3, "m^3");
  for (std::size_t m = 0; m < model.maps.size(); ++m) {
    const std::string& name = model.maps[m].name;
    run.set("snow.volume_m3." + name, state.depth_m[m].sum() * g.cell_area_m2(), "m^3");
    run.set("snow.max_depth_m." + name, state.depth_m[m].maxCoeff(), "m");
  }
}

// The snow surfaces as OBJ (the runner writes the fields as .npy itself).
void write_surfaces(Run& run, const SnowModel& model, const SnowState& state, const std::string& dir) {
  for (std::size_t m = 0; m < model.maps.size(); ++m) {
    const std::string file = "snow_surface_" + model.maps[m].name + ".obj";
    write_obj((std::filesystem::path(dir) / file).string(), snow_surface_mesh(model.maps[m], state.depth_m[m]));
    run.files.push_back(file);
  }
}

class CompiledSnow final : public CompiledSolver {
 public:
  CompiledSnow(const Scene& scene, const SnowSpec& spec)
      : model_(build_snow_model(scene, spec.options)) {
    for (std::size_t m = 0; m < spec.options.groups.size(); ++m) {
      if (spec.options.groups[m].ground) ground_map_ = static_cast<int>(m);
    }
    parameters_ = {
        {"repose_angle_deg", "deg", kDeg, 0.0, 90.0 * kDeg, spec.params.repose_angle_rad,
         "the snow angle of repose: steeper snow slopes move"},
        {"spread_deg", "deg", kDeg, 0.0, 180.0 * kDeg, spec.params.direction_spread_rad,
         "standard deviation of each angular deviation of a snowfall direction"},
        {"snowfall_scale", "1", 1.0, 0.01, 100.0, spec.params.snowfall_scale,
         "settled snow depth per depth of the scene's snowfall (how loosely snow packs)"},
        {"edge_hold_m", "m", 1.0, 0.0, 1.0, spec.params.edge_hold_m,
         "snow an edge cell keeps against falling off its map (a grain layer; more with cohesion)"},
    };
  }

  const std::vector<ParameterInfo>& parameters() const override { return parameters_; }

  Run run(const std::vector<double>& values_si, const RunOptions& options) const override {
    check_values(parameters_, values_si, "snow");
    const Stopwatch clock;
    const SnowParams params{values_si[0], values_si[1], values_si[2], values_si[3]};
    SnowState state;
    std::unique_ptr<SnowPictureSeries> pictures;
    std::function<void(int, const SnowState&)> on_step;
    if (!options.output_dir.empty() && model_.options.pictures.any()) {
      pictures = std::make_unique<SnowPictureSeries>(model_, params.snowfall_scale, options.output_dir);
      pictures->on_state(make_snow_state(model_));
      on_step = [&](int, const SnowState& s) { pictures->on_state(s); };
    }
    const SnowRunSummary summary = simulate_snow(model_, params, &state, on_step);
    Run run;
    run.solver = "snow";
    run.wall_s = clock.wall_s();
    run.cpu_s = clock.cpu_s();
    run.stages = {"snow_maps", model_.options.renderer == SnowRenderer::kCpu ? "shadow_maps:cpu" : "shadow_maps:osmesa",
                  "accumulation", "stabilisation"};
    for (std::size_t m = 0; m < model_.maps.size(); ++m) {
      run.fields["snow_depth_final." + model_.maps[m].name] = HeightField(model_.grid, state.depth_m[m]);
      run.fields["snow_probability." + model_.maps[m].name] = HeightField(model_.grid, summary.probability.per_map[m]);
    }
    if (ground_map_ >= 0) {
      const SnowMap& ground = model_.maps[static_cast<std::size_t>(ground_map_)];
      run.fields["height_initial"] = HeightField(model_.grid, ground.base.z_m);
      run.fields["height_final"] =
          HeightField(model_.grid, ground.base.z_m + state.depth_m[static_cast<std::size_t>(ground_map_)]);
    }
    add_measures(run, model_, state, summary);
    if (!options.output_dir.empty()) write_surfaces(run, model_, state, options.output_dir);
    if (pictures) run.files.insert(run.files.end(), pictures->files().begin(), pictures->files().end());
    return run;
  }

 private:
  SnowModel model_;
  int ground_map_ = -1;
  std::vector<ParameterInfo> parameters_;
};

}  // namespace

std::vector<SectionType> SnowSolver::sections() const { return {snow_section_type()}; }

bool SnowSolver::can_run(const Scene& scene, std::string* why) const {
  if (scene.section<SnowSection>() != nullptr) return true;
  if (why != nullptr) *why = "the scene has no snow: section";
  return false;
}

std::unique_ptr<CompiledSolver> SnowSolver::compile(const Scene& scene) const {
  const SnowSection* section = scene.section<SnowSection>();
  if (section == nullptr) throw InputError(scene.source_path + ": the snow solver needs a snow: section");
  return std::make_unique<CompiledSnow>(scene, section->spec);
}

}  // namespace repose
