#pragma once
// Erosion (the ground paper, 3.5, after Sumner et al. 1999): wherever the
// height difference dh between 4-neighbours exceeds cell_size * tan(theta),
// material moves from the higher cell to the lower one.
//
// Amount per pass: sigma * (dh - cell_size * tan(theta)), the excess over
// the angle of repose, not the paper's sigma * dh. Moving a fraction of the
// whole difference would carry a slope just past the threshold far below
// it (for dh slightly above the limit, sigma * dh flattens it by sigma*dh),
// so the settled slope would depend on sigma and never sit at theta; moving
// a fraction of the excess settles every pair at exactly tan(theta), which
// is what the angle of repose means and what the tests check. sigma keeps
// the paper's role: how fast (and, below 1/5, how smoothly) slopes settle.
//
// Each pass is a Jacobi update over the remembered cells (ErosionMemory):
// all fluxes are computed from the heights at the start of the pass, then
// applied, so the result does not depend on visiting order and a symmetric
// ground stays symmetric. Stability limit: sigma <= 1/4 (ground_params.h).
// Cells that changed join the memory, so the eroding region spreads from
// the contact border outwards, one ring per pass, and its cost follows it.
//
// Material of a pair: the higher (source) cell's theta, sigma and En; a
// pass p only moves material out of cells whose En > p.
// Never above an object: the flux into a cell is scaled down so that the
// cell does not rise above the ceiling (the lowest object underside there).
// Boundary: closed. No pair crosses the grid edge, nothing leaves.
// Inclined bed (GroundModelSpec::bed_slope_rad = zeta > 0, a bed-aligned
// chute: x down the slope, heights normal to the bed, gravity tilted): a
// pair's surface makes the angle atan(d / cell) - zeta with the horizontal
// along x, so the repose rule |angle| <= theta allows the difference
// d = h(i+1) - h(i) in [cell tan(zeta - theta), cell tan(zeta + theta)]
// (no upper limit once zeta + theta >= 90 deg); across the slope the line
// is level and |d| cos(zeta) <= cell tan(theta). The excess over a limit
// moves as above, from the side that loses, each side's own material
// deciding; with zeta > theta even a layer of uniform depth is over-steep,
// so material flows down the bed until it piles against an object or the
// grid's end. Heights stay material above the bed: a pass takes no more out
// of a cell than it holds (each cell's outflows scaled down together).
// Tolerance: an excess below kErosionToleranceFraction * cell_size is left
// alone, so a settled slope exceeds tan(theta) by at most that fraction
// (1e-6), and a settled region stops being active: a remembered cell is
// forgotten once its time is up and it is settled (erosion_memory.h), so
// a surface left alone reaches tan(theta) to that tolerance, whatever En.

#include <cstdint>
#include <vector>

#include "models/ground/collision.h"

namespace repose {

struct GroundModel;
struct GroundParams;
struct GroundState;

inline constexpr double kErosionToleranceFraction = 1e-6;

struct ErosionResult {
  int passes = 0;
  long long pair_visits = 0;  // work done: neighbour pairs examined
  long long moves = 0;        // pairs that moved material
};

// Runs max(En) passes over the cells in state->erosion. Does not validate
// params (validate() does, once per run), so it can be driven with sigma
// beyond the stability limit to measure what happens there.
ErosionResult erode(const GroundModel& model, const GroundParams& params, const Ceiling& ceiling, GroundState* state);

// The height difference a pair may have, per material (indexed like
// params.materials): cell_size * tan(theta).
std::vector<double> max_height_differences(const GroundModel& model, const GroundParams& params);

// True when no 4-neighbour pair of `cell` exceeds its max height difference
// (the higher cell's material) by more than the tolerance.
bool is_settled(const GroundModel& model, const std::vector<double>& max_dh_m, const HeightField& height,
                std::int64_t cell);

}  // namespace repose
