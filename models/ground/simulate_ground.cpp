#include "models/ground/simulate_ground.h"

#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "models/core/config/initial_height.h"
#include "models/ground/collision.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_state.h"
#include "models/ground/ground_step.h"
#include "models/ground/substep_count.h"

namespace repose {

namespace {

std::unique_ptr<UndersideRenderer> make_renderer(const GroundModel& model) {
  return model.options.collision == GroundModelSpec::Collision::kOsmesa ? make_osmesa_underside_renderer()
                                                                        : make_cpu_underside_renderer();
}

bool any_translation(const ObjectSpec& o) {
  for (const Keyframe& k : o.keyframes) {
    if (k.pose.position_m != o.keyframes.front().pose.position_m) return true;
  }
  return false;
}

bool any_rotation(const ObjectSpec& o) {
  for (const Keyframe& k : o.keyframes) {
    if (k.pose.orientation.angularDistance(o.keyframes.front().pose.orientation) > 0.0) return true;
  }
  return false;
}

}  // namespace

std::vector<std::string> ground_stages(const GroundModel& model, const GroundParams& params) {
  std::vector<std::string> stages;
  if (!model.objects.empty()) {
    stages.push_back(model.options.collision == GroundModelSpec::Collision::kOsmesa ? "collision:osmesa"
                                                                                      : "collision:cpu");
    stages.push_back("displacement");
  }
  bool translates = false, rotates = false, coarse = false;
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    translates = translates || any_translation(model.objects[o]);
    rotates = rotates || any_rotation(model.objects[o]);
    coarse = coarse || uses_coarse_grid(model, static_cast<int>(o), model.objects[o].keyframes.front().pose);
  }
  if (translates && model.options.sweep) stages.push_back("sweep");
  if (!model.options.sweep && model.options.substeps > 1) {
    stages.push_back(fmt::format("substeps:{}", model.options.substeps));
  }
  if (rotates) stages.push_back("rotation-substeps");
  bool erodes = false;
  for (const Material& m : params.materials) erodes = erodes || m.repose_angle_rad < std::numbers::pi / 2;
  if (erodes && !model.objects.empty()) stages.push_back("erosion");
  if (coarse) stages.push_back("multires");
  if (has_free_bodies(model)) {
    stages.push_back("free-bodies:ode");
    if (model.free_bodies.bearing.law == BekkerBearing::Law::kBekker) stages.push_back("bearing:bekker");
  }
  return stages;
}

GroundRun simulate_ground(const GroundModel& model, const GroundParams& params, const HeightField& initial,
                          const ProgressFn& progress) {
  validate(params, model);
  check_counts(model);  // before anything runs
  std::unique_ptr<UndersideRenderer> renderer = make_renderer(model);
  GroundRun run;
  run.initial_height = initial;
  run.stages = ground_stages(model, params);
  GroundState state = make_ground_state(model, initial);
  const int steps = model.time.step_count();
  run.step_wall_s.reserve(static_cast<std::size_t>(steps));
  // free bodies: ODE's world, and a copy of the model whose free objects' keyframes each step sets
  std::unique_ptr<FreeBodyDrive> drive;
  std::optional<GroundModel> driven;
  if (has_free_bodies(model)) {
    drive = std::make_unique<FreeBodyDrive>(model, initial);
    driven.emplace(model);
  }
  for (int s = 0; s < steps; ++s) {
    const auto start = std::chrono::steady_clock::now();
    if (drive) drive->advance(state, &*driven);
    const StepReport r = step(driven ? *driven : model, params, *renderer, &state);
    if (drive) drive->refresh_field(state.height);
    run.step_wall_s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    run.contact_cells += r.contact_cells;
    report(progress, static_cast<double>(s + 1) / steps, "ground steps");
  }
  run.steps = steps;
  if (drive) run.free_bodies = drive->reports();
  run.ledger = state.ledger;
  run.final_height = std::move(state.height);
  run.final_volume_m3 = run.final_height.volume_m3();
  return run;
}

GroundRun simulate_ground(const Scene& scene, const GroundParams& params, const ProgressFn& progress) {
  const GroundModel model = build_ground_model(scene);
  return simulate_ground(model, params, make_initial_height(scene), progress);
}

}  // namespace repose
