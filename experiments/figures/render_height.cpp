#include "experiments/figures/render_height.h"

#include <numbers>
#include <vector>

#include "experiments/figures/render_image.h"
#include "models/core/run/output_directory.h"
#include "models/core/io/png_io.h"

namespace repose::cli {
namespace {

std::vector<TriangleMesh> objects_at(const Scene* scene, double time_s) {
  std::vector<TriangleMesh> meshes;
  if (scene == nullptr) return meshes;
  for (const ObjectSpec& object : scene->objects) meshes.push_back(transformed(object.body, object.pose_at(time_s)));
  return meshes;
}

// The scene's camera if it has one, else a view of the whole field; then the overrides.
CameraSpec camera_for(const HeightField& field, const std::vector<TriangleMesh>& objects, const Scene* scene,
                      const CameraOverrides& overrides) {
  CameraSpec camera;
  if (scene != nullptr && scene->camera) {
    camera = *scene->camera;
  } else {
    const CameraSpec size_only;
    camera = default_camera(field, objects, overrides.width_px.value_or(size_only.width_px),
                            overrides.height_px.value_or(size_only.height_px));
  }
  if (overrides.width_px) camera.width_px = *overrides.width_px;
  if (overrides.height_px) camera.height_px = *overrides.height_px;
  if (overrides.position_m) camera.position_m = *overrides.position_m;
  if (overrides.target_m) camera.target_m = *overrides.target_m;
  if (overrides.fov_y_deg) camera.fov_y_rad = *overrides.fov_y_deg * std::numbers::pi / 180.0;
  return camera;
}

}  // namespace

void render_height_png(const std::string& png_path, const HeightField& field, const Scene* scene, double time_s,
                       const CameraOverrides& overrides) {
  const std::vector<TriangleMesh> objects = objects_at(scene, time_s);
  const RgbImage image = render_image(field, objects, camera_for(field, objects, scene, overrides));
  write_file_atomically(png_path, [&](const std::string& temporary) { write_png_rgb(temporary, image); });
}

}  // namespace repose::cli
