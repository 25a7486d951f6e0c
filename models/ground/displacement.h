#pragma once
// Compression and displacement (the ground paper, 3.4, after Sumner et al.
// 1999). In every colliding cell the intersected height dh' = h - underside
// is removed; alpha*dh' is carried towards the border of the contact region
// and (1 - alpha)*dh' is compressed away (recorded in the ledger).
//
// Pressing (the object moves down, or not at all): a 4-neighbour distance
// transform gives each contact cell its distance to the border (1 next to a
// free cell); cells are processed from the inside out and each hands its
// carried material in equal shares to its neighbours one step nearer the
// border, so it arrives on the ring of free cells just outside the contact.
// Dragging (horizontal or upward motion): cells are processed from the rear
// of the contact region to the front (by position along the motion), each
// handing its material in equal shares to the neighbours that are not
// behind it along the motion (and, among contact cells, processed after it),
// so nothing is pushed backwards.
// Then, where a receiving cell rises above an object's underside, the excess
// moves further out: towards the nearest cell that no object covers, level
// by level (level: 4-neighbour distance to such a cell through free cells),
// farthest level first, in equal shares to the neighbours one level nearer;
// when dragging, not backwards unless that is the only way out (leaving it
// above the object's underside would be worse). Objects whose footprints touch are
// displaced as one region (ground_step.cpp), so this never pushes material
// under another object.
//
// Boundary: open. Material handed to a cell beyond the grid's edge leaves
// and is recorded as left_grid_m3 (an object larger than the grid pushes its
// material off the grid). Excess that cannot reach an uncovered cell (a
// pocket enclosed by contact, or only reachable backwards while dragging)
// stays where it is.

#include <Eigen/Core>

#include "models/ground/collision.h"

namespace repose {

struct GroundModel;
struct GroundParams;
struct GroundState;

struct DisplacementResult {
  int contact_cells = 0;
  double removed_m3 = 0.0;    // sum of dh' * cell area
  double displaced_m3 = 0.0;  // alpha * dh' * cell area
};

// motion_m: how far the object moved over this (sub)step, world frame. The
// changed cells join state->erosion.
DisplacementResult displace(const GroundModel& model, const GroundParams& params, const Underside& contact,
                            const Ceiling& ceiling, const Eigen::Vector3d& motion_m, GroundState* state);

// True when a motion counts as dragging: it moves horizontally by more than
// `min_horizontal_m` and not downwards.
bool is_drag(const Eigen::Vector3d& motion_m, double min_horizontal_m);

}  // namespace repose
