#pragma once
// Where a granular column stands before its gate is removed (dem.initial:
// column), in the scene's coordinates: shared by every particle reference.

#include <numbers>
#include <string>

#include <Eigen/Core>

#include "models/core/config/scene.h"
#include "validation/particles/dem_section.h"

namespace repose {

struct ColumnGeometry {
  DemSpec::ColumnShape shape = DemSpec::ColumnShape::kCylinder;
  Eigen::Vector2d axis_xy_m = Eigen::Vector2d::Zero();  // cylinder: its axis (the grid's centre; a quarter's corner)
  // cylinder: the azimuths the grains spread over, from the +x axis: all of
  // them for a cylinder, [0, pi/2] for a quarter between its symmetry walls
  double azimuth_begin_rad = -std::numbers::pi;
  double azimuth_span_rad = 2.0 * std::numbers::pi;
  double back_wall_x_m = 0.0;  // slot: the wall the column leans on (the grid's x_min edge)
  double gate_x_m = 0.0;       // slot: the gate plane, back_wall_x_m + width_m
  double gap_m = 0.0;          // slot: the distance between the side walls (the grid's y extent)
  double width_m = 0.0;        // slot: L0 along x; cylinder: radius R0
  double height_m = 0.0;       // H0, the intended settled height
  double footprint_m2 = 0.0;   // slot: L0 * gap; cylinder: pi R0^2; quarter: pi R0^2 / 4
};

// The shape's name in scene files: slot, cylinder, quarter_cylinder.
std::string column_shape_name(DemSpec::ColumnShape shape);

// A cylinder or its quarter: a radial collapse, measured from the axis.
inline bool is_axisymmetric(DemSpec::ColumnShape shape) { return shape != DemSpec::ColumnShape::kSlot; }

// Requires scene.dem with initial == column; throws InputError when the
// column does not fit the grid (a slot longer than the grid, a cylinder
// wider than half of it, a quarter wider than it).
ColumnGeometry column_geometry(const Scene& scene);
ColumnGeometry column_geometry(const DemSpec& dem, const Scene& scene);

// Height of the settled grains: bed_depth_m for a bed, column_height_m for a column.
double settled_height_m(const DemSpec& dem);

}  // namespace repose
