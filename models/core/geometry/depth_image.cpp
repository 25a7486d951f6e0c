#include "models/core/geometry/depth_image.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace repose {

namespace {

// Twice the signed area of (a, b, p) in the xy plane.
double edge(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
}

// Writes the z of triangle (a, b, c) into every cell whose centre it covers,
// keeping the lowest (from below) or highest (from above).
void rasterise(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, const Grid& grid,
               ViewFrom view, DepthImage* img) {
  const Eigen::Vector2d a2 = a.head<2>(), b2 = b.head<2>(), c2 = c.head<2>();
  const double area = edge(a2, b2, c2);
  if (area == 0.0) return;  // vertical triangle: seen edge-on, covers no cell centre
  const double h = grid.cell_size_m;
  // the cell centres within [lo, hi]: max(0, ceil(.)) and min(n - 1, floor(.))
  // by integer conversion (std::ceil and std::floor are library calls on
  // SSE2 and were a third of this function's cost); clamped first, so the
  // conversion is exact and cannot overflow
  auto index_range = [&](double lo, double hi, double origin, int n, int* first, int* last) {
    const double f = std::clamp((lo - origin) / h - 0.5, -1.0, static_cast<double>(n));
    const double l = std::clamp((hi - origin) / h - 0.5, -1.0, static_cast<double>(n));
    const int fi = static_cast<int>(f), li = static_cast<int>(l);  // toward zero
    *first = std::max(0, fi + (fi < f ? 1 : 0));
    *last = std::min(n - 1, li - (li > l ? 1 : 0));
  };
  int i0, i1, j0, j1;
  index_range(std::min({a.x(), b.x(), c.x()}), std::max({a.x(), b.x(), c.x()}), grid.origin_x_m, grid.nx, &i0, &i1);
  index_range(std::min({a.y(), b.y(), c.y()}), std::max({a.y(), b.y(), c.y()}), grid.origin_y_m, grid.ny, &j0, &j1);
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const Eigen::Vector2d p(grid.centre_x(i), grid.centre_y(j));
      const double wa = edge(b2, c2, p) / area;
      const double wb = edge(c2, a2, p) / area;
      const double wc = 1.0 - wa - wb;
      // closed on all edges: a centre on a shared edge is seen by both triangles, same z
      if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
      const double z = wa * a.z() + wb * b.z() + wc * c.z();
      double& out = img->z_m(j, i);
      if (!img->covered(j, i) || (view == ViewFrom::kBelow ? z < out : z > out)) out = z;
      img->covered(j, i) = 1;
    }
  }
}

DepthImage empty_image(const Grid& grid, ViewFrom view) {
  DepthImage img;
  img.grid = grid;
  img.view = view;
  img.z_m = ArrayXXdR::Constant(grid.ny, grid.nx, std::numeric_limits<double>::quiet_NaN());
  img.covered.setZero(grid.ny, grid.nx);
  return img;
}

void rasterise(const TriangleMesh& m, ViewFrom view, DepthImage* img) {
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    rasterise(m.V.row(m.F(f, 0)), m.V.row(m.F(f, 1)), m.V.row(m.F(f, 2)), img->grid, view, img);
  }
}

}  // namespace

DepthImage depth_image_cpu(const std::vector<TriangleMesh>& meshes, const Grid& grid, ViewFrom view) {
  DepthImage img = empty_image(grid, view);
  for (const TriangleMesh& m : meshes) rasterise(m, view, &img);
  return img;
}

DepthImage depth_image_cpu(const TriangleMesh& mesh, const Grid& grid, ViewFrom view) {
  DepthImage img = empty_image(grid, view);
  rasterise(mesh, view, &img);
  return img;
}

}  // namespace repose
