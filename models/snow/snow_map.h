#pragma once
// Snow maps (the snow paper 2.1, Fig. 2): one per group of objects, the
// group's orthographic top-down Z-buffer on the snow grid. Covered cells are
// where snow can lie (the snow-possible area) and their z is the surface it
// lies on; snow depth is accumulated on top of it (SnowState).
//
// The ground group's map is the ground height field itself, sampled at the
// snow grid's cell centres (every cell covered); an object group's map is
// rendered from its meshes (TopDownRenderer, CPU or OSMesa).
//
// Departure: the paper gives each map its own resolution; here all maps
// share one grid, so snow falling from one map to another lands in the same
// cell index (stabilisation.h) with no resampling.

#include <string>
#include <vector>

#include "models/core/geometry/depth_image.h"
#include "models/core/geometry/height_field.h"
#include "models/core/geometry/triangle_mesh.h"
#include "models/snow/top_down_renderer.h"

namespace repose {

struct SnowMap {
  std::string name;
  DepthImage base;  // ViewFrom::kAbove; z only meaningful where covered
  // ny x nx: the lowest underside of another group over the cell, +inf
  // where none (snow_ceilings: snow on this map never rises above it).
  ArrayXXdR ceiling_z_m;

  const Grid& grid() const { return base.grid; }
  bool covered(int i, int j) const { return base.is_covered(i, j); }
  double base_z(int i, int j) const { return base.z(i, j); }
  double ceiling_z(int i, int j) const { return ceiling_z_m(j, i); }
};

// A group's map from its meshes (world coordinates).
SnowMap make_object_snow_map(const std::string& name, const std::vector<TriangleMesh>& meshes, const Grid& grid,
                             TopDownRenderer* renderer);

// The ground's map: its heights at the grid's cell centres (bilinear when
// the grids differ), every cell covered.
SnowMap make_ground_snow_map(const std::string& name, const HeightField& ground, const Grid& grid);

// Ceilings (a departure: the paper's maps have none, so its snow could pile
// up inside an object standing on a lower map). For each map and each other
// group seen over a cell: when that group reaches above the map's surface
// there (its highest z > base z), it bounds the snow at its lowest z, or at
// the surface itself when it reaches below it (a box standing on the
// ground, a leg: no room). A group lying wholly below (the ground under a
// table top) bounds nothing. The ceiling is the lowest bound. Limitation: a
// group with parts both below and above a map (a cabinet round a shelf of
// another group) leaves that map no room.
// group_meshes: every group's geometry, indexed like maps.
void set_snow_ceilings(const std::vector<std::vector<TriangleMesh>>& group_meshes, std::vector<SnowMap>* maps);

}  // namespace repose
