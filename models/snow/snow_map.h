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

  const Grid& grid() const { return base.grid; }
  bool covered(int i, int j) const { return base.is_covered(i, j); }
  double base_z(int i, int j) const { return base.z(i, j); }
};

// A group's map from its meshes (world coordinates).
SnowMap make_object_snow_map(const std::string& name, const std::vector<TriangleMesh>& meshes, const Grid& grid,
                             TopDownRenderer* renderer);

// The ground's map: its heights at the grid's cell centres (bilinear when
// the grids differ), every cell covered.
SnowMap make_ground_snow_map(const std::string& name, const HeightField& ground, const Grid& grid);

}  // namespace repose
