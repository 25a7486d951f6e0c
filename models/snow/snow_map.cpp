#include "models/snow/snow_map.h"

#include <algorithm>
#include <limits>

#include "models/core/base/error.h"

namespace repose {

SnowMap make_object_snow_map(const std::string& name, const std::vector<TriangleMesh>& meshes, const Grid& grid,
                             TopDownRenderer* renderer) {
  SnowMap map{name, renderer->render(meshes, grid), {}};
  // uncovered cells hold NaN in the CPU image and the far plane in the GL one: make them alike
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      if (!map.covered(i, j)) map.base.z_m(j, i) = 0.0;
    }
  }
  map.ceiling_z_m = ArrayXXdR::Constant(grid.ny, grid.nx, std::numeric_limits<double>::infinity());
  return map;
}

SnowMap make_ground_snow_map(const std::string& name, const HeightField& ground, const Grid& grid) {
  SnowMap map;
  map.name = name;
  map.base.grid = grid;
  map.base.view = ViewFrom::kAbove;
  map.base.z_m.resize(grid.ny, grid.nx);
  map.base.covered.setOnes(grid.ny, grid.nx);
  map.ceiling_z_m = ArrayXXdR::Constant(grid.ny, grid.nx, std::numeric_limits<double>::infinity());
  const bool same_grid = ground.grid() == grid;
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      map.base.z_m(j, i) = same_grid ? ground.at(i, j) : ground.sample(grid.centre_x(i), grid.centre_y(j));
    }
  }
  return map;
}

void set_snow_ceilings(const std::vector<std::vector<TriangleMesh>>& group_meshes, std::vector<SnowMap>* maps) {
  REPOSE_DEMAND(group_meshes.size() == maps->size());
  for (std::size_t g = 0; g < group_meshes.size(); ++g) {
    if (maps->empty()) return;
    const Grid& grid = maps->front().grid();
    const DepthImage lowest = depth_image_cpu(group_meshes[g], grid, ViewFrom::kBelow);
    const DepthImage highest = depth_image_cpu(group_meshes[g], grid, ViewFrom::kAbove);
    for (std::size_t m = 0; m < maps->size(); ++m) {
      if (m == g) continue;
      SnowMap& map = (*maps)[m];
      for (int j = 0; j < grid.ny; ++j) {
        for (int i = 0; i < grid.nx; ++i) {
          if (!map.covered(i, j) || !highest.is_covered(i, j) || !(highest.z(i, j) > map.base_z(i, j))) continue;
          const double bound = std::max(lowest.z(i, j), map.base_z(i, j));
          map.ceiling_z_m(j, i) = std::min(map.ceiling_z_m(j, i), bound);
        }
      }
    }
  }
}

}  // namespace repose
