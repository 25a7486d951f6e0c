#pragma once
// The scene: an immutable description of what is there, in SI units, loaded
// from YAML and validated once (scene_loader.h). Nothing here changes during
// a simulation; each model keeps its own state.
//
// The common part (ground grid and initial heights, which material lies
// where, objects and their motion, time, camera) is what every solver reads.
// What only one solver (or family) reads is its section (scene_section.h),
// defined in its own folder: ground_model (models/ground/ground_section.h),
// dem (validation/particles/dem_section.h), ...

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/core/config/dynamic_body.h"
#include "models/core/geometry/grid.h"
#include "models/core/geometry/height_field.h"
#include "models/core/config/scene_section.h"
#include "models/core/geometry/triangle_mesh.h"

namespace repose {

// How the ground's initial heights are made.
struct InitialHeight {
  // given: a field given in code on the scene's grid (calibration starts a
  // heuristic from a reference's settled surface); not written to files.
  enum class Kind { kFlat, kNoise, kFile, kGiven };
  Kind kind = Kind::kFlat;
  double height_m = 0.0;        // flat: the height; noise: the mean; file: an offset added
  double amplitude_m = 0.0;     // noise: peak deviation from the mean
  double correlation_m = 0.0;   // noise: smoothing length (0: white noise per cell)
  std::string path;             // file: .npy (metres) or 16-bit .png, absolute
  double png_height_scale_m = 1.0;  // file, png: height of the value 65535
  std::shared_ptr<const HeightField> given;  // given: on the scene's grid
};

// An axis-aligned rectangle of the ground covered by one material, by name:
// what a material is made of (its parameters) belongs to the solver that
// reads it (the ground model's materials are in its section).
struct MaterialRegion {
  std::string material;
  double x_min_m = 0, x_max_m = 0, y_min_m = 0, y_max_m = 0;
  std::string location;  // FILE:LINE:COL of its material key, for messages (empty when made in code)
};

struct GroundSpec {
  Grid grid;
  InitialHeight initial;
  std::string material = "sand";         // everywhere no region covers
  std::string material_location;         // FILE:LINE:COL of ground.material (empty when absent or made in code)
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
  std::vector<Keyframe> keyframes;  // sorted by time, at least one; a free body: its initial pose at t = 0
  std::optional<DynamicBody> dynamic;  // set: a free body (dynamic_body.h), not moved along keyframes

  // Pose at time t: position linear, orientation slerp between keyframes;
  // held constant before the first and after the last.
  Pose pose_at(double time_s) const;
  // The body's volume: exact for the primitives (times the scale's
  // product), the closed mesh's volume for a mesh.
  double volume_m3() const;
  // A free body's mass: dynamic->mass_kg, or its density times volume_m3().
  double mass_kg() const;
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

struct Scene {
  std::string source_path;  // the file it came from (absolute), for messages and the manifest
  std::string name;
  std::uint64_t seed = 0;
  GroundSpec ground;
  std::vector<ObjectSpec> objects;
  TimeSpec time;
  std::optional<CameraSpec> camera;
  // The solvers' sections by key ("ground_model", "dem", ...), each read and
  // validated by its solver's reader. Shared, immutable.
  std::map<std::string, std::shared_ptr<const SceneSection>> sections;

  // The section of type T (T::kKey), or nullptr when the scene has none.
  template <class T>
  const T* section() const {
    const auto it = sections.find(T::kKey);
    return it == sections.end() ? nullptr : &dynamic_cast<const T&>(*it->second);
  }
  bool has_section(const std::string& key) const { return sections.count(key) != 0; }
};

}  // namespace repose
