#include "models/core/geometry/depth_image.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace repose {

namespace {

// Twice the signed area of (a, b, p) in the xy plane.
double edge(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
}

// The indices of the cell centres within [lo, hi] along an axis of n
// cells, lo and hi in cell units (cell_units): max(0, ceil(lo)) to
// min(n - 1, floor(hi)); empty when first > last. By integer conversion:
// std::ceil and std::floor are library calls on SSE2, and this runs for
// every triangle. Clamped first, so the conversion is exact and cannot overflow.
inline void centre_range(double lo, double hi, int n, int* first, int* last) {
  const double f = std::clamp(lo, -1.0, static_cast<double>(n));
  const double l = std::clamp(hi, -1.0, static_cast<double>(n));
  const int fi = static_cast<int>(f), li = static_cast<int>(l);  // toward zero
  *first = std::max(0, fi + (fi < f ? 1 : 0));
  *last = std::min(n - 1, li - (li > l ? 1 : 0));
}

// Coordinates in cell units, (x - origin) / h - 0.5: cell i's centre is at i.
// Rounding keeps it monotonic, so the lowest over a triangle's corners is
// that of their lowest x, and it can be computed once per vertex.
Eigen::ArrayXd cell_units(const TriangleMesh& m, int axis, double origin, double h) {
  Eigen::ArrayXd u(m.V.rows());
  for (Eigen::Index r = 0; r < m.V.rows(); ++r) u[r] = (m.V(r, axis) - origin) / h - 0.5;
  return u;
}

// Keeps the lowest (from below) or highest (from above) z of a cell centre.
inline void draw(int i, int j, double z, ViewFrom view, DepthImage* img) {
  double& out = img->z_m(j, i);
  if (!img->covered(j, i) || (view == ViewFrom::kBelow ? z < out : z > out)) out = z;
  img->covered(j, i) = 1;
}

// Writes the z of triangle (a, b, c) into every cell whose centre it covers
// among cells [i0, i1] x [j0, j1], keeping the lowest (from below) or highest
// (from above). hits: where given, each covered centre of face `face` is
// appended (DepthImageCpuCache).
void rasterise(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, int i0, int i1, int j0,
               int j1, ViewFrom view, DepthImage* img, int face, std::vector<DepthImageCpuCache::Hit>* hits) {
  const Grid& grid = img->grid;
  const Eigen::Vector2d a2 = a.head<2>(), b2 = b.head<2>(), c2 = c.head<2>();
  const double area = edge(a2, b2, c2);
  if (area == 0.0) return;  // vertical triangle: seen edge-on, covers no cell centre
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const Eigen::Vector2d p(grid.centre_x(i), grid.centre_y(j));
      const double wa = edge(b2, c2, p) / area;
      const double wb = edge(c2, a2, p) / area;
      const double wc = 1.0 - wa - wb;
      // closed on all edges: a centre on a shared edge is seen by both triangles, same z
      if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
      draw(i, j, wa * a.z() + wb * b.z() + wc * c.z(), view, img);
      if (hits) hits->push_back({face, i, j, wa, wb, wc});
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

// Most triangles of a body on a height-field grid cover no cell centre at
// all: the range of centres they span is found first, from cell units.
void rasterise(const TriangleMesh& m, ViewFrom view, DepthImage* img,
               std::vector<DepthImageCpuCache::Hit>* hits = nullptr) {
  const Grid& g = img->grid;
  const Eigen::ArrayXd ux = cell_units(m, 0, g.origin_x_m, g.cell_size_m);
  const Eigen::ArrayXd uy = cell_units(m, 1, g.origin_y_m, g.cell_size_m);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const int a = m.F(f, 0), b = m.F(f, 1), c = m.F(f, 2);
    int i0, i1, j0, j1;
    centre_range(std::min(ux[a], std::min(ux[b], ux[c])), std::max(ux[a], std::max(ux[b], ux[c])), g.nx, &i0, &i1);
    if (i0 > i1) continue;
    centre_range(std::min(uy[a], std::min(uy[b], uy[c])), std::max(uy[a], std::max(uy[b], uy[c])), g.ny, &j0, &j1);
    if (j0 > j1) continue;
    rasterise(m.V.row(a), m.V.row(b), m.V.row(c), i0, i1, j0, j1, view, img, static_cast<int>(f), hits);
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

bool DepthImageCpuCache::same_footing(const TriangleMesh& mesh, const Grid& grid, ViewFrom view) const {
  if (!valid_ || !(grid == grid_) || view != view_ || mesh.F.rows() != faces_.rows()) return false;
  if (static_cast<std::size_t>(2 * mesh.V.rows()) != xy_.size()) return false;
  if (mesh.F.size() > 0 && std::memcmp(mesh.F.data(), faces_.data(), sizeof(int) * mesh.F.size()) != 0) return false;
  for (Eigen::Index r = 0; r < mesh.V.rows(); ++r) {
    // bit for bit: equal as numbers is not enough (-0.0 and 0.0)
    if (std::memcmp(&mesh.V(r, 0), &xy_[2 * static_cast<std::size_t>(r)], 2 * sizeof(double)) != 0) return false;
  }
  return true;
}

DepthImage DepthImageCpuCache::render(const TriangleMesh& mesh, const Grid& grid, ViewFrom view) {
  DepthImage img = empty_image(grid, view);
  if (same_footing(mesh, grid, view)) {
    for (const Hit& h : hits_) {
      const double za = mesh.V(mesh.F(h.face, 0), 2), zb = mesh.V(mesh.F(h.face, 1), 2), zc = mesh.V(mesh.F(h.face, 2), 2);
      draw(h.i, h.j, h.wa * za + h.wb * zb + h.wc * zc, view, &img);
    }
    return img;
  }
  hits_.clear();
  rasterise(mesh, view, &img, &hits_);
  valid_ = true;
  grid_ = grid;
  view_ = view;
  faces_ = mesh.F;
  xy_.resize(2 * static_cast<std::size_t>(mesh.V.rows()));
  for (Eigen::Index r = 0; r < mesh.V.rows(); ++r) {
    xy_[2 * static_cast<std::size_t>(r)] = mesh.V(r, 0);
    xy_[2 * static_cast<std::size_t>(r) + 1] = mesh.V(r, 1);
  }
  return img;
}

}  // namespace repose
