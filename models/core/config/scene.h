#pragma once
// The scene: an immutable description of what is there, in SI units, loaded
// from YAML and validated once (scene_loader.h). Nothing here changes during
// a simulation; each model keeps its own state.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/core/geometry/grid.h"
#include "models/core/config/material.h"
#include "models/core/geometry/triangle_mesh.h"

namespace repose {

// How the ground's initial heights are made.
struct InitialHeight {
  enum class Kind { kFlat, kNoise, kFile };
  Kind kind = Kind::kFlat;
  double height_m = 0.0;        // flat: the height; noise: the mean; file: an offset added
  double amplitude_m = 0.0;     // noise: peak deviation from the mean
  double correlation_m = 0.0;   // noise: smoothing length (0: white noise per cell)
  std::string path;             // file: .npy (metres) or 16-bit .png, absolute
  double png_height_scale_m = 1.0;  // file, png: height of the value 65535
};

// An axis-aligned rectangle of the ground covered by one material.
struct MaterialRegion {
  Material material;
  double x_min_m = 0, x_max_m = 0, y_min_m = 0, y_max_m = 0;
};

struct GroundSpec {
  Grid grid;
  InitialHeight initial;
  Material material;                     // everywhere no region covers
  std::vector<MaterialRegion> regions;   // later regions win where they overlap
};

struct Keyframe {
  double time_s = 0.0;
  Pose pose;
};

struct ObjectSpec {
  enum class Shape { kSphere, kBox, kCylinder, kCapsule, kMesh };
  std::string name;
  Shape shape = Shape::kSphere;
  double radius_m = 0.0;                               // sphere, cylinder, capsule
  double half_height_m = 0.0;                          // cylinder, capsule (of the straight part)
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();  // box
  std::string mesh_path;                               // mesh: absolute path of the OBJ/STL
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();     // applied to the body before placing
  TriangleMesh body;   // the tessellated (or loaded), scaled body in body coordinates
  bool simple = false; // may be computed on a coarser height field (multi-resolution rule)
  std::vector<Keyframe> keyframes;  // sorted by time, at least one

  // Pose at time t: position linear, orientation slerp between keyframes;
  // held constant before the first and after the last.
  Pose pose_at(double time_s) const;
};

struct TimeSpec {
  double step_s = 1.0 / 30.0;
  double duration_s = 1.0;
  int step_count() const;  // ceil(duration / step)
};

// A view for figures. Looks from position_m to target_m.
struct CameraSpec {
  Eigen::Vector3d position_m = Eigen::Vector3d(0, -1, 1);
  Eigen::Vector3d target_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  double fov_y_rad = 0.7853981633974483;  // 45 deg
  int width_px = 800;
  int height_px = 600;
};

// Options of the ground model that are part of the scene (not fitted).
struct GroundModelSpec {
  bool sweep = true;             // sweep translating objects between frames
  int substeps = 1;              // substeps per frame when not sweeping (>= 1)
  double max_substep_angle_rad = 0.08726646259971647;  // rotation per substep for rotating objects (5 deg)
  int erosion_memory_steps = 30; // steps an eroded cell keeps eroding
  int coarse_factor = 2;         // coarsening of the grid for 'simple' or far objects (>= 1)
  double far_distance_m = 0.0;   // objects farther than this from the camera use the coarse grid (0: never)
  enum class Collision { kOsmesa, kCpu };
  Collision collision = Collision::kCpu;
};

// Grains and contact law of the DEM reference runs (LIGGGHTS), for scenes
// that are also run as a reference. Young's modulus is softened, as DEM
// practice does, to allow a practical time step.
struct DemSpec {
  double grain_radius_m = 0.002;
  double radius_spread = 0.1;          // relative half-width of a uniform radius distribution [0, 0.5)
  double density_kg_m3 = 2500.0;
  double youngs_modulus_pa = 5.0e6;    // softened
  double poisson_ratio = 0.3;
  double restitution = 0.5;            // (0, 1]
  double friction = 0.5;               // sliding, grain-grain and grain-wall
  double rolling_friction = 0.1;
  enum class RollingModel { kCdt, kEpsd2 };
  RollingModel rolling_model = RollingModel::kCdt;
  double cohesion_energy_density_j_m3 = 0.0;  // sjkr cohesion; 0: none
  double time_step_s = 1.0e-5;          // refused above 20 % of the Rayleigh time
  double bed_depth_m = 0.02;            // depth of the settled bed the ground is made of
  double settle_kinetic_energy_j = 1.0e-7;  // settling ends below this total kinetic energy
  double gravity_m_s2 = 9.81;
  double dump_interval_s = 0.01;

  // The grains the run starts from. bed: a settled layer of bed_depth_m over
  // the whole grid. column: a column of grains settled behind a gate that is
  // removed at t = 0 (column collapse, piles); bed_depth_m is then unused.
  //   slot: quasi-2-D; the column fills x from the grid's x_min edge to
  //     x_min + column_width_m across the grid's whole y extent (the grid's
  //     y extent is the gap between the two side walls); the gate is the
  //     plane x = x_min + column_width_m.
  //   cylinder: axisymmetric; a cylinder of radius column_width_m on the
  //     grid's centre; the gate is the cylinder wall.
  enum class Initial { kBed, kColumn };
  Initial initial = Initial::kBed;
  enum class ColumnShape { kSlot, kCylinder };
  ColumnShape column_shape = ColumnShape::kCylinder;
  double column_width_m = 0.02;   // slot: length L0 along x; cylinder: radius R0
  double column_height_m = 0.04;  // H0, the settled column's intended height

  // The floor (z = 0). smooth: a plane of the grains' own material. rough: a
  // plane whose rolling friction with the grains is floor_rolling_friction,
  // standing in for the base of glued grains the column-collapse and pile
  // experiments use (single grains would otherwise roll far over a smooth plane).
  enum class Floor { kSmooth, kRough };
  Floor floor = Floor::kSmooth;
  double floor_rolling_friction = 1.0;  // rough floor only
};

struct Scene {
  std::string source_path;  // the file it came from (absolute), for messages and the manifest
  std::string name;
  std::uint64_t seed = 0;
  GroundSpec ground;
  std::vector<ObjectSpec> objects;
  TimeSpec time;
  std::optional<CameraSpec> camera;
  GroundModelSpec ground_model;
  std::optional<DemSpec> dem;  // present when the scene can run as a DEM reference
};

}  // namespace repose
