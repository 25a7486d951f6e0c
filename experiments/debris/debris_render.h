#pragma once
// The debris flow's collapse in 3-D (issue 14: "from contours to a rendered
// collapse in each engine"): a debris run folder, as every engine writes it
// (validation/rigid/debris_run.h, write_debris_run: terrain.obj, parts.json,
// front.csv, frames/elements_NNN.npy and frames/parts_NNN.npy), drawn
// off-screen with OSMesa through the figures' renderer
// (experiments/figures/render_image.h, render_coloured_meshes) from an
// oblique camera: the terrain mesh shaded by height, the elements as
// subdivided icosahedra coloured by radius, the building parts as their
// prisms (validation/liggghts_debris part_mesh), grey while in place and
// red once their centre has moved more than moved_threshold_m from frame 0.
// The same camera for every frame of a run, so the frames form a series.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "experiments/figures/render_image.h"
#include "models/core/geometry/triangle_mesh.h"
#include "models/core/io/png_io.h"
#include "validation/rigid/debris_world.h"

namespace repose {

struct DebrisRenderOptions {
  int frames = 6;                   // >= 1: frames drawn, spread evenly from the first to the last
  int width_px = 800;               // >= 1
  int height_px = 600;              // >= 1
  double azimuth_deg = 55.0;        // camera direction seen from above, from +x towards +y (55: from the
                                    // north-east, the debris scene's flow coming towards it)
  double elevation_deg = 30.0;      // (0, 90): camera above the horizontal
  double margin_m = 6.0;            // >= 0: the view frames the elements and buildings this much wider
  int sphere_segments = 6;          // 3..16: make_sphere's divisions around (6: 60 triangles per element)
  double moved_threshold_m = 0.05;  // > 0: a part drawn as moved beyond this (DebrisRunOptions' default)
  RenderImageOptions image;         // light, supersampling, background (ground and object colours unused)
  Eigen::Vector3d terrain_low_rgb = Eigen::Vector3d(0.42, 0.58, 0.36);   // 0..1, at the lowest height
  Eigen::Vector3d terrain_high_rgb = Eigen::Vector3d(0.86, 0.84, 0.74);  // 0..1, at the highest height
  Eigen::Vector3d element_small_rgb = Eigen::Vector3d(0.35, 0.20, 0.10); // 0..1, at the smallest radius
  Eigen::Vector3d element_large_rgb = Eigen::Vector3d(0.95, 0.55, 0.20); // 0..1, at the largest radius
  Eigen::Vector3d part_rgb = Eigen::Vector3d(0.62, 0.66, 0.78);          // 0..1, a part in place
  Eigen::Vector3d moved_part_rgb = Eigen::Vector3d(0.85, 0.12, 0.10);    // 0..1, a part that moved
  void validate() const;            // InputError naming the field
};

// One frame of a run: elements (#E by 4: x y z r) and part poses.
struct DebrisRenderFrame {
  double time_s = 0.0;
  Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor> elements;
  std::vector<Pose> parts;
};

// What a run folder holds for the pictures.
struct DebrisRunFrames {
  TriangleMesh terrain;
  std::vector<DebrisPart> parts;  // hull_m (body frame) and building; centre_m zero
  std::vector<DebrisRenderFrame> frames;
};

// Reads run_dir's terrain.obj, parts.json, front.csv (the frames' times) and
// frames/. Throws InputError naming the file for one missing or malformed,
// or whose shape disagrees with parts.json or front.csv.
DebrisRunFrames read_debris_run_frames(const std::string& run_dir);

// `wanted` frame indices spread evenly over [0, count - 1] (rounded, repeats dropped).
std::vector<int> picked_frames(int count, int wanted);

// One camera for the whole series: framing the picked frames' elements and
// every part (with the margin), from the options' azimuth and elevation.
CameraSpec debris_camera(const DebrisRunFrames& run, const std::vector<int>& picks, const DebrisRenderOptions& options);

// Frame k drawn through `camera`. Throws InputError for bad options or k out of range.
RgbImage render_debris_frame(const DebrisRunFrames& run, int k, const CameraSpec& camera,
                             const DebrisRenderOptions& options);

// Renders the picked frames of run_dir to PREFIX_NNN.png (NNN the frame's
// index in the run; png_prefix may hold a folder) and returns the paths written.
std::vector<std::string> write_debris_renders(const std::string& run_dir, const std::string& png_prefix,
                                              const DebrisRenderOptions& options);

}  // namespace repose
