#include "validation/particles/column_geometry.h"

#include <algorithm>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "validation/particles/dem_section.h"

namespace repose {

std::string column_shape_name(DemSpec::ColumnShape shape) {
  switch (shape) {
    case DemSpec::ColumnShape::kSlot: return "slot";
    case DemSpec::ColumnShape::kCylinder: return "cylinder";
    case DemSpec::ColumnShape::kQuarterCylinder: return "quarter_cylinder";
  }
  REPOSE_DEMAND(false);
  return {};
}

double settled_height_m(const DemSpec& dem) {
  return dem.initial == DemSpec::Initial::kColumn ? dem.column_height_m : dem.bed_depth_m;
}

ColumnGeometry column_geometry(const Scene& scene) { return column_geometry(require_dem(scene, "a particle reference"), scene); }

ColumnGeometry column_geometry(const DemSpec& dem, const Scene& scene) {
  REPOSE_DEMAND(dem.initial == DemSpec::Initial::kColumn);
  const Grid& g = scene.ground.grid;
  ColumnGeometry c;
  c.shape = dem.column_shape;
  c.width_m = dem.column_width_m;
  c.height_m = dem.column_height_m;
  c.axis_xy_m = Eigen::Vector2d(g.origin_x_m + 0.5 * g.extent_x_m(), g.origin_y_m + 0.5 * g.extent_y_m());
  c.back_wall_x_m = g.origin_x_m;
  c.gate_x_m = g.origin_x_m + dem.column_width_m;
  c.gap_m = g.extent_y_m();
  const double diameter = 2.0 * dem.grain_radius_m * (1.0 + dem.radius_spread);
  if (c.shape == DemSpec::ColumnShape::kSlot) {
    c.footprint_m2 = c.width_m * c.gap_m;
    if (c.width_m >= g.extent_x_m()) {
      throw InputError(fmt::format("{}: dem: column_width_m: the slot column ({} m) must be shorter than the grid's x "
                                   "extent ({} m), which is where it collapses to",
                                   scene.source_path, c.width_m, g.extent_x_m()));
    }
  } else if (c.shape == DemSpec::ColumnShape::kCylinder) {
    c.footprint_m2 = std::numbers::pi * c.width_m * c.width_m;
    if (2.0 * c.width_m >= std::min(g.extent_x_m(), g.extent_y_m())) {
      throw InputError(fmt::format("{}: dem: column_width_m: the cylinder's radius ({} m) must be less than half the "
                                   "grid's smaller extent ({} m)",
                                   scene.source_path, c.width_m, std::min(g.extent_x_m(), g.extent_y_m())));
    }
  } else {
    c.axis_xy_m = Eigen::Vector2d(g.origin_x_m, g.origin_y_m);
    c.footprint_m2 = 0.25 * std::numbers::pi * c.width_m * c.width_m;
    c.azimuth_begin_rad = 0.0;
    c.azimuth_span_rad = 0.5 * std::numbers::pi;
    if (c.width_m >= std::min(g.extent_x_m(), g.extent_y_m())) {
      throw InputError(fmt::format("{}: dem: column_width_m: the quarter cylinder's radius ({} m) must be less than "
                                   "the grid's smaller extent ({} m), which is where it collapses to",
                                   scene.source_path, c.width_m, std::min(g.extent_x_m(), g.extent_y_m())));
    }
  }
  if (std::min(c.width_m, c.shape == DemSpec::ColumnShape::kSlot ? c.gap_m : c.width_m) < 2.0 * diameter) {
    throw InputError(fmt::format("{}: dem: the column ({} m wide, slot gap {} m) must be at least two grain diameters "
                                 "({} m) across",
                                 scene.source_path, c.width_m, c.gap_m, 2.0 * diameter));
  }
  return c;
}

}  // namespace repose
