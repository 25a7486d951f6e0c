#pragma once
// The calibrated parameters of the ground model: one Material (alpha, theta,
// sigma, En) per material of the GroundModel, in the model's order. A fit
// changes these between runs without re-reading or rebuilding the scene.

#include <vector>

#include "models/ground/material.h"

namespace repose {

struct GroundModel;

// Largest sigma the erosion scheme accepts. Erosion moves sigma * excess
// across every over-steep neighbour pair at once (a Jacobi update, so the
// result does not depend on the order cells are visited). Analysis of the
// excess e = dh - cell_size * tan(theta) after one pass:
//   two cells:            e' = (1 - 2 sigma) e   (overshoot above 1/2)
//   a peak, 4 lower nbrs: e' = (1 - 5 sigma) e   (overshoot above 1/5)
//   checkerboard:         e' = (1 - 8 sigma) e   (overshoot above 1/8,
//                                                 diverges above 1/4)
// so 1/4 is the stability limit of the worst pattern: above it a rough
// surface grows instead of settling (measured in erosion_test.cpp,
// ErosionStability.*). Below it any overshoot flips the pair's excess
// negative, which stops the flux, so the scheme settles. The paper's 0.2
// lies under the limit. Values above it are refused, not clamped (the
// constant, kSigmaMax, is in models/ground/material.h so the scene loader
// refuses them too).

struct GroundParams {
  std::vector<Material> materials;  // indexed like GroundModel::materials
};

// The scene's own materials (ground material, then each region's).
GroundParams default_params(const GroundModel& model);

// Throws InputError naming the material and field when a value is out of
// range: alpha in [0, 1], repose_angle_rad in (0, pi/2], sigma in (0,
// kSigmaMax], erosion_iterations >= 1, at most kMaxErosionPasses passes on
// the model's cells (Material::erosion_passes); and when the count does not match.
void validate(const GroundParams& params, const GroundModel& model);

}  // namespace repose
