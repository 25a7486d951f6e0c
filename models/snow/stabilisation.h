#pragma once
// Stabilisation and falling (the snow paper 2.4.1, Fig. 6, and 2.4.2):
// snow moves from a cell to those of its 4 neighbours whose slope to it
// exceeds the snow angle of repose, shared equally among them.
//
// Surface height H = map base z + snow depth. For a cell c of map m and a
// neighbour position n on the grid:
//   - n in m's snow-possible area: the pair (m, c) -> (m, n);
//   - else snow pushed that way falls (2.4.2) onto the highest map covering
//     n whose surface there is lower than H(c) (ties: the earlier group),
//     and the pair's slope is measured to that surface;
//   - else, if no map covers n at all, the snow leaves the scene (ledger);
//   - else (only higher surfaces at n: a wall) nothing moves that way.
// Positions off the grid are closed: nothing crosses the grid's edge.
//
// Amount (the paper says "move the snow" without an amount): cell c moves
// A = min(s_c, f * sum_n e_n), with e_n = min(H_c - H_n - h tan(theta), s_c)
// the excess over the repose slope of each over-steep pair (capped by the
// snow there: no excess moves snow that is not there), and each of the k
// over-steep neighbours receives A / k (Fig. 6 (c)-(e): equal shares). As
// the ground's erosion (models/ground/erosion.h), a fraction of the excess
// rather than of the whole difference, so a settled slope sits at theta.
//
// Jacobi update: all amounts come from the heights at the start of the
// pass, then every cell gathers what its neighbours send, summed as
// (from west + from east) + (from south + from north), so that mirrored and
// transposed scenes give mirrored bits and no result depends on the order
// cells are stored or visited. Snow is conserved to round-off.
//
// Stability limit f <= 1/4 (kSnowMovedFractionMax), as for the ground's
// sigma: a pair's excess goes to (1 - 2f) e, a peak with four lower
// neighbours to (1 - 5f) e, a checkerboard to (1 - 8f) e, which diverges
// above f = 1/4. Above it snow_options' validate refuses; stabilisation_pass
// itself runs any f so that tests can see the divergence.
//
// Tolerance: a pair whose capped excess is below tolerance_m moves nothing,
// so a settled map has no pair steeper than tan(theta) + tolerance / h
// except where the higher cell holds less than tolerance_m of snow.
//
// Edge hold (a departure, off by default): a pair whose snow would fall off
// the map (onto a lower map or out of the scene) moves only the snow above
// the first edge_hold_m of the source cell, e_n = min(H_c - H_n - h tan(theta),
// s_c - edge_hold_m). A granular layer lying flat on a plate up to its edge
// has no slope to slide down: the DEM snowfall keeps about one grain layer
// on the table's edge cells (experiments/snow_calibration_*.yaml), where the
// paper's rule empties them, which its fit then makes up for with a steeper
// angle.
//
// Ceilings (a departure, snow_map.h: set_snow_ceilings): snow never rises
// above the underside of another group over a cell (a table top over the
// ground, a box standing on it). What a cell receives in a pass is scaled
// down to the room left under its ceiling at the start of the pass, and the
// senders keep the rest, so the limit costs no snow.

#include <vector>

#include "models/core/geometry/height_field.h"
#include "models/snow/snow_map.h"

namespace repose {

struct SnowModel;
struct SnowParams;
struct SnowState;

struct StabilisationRule {
  double tan_repose = 1.0;      // tan of the snow angle of repose (may be huge: 90 deg)
  double moved_fraction = 0.2;  // f
  double tolerance_m = 1e-6;
  double edge_hold_m = 0.0;     // snow kept at a map's edge against falling off it
};

struct PassResult {
  long long moving_cells = 0;  // cells that sent snow
  double moved_m3 = 0.0;
  double left_scene_m3 = 0.0;
};

// One Jacobi pass over every map. depth: per map, ny x nx.
PassResult stabilisation_pass(const std::vector<SnowMap>& maps, const StabilisationRule& rule,
                              std::vector<ArrayXXdR>* depth);

struct StabilisationResult {
  int passes = 0;
  bool settled = false;  // the last pass moved nothing
  double moved_m3 = 0.0;
  double left_scene_m3 = 0.0;
};

// Passes until settled or options.max_stabilisation_passes; snow that leaves
// the scene goes to state->ledger.
StabilisationResult stabilise(const SnowModel& model, const SnowParams& params, SnowState* state);

}  // namespace repose
