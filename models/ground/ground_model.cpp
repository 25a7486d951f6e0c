#include "models/ground/ground_model.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/ground/free_body_drive.h"
#include "models/ground/ground_section.h"

namespace repose {

namespace {

// Cell index range [first, last] whose centres lie in [lo, hi] along one axis.
void centre_range(double lo, double hi, double origin, double h, int n, int* first, int* last) {
  *first = std::max(0, static_cast<int>(std::ceil((lo - origin) / h - 0.5)));
  *last = std::min(n - 1, static_cast<int>(std::floor((hi - origin) / h - 0.5)));
}

}  // namespace

GroundModel make_plain_ground_model(const Grid& grid, const Material& material, const GroundModelSpec& options) {
  validate(options);
  GroundModel model;
  model.grid = grid;
  model.materials = {material};
  model.material_index.assign(grid.cell_count(), 0);
  model.options = options;
  return model;
}

bool keyframed_objects_only(const Scene& scene, std::string* why) {
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    if (!scene.objects[k].dynamic) continue;
    if (why != nullptr) {
      *why = fmt::format("objects[{}] ('{}'): a free body (dynamic:) moves only in the particle engines (liggghts, "
                         "bullet, ode) and the ground model (ground); this model moves objects along keyframes "
                         "(motion:)",
                         k, scene.objects[k].name);
    }
    return false;
  }
  return true;
}

GroundModel build_ground_model(const Scene& scene) {
  const GroundSpec& ground = scene.ground;
  // material_index is 8-bit: the ground's material and at most 254 regions
  REPOSE_DEMAND(ground.regions.size() <= 254 && "the ground model's section reader refuses more");
  const GroundModelSection& section = ground_model_section(scene);
  GroundModel model = make_plain_ground_model(ground.grid, section.material(ground.material), section.options);
  const Grid& g = model.grid;
  for (std::size_t r = 0; r < ground.regions.size(); ++r) {
    const MaterialRegion& region = ground.regions[r];
    model.materials.push_back(section.material(region.material));
    int i0, i1, j0, j1;
    centre_range(region.x_min_m, region.x_max_m, g.origin_x_m, g.cell_size_m, g.nx, &i0, &i1);
    centre_range(region.y_min_m, region.y_max_m, g.origin_y_m, g.cell_size_m, g.ny, &j0, &j1);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) model.material_index[static_cast<std::size_t>(model.cell(i, j))] = r + 1;
    }
  }
  model.free_bodies = section.free_bodies;
  validate(model.free_bodies);
  model.objects = scene.objects;
  for (const ObjectSpec& object : model.objects) model.swept_bodies.push_back(make_swept_body(object.body));
  model.time = scene.time;
  model.camera = scene.camera;
  check_free_bodies(model, scene.source_path);
  return model;
}

}  // namespace repose
