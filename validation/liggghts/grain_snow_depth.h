#pragma once
// Settled grains (the DEM snowfall reference) as the snow model's depth
// maps, so the two compare cell by cell: each grain is given to the snow map
// it lies on, the map with the highest surface under the grain's footprint
// (the cells its centre +- radius touches) that is not above the grain's
// centre (a grain under a table top lies on the ground, one on the top on
// the table, also where its centre overhangs the top's edge); each map's depth is the surface of
// its grains (surface_height.h: the same probe sphere as every particle
// reference) above the map's surface, 0 where the map has no surface or no
// grain reaches above it.

#include <vector>

#include "models/snow/snow_model.h"
#include "validation/particles/grain_set.h"
#include "validation/particles/surface_height.h"

namespace repose {

// The index of the map each grain lies on (-1: outside the grid, or below every map's surface).
std::vector<int> snow_map_of_grains(const GrainSet& grains, const std::vector<SnowMap>& maps);

// Depth (m) per map, ny x nx on the maps' grid, in maps' order.
std::vector<ArrayXXdR> grain_snow_depth(const GrainSet& grains, const std::vector<SnowMap>& maps,
                                        const SurfaceHeightOptions& surface);

}  // namespace repose
