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

// The load (N) the ground bears under the body at sinkage_m: Bekker's
// pressure at that depth over the patch there. 0 at 0, with the law off or
// no covered cell.
double bearing_load_n(const BekkerBearing& bearing, const DepthImage& underside, double sinkage_m);

// Where an impact stops: the body, at from_m below the surface, carries
// energy_j (J) of downward motion into the ground; it sinks until the
// ground's work, the integral of bearing_load_n less weight_n, has taken
// that energy (capped at height_m). The integral starts at the deeper of
// from_m and the weight's static sinkage: the weight is taken as borne
// quasi-statically (a body set down sinks to Bekker's static sinkage, not
// to the ~(n+1)^(1/n) times deeper stop of a sudden release on a
// rigid-plastic ground), only the impact's energy beyond. Independent of
// how finely the impact is sampled in time, unlike a sinkage from the
// impact's mean force over a step (which grows as the step shrinks).
// from_m (clamped to [0, height_m]) when the energy is 0 or the law is off.
double impact_sinkage_m(const BekkerBearing& bearing, const DepthImage& underside, double height_m, double from_m,
                        double weight_n, double energy_j);

}  // namespace repose
