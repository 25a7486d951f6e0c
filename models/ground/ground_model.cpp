#include "models/ground/ground_model.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

namespace {

void validate_options(const GroundModelSpec& o) {
  if (o.substeps < 1) throw InputError(fmt::format("ground_model.substeps = {}: must be >= 1", o.substeps));
  if (o.coarse_factor < 1) {
    throw InputError(fmt::format("ground_model.coarse_factor = {}: must be >= 1", o.coarse_factor));
  }
  if (o.erosion_memory_steps < 0 || o.erosion_memory_steps > 65000) {
    throw InputError(
        fmt::format("ground_model.erosion_memory_steps = {}: must be in [0, 65000]", o.erosion_memory_steps));
  }
  if (!(o.max_substep_angle_rad > 0.0)) {
    throw InputError(fmt::format("ground_model.max_substep_angle_rad = {}: must be > 0", o.max_substep_angle_rad));
  }
}

// Cell index range [first, last] whose centres lie in [lo, hi] along one axis.
void centre_range(double lo, double hi, double origin, double h, int n, int* first, int* last) {
  *first = std::max(0, static_cast<int>(std::ceil((lo - origin) / h - 0.5)));
  *last = std::min(n - 1, static_cast<int>(std::floor((hi - origin) / h - 0.5)));
}

}  // namespace

GroundModel make_plain_ground_model(const Grid& grid, const Material& material, const GroundModelSpec& options) {
  validate_options(options);
  GroundModel model;
  model.grid = grid;
  model.materials = {material};
  model.material_index.assign(grid.cell_count(), 0);
  model.options = options;
  return model;
}

GroundModel build_ground_model(const Scene& scene) {
  const GroundSpec& ground = scene.ground;
  if (ground.regions.size() > 254) {
    throw InputError(fmt::format("{}: ground.regions: {} regions, at most 254 are supported", scene.source_path,
                                 ground.regions.size()));
  }
  GroundModel model = make_plain_ground_model(ground.grid, ground.material, scene.ground_model);
  const Grid& g = model.grid;
  for (std::size_t r = 0; r < ground.regions.size(); ++r) {
    const MaterialRegion& region = ground.regions[r];
    model.materials.push_back(region.material);
    int i0, i1, j0, j1;
    centre_range(region.x_min_m, region.x_max_m, g.origin_x_m, g.cell_size_m, g.nx, &i0, &i1);
    centre_range(region.y_min_m, region.y_max_m, g.origin_y_m, g.cell_size_m, g.ny, &j0, &j1);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) model.material_index[static_cast<std::size_t>(model.cell(i, j))] = r + 1;
    }
  }
  model.objects = scene.objects;
  for (const ObjectSpec& object : model.objects) model.swept_bodies.push_back(make_swept_body(object.body));
  model.time = scene.time;
  model.camera = scene.camera;
  return model;
}

}  // namespace repose
