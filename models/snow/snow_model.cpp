#include "models/snow/snow_model.h"

#include <cmath>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/initial_height.h"
#include "models/snow/ground_surface_mesh.h"

namespace repose {

SnowModel build_snow_model(const std::vector<SnowGroupGeometry>& groups, const Grid& grid, const SnowOptions& options,
                           const TimeSpec& time, std::uint64_t seed) {
  validate(options);
  REPOSE_DEMAND(groups.size() == options.groups.size());
  if (grid.nx < 1 || grid.ny < 1 || !(grid.cell_size_m > 0.0)) {
    throw InputError(fmt::format("snow: the snow grid {} x {} of {} m cells is empty", grid.nx, grid.ny,
                                 grid.cell_size_m));
  }
  SnowModel model;
  model.options = options;
  model.time = time;
  model.seed = seed;
  model.grid = grid;
  TopDownRenderer renderer(options.renderer);
  std::vector<std::vector<TriangleMesh>> group_meshes;
  for (const SnowGroupGeometry& g : groups) {
    if (g.ground != nullptr) {
      model.ground_map = static_cast<int>(model.maps.size());
      model.maps.push_back(make_ground_snow_map(g.name, *g.ground, grid));
      group_meshes.push_back({ground_surface_mesh(*g.ground)});
    } else {
      model.maps.push_back(make_object_snow_map(g.name, g.meshes, grid, &renderer));
      group_meshes.push_back(g.meshes);
    }
    for (const TriangleMesh& m : group_meshes.back()) {
      model.occluders.push_back(m);
      model.occluder_map.push_back(static_cast<int>(model.maps.size()) - 1);
    }
  }
  set_snow_ceilings(group_meshes, &model.maps);
  return model;
}

namespace {

Grid snow_grid(const Grid& ground, double cell_size_m) {
  if (cell_size_m == 0.0) return ground;
  Grid g = ground;
  g.cell_size_m = cell_size_m;
  g.nx = std::max(1, static_cast<int>(std::lround(ground.extent_x_m() / cell_size_m)));
  g.ny = std::max(1, static_cast<int>(std::lround(ground.extent_y_m() / cell_size_m)));
  return g;
}

}  // namespace

SnowModel build_snow_model(const Scene& scene, const SnowOptions& options) {
  validate(options);
  validate_picture_times(options.pictures, scene.time.duration_s);
  const HeightField ground = make_initial_height(scene);
  std::vector<SnowGroupGeometry> groups;
  for (const SnowGroupSpec& spec : options.groups) {
    SnowGroupGeometry g;
    g.name = spec.name;
    if (spec.ground) g.ground = &ground;
    for (const std::string& object_name : spec.objects) {
      const ObjectSpec* found = nullptr;
      for (const ObjectSpec& o : scene.objects) {
        if (o.name == object_name) found = &o;
      }
      if (found == nullptr) {
        throw InputError(fmt::format("snow: group '{}' names object '{}', which the scene does not have", spec.name,
                                     object_name));
      }
      g.meshes.push_back(transformed(found->body, found->pose_at(0.0)));
    }
    groups.push_back(std::move(g));
  }
  return build_snow_model(groups, snow_grid(scene.ground.grid, options.cell_size_m), options, scene.time, scene.seed);
}

}  // namespace repose
