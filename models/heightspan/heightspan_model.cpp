#include "models/heightspan/heightspan_model.h"

#include <cmath>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/heightspan/holds_material.h"

namespace repose {

namespace {

HeldObject make_held(const GroundModel& ground, int object) {
  const ObjectSpec& o = ground.objects[static_cast<std::size_t>(object)];
  const double h = ground.grid.cell_size_m;
  const double radius_m = o.body.V.rowwise().norm().maxCoeff();
  const int half_cells = static_cast<int>(std::ceil(radius_m / h)) + 2;
  const Pose p0 = o.pose_at(0.0);
  HeldObject held;
  held.object = object;
  held.position0_xy = p0.position_m.head<2>();
  held.grid0 = ground.grid;
  held.grid0.nx = held.grid0.ny = 2 * half_cells;
  // aligned with the ground's cells at time 0
  held.grid0.origin_x_m = ground.grid.origin_x_m +
                          h * (std::floor((p0.position_m.x() - ground.grid.origin_x_m) / h) - half_cells + 1);
  held.grid0.origin_y_m = ground.grid.origin_y_m +
                          h * (std::floor((p0.position_m.y() - ground.grid.origin_y_m) / h) - half_cells + 1);
  return held;
}

}  // namespace

Grid HeightSpanModel::map_grid(const HeldObject& h, const Pose& pose) const {
  Grid g = h.grid0;
  g.origin_x_m += pose.position_m.x() - h.position0_xy.x();
  g.origin_y_m += pose.position_m.y() - h.position0_xy.y();
  return g;
}

HeightSpanModel build_heightspan_model(const Scene& scene) {
  // the height-span model moves objects along keyframes only (the ground model alone drives free bodies)
  if (std::string why; !keyframed_objects_only(scene, &why)) throw InputError(fmt::format("{}: {}", scene.source_path, why));
  HeightSpanModel model;
  model.ground = build_ground_model(scene);
  model.options = heightspan_section(scene).options;
  validate(model.options);
  model.seed = scene.seed;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const ObjectSpec& object = scene.objects[o];
    if (!holds_material(scene, object)) {
      model.ground_path.push_back(static_cast<int>(o));
      continue;
    }
    if (!is_closed_manifold(object.body)) {
      throw InputError(fmt::format("{}: object '{}' holds material (heightspan.holds_material) but its mesh is not "
                                   "closed, so its spans are undefined: close the mesh or set holds_material: false",
                                   scene.source_path, object.name));
    }
    model.held.push_back(make_held(model.ground, static_cast<int>(o)));
  }
  return model;
}

}  // namespace repose
