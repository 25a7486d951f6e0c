#pragma once
// Multi-resolution (the ground paper, 3.6): a contact computed on a height
// field coarsened by GroundModelSpec::coarse_factor, for objects marked
// `simple` or farther than far_distance_m from the camera.
//
// 1. A patch of whole coarse cells around the object's footprint (margin:
//    half the footprint plus two coarse cells) is restricted from the fine
//    field by averaging (conservative).
// 2. Collision, displacement and erosion run on the patch.
// 3. The change of each coarse cell is mapped back by bilinear interpolation
//    onto the fine cells of the coarse cells that changed, and nowhere else;
//    then each changed coarse cell's fine cells get an equal share of the
//    difference between the coarse change and the sum of the interpolated
//    ones, so every coarse cell's volume change is carried over exactly and
//    nothing is lost. The changed fine cells join the fine erosion memory
//    (remembered at full resolution), so the next steps smooth them there.
//    Interpolation can take a fine cell below the base where its block's
//    neighbours stand higher: then the block's negative cells are lifted to
//    zero and its positive ones scaled down, keeping the block's volume.
// Limits: coarse cells that would reach past the grid's edge are left out
// of the patch (a strip narrower than coarse_factor cells at the far edges is
// not deformed by coarse objects); material pushed past the patch's edge
// is recorded as left_grid_m3; the object's underside caps the ground at
// coarse resolution only.

#include <Eigen/Core>

#include "models/core/geometry/triangle_mesh.h"
#include "models/ground/collision.h"

namespace repose {

struct GroundModel;
struct GroundParams;
struct GroundState;

struct CoarseContactResult {
  int contact_cells = 0;  // coarse cells
  int changed_fine_cells = 0;
};

// faces_down: the faces turned down of the object's collision mesh (world)
// and the whole mesh's box (faces_down.h); motion_m as for displace().
CoarseContactResult deform_coarse(const GroundModel& model, const GroundParams& params, const FacesDown& faces_down,
                                  const Eigen::Vector3d& motion_m, UndersideRenderer& renderer, GroundState* state);

}  // namespace repose
