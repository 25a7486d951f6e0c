#pragma once
// One time step of the ground model: step(model, params, renderer, state)
// advances state by model.time.step_s.
//
// Substeps: rotating objects (a rolling wheel) are substepped so that no
// object turns by more than max_substep_angle_rad per substep; without
// sweeping, at least options.substeps substeps (1: the streaky no-sweep
// case); at most kMaxSubstepsPerStep (substep_count.h: an InputError
// beyond). Per substep: for each object its collision mesh (the swept mesh
// between the substep's start and end poses when sweeping, else the body at
// the end pose), its underside over its footprint, compression and
// displacement (coarse objects on a coarsened patch, coarse_contact.h);
// then erosion over the remembered cells, capped by the fine objects'
// undersides. The erosion memory counts down once per step.

#include "models/ground/collision.h"
#include "models/ground/erosion.h"

namespace repose {

struct GroundModel;
struct GroundParams;
struct GroundState;

struct StepReport {
  int substeps = 0;
  int contact_cells = 0;   // summed over objects and substeps (coarse objects: coarse cells)
  int swept_objects = 0;   // object-substeps that used a swept mesh
  int coarse_objects = 0;  // object-substeps computed on a coarse patch
  ErosionResult erosion;   // summed over substeps
};

// True when the object at `pose` is computed on the coarse grid.
bool uses_coarse_grid(const GroundModel& model, int object, const Pose& pose);

StepReport step(const GroundModel& model, const GroundParams& params, UndersideRenderer& renderer,
                GroundState* state);

}  // namespace repose
