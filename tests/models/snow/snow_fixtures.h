#pragma once
// Small snow scenes for the tests: a flat ground of n x n cells of 1 cm
// centred on the origin, and horizontal plates (thin boxes) above it.

#include <vector>

#include "models/core/geometry/height_field.h"
#include "models/core/geometry/triangle_mesh.h"
#include "models/snow/snow_model.h"

namespace repose::testing {

inline Grid centred_grid(int n, double cell_m = 0.01) { return Grid{n, n, cell_m, -0.5 * n * cell_m, -0.5 * n * cell_m}; }

// A plate of half size (hx, hy), 1 cm thick, whose top is at z_top, centred at (cx, cy).
inline TriangleMesh plate(double hx, double hy, double z_top, double cx = 0.0, double cy = 0.0) {
  Pose pose;
  pose.position_m = Eigen::Vector3d(cx, cy, z_top - 0.005);
  return transformed(make_box(Eigen::Vector3d(hx, hy, 0.005)), pose);
}

inline SnowOptions vertical_snow_options(int direction_count = 1) {
  SnowOptions o;
  o.direction_count = direction_count;
  return o;
}

// Ground (group "ground", flat at 0) plus one group per plate, in that order.
inline SnowModel plates_over_ground(const HeightField& ground, const std::vector<TriangleMesh>& plates,
                                    SnowOptions options, std::uint64_t seed = 1, bool with_ground = true) {
  std::vector<SnowGroupGeometry> groups;
  options.groups.clear();
  if (with_ground) {
    groups.push_back({"ground", &ground, {}});
    options.groups.push_back({"ground", true, {}});
  }
  for (std::size_t k = 0; k < plates.size(); ++k) {
    const std::string name = "plate" + std::to_string(k);
    groups.push_back({name, nullptr, {plates[k]}});
    options.groups.push_back({name, false, {name}});
  }
  TimeSpec time;
  time.step_s = 1.0;
  time.duration_s = 1.0;
  return build_snow_model(groups, ground.grid(), options, time, seed);
}

}  // namespace repose::testing
