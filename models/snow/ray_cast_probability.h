#pragma once
// The baseline the snow paper compares against (3.3, Table 1, after its
// ref. 7): the snow probability by ray casting. From each snow-map cell's
// surface point, one ray per snowfall direction goes back up towards where
// the snow comes from (-travel); the point is lit for that direction when
// the ray meets nothing beyond the same bias the shadow maps use
// (shadow_map.h). Independent of the shadow maps: no image, no pixels, exact
// intersections with Embree 3 (BVH), so the two differ by the shadow map's
// sampling only.
//
// Departure: the paper's baseline casts from polygon vertices with no
// acceleration structure (its cost grows with the square of the triangle
// count); this one casts from the same cells as the shadow maps through a
// BVH, the fair modern baseline.

#include <vector>

#include <Eigen/Core>

#include "models/snow/snow_model.h"
#include "models/snow/snow_probability.h"

namespace repose {

SnowProbability snow_probability_ray_cast(const SnowModel& model, const std::vector<Eigen::Vector3d>& directions);

}  // namespace repose
