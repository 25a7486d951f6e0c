#include "models/heightspan/simulate_heightspan.h"

#include <chrono>
#include <cmath>
#include <numbers>

#include "models/core/base/error.h"
#include "models/ground/collision.h"
#include "models/heightspan/heightspan_model.h"
#include "models/heightspan/heightspan_state.h"
#include "models/heightspan/heightspan_step.h"

namespace repose {

namespace {

std::unique_ptr<UndersideRenderer> make_renderer(const HeightSpanModel& model) {
  const bool osmesa = model.ground.options.collision == GroundModelSpec::Collision::kOsmesa;
  return osmesa && !model.ground_path.empty() ? make_osmesa_underside_renderer() : make_cpu_underside_renderer();
}

void record(const HeightSpanStepReport& r, HeightSpanRun* run) {
  run->contact_cells += r.contact_cells;
  run->taken_up_m3 += r.taken_up_m3;
  run->wedge_kept_m3 += r.wedge_kept_m3;
  run->wedge_laid_m3 += r.wedge_laid_m3;
  run->side_cut_m3 += r.side_cut_m3;
  run->over_lip_m3 += r.over_lip_m3;
  run->span_to_ground_m3 += r.span_erosion.to_ground_m3;
  run->ground_to_span_m3 += r.span_erosion.from_ground_m3;
  run->span_to_particles_m3 += r.span_erosion.to_particles_m3;
  run->resampled += r.resampled;
}

}  // namespace

std::vector<std::string> heightspan_stages(const HeightSpanModel& model, const GroundParams& params) {
  std::vector<std::string> stages;
  if (model.ground.objects.empty()) return stages;
  const bool osmesa = model.ground.options.collision == GroundModelSpec::Collision::kOsmesa;
  stages.push_back(osmesa && !model.ground_path.empty() ? "collision:osmesa" : "collision:cpu");
  stages.push_back("displacement");
  if (!model.held.empty()) {
    stages.push_back(model.options.span_maps == HeightSpanSpec::SpanMaps::kOsmesa ? "span-maps:osmesa"
                                                                                 : "span-maps:cpu");
    stages.push_back("span-erosion");
  }
  bool erodes = false;
  for (const Material& m : params.materials) erodes = erodes || m.repose_angle_rad < std::numbers::pi / 2;
  if (erodes) stages.push_back("erosion");
  return stages;
}

HeightSpanRun simulate_heightspan(const HeightSpanModel& model, const GroundParams& params, const HeightField& initial,
                                  const ProgressFn& progress, const FrameFn& frame) {
  validate(params, model.ground);
  std::unique_ptr<UndersideRenderer> renderer = make_renderer(model);
  HeightSpanRun run;
  run.initial_height = initial;
  run.stages = heightspan_stages(model, params);
  HeightSpanState state = make_heightspan_state(model, initial);
  run.initial_m3 = accounted_m3(state);
  run.held_m3.resize(model.held.size());
  const int steps = model.ground.time.step_count();
  const double interval = model.options.frame_interval_s;
  int frames = 0;
  if (frame && interval > 0.0) frame(frames++, state);
  for (int s = 0; s < steps; ++s) {
    const auto start = std::chrono::steady_clock::now();
    record(step(model, params, *renderer, &state), &run);
    run.step_wall_s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    run.time_s.push_back(state.ground.time_s);
    for (std::size_t k = 0; k < model.held.size(); ++k) run.held_m3[k].push_back(state.held[k].map.material_m3());
    run.in_flight_m3.push_back(state.particles.in_flight_m3());
    const double imbalance = run.initial_m3 - accounted_m3(state);
    REPOSE_DEMAND(std::isfinite(imbalance));
    run.imbalance_m3.push_back(imbalance);
    run.max_abs_imbalance_m3 = std::max(run.max_abs_imbalance_m3, std::abs(imbalance));
    if (frame && interval > 0.0 && state.ground.time_s >= frames * interval - 1e-9 * interval) frame(frames++, state);
    report(progress, static_cast<double>(s + 1) / steps, "heightspan steps");
  }
  run.steps = steps;
  run.ledger = state.ground.ledger;
  run.final_height = state.ground.height;
  run.wedge_final_m3 = wedge_m3(state);
  const ParticleSystem& p = state.particles;
  run.particles_built = p.built;
  run.particles_released = p.released;
  run.particles_on_spans = p.landed_on_spans;
  run.particles_on_ground = p.landed_on_ground;
  run.particles_left_grid = p.left_grid;
  if (p.built) run.stages.push_back("particles");
  return run;
}

}  // namespace repose
