#pragma once
// How deep a body's load presses it into the ground under Bekker's law
// (bekker_bearing.h), for any body shape: the body's contact patch when its
// lowest point is z below the undisturbed surface is the set of cells over
// which its underside lies within z of that lowest point (its horizontal
// cross-section at the surface), of area A(z) and smaller width b(z); the
// mean pressure W / A(z) must equal Bekker's pressure at z. A(z) grows with
// z, so z = bekker_sinkage(W / A(z), b(z)) has one crossing, found by
// bisection. A flat box: A is its footprint at every z, and z is Bekker's
// plate sinkage; a sphere: A(z) = pi (2 R z - z^2), so heavier loads spread
// over wider patches.

#include "models/core/geometry/depth_image.h"
#include "models/ground/bekker_bearing.h"

namespace repose {

// A body's patch at one depth.
struct ContactPatch {
  double area_m2 = 0.0;
  // The smaller width: sqrt(12 lambda_min) of the cells' second moments
  // (a rectangle's shorter side, 1.73 radii of a disc), at least one cell.
  double width_m = 0.0;
  int cells = 0;
};

// The cells of `underside` (a depth image from below, ViewFrom::kBelow)
// covered at or below level_m.
ContactPatch patch_below(const DepthImage& underside, double level_m);

// The sinkage (m, below the undisturbed surface) at which the body whose
// underside is `underside` bears load_n (>= 0) under Bekker's law; capped at
// height_m (the body's vertical extent: buried) when even its whole
// footprint does not bear the load. 0 when the load is 0, the law is off or
// the underside covers no cell.
double bearing_sinkage_m(const BekkerBearing& bearing, const DepthImage& underside, double height_m, double load_n);

}  // namespace repose
