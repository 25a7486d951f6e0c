#include "models/snow/snow_surface_mesh.h"

#include <vector>

#include "models/core/base/error.h"

namespace repose {

TriangleMesh snow_surface_mesh(const SnowMap& map, const ArrayXXdR& depth_m, double min_depth_m) {
  const Grid& g = map.grid();
  REPOSE_DEMAND(depth_m.rows() == g.ny && depth_m.cols() == g.nx);
  // vertex index per cell, -1 where the cell has no snow surface
  std::vector<int> vertex(g.cell_count(), -1);
  std::vector<Eigen::Vector3d> points;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      if (!map.covered(i, j) || !(depth_m(j, i) > min_depth_m)) continue;
      vertex[static_cast<std::size_t>(j) * g.nx + i] = static_cast<int>(points.size());
      points.emplace_back(g.centre_x(i), g.centre_y(j), map.base_z(i, j) + depth_m(j, i));
    }
  }
  std::vector<Eigen::Vector3i> faces;
  for (int j = 0; j + 1 < g.ny; ++j) {
    for (int i = 0; i + 1 < g.nx; ++i) {
      const std::size_t c = static_cast<std::size_t>(j) * g.nx + i;
      const int a = vertex[c], b = vertex[c + 1], d = vertex[c + g.nx], e = vertex[c + g.nx + 1];
      if (a < 0 || b < 0 || d < 0 || e < 0) continue;
      faces.emplace_back(a, b, e);  // counter-clockwise seen from above
      faces.emplace_back(a, e, d);
    }
  }
  TriangleMesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t k = 0; k < points.size(); ++k) mesh.V.row(static_cast<Eigen::Index>(k)) = points[k].transpose();
  mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t k = 0; k < faces.size(); ++k) mesh.F.row(static_cast<Eigen::Index>(k)) = faces[k].transpose();
  return mesh;
}

}  // namespace repose
