#pragma once
// Compression and displacement (the ground paper, 3.4, after Sumner et al.
// 1999). In every colliding cell the intersected height dh' = h - underside
// is removed; alpha*dh' is carried towards the border of the contact region
// and (1 - alpha)*dh' is compressed away (recorded in the ledger). While
// dragging, alpha is the material's drag value (Material::displaced_fraction).
//
// Pressing (the object moves down, or not at all): a 4-neighbour distance
// transform gives each contact cell its distance to the border (1 next to a
// free cell); cells are processed from the inside out and each hands its
// carried material in equal shares to its neighbours one step nearer the
// border, so it arrives on the ring of free cells just outside the contact.
// Dragging (horizontal or upward motion): cells are processed from the rear
// of the contact region to the front (by position along the motion), each
// handing its material in equal shares to the neighbours that are not
// behind it along the motion; among contact cells beside it, only to those
// nearer the border. Cells tied in both never exchange material, so the
// result does not depend on storage order: a drag along an axis is
// mirror-symmetric about it, a diagonal drag about the diagonal.
// Then the material that stands above an object's underside, or heaps on
// open ground beyond what material can heap, moves further out
// (excess_routing.h). Objects whose footprints touch are displaced as one
// region (ground_step.cpp), so this never pushes material under another
// object.
//
// Floor (departure: the paper has none): heights are material above a base
// at z = 0; below it is bedrock. An object reaching below the base removes
// material down to the base only, and the ledger records the largest volume
// of bedrock one contact overlapped (VolumeLedger::bedrock_m3). Heights
// never go below zero.
//
// Contact: a cell collides when its height exceeds the underside by more
// than kContactToleranceFraction * cell_size. A cell left at an underside
// by the last step stands there to round-off, and whether it counted as a
// contact (passing material on) or not (receiving it) decided by round-off
// made mirror images of a drag differ by millimetres.
//
// Boundary: open. Material handed to a cell beyond the grid's edge leaves
// and is recorded as left_grid_m3 (an object larger than the grid pushes its
// material off the grid).

#include <Eigen/Core>

#include "models/ground/collision.h"

namespace repose {

struct GroundModel;
struct GroundParams;
struct GroundState;

struct DisplacementResult {
  int contact_cells = 0;
  double removed_m3 = 0.0;    // sum of dh' * cell area
  double displaced_m3 = 0.0;  // displaced fraction * dh' * cell area
  double bedrock_m3 = 0.0;    // sum of (base - underside) * cell area where the underside is below the base
};

// motion_m: how far the object moved over this (sub)step, world frame. The
// changed cells join state->erosion.
DisplacementResult displace(const GroundModel& model, const GroundParams& params, const Underside& contact,
                            const Ceiling& ceiling, const Eigen::Vector3d& motion_m, GroundState* state);

// True when a motion counts as dragging: it moves horizontally by more than
// `min_horizontal_m` and not downwards (a descent below 1e-9 of the
// horizontal motion is round-off of keyframe interpolation, not a descent).
bool is_drag(const Eigen::Vector3d& motion_m, double min_horizontal_m);

}  // namespace repose
