#pragma once
// Scene files (YAML) -> a validated Scene, and the resolved scene back to
// YAML for run manifests. The format, in SI units with units in key names
// and angles in degrees (see experiments/scenes/default_ground.yaml):
//
//   name: my_scene                 # optional (default: the file name)
//   seed: 7                        # optional (default 0), drives every random choice
//   time: {step_s: 0.0333, duration_s: 2.0}
//   ground:
//     extent_m: [1.0, 1.0]
//     cell_size_m: 0.004           # or resolution: [nx, ny]; exactly one; square cells
//     origin_m: [-0.5, -0.5]       # optional lower-left corner (default: centred on 0)
//     initial_height: {kind: flat, height_m: 0.05}
//       # or {kind: noise, mean_m, amplitude_m, correlation_m}
//       # or {kind: file, path: h.npy | h.png, height_scale_m (png only), offset_m}
//     material: sand               # a material name: a preset (sand, mud, snow) or one a
//                                  # solver's section defines (ground_model.materials)
//     regions: [{material: mud, x_range_m: [a, b], y_range_m: [a, b]}]
//   objects:
//     - name: ball
//       shape: sphere              # sphere (radius_m), box (half_extents_m or size_m),
//                                  # cylinder/capsule (radius_m, half_height_m), mesh (mesh, path
//                                  # relative to this file, OBJ/STL, closed)
//       scale: 1.0                 # optional: a number or [sx, sy, sz]
//       simple: false              # optional
//       motion:                    # keyframes, times strictly increasing; one = static
//         - {time_s: 0, position_m: [0, 0, 0.1], orientation_deg: [roll, pitch, yaw]}
//       # or, instead of motion, a free body (dynamic_body.h): {mass_kg | density_kg_m3,
//       # position_m, orientation_deg, velocity_m_s, angular_velocity_rad_s}
//       dynamic: {density_kg_m3: 7800, position_m: [0, 0, 0.05]}
//   camera: {position_m, target_m, up, fov_y_deg, width_px, height_px}   # optional
//   ground_model: {...}            # sections: one per solver (family), each read by the
//   dem: {...}                     # SectionType its folder defines (scene_section.h); the
//                                  # loader is given the list (the solver registry's)
//
// orientation_deg [roll, pitch, yaw] is applied as Rz(yaw) * Ry(pitch) * Rx(roll).
// Every error is one InputError line: FILE:LINE:COL: KEY.PATH: expected WHAT, got WHAT.

#include <string>

#include <yaml-cpp/yaml.h>

#include "models/core/config/scene.h"
#include "models/core/config/scene_section.h"

namespace repose {

// Loads and validates a scene file. Mesh and height files named by the
// scene are read (and checked) now, relative to the scene file's folder.
Scene load_scene(const std::string& path, const SectionTypes& sections);
// The same from text; `pretend_path` is used in messages and to resolve
// relative paths.
Scene load_scene_from_string(const std::string& yaml, const std::string& pretend_path, const SectionTypes& sections);

// The same from a parsed document (e.g. a scene file with an experiment's
// overrides applied); `path` is the scene file, for messages and relative paths.
Scene load_scene_from_node(const YAML::Node& root, const std::string& path, const SectionTypes& sections);

// A short human summary (a few lines) for `repose check`.
std::string describe_scene(const Scene& scene);

// The resolved scene (every default filled, absolute paths, degrees) as a
// YAML map that load_scene_from_string reads back to the same scene.
void write_scene_yaml(const Scene& scene, YAML::Emitter& out);
std::string scene_to_yaml(const Scene& scene);

// Rz(yaw) * Ry(pitch) * Rx(roll) from [roll, pitch, yaw] in degrees, and back.
Eigen::Quaterniond orientation_from_rpy_deg(const Eigen::Vector3d& roll_pitch_yaw_deg);
Eigen::Vector3d rpy_deg_from_orientation(const Eigen::Quaterniond& q);

}  // namespace repose
