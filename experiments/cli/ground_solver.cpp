// `repose run --solver ground`: the ground heuristic over the whole scene,
// with the scene's own materials as its parameters.
#include <algorithm>
#include <vector>

#include "experiments/figures/render_height.h"
#include "experiments/cli/solvers.h"
#include "models/core/io/height_field_io.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_params.h"
#include "models/ground/simulate_ground.h"
#include "models/ground/streaks.h"

namespace repose::cli {
namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

void run_ground_solver(RunContext& context) {
  const GroundModel model = build_ground_model(context.scene);
  const GroundParams params = default_params(model);
  validate(params, model);
  const GroundRun run = simulate_ground(model, params, context.initial_height, context.progress);

  write_height_field_npy(context.out.path("height_final.npy"), run.final_height);
  context.manifest.add_file("height_final.npy");
  render_height_png(context.out.path("height_final.png"), run.final_height, &context.scene,
                    context.scene.time.duration_s, CameraOverrides{});
  context.manifest.add_file("height_final.png");

  // Streaks along each moving object's path (streaks.h); ridges count above 5 % of a cell.
  std::vector<std::pair<std::string, StreakStats>> streaks;
  for (const ObjectSpec& object : context.scene.objects) {
    const StreakStats s = streaks_along_path(run.final_height, object, context.scene.time,
                                             0.05 * run.final_height.grid().cell_size_m);
    if (s.samples > 0) streaks.emplace_back(object.name, s);
  }

  context.manifest.set_stages_built(run.stages);
  context.manifest.set_results([run, streaks](JsonWriter& json) {
    json.key("steps").integer(run.steps);
    json.key("step_wall_s_median").number(median(run.step_wall_s));
    double total = 0.0;
    for (double t : run.step_wall_s) total += t;
    json.key("steps_wall_s_total").number(total);
    json.key("step_wall_s_mean").number(run.steps > 0 ? total / run.steps : 0.0);
    json.key("streaks").begin_object();
    for (const auto& [name, s] : streaks) {
      json.key(name).begin_object();
      json.key("samples").integer(s.samples);
      json.key("rms_m").number(s.rms_m);
      json.key("range_m").number(s.range_m);
      json.key("ridges").integer(s.ridges);
      json.end_object();
    }
    json.end_object();
    json.key("contact_cells_total").integer(run.contact_cells);
    json.key("volume").begin_object();
    json.key("initial_m3").number(run.ledger.initial_m3);
    json.key("final_m3").number(run.final_volume_m3);
    json.key("compressed_m3").number(run.ledger.compressed_m3);
    json.key("left_grid_m3").number(run.ledger.left_grid_m3);
    json.key("imbalance_m3").number(run.ledger.imbalance_m3(run.final_volume_m3));
    json.end_object();
  });
}

}  // namespace repose::cli
