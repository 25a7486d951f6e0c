#pragma once
// What the height-span model changes while it runs: the ground model's
// state (height field, erosion memory, poses, ledger), each held object's
// span map with the material on it and the pose it was built at, the
// particles in the air and their generator.

#include <random>
#include <vector>

#include "models/ground/ground_state.h"
#include "models/heightspan/drag_wedge.h"
#include "models/heightspan/particles.h"
#include "models/heightspan/span_erosion.h"
#include "models/heightspan/span_map.h"
#include "models/heightspan/span_peeler.h"

namespace repose {

struct HeightSpanModel;

struct ObjectSpans {
  SpanMap map;
  Pose pose;  // the object's pose the map was built for
  SpanErosionScratch erosion_scratch;  // reused by erode_spans
  DragWedge wedge;  // driven ahead of the object while it drags (heightspan.wedge_fraction)
};

struct HeightSpanState {
  GroundState ground;
  std::vector<ObjectSpans> held;  // one per model.held
  ParticleSystem particles;
  std::mt19937_64 rng;
  // peels the maps as objects turn (heightspan.span_maps); shared by copies of a state on one thread
  std::shared_ptr<SpanPeeler> peeler;
};

// The state at time 0: the ground's (make_ground_state), each held object's
// map at its first pose with no material on it, no particles, the generator
// seeded with the model's seed, the peeler the options ask for (InputError
// when OpenGL cannot be started for the OSMesa path).
HeightSpanState make_heightspan_state(const HeightSpanModel& model, HeightField initial);

// Material on every held object's spans (m^3).
double held_m3(const HeightSpanState& state);
// Material in the held objects' wedges (m^3; drag_wedge.h).
double wedge_m3(const HeightSpanState& state);
// Everything the model accounts for (m^3): ground + spans + particles in the
// air + wedges + compressed + left the grid. Constant to round-off (the ledger).
double accounted_m3(const HeightSpanState& state);

}  // namespace repose
