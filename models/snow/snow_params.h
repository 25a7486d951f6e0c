#pragma once
// The calibrated parameters of the snow model (the snow paper, 2.2.2 and
// 2.4.1): what a fit changes between runs without rebuilding the snow maps.
//   repose_angle_rad: the snow angle of repose. Stabilisation moves snow
//     across every 4-neighbour pair steeper than this. [0, pi/2]
//   direction_spread_rad: standard deviation of each of the two angular
//     deviations of a snowfall direction from the main direction (the
//     paper's 2-D normal distribution, snowfall_directions.h). [0, pi]
//   snowfall_scale: the depth of settled snow per depth of the scene's
//     snowfall M(t) (how loosely it packs); 1 takes M as the settled depth. (0, 100]
//   edge_hold_m: the snow an edge cell keeps against falling off its map
//     (stabilisation.h; a departure, 0 is the paper's rule): about a grain
//     layer for dry grains, more where cohesion holds snow at an edge. [0, 1]
// All are fitted: the angle to cohesive DEM snow, the spread to how far
// snow reaches under an obstacle, the scale to the depth on open ground.

namespace repose {

struct SnowParams {
  double repose_angle_rad = 0.7853981633974483;       // 45 deg, the paper's Fig. 8 and 9 scenes
  double direction_spread_rad = 0.17453292519943295;  // 10 deg
  double snowfall_scale = 1.0;
  double edge_hold_m = 0.0;
};

// Throws FieldError (an InputError) naming the scene key (repose_angle_deg,
// spread_deg, snowfall_scale, edge_hold_m) and its rule.
void validate(const SnowParams& params);

}  // namespace repose
