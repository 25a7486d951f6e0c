#include "models/snow/top_down_renderer.h"

#include <algorithm>

#include "models/core/gl/osmesa_depth_renderer.h"

namespace repose {

TopDownRenderer::TopDownRenderer(SnowRenderer kind) : kind_(kind) {
  if (kind_ == SnowRenderer::kOsmesa) gl_ = std::make_unique<OsmesaDepthRenderer>();
}

TopDownRenderer::~TopDownRenderer() = default;
TopDownRenderer::TopDownRenderer(TopDownRenderer&&) noexcept = default;
TopDownRenderer& TopDownRenderer::operator=(TopDownRenderer&&) noexcept = default;

DepthImage TopDownRenderer::render(const std::vector<TriangleMesh>& meshes, const Grid& grid) {
  if (kind_ == SnowRenderer::kCpu) return depth_image_cpu(meshes, grid, ViewFrom::kAbove);
  Aabb box;
  for (const TriangleMesh& m : meshes) {
    for (Eigen::Index v = 0; v < m.V.rows(); ++v) box.extend(m.V.row(v).transpose());
  }
  if (box.empty()) box.extend(Eigen::Vector3d::Zero());
  // a margin so that no surface sits on the far plane (counted as not covered)
  const double margin = 1e-3 + 0.01 * (box.max.z() - box.min.z());
  return gl_->render(meshes, grid, ViewFrom::kAbove, DepthRange{box.min.z() - margin, box.max.z() + margin});
}

}  // namespace repose
