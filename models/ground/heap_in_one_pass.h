#pragma once
// The heap on open ground laid at once (GroundModelSpec::heap_laying:
// one_pass), in place of the portions swept outwards ring by ring
// (excess_routing.h, 2). The material displaced onto uncovered cells
// (the sources) is pooled and laid as the surface
//     h(c) = max(ground(c), min(crest, L - phi(c))),
// phi(c): the least sum of repose steps (cell_size * tan(theta) of the
// giving cell's material) along a path from a source to c over the moves
// the portions' routing allows (outwards through the rings, within a ring
// away from the footprint's centre; while dragging, ahead first, then not
// backwards, then any way: the same tiers), phi = 0 at the sources. L is
// the one level at which the material fits (sum of what the cells take =
// what was displaced), found exactly from the sorted levels at which each
// cell starts and stops taking. So where material is laid, no cell stands
// more than a repose step above a cell it could have passed material to,
// and no cell above the crest; the ground already there never moves.
// Beyond the grid's edge the ground continues at the edge cell's height
// and takes any amount (it leaves: left_grid_m3), so L never rises above
// that level plus the step. The heap spreads over the rings until a ring
// that takes nothing (first 4 rings beyond the sources' farthest one, then
// as many more as the outer ring's depth over the repose step); material that fits nowhere (everything up to the crest)
// stays on its sources. No visiting order enters: mirrored scenes give
// mirrored heaps (to round-off of the level's sum).
// Departure from the portions: shares are not equal per neighbour; the
// heap is the one the angle of repose allows, not a sweep's outcome.

#include <cstdint>
#include <utility>
#include <vector>

#include "models/ground/excess_routing.h"

namespace repose {

class Rings;

// sources: (cell, material displaced onto it), already taken off the
// cells' heights; every cell is in a ring of `rings`. received gets what
// each cell takes.
void lay_heap_in_one_pass(const ExcessRouting& in, const std::vector<std::pair<std::int64_t, double>>& sources,
                          Rings* rings, Received* received, GroundState* state);

}  // namespace repose
