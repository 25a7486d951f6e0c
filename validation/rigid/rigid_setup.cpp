#include "validation/rigid/rigid_setup.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "validation/liggghts/liggghts_script.h"
#include "validation/rigid/rigid_simulation.h"

namespace repose {

namespace {

// uniform in [0, 1) from the top 53 bits: the same on every standard library
double unit_draw(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

double largest_radius_m(const DemSpec& dem) { return dem.grain_radius_m * (1.0 + dem.radius_spread); }

RigidContactLaw contact_law(const DemSpec& dem) {
  return {dem.friction, dem.restitution, dem.rolling_friction};
}

// The highest point an object reaches: its body's farthest vertex from the
// body origin above each keyframe's position (any orientation in between).
double object_top_m(const ObjectSpec& object) {
  double reach = 0.0;
  for (Eigen::Index v = 0; v < object.body.V.rows(); ++v) reach = std::max(reach, object.body.V.row(v).norm());
  double top = 0.0;
  for (const Keyframe& k : object.keyframes) top = std::max(top, k.pose.position_m.z() + reach);
  return top;
}

// Floor (top face z = 0) and four side walls on the grid's edges, up to z_top.
std::vector<StaticBox> ground_box(const DemSpec& dem, const Grid& grid, double z_top_m) {
  const double t = std::max(10.0 * largest_radius_m(dem), 0.01);  // wall thickness
  const double x0 = grid.origin_x_m, x1 = x0 + grid.extent_x_m();
  const double y0 = grid.origin_y_m, y1 = y0 + grid.extent_y_m();
  const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  const double hx = 0.5 * grid.extent_x_m() + t, hy = 0.5 * grid.extent_y_m() + t, hz = 0.5 * z_top_m;
  const double floor_mu_r = dem.floor == DemSpec::Floor::kRough ? dem.floor_rolling_friction : dem.rolling_friction;
  const double mu_r = dem.rolling_friction;
  return {
      {{cx, cy, -0.5 * t}, {hx, hy, 0.5 * t}, floor_mu_r},
      {{x0 - 0.5 * t, cy, hz}, {0.5 * t, hy, hz}, mu_r},
      {{x1 + 0.5 * t, cy, hz}, {0.5 * t, hy, hz}, mu_r},
      {{cx, y0 - 0.5 * t, hz}, {hx, 0.5 * t, hz}, mu_r},
      {{cx, y1 + 0.5 * t, hz}, {hx, 0.5 * t, hz}, mu_r},
  };
}

RigidWorldSpec world_of(const RigidInputs& in, GrainSet grains, double z_top_m) {
  RigidWorldSpec w;
  w.grains = std::move(grains);
  w.density_kg_m3 = in.dem.density_kg_m3;
  w.gravity_m_s2 = in.dem.gravity_m_s2;
  w.law = contact_law(in.dem);
  w.walls = ground_box(in.dem, in.grid, z_top_m);
  w.bounds = {in.grid.origin_x_m, in.grid.origin_x_m + in.grid.extent_x_m(), in.grid.origin_y_m,
              in.grid.origin_y_m + in.grid.extent_y_m(), z_top_m};
  return w;
}

double grains_top_m(const GrainSet& grains) {
  double top = 0.0;
  for (Eigen::Index g = 0; g < grains.size(); ++g) top = std::max(top, grains.position_m(g, 2) + grains.radius_m(g));
  return top;
}

// One layer of lattice points (x, y), row by row: over the grid, or inside
// a column's gate, every grain clear of the walls by its jitter.
std::vector<Eigen::Vector2d> lattice_layer(const RigidInputs& in, double r_max, double spacing) {
  double x0 = in.grid.origin_x_m, x1 = x0 + in.grid.extent_x_m();
  const double y0 = in.grid.origin_y_m, y1 = y0 + in.grid.extent_y_m();
  if (in.column && in.column->shape == DemSpec::ColumnShape::kSlot) x1 = in.column->gate_x_m;
  const bool cylinder = in.column && in.column->shape == DemSpec::ColumnShape::kCylinder;
  const int nx = static_cast<int>(std::floor((x1 - x0 - 2.0 * r_max) / spacing)) + 1;
  const int ny = static_cast<int>(std::floor((y1 - y0 - 2.0 * r_max) / spacing)) + 1;
  std::vector<Eigen::Vector2d> layer;
  if (x1 - x0 < 2.0 * r_max || y1 - y0 < 2.0 * r_max) return layer;
  const double x_first = x0 + 0.5 * (x1 - x0 - (nx - 1) * spacing);
  const double y_first = y0 + 0.5 * (y1 - y0 - (ny - 1) * spacing);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const Eigen::Vector2d p(x_first + i * spacing, y_first + j * spacing);
      // the gate ring's flat faces lie inside the circle by R (1 - cos(pi/32)); keep a spacing clear
      if (cylinder && (p - in.column->axis_xy_m).norm() > in.column->width_m - spacing) continue;
      layer.push_back(p);
    }
  }
  return layer;
}

// The gate a column settles behind: a wall at x = gate_x_m across the slot,
// or a ring of boxes whose inner faces are tangent to the cylinder.
std::vector<StaticBox> column_gate(const ColumnGeometry& c, const DemSpec& dem, const Grid& grid, double z_top_m) {
  const double t = std::max(10.0 * largest_radius_m(dem), 0.01);
  const double hz = 0.5 * z_top_m;
  if (c.shape == DemSpec::ColumnShape::kSlot) {
    return {{{c.gate_x_m + 0.5 * t, grid.origin_y_m + 0.5 * grid.extent_y_m(), hz},
             {0.5 * t, 0.5 * grid.extent_y_m() + t, hz}, dem.rolling_friction, 0.0}};
  }
  constexpr int kSides = 32;
  const double half_chord = c.width_m * std::tan(std::numbers::pi / kSides) + 0.5 * t;  // overlapping corners
  std::vector<StaticBox> ring;
  for (int k = 0; k < kSides; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kSides;
    const Eigen::Vector2d centre = c.axis_xy_m + (c.width_m + 0.5 * t) * Eigen::Vector2d(std::cos(a), std::sin(a));
    ring.push_back({{centre.x(), centre.y(), hz}, {0.5 * t, half_chord, hz}, dem.rolling_friction, a});
  }
  return ring;
}

}  // namespace

RigidInputs rigid_inputs(const Scene& scene, const std::string& solver) {
  const DemSpec& dem = require_dem(scene, solver);
  if (dem.sides == DemSpec::Sides::kPeriodic) {
    throw InputError(fmt::format("{}: dem: sides: periodic side walls are LIGGGHTS only; {} needs sides: walls",
                                 scene.source_path, solver));
  }
  if (dem.initial == DemSpec::Initial::kColumn && dem.column_shape == DemSpec::ColumnShape::kQuarterCylinder) {
    throw InputError(fmt::format("{}: dem: column_shape: a quarter cylinder needs frictionless symmetry walls, which "
                                 "only LIGGGHTS has here; {} needs column_shape: cylinder or slot",
                                 scene.source_path, solver));
  }
  if (dem.initial == DemSpec::Initial::kSnowfall) {
    throw InputError(fmt::format("{}: dem: initial: snowfall is LIGGGHTS only; {} needs bed or column", scene.source_path, solver));
  }
  RigidInputs in{dem, scene.ground.grid, scene.objects, scene.time, scene.seed, std::nullopt, std::nullopt};
  if (dem.initial == DemSpec::Initial::kColumn) in.column = column_geometry(dem, scene);
  if (measures_impact(dem)) in.chute = chute_geometry(dem, scene);
  return in;
}

long rigid_grain_count(const RigidInputs& in, const RigidOptions& options) {
  const double footprint = in.column ? in.column->footprint_m2 : in.grid.extent_x_m() * in.grid.extent_y_m();
  const double volume = footprint * settled_height_m(in.dem) * options.packing_fraction;
  return std::lround(volume / mean_grain_volume_m3(in.dem));
}

GrainSet grain_lattice(const RigidInputs& in, const RigidOptions& options) {
  const double r_max = largest_radius_m(in.dem);
  const double spacing = 2.0 * r_max * (1.0 + options.lattice_gap_fraction);
  const double jitter = 0.9 * options.lattice_gap_fraction * r_max;  // below half the gap: no overlaps
  const std::vector<Eigen::Vector2d> layer = lattice_layer(in, r_max, spacing);
  if (layer.empty()) {
    throw InputError(fmt::format("ground: the grains' region ({} x {} m) is narrower than one grain ({} m across)",
                                 in.grid.extent_x_m(), in.grid.extent_y_m(), 2.0 * r_max));
  }
  const std::vector<double> radii = grain_radii_m(in.dem);
  const long count = rigid_grain_count(in, options);
  const long per_layer = static_cast<long>(layer.size());
  std::mt19937_64 rng(in.seed);
  GrainSet grains;
  grains.position_m.resize(count, 3);
  grains.radius_m.resize(count);
  for (long g = 0; g < count; ++g) {
    const Eigen::Vector2d& xy = layer[static_cast<std::size_t>(g % per_layer)];
    const Eigen::Vector3d lattice(xy.x(), xy.y(), r_max + jitter + static_cast<double>(g / per_layer) * spacing);
    grains.radius_m(g) = radii[rng() % radii.size()];
    for (int a = 0; a < 3; ++a) grains.position_m(g, a) = lattice[a] + jitter * (2.0 * unit_draw(rng) - 1.0);
  }
  return grains;
}

RigidWorldSpec settling_world(const RigidInputs& in, const RigidOptions& options) {
  GrainSet grains = grain_lattice(in, options);
  const double top = grains_top_m(grains) + 4.0 * largest_radius_m(in.dem);
  RigidWorldSpec w = world_of(in, std::move(grains), top);
  if (in.column) {
    const std::vector<StaticBox> gate = column_gate(*in.column, in.dem, in.grid, top);
    w.walls.insert(w.walls.end(), gate.begin(), gate.end());
  }
  return w;
}

RigidWorldSpec run_world(const RigidInputs& in, const GrainSet& settled) {
  double top = grains_top_m(settled);
  for (const ObjectSpec& o : in.objects) top = std::max(top, object_top_m(o));
  top = std::max(top, chute_splash_top_m(in.dem, in.grid));  // side walls high enough that no splash leaves the chute
  RigidWorldSpec w = world_of(in, settled, top + 4.0 * largest_radius_m(in.dem));
  w.objects = kinematic_objects(in.objects);
  w.bodies = free_body_objects(in.objects);
  w.gravity_direction = gravity_direction(in.dem);
  return w;
}

}  // namespace repose
