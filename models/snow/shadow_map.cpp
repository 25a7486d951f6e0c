#include "models/snow/shadow_map.h"

#include <cmath>

#include "models/core/base/error.h"

namespace repose {

LightFrame light_frame(const Eigen::Vector3d& travel) {
  LightFrame f;
  f.w = -travel.normalized();
  REPOSE_DEMAND(f.w.z() > 0.0);
  // perpendicular to w for every w with w.z > 0, and x when w = z
  f.u = Eigen::Vector3d(f.w.z(), 0.0, -f.w.x()).normalized();
  f.v = f.w.cross(f.u);
  return f;
}

double shadow_bias_m(const Eigen::Vector3d& travel, double pixel_m, double shadow_bias_cells) {
  const Eigen::Vector3d t = travel.normalized();
  const double tan_tilt = std::sqrt(t.x() * t.x() + t.y() * t.y()) / -t.z();
  return shadow_bias_cells * pixel_m * (1.0 + tan_tilt);
}

bool ShadowMap::is_lit(const Eigen::Vector3d& p_world) const {
  const Eigen::Vector3d p = frame.to_light(p_world);
  const Grid& g = depth.grid;
  const int i = static_cast<int>(std::floor((p.x() - g.origin_x_m) / g.cell_size_m));
  const int j = static_cast<int>(std::floor((p.y() - g.origin_y_m) / g.cell_size_m));
  if (!g.contains(i, j) || !depth.is_covered(i, j)) return true;
  return p.z() + bias_m >= depth.z(i, j);
}

namespace {

// Pixels of pixel_m covering `box` (in u, v) with one pixel of margin.
Grid light_grid(const Aabb& box, double pixel_m) {
  Grid g;
  g.cell_size_m = pixel_m;
  g.origin_x_m = (std::floor(box.min.x() / pixel_m) - 1.0) * pixel_m;
  g.origin_y_m = (std::floor(box.min.y() / pixel_m) - 1.0) * pixel_m;
  g.nx = static_cast<int>(std::ceil((box.max.x() - g.origin_x_m) / pixel_m)) + 1;
  g.ny = static_cast<int>(std::ceil((box.max.y() - g.origin_y_m) / pixel_m)) + 1;
  return g;
}

// The corners of the maps' grid at the lowest and highest covered height.
void extend_by_maps(const std::vector<SnowMap>& maps, const LightFrame& frame, Aabb* box) {
  double z_lo = 0.0, z_hi = 0.0;
  bool any = false;
  for (const SnowMap& m : maps) {
    for (int j = 0; j < m.grid().ny; ++j) {
      for (int i = 0; i < m.grid().nx; ++i) {
        if (!m.covered(i, j)) continue;
        z_lo = any ? std::min(z_lo, m.base_z(i, j)) : m.base_z(i, j);
        z_hi = any ? std::max(z_hi, m.base_z(i, j)) : m.base_z(i, j);
        any = true;
      }
    }
  }
  if (!any) return;
  const Grid& g = maps.front().grid();
  for (double x : {g.origin_x_m, g.origin_x_m + g.extent_x_m()}) {
    for (double y : {g.origin_y_m, g.origin_y_m + g.extent_y_m()}) {
      for (double z : {z_lo, z_hi}) box->extend(frame.to_light({x, y, z}));
    }
  }
}

}  // namespace

ShadowMap render_shadow_map(const std::vector<TriangleMesh>& occluders, const std::vector<SnowMap>& maps,
                            const Eigen::Vector3d& travel, double pixel_m, double shadow_bias_cells,
                            TopDownRenderer* renderer) {
  REPOSE_DEMAND(pixel_m > 0.0);
  ShadowMap shadow;
  shadow.frame = light_frame(travel);
  shadow.bias_m = shadow_bias_m(travel, pixel_m, shadow_bias_cells);
  const Eigen::Matrix3d to_light = (Eigen::Matrix3d() << shadow.frame.u.transpose(), shadow.frame.v.transpose(),
                                    shadow.frame.w.transpose()).finished();
  std::vector<TriangleMesh> in_light;
  in_light.reserve(occluders.size());
  Aabb box;
  for (const TriangleMesh& m : occluders) {
    TriangleMesh t{(m.V * to_light.transpose()).eval(), m.F};
    for (Eigen::Index v = 0; v < t.V.rows(); ++v) box.extend(t.V.row(v).transpose());
    in_light.push_back(std::move(t));
  }
  extend_by_maps(maps, shadow.frame, &box);
  if (box.empty()) box.extend(Eigen::Vector3d::Zero());
  shadow.depth = renderer->render(in_light, light_grid(box, pixel_m));
  return shadow;
}

}  // namespace repose
