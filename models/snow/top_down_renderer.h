#pragma once
// Orthographic depth images seen from above, the one operation the snow
// model draws with: the snow maps (top-down Z-buffer per group, the snow
// paper 2.1) and the shadow maps (the scene turned into a snowfall
// direction's frame and seen from above along it, 2.2.3).
//
// Two paths compute the same image (models/core/geometry/depth_image.h):
//   kCpu    - depth_image_cpu, a vertical ray per cell centre (the main path)
//   kOsmesa - OpenGL rasterisation through OSMesa, as the paper uses the
//             graphics hardware; the depth range is fitted around the meshes,
//             so z is quantised to (range) / 2^24.

#include <memory>
#include <vector>

#include "models/core/geometry/depth_image.h"
#include "models/core/geometry/triangle_mesh.h"

namespace repose {

class OsmesaDepthRenderer;

enum class SnowRenderer { kCpu, kOsmesa };

class TopDownRenderer {
 public:
  explicit TopDownRenderer(SnowRenderer kind = SnowRenderer::kCpu);
  ~TopDownRenderer();
  TopDownRenderer(TopDownRenderer&&) noexcept;
  TopDownRenderer& operator=(TopDownRenderer&&) noexcept;

  // The highest surface over each cell centre of `grid`.
  DepthImage render(const std::vector<TriangleMesh>& meshes, const Grid& grid);
  SnowRenderer kind() const { return kind_; }

 private:
  SnowRenderer kind_;
  std::unique_ptr<OsmesaDepthRenderer> gl_;  // kOsmesa only: one context per renderer
};

}  // namespace repose
