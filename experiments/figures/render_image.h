#pragma once
// Figures: a shaded height field with the scene's objects, seen through a
// perspective camera (CameraSpec, models/core/config/scene.h), rendered off-screen
// with OSMesa into an RGB image (write it with write_png_rgb).
//
// Shading is computed per vertex on the CPU (Lambert with a directional light
// plus ambient), so the picture depends only on the inputs: the same input
// gives the same bytes. The ground is coloured by height (dark sand low,
// light sand high); objects get one colour, flat-shaded per face and lit on
// whichever side faces the camera. Antialiasing: rendered `supersample` times
// larger and box-filtered down.

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "models/core/geometry/height_field.h"
#include "models/core/io/png_io.h"
#include "models/core/config/scene.h"
#include "models/core/geometry/triangle_mesh.h"

namespace repose {

struct RenderImageOptions {
  int supersample = 2;  // render at this factor and average down (1: no antialiasing)
  // direction towards the light (normalised when used): from the south-west, high
  Eigen::Vector3d light_direction = Eigen::Vector3d(-0.5, -0.3, 1.0);
  double ambient = 0.35;  // fraction of the colour lit without the light, [0, 1]
  Eigen::Vector3d ground_low_rgb = Eigen::Vector3d(0.55, 0.45, 0.30);   // 0..1, at the lowest height
  Eigen::Vector3d ground_high_rgb = Eigen::Vector3d(0.95, 0.89, 0.72);  // 0..1, at the highest height
  Eigen::Vector3d object_rgb = Eigen::Vector3d(0.80, 0.30, 0.22);       // 0..1
  Eigen::Vector3d background_rgb = Eigen::Vector3d(1.0, 1.0, 1.0);      // 0..1
};

// Looks at the middle of `box` from `from_direction` (any length; not
// vertical), far enough that the box's bounding sphere fits the 45-degree
// view; up is +z.
CameraSpec camera_around(const Aabb& box, const Eigen::Vector3d& from_direction, int width_px, int height_px);

// Looks at the middle of the field from the south-east (+x, -y) at 35 degrees
// elevation, far enough that the field and the objects fit the 45-degree view.
CameraSpec default_camera(const HeightField& field, const std::vector<TriangleMesh>& objects = {},
                          int width_px = 800, int height_px = 600);

// Throws InputError for a camera that cannot be used (size < 1 or beyond the
// off-screen buffer, fov outside (0, pi), position at the target, up along
// the view direction) or supersample < 1.
RgbImage render_image(const HeightField& field, const std::vector<TriangleMesh>& objects, const CameraSpec& camera,
                      const RenderImageOptions& options = {});

// A triangle mesh with a colour per vertex (0..1, one per row of mesh.V),
// smooth-shaded with area-weighted vertex normals and lit on the side that
// faces the camera (for sheets seen from either side).
struct ColouredMesh {
  TriangleMesh mesh;
  std::vector<Eigen::Vector3d> vertex_rgb;
};

// The meshes alone (no ground), through the same camera, light, background and
// supersampling as render_image; throws InputError as render_image does, and
// for a mesh whose vertex_rgb does not have a colour per vertex.
RgbImage render_coloured_meshes(const std::vector<ColouredMesh>& meshes, const CameraSpec& camera,
                                const RenderImageOptions& options = {});

// Where a world point lands in the image: (column, row) in pixels from the
// top-left corner, or nothing when it is behind the camera.
std::optional<Eigen::Vector2d> project_to_image(const CameraSpec& camera, const Eigen::Vector3d& point_m);

}  // namespace repose
