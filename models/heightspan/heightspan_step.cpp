#include "models/heightspan/heightspan_step.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/ground/displacement.h"
#include "models/ground/ground_params.h"
#include "models/ground/substep_count.h"
#include "models/heightspan/drag_wedge.h"
#include "models/heightspan/ground_contact.h"
#include "models/heightspan/heightspan_model.h"
#include "models/heightspan/heightspan_state.h"
#include "models/heightspan/rigid_velocity.h"
#include "models/heightspan/side_cut.h"
#include "models/heightspan/span_motion.h"

namespace repose {

namespace {

double top_at(const ObjectSpec& object, const Pose& pose) {
  const Eigen::Vector3d up = pose.orientation.conjugate() * Eigen::Vector3d::UnitZ();
  return (object.body.V * up).maxCoeff() + pose.position_m.z();
}

void accumulate(const ErosionResult& e, ErosionResult* sum) {
  sum->passes += e.passes;
  sum->pair_visits += e.pair_visits;
  sum->moves += e.moves;
}

void accumulate(const SpanErosionResult& e, SpanErosionResult* sum) {
  sum->passes += e.passes;
  sum->moves += e.moves;
  sum->to_ground_m3 += e.to_ground_m3;
  sum->from_ground_m3 += e.from_ground_m3;
  sum->to_particles_m3 += e.to_particles_m3;
}

// The wedge's source (heightspan.wedge_source, drag_wedge.h): the drag's compression, the lip's push-ahead or
// both, with one fraction (both) or each with its own (split: the lip's is lip_wedge_fraction).
double compression_wedge_fraction(const HeightSpanSpec& o) {
  return o.wedge_source != HeightSpanSpec::WedgeSource::kLip ? o.wedge_fraction : 0.0;
}
LipWedge lip_wedge(const HeightSpanSpec& o, DragWedge* wedge) {
  using W = HeightSpanSpec::WedgeSource;
  const double fraction = o.wedge_source == W::kCompression ? 0.0
                          : o.wedge_source == W::kSplit     ? o.lip_wedge_fraction
                                                            : o.wedge_fraction;
  if (!(fraction > 0.0)) return {};
  return {wedge, fraction};
}

// heightspan.press_fraction (drag_wedge.h): the materials a held object presses into, with that
// fraction of what they would compress displaced instead. None when the option is 0.
std::optional<GroundParams> pressing_params(const HeightSpanSpec& o, const GroundParams& params) {
  if (!(o.press_fraction > 0.0)) return std::nullopt;
  GroundParams p = params;
  for (Material& m : p.materials) m.alpha += o.press_fraction * (1.0 - m.alpha);
  return p;
}

// pressing: pressing_params(model.options, params), made once per step (none when press_fraction is 0).
void substep(const HeightSpanModel& model, const GroundParams& params, const std::optional<GroundParams>& pressing,
             UndersideRenderer& renderer, const std::vector<Pose>& from, const std::vector<Pose>& to, double dt_s,
             HeightSpanState* state, HeightSpanStepReport* report) {
  const GroundModel& ground = model.ground;
  Ceiling ceiling;
  std::vector<Eigen::Vector3d> motions;
  std::vector<RigidVelocity> velocities;  // the held objects'
  for (std::size_t k = 0; k < model.held.size(); ++k) {
    const int o = model.held[k].object;
    const Eigen::Vector3d motion = to[o].position_m - from[o].position_m;
    ObjectSpans& spans = state->held[k];
    velocities.push_back(rigid_velocity(from[o], to[o], dt_s));
    report->resampled += move_spans(model, model.held[k], to[o], velocities.back(), *state->peeler, &spans, &state->particles,
                                     &state->rng)
                             .resampled;
    const double wedge_before_m3 = spans.wedge.volume_m3;
    report->taken_up_m3 += take_up_ground(ground, &spans.map, &state->ground, motion,
                                          {model.options.intake_layer_m, model.options.intake_fraction},
                                          lip_wedge(model.options, &spans.wedge));
    report->side_cut_m3 += cut_beside(ground, spans.map, model.options.side_cut_m, motion, &spans.wedge, &state->ground);
    report->wedge_kept_m3 += spans.wedge.volume_m3 - wedge_before_m3;  // the lip's wedge and the side cut
    ceiling.undersides.push_back(
        underside_of(spans.map, ground.grid, top_at(ground.objects[o], to[o]), model.options.shear_layer_m));
    motions.push_back(motion);
  }
  for (const int o : model.ground_path) {
    const ObjectSpec& object = ground.objects[static_cast<std::size_t>(o)];
    Underside u = find_underside(transformed(object.body, to[o]), state->ground.height, renderer);
    if (!u.empty()) u.top_m = top_at(object, to[o]);
    ceiling.undersides.push_back(std::move(u));
    motions.push_back(to[o].position_m - from[o].position_m);
  }
  for (std::size_t k = 0; k < ceiling.undersides.size(); ++k) {
    const double compressed_before_m3 = state->ground.ledger.compressed_m3;
    const bool held_drags = k < model.held.size() && drags(ground, motions[k]);
    const bool presses = k < model.held.size() && pressing && !held_drags;
    report->contact_cells += displace(ground, presses ? *pressing : params, ceiling.undersides[k], ceiling, motions[k],
                                      &state->ground)
                                 .contact_cells;
    if (k < model.held.size()) {
      const double compressed_m3 = state->ground.ledger.compressed_m3 - compressed_before_m3;
      ObjectSpans& spans = state->held[k];
      const WedgeFractions fractions{compression_wedge_fraction(model.options), model.options.press_wedge_fraction};
      const double kept_m3 = keep_in_wedge(ground, compressed_m3, fractions, motions[k], &spans.wedge, &state->ground);
      report->wedge_kept_m3 += kept_m3;
      report->over_lip_m3 += feed_over_lip(ground.grid, held_drags ? kept_m3 : 0.0, model.options.over_lip_fraction,
                                           &spans.wedge, &spans.map);  // a share of the drag's alone
      report->wedge_laid_m3 += lay_wedge(ground, spans.map, motions[k], &spans.wedge, &state->ground);
    }
  }
  accumulate(erode(ground, params, ceiling, &state->ground), &report->ground_erosion);
  for (std::size_t k = 0; k < model.held.size(); ++k) {
    accumulate(erode_spans(model, params, velocities[k], &state->held[k], &state->ground, &state->particles,
                           &state->rng),
               &report->span_erosion);
  }
  std::vector<SpanMap*> maps;
  for (ObjectSpans& s : state->held) maps.push_back(&s.map);
  advance_particles(dt_s, ground, maps, &state->particles, &state->ground);
}

}  // namespace

int heightspan_substeps(const HeightSpanModel& model, const std::vector<Pose>& from, const std::vector<Pose>& to,
                        int step_index) {
  double needed = 1.0;
  const double cell_m = model.options.max_substep_cells * model.ground.grid.cell_size_m;
  for (std::size_t o = 0; o < from.size(); ++o) {
    needed = std::max(needed, (to[o].position_m - from[o].position_m).norm() / cell_m);
    needed = std::max(needed, from[o].orientation.angularDistance(to[o].orientation) / model.options.max_substep_angle_rad);
  }
  if (!(needed <= kMaxSubstepsPerStep)) {
    throw InputError(fmt::format("heightspan: step {} needs {:.3g} substeps (an object moves more than {} cells or "
                                 "turns more than {} times heightspan.max_substep_angle_deg), at most {}: raise "
                                 "heightspan.max_substep_cells or shorten time.step_s",
                                 step_index, needed, kMaxSubstepsPerStep * model.options.max_substep_cells,
                                 kMaxSubstepsPerStep, kMaxSubstepsPerStep));
  }
  return static_cast<int>(std::ceil(needed - 1e-9));
}

HeightSpanStepReport step(const HeightSpanModel& model, const GroundParams& params, UndersideRenderer& renderer,
                          HeightSpanState* state) {
  HeightSpanStepReport report;
  const GroundModel& ground = model.ground;
  const double dt = ground.time.step_s;
  const double t0 = state->ground.step_index * dt;  // not accumulated: no drift over many steps
  const std::size_t n_objects = ground.objects.size();
  std::vector<Pose> end(n_objects);
  for (std::size_t o = 0; o < n_objects; ++o) end[o] = ground.objects[o].pose_at(t0 + dt);
  const int substeps = heightspan_substeps(model, state->ground.previous_poses, end, state->ground.step_index);
  report.substeps = substeps;
  std::vector<Pose> poses = state->ground.previous_poses;
  const std::optional<GroundParams> pressing = pressing_params(model.options, params);
  for (int s = 1; s <= substeps; ++s) {
    std::vector<Pose> to(n_objects);
    for (std::size_t o = 0; o < n_objects; ++o) {
      to[o] = s == substeps ? end[o] : ground.objects[o].pose_at(t0 + dt * s / substeps);
    }
    substep(model, params, pressing, renderer, poses, to, dt / substeps, state, &report);
    poses = to;
  }
  const std::vector<double> max_dh = max_height_differences(ground, params);
  state->ground.erosion.end_step([&](std::int64_t c) { return is_settled(ground, max_dh, state->ground.height, c); });
  state->ground.previous_poses = end;
  ++state->ground.step_index;
  state->ground.time_s = state->ground.step_index * dt;
  return report;
}

}  // namespace repose
