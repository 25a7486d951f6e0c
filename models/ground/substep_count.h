#pragma once
// How many substeps a step of the ground model takes (ground_step.h), and
// the bounds on that count. The count is derived from the input (rotation
// per step / ground_model.max_substep_angle_deg, or ground_model.substeps
// without sweeping), so it is computed in floating point and refused, with
// an InputError naming the option, before any conversion to an integer
// could overflow: max_substep_angle_deg = 1e-300 once overflowed the cast
// (undefined behaviour) and silently ran one substep, and 1e-6 asked for
// 9e7 substeps in one step (issue 16).

#include <vector>

#include "models/core/geometry/triangle_mesh.h"

namespace repose {

struct GroundModel;

// At most this many substeps in one step (a half turn in 0.018 deg substeps).
inline constexpr int kMaxSubstepsPerStep = 10000;
// At most this many substeps in one run.
inline constexpr double kMaxSubstepsPerRun = 1e7;

// Substeps for the step that moves the objects from `from` to `to` (one
// pose per object). step_index names the step in the message. Throws
// InputError when more than kMaxSubstepsPerStep are needed.
int substep_count(const GroundModel& model, const std::vector<Pose>& from, const std::vector<Pose>& to,
                  int step_index);

// Every step of the model's run, before it starts: throws InputError when a
// step needs more than kMaxSubstepsPerStep substeps or the run more than
// kMaxSubstepsPerRun, or when ground_model.coarse_factor exceeds the grid.
void check_counts(const GroundModel& model);

}  // namespace repose
