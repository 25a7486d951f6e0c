#pragma once
// The scene's keyframed objects as LIGGGHTS move/mesh fixes: per segment
// between consecutive keyframe times of any object, a linear velocity and,
// where the orientation changes, a constant-rate rotation superposed on it.

#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/core/config/scene.h"
#include "models/core/geometry/triangle_mesh.h"
#include "validation/particles/dem_section.h"

namespace repose {

// Steps of `step_s` in `time_s`, rounded to the nearest.
long liggghts_steps(double time_s, double step_s);

// Position of an object at time t: linear between keyframes, held outside.
Eigen::Vector3d position_at(const ObjectSpec& object, double t);

// Does any keyframe turn the object away from its first orientation?
bool rotates(const ObjectSpec& object);

// A box the keyframed object's body stays in over its whole motion: the
// body's box at its (fixed) orientation carried through the keyframe
// positions, or for a turning object the ball of its farthest vertex from
// the body origin about each keyframe position (positions are linear
// between keyframes, so either covers every time in between).
Aabb swept_bounds(const ObjectSpec& object);

// Writes every segment's fixes, its `run N` and the unfixes; object k's mesh
// is the fix mesh_fix_ids[k] (free bodies are skipped). Returns the steps of the whole run.
long write_motion(std::ostringstream& s, const Scene& scene, const DemSpec& dem,
                  const std::vector<std::string>& mesh_fix_ids);

}  // namespace repose
