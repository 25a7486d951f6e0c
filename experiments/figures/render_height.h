#pragma once
// Shaded pictures of a height field (with the scene's objects) for figures,
// shared by `repose render` and `repose run`.

#include <optional>
#include <string>

#include "models/core/geometry/height_field.h"
#include "models/core/config/scene.h"

namespace repose::cli {

// Camera overrides from the command line; unset fields keep the scene's
// camera, or a default view of the whole field.
struct CameraOverrides {
  std::optional<Eigen::Vector3d> position_m;
  std::optional<Eigen::Vector3d> target_m;
  std::optional<double> fov_y_deg;
  std::optional<int> width_px;
  std::optional<int> height_px;
};

// Renders `field` with the objects of `scene` (if any) posed at time_s and
// writes the PNG atomically (temporary file + rename).
void render_height_png(const std::string& png_path, const HeightField& field, const Scene* scene, double time_s,
                       const CameraOverrides& overrides);

}  // namespace repose::cli
