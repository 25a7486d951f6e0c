#pragma once
// Where displaced material goes once it has left the contact cells (the
// ground paper, 3.4, last paragraph): cells whose height exceeds the
// object's underside pass the excess to cells outside the contact region
// "so that every cell stays below the object's underside".
//
// 1. Under an object (finite ceiling): the excess moves towards the nearest
//    cell that no object covers, level by level (level: 4-neighbour distance
//    to such a cell through cells not in contact), farthest level first, in
//    equal shares to the neighbours one level nearer; when dragging, not
//    backwards unless that is the only way out.
// 2. On open ground (no object above). Departure from the paper, which lets
//    the first uncovered cell take everything: that stacks the material of
//    a whole furrow into single cells at the footprint's edge (columns of
//    25 cm beside a 5 cm sphere, issue 16). Here displaced material heaps as
//    material can: a cell takes it only up to
//        cap = min(crest, lowest outward neighbour + cell_size * tan(theta)),
//    crest = max(the objects' highest point, the highest ground around the
//    contact before it), and passes the rest outward (rings of 4-neighbour
//    distance from the objects, through uncovered cells), in equal shares,
//    not backwards while dragging unless that is the only way. While
//    dragging, a cell sheds forwards first (to its onward neighbours ahead
//    along the motion) and sideways only when none lies ahead: a blade or a
//    sphere drives its heap ahead of it, where the advancing object meets
//    it again, as the DEM references do (ref_bulldoze: a crescent ahead,
//    levees of a millimetre or two beside the trench). Shedding sideways as
//    readily as forwards left most of a bulldozed heap beside the trench,
//    at half the reference's height (cross-validated R² of the bulldozing
//    blade 0.63, of the sideways cylinder 0.67; now 0.81 and 0.82, the
//    sphere drag's unchanged at 0.82: experiments/calibration_default.yaml).
//    So the heap
//    beside an object is never steeper outwards than the angle of repose
//    when it is laid down, and never higher than what pushed it or the
//    ground it leans on (theta = 90 deg: a wall up to the crest). A cell
//    passes on at most what this displacement gave it: the ground already
//    there is erosion's business.
//    Each ring is a Jacobi update (caps from the heights before the ring
//    moves), so the result does not depend on visiting order.
//
// Boundary: open. Beyond the grid's edge the ground is taken to continue at
// the edge cell's height; material passed there leaves (left_grid_m3).
// Material with nowhere to go (excess under an object only reachable
// backwards while dragging, or open ground hemmed in by objects whose
// footprints do not touch) stays where it is.

#include <array>
#include <cstdint>
#include <vector>

#include "models/ground/contact_region.h"

namespace repose {

struct GroundModel;
struct GroundParams;
struct GroundState;

struct ExcessRouting {
  const GroundModel& model;
  const GroundParams& params;
  const Ceiling& ceiling;
  const DragDirection& dir;
  const ContactRegion& region;
  double crest_m;  // highest a heap on open ground may stand

  // Set by route_excess. A pocket: an uncovered cell of the footprint that
  // only covered cells join to open ground (a gap between two objects).
  // It fills up to the crest; beyond, its excess leaves as from under an
  // object (through the contact cells if need be), or it would grow into a
  // column as high as the whole region's material (issue 16).
  Footprint window{};  // the footprint and one ring around it
  std::vector<char> pocket{};
  std::vector<double> repose_step_m{};  // per material: cell_size * tan(theta)
  // Whether a cell on open ground may shed towards kNeighbours[m] in tier t
  // (0: ahead along a drag; 1: not backwards; 2: any way), found once.
  std::array<std::array<bool, 4>, 3> tier_allows{};
  // The same as lists: tier t allows kNeighbours[tier_dirs[t][0 .. tier_dir_count[t])].
  std::array<std::array<int, 4>, 3> tier_dirs{};
  std::array<int, 3> tier_dir_count{};
  // How high the cell may stand before its material must move on: the
  // ceiling under an object (the base where that is lower), the crest in a
  // pocket, +inf on open ground.
  double limit_at(int i, int j) const;
  bool on_open_ground(int i, int j) const { return std::isinf(limit_at(i, j)); }
};

// Moves excess as above. received: what this displacement has put on each
// free cell (updated; every cell that changes has an entry).
void route_excess(ExcessRouting in, Received* received, GroundState* state);

}  // namespace repose
