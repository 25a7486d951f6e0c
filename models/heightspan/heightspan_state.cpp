#include "models/heightspan/heightspan_state.h"

#include "models/heightspan/heightspan_model.h"

namespace repose {

HeightSpanState make_heightspan_state(const HeightSpanModel& model, HeightField initial) {
  HeightSpanState state;
  state.peeler = model.options.span_maps == HeightSpanSpec::SpanMaps::kOsmesa ? std::shared_ptr<SpanPeeler>(make_osmesa_span_peeler())
                                                                           : std::shared_ptr<SpanPeeler>(make_cpu_span_peeler());
  state.ground = make_ground_state(model.ground, std::move(initial));
  for (const HeldObject& h : model.held) {
    const ObjectSpec& o = model.ground.objects[static_cast<std::size_t>(h.object)];
    ObjectSpans spans;
    spans.pose = o.pose_at(0.0);
    spans.map = state.peeler->peel(transformed(o.body, spans.pose), model.map_grid(h, spans.pose));
    state.held.push_back(std::move(spans));
  }
  state.rng.seed(model.seed);
  return state;
}

double held_m3(const HeightSpanState& state) {
  double sum = 0.0;
  for (const ObjectSpans& h : state.held) sum += h.map.material_m3();
  return sum;
}

double wedge_m3(const HeightSpanState& state) {
  double sum = 0.0;
  for (const ObjectSpans& h : state.held) sum += h.wedge.volume_m3;
  return sum;
}

double accounted_m3(const HeightSpanState& state) {
  const VolumeLedger& l = state.ground.ledger;
  return state.ground.height.volume_m3() + held_m3(state) + state.particles.in_flight_m3() + wedge_m3(state) +
         l.compressed_m3 + l.left_grid_m3;
}

}  // namespace repose
