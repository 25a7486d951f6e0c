#include "models/snow/snow_map.h"

namespace repose {

SnowMap make_object_snow_map(const std::string& name, const std::vector<TriangleMesh>& meshes, const Grid& grid,
                             TopDownRenderer* renderer) {
  SnowMap map{name, renderer->render(meshes, grid)};
  // uncovered cells hold NaN in the CPU image and the far plane in the GL one: make them alike
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      if (!map.covered(i, j)) map.base.z_m(j, i) = 0.0;
    }
  }
  return map;
}

SnowMap make_ground_snow_map(const std::string& name, const HeightField& ground, const Grid& grid) {
  SnowMap map;
  map.name = name;
  map.base.grid = grid;
  map.base.view = ViewFrom::kAbove;
  map.base.z_m.resize(grid.ny, grid.nx);
  map.base.covered.setOnes(grid.ny, grid.nx);
  const bool same_grid = ground.grid() == grid;
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      map.base.z_m(j, i) = same_grid ? ground.at(i, j) : ground.sample(grid.centre_x(i), grid.centre_y(j));
    }
  }
  return map;
}

}  // namespace repose
