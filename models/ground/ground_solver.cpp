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
#include "models/ground/simulate_ground.h"
#include "models/ground/streaks.h"

namespace repose {

namespace {

enum class Field { kAlpha, kReposeAngle, kSigma };

struct MaterialParameter {
  std::string material;
  Field field;
};

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
  run.set("volume.imbalance_m3", g.ledger.imbalance_m3(g.final_volume_m3), "m^3");
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
      : scene_(scene), model_(build_ground_model(scene)), initial_(make_initial_height(scene)) {
    for (const Material& m : model_.materials) {
      const bool seen = std::any_of(targets_.begin(), targets_.end(),
                                    [&](const MaterialParameter& p) { return p.material == m.name; });
      if (!seen) declare(m);
    }
  }

  const std::vector<ParameterInfo>& parameters() const override { return parameters_; }

  Run run(const std::vector<double>& values_si, const RunOptions& options) const override {
    check_values(parameters_, values_si, "ground");
    const Stopwatch clock;
    const GroundParams params = params_for(values_si);
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
  void declare(const Material& m) {
    const double deg = std::numbers::pi / 180.0;
    auto add = [&](const std::string& field, Field f, const std::string& unit, double si_per_unit, double lo,
                   double hi, double value, const std::string& what) {
      parameters_.push_back({m.name + "." + field, unit, si_per_unit, lo, hi, value, what});
      targets_.push_back({m.name, f});
    };
    add("alpha", Field::kAlpha, "1", 1.0, 0.0, 1.0, m.alpha, "fraction of the intersected height displaced");
    add("repose_angle_deg", Field::kReposeAngle, "deg", deg, 1e-6 * deg, 90.0 * deg, m.repose_angle_rad,
        "angle of repose: steeper slopes erode");
    add("sigma", Field::kSigma, "1", 1.0, 1e-9, kSigmaMax, m.sigma, "fraction of the excess moved per erosion pass");
  }

  GroundParams params_for(const std::vector<double>& values_si) const {
    GroundParams params = default_params(model_);
    for (std::size_t k = 0; k < targets_.size(); ++k) {
      for (Material& m : params.materials) {
        if (m.name != targets_[k].material) continue;
        if (targets_[k].field == Field::kAlpha) m.alpha = values_si[k];
        if (targets_[k].field == Field::kReposeAngle) m.repose_angle_rad = values_si[k];
        if (targets_[k].field == Field::kSigma) m.sigma = values_si[k];
      }
    }
    validate(params, model_);
    return params;
  }

  Scene scene_;
  GroundModel model_;
  HeightField initial_;
  std::vector<ParameterInfo> parameters_;
  std::vector<MaterialParameter> targets_;  // per parameter
};

}  // namespace

std::vector<SectionType> GroundSolver::sections() const { return {ground_model_section_type()}; }

std::unique_ptr<CompiledSolver> GroundSolver::compile(const Scene& scene) const {
  return std::make_unique<CompiledGround>(scene);
}

}  // namespace repose
