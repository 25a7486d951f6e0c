#include "models/terrain/terrain_surface.h"

#include <algorithm>
#include <cmath>

#include "models/core/base/error.h"

namespace repose {

namespace {

Point2 xy(const TriangleMesh& mesh, int v) { return Point2(mesh.V(v, 0), mesh.V(v, 1)); }

}  // namespace

TerrainSurface::TerrainSurface(TriangleMesh mesh) : mesh_(std::move(mesh)) {
  REPOSE_DEMAND(!mesh_.empty());
  const Aabb box = bounding_box(mesh_);
  lo_ = Point2(box.min.x(), box.min.y());
  const double width = std::max(box.max.x() - box.min.x(), box.max.y() - box.min.y());
  // about one triangle per bucket
  const double per_side = std::max(1.0, std::sqrt(static_cast<double>(mesh_.F.rows())));
  bucket_m_ = std::max(width / per_side, 1e-9 * (1.0 + width));
  nx_ = std::max(1, static_cast<int>(std::ceil((box.max.x() - box.min.x()) / bucket_m_)) + 1);
  ny_ = std::max(1, static_cast<int>(std::ceil((box.max.y() - box.min.y()) / bucket_m_)) + 1);
  buckets_.assign(static_cast<std::size_t>(nx_) * ny_, {});
  for (int f = 0; f < mesh_.F.rows(); ++f) {
    Point2 a = xy(mesh_, mesh_.F(f, 0)), b = xy(mesh_, mesh_.F(f, 1)), c = xy(mesh_, mesh_.F(f, 2));
    const int x0 = bucket_x(std::min({a.x(), b.x(), c.x()})), x1 = bucket_x(std::max({a.x(), b.x(), c.x()}));
    const int y0 = bucket_y(std::min({a.y(), b.y(), c.y()})), y1 = bucket_y(std::max({a.y(), b.y(), c.y()}));
    for (int j = y0; j <= y1; ++j) {
      for (int i = x0; i <= x1; ++i) buckets_[static_cast<std::size_t>(j) * nx_ + i].push_back(f);
    }
  }
}

int TerrainSurface::bucket_x(double x) const {
  return std::clamp(static_cast<int>(std::floor((x - lo_.x()) / bucket_m_)), 0, nx_ - 1);
}
int TerrainSurface::bucket_y(double y) const {
  return std::clamp(static_cast<int>(std::floor((y - lo_.y()) / bucket_m_)), 0, ny_ - 1);
}

std::optional<double> TerrainSurface::height_at(const Point2& p) const {
  const auto& faces = buckets_[static_cast<std::size_t>(bucket_y(p.y())) * nx_ + bucket_x(p.x())];
  for (int f : faces) {
    const Eigen::Vector3d a = mesh_.V.row(mesh_.F(f, 0)), b = mesh_.V.row(mesh_.F(f, 1)), c = mesh_.V.row(mesh_.F(f, 2));
    const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    if (det == 0.0) continue;
    const double u = ((p.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (p.y() - a.y())) / det;
    const double v = ((b.x() - a.x()) * (p.y() - a.y()) - (p.x() - a.x()) * (b.y() - a.y())) / det;
    // a point on a shared edge belongs to either face: both give the same height
    constexpr double kEdge = -1e-12;
    if (u >= kEdge && v >= kEdge && u + v <= 1.0 - kEdge) return a.z() + u * (b.z() - a.z()) + v * (c.z() - a.z());
  }
  return std::nullopt;
}

std::vector<int> TerrainSurface::faces_near(const Point2& lo, const Point2& hi) const {
  std::vector<int> out;
  for (int j = bucket_y(lo.y()); j <= bucket_y(hi.y()); ++j) {
    for (int i = bucket_x(lo.x()); i <= bucket_x(hi.x()); ++i) {
      const auto& faces = buckets_[static_cast<std::size_t>(j) * nx_ + i];
      out.insert(out.end(), faces.begin(), faces.end());
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

HeightField sample_height_field(const TerrainSurface& surface, const Grid& grid, double outside_height_m) {
  HeightField field(grid, outside_height_m);
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      const std::optional<double> h = surface.height_at(Point2(grid.centre_x(i), grid.centre_y(j)));
      if (h) field.at(i, j) = *h;
    }
  }
  return field;
}

Grid covering_grid(const TriangleMesh& mesh, double cell_size_m) {
  REPOSE_DEMAND(cell_size_m > 0.0 && !mesh.empty());
  const Aabb box = bounding_box(mesh);
  Grid grid;
  grid.cell_size_m = cell_size_m;
  grid.origin_x_m = box.min.x() - cell_size_m;
  grid.origin_y_m = box.min.y() - cell_size_m;
  grid.nx = static_cast<int>(std::ceil((box.max.x() - box.min.x()) / cell_size_m)) + 2;
  grid.ny = static_cast<int>(std::ceil((box.max.y() - box.min.y()) / cell_size_m)) + 2;
  return grid;
}

}  // namespace repose
