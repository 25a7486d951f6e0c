#pragma once
// One time step of the height-span model (the height-span paper, 2):
// step(model, params, renderer, state) advances state by model's time step.
//
// Substeps: so that no object moves more than max_substep_cells cells nor
// turns more than max_substep_angle_deg per substep (an object faster than
// a cell per step is substepped, not swept; departure from the ground
// model, whose sweep would not carry the material on the spans). Per
// substep:
//   1. every held object's span map follows it (span_motion.h);
//   2. collision: the held objects' undersides from their maps, the others'
//      from the ground model's Z-buffer (models/ground/collision.h); held
//      objects take up the ground above their spans (ground_contact.h)
//      and, while they drag, cut the ground beside them (side_cut.h);
//   3. compression and displacement of what they intersect, object by
//      object, by the ground model (models/ground/displacement.h; objects
//      whose footprints touch are not merged into one region as the ground
//      model's step merges them: a departure); what a drag compresses goes
//      partly into the object's wedge and from there partly over its lip
//      into it (drag_wedge.h);
//   4. ground erosion (models/ground/erosion.h), capped by all undersides;
//   5. erosion on the spans (span_erosion.h);
//   6. the particles in the air fall and land (particles.h).
// The erosion memory counts down once per step, as the ground model's does.

#include "models/ground/collision.h"
#include "models/ground/erosion.h"
#include "models/heightspan/span_erosion.h"

namespace repose {

struct HeightSpanModel;
struct HeightSpanState;
struct GroundParams;

struct HeightSpanStepReport {
  int substeps = 0;
  int contact_cells = 0;
  double taken_up_m3 = 0.0;  // ground scooped onto spans
  double wedge_kept_m3 = 0.0, wedge_laid_m3 = 0.0;  // into and out of the objects' wedges (drag_wedge.h)
  double side_cut_m3 = 0.0;  // cut beside dragged objects, into their wedges (part of wedge_kept_m3; side_cut.h)
  double over_lip_m3 = 0.0;  // out of the wedges over the objects' lips into them (drag_wedge.h: feed_over_lip)
  int resampled = 0;         // object-substeps that turned (maps peeled again)
  ErosionResult ground_erosion;
  SpanErosionResult span_erosion;
};

// Substeps of the step from `from` to `to` (one pose per object); InputError
// above kMaxSubstepsPerStep (models/ground/substep_count.h).
int heightspan_substeps(const HeightSpanModel& model, const std::vector<Pose>& from, const std::vector<Pose>& to,
                        int step_index);

HeightSpanStepReport step(const HeightSpanModel& model, const GroundParams& params, UndersideRenderer& renderer,
                          HeightSpanState* state);

}  // namespace repose
