#pragma once
// A small DEM scene built in code for the validation tests: a 4 cm x 4 cm
// grid of 4 mm cells, a 12 mm bed of ~340 grains of radius 2 mm, and
// optionally a sphere of radius 8 mm pressed 6 mm into the bed and lifted out.

#include "models/core/config/scene.h"
#include "validation/particles/dem_section.h"
#include "models/core/geometry/triangle_mesh.h"

namespace repose::testing {

inline Scene small_dem_scene(bool with_indenter) {
  Scene s;
  s.name = "small_dem";
  s.source_path = "small_dem.yaml";
  s.seed = 7;
  s.ground.grid = Grid{10, 10, 0.004, 0.0, 0.0};
  s.time.duration_s = 0.2;
  DemSpec dem;
  dem.grain_radius_m = 0.002;
  dem.radius_spread = 0.1;
  dem.bed_depth_m = 0.012;
  dem.time_step_s = 1.0e-5;
  dem.dump_interval_s = 0.05;
  s = with_dem(std::move(s), dem);
  if (with_indenter) {
    ObjectSpec ball;
    ball.name = "ball";
    ball.shape = ObjectSpec::Shape::kSphere;
    ball.radius_m = 0.008;
    ball.body = make_sphere(0.008, 16);
    const Eigen::Vector3d top(0.02, 0.02, 0.023), bottom(0.02, 0.02, 0.014);
    ball.keyframes = {{0.0, Pose{top, Eigen::Quaterniond::Identity()}},
                      {0.1, Pose{bottom, Eigen::Quaterniond::Identity()}},
                      {0.2, Pose{top, Eigen::Quaterniond::Identity()}}};
    s.objects.push_back(ball);
  }
  return s;
}

}  // namespace repose::testing

namespace repose::testing {

// A column of grains (dem.initial: column) for the column tests: a slot
// 12 mm wide (the grid's y extent) with a column 16 mm long against x = 0, or
// a cylinder of radius 12 mm on the centre of a 12 cm x 12 cm floor; grains
// of radius 2 mm, height `height_m`, on a rough floor.
inline Scene column_dem_scene(DemSpec::ColumnShape shape, double height_m) {
  Scene s;
  s.name = "column_dem";
  s.source_path = "column_dem.yaml";
  s.seed = 9;
  const bool slot = shape == DemSpec::ColumnShape::kSlot;
  s.ground.grid = slot ? Grid{40, 3, 0.004, 0.0, 0.0} : Grid{30, 30, 0.004, 0.0, 0.0};
  s.time.duration_s = 0.3;
  DemSpec dem;
  dem.grain_radius_m = 0.002;
  dem.radius_spread = 0.1;
  dem.time_step_s = 2.0e-5;
  dem.dump_interval_s = 0.05;
  dem.initial = DemSpec::Initial::kColumn;
  dem.column_shape = shape;
  dem.column_width_m = slot ? 0.016 : 0.012;
  dem.column_height_m = height_m;
  dem.floor = DemSpec::Floor::kRough;
  s = with_dem(std::move(s), dem);
  return s;
}

}  // namespace repose::testing
