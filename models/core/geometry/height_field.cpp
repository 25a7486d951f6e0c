#include "models/core/geometry/height_field.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "models/core/base/error.h"

namespace repose {

HeightField::HeightField(const Grid& grid, double initial_height_m)
    : grid_(grid), h_(ArrayXXdR::Constant(grid.ny, grid.nx, initial_height_m)) {
  REPOSE_DEMAND(grid.nx > 0 && grid.ny > 0 && grid.cell_size_m > 0.0);
}

HeightField::HeightField(const Grid& grid, ArrayXXdR heights) : grid_(grid), h_(std::move(heights)) {
  REPOSE_DEMAND(grid.nx > 0 && grid.ny > 0 && grid.cell_size_m > 0.0);
  REPOSE_DEMAND(h_.rows() == grid.ny && h_.cols() == grid.nx);
}

double HeightField::sample(double x_m, double y_m) const {
  // continuous index with cell centres at integers
  const double fx = (x_m - grid_.origin_x_m) / grid_.cell_size_m - 0.5;
  const double fy = (y_m - grid_.origin_y_m) / grid_.cell_size_m - 0.5;
  const double cx = std::clamp(fx, 0.0, static_cast<double>(grid_.nx - 1));
  const double cy = std::clamp(fy, 0.0, static_cast<double>(grid_.ny - 1));
  const int i0 = std::min(static_cast<int>(std::floor(cx)), std::max(grid_.nx - 2, 0));
  const int j0 = std::min(static_cast<int>(std::floor(cy)), std::max(grid_.ny - 2, 0));
  const int i1 = std::min(i0 + 1, grid_.nx - 1);
  const int j1 = std::min(j0 + 1, grid_.ny - 1);
  const double tx = cx - i0;
  const double ty = cy - j0;
  const double lower = (1 - tx) * at(i0, j0) + tx * at(i1, j0);
  const double upper = (1 - tx) * at(i0, j1) + tx * at(i1, j1);
  return (1 - ty) * lower + ty * upper;
}

double HeightField::min_height_m() const {
  REPOSE_DEMAND(h_.size() > 0);
  return h_.minCoeff();
}

double HeightField::max_height_m() const {
  REPOSE_DEMAND(h_.size() > 0);
  return h_.maxCoeff();
}

double HeightField::volume_m3() const { return h_.sum() * grid_.cell_area_m2(); }

namespace {

// Overlap of target cell k (along one axis) with the source cells, as
// (source index, overlap length) pairs.
struct Overlap {
  int index;
  double length_m;
};

std::vector<std::vector<Overlap>> axis_overlaps(double src_origin, double src_h, int src_n, double dst_origin,
                                                double dst_h, int dst_n) {
  std::vector<std::vector<Overlap>> out(dst_n);
  for (int k = 0; k < dst_n; ++k) {
    const double a = dst_origin + k * dst_h;
    const double b = a + dst_h;
    const int first = std::max(0, static_cast<int>(std::floor((a - src_origin) / src_h)));
    const int last = std::min(src_n - 1, static_cast<int>(std::floor((b - src_origin) / src_h)));
    for (int s = first; s <= last; ++s) {
      const double lo = std::max(a, src_origin + s * src_h);
      const double hi = std::min(b, src_origin + (s + 1) * src_h);
      if (hi > lo) out[k].push_back({s, hi - lo});
    }
  }
  return out;
}

}  // namespace

HeightField resample_conservative(const HeightField& source, const Grid& target) {
  const Grid& s = source.grid();
  const auto ox = axis_overlaps(s.origin_x_m, s.cell_size_m, s.nx, target.origin_x_m, target.cell_size_m, target.nx);
  const auto oy = axis_overlaps(s.origin_y_m, s.cell_size_m, s.ny, target.origin_y_m, target.cell_size_m, target.ny);
  HeightField out(target, 0.0);
  const double inv_area = 1.0 / target.cell_area_m2();
  for (int j = 0; j < target.ny; ++j) {
    for (int i = 0; i < target.nx; ++i) {
      double v = 0.0;
      for (const Overlap& y : oy[j]) {
        for (const Overlap& x : ox[i]) v += source.at(x.index, y.index) * x.length_m * y.length_m;
      }
      out.at(i, j) = v * inv_area;
    }
  }
  return out;
}

HeightField resample_bilinear(const HeightField& source, const Grid& target) {
  HeightField out(target, 0.0);
  for (int j = 0; j < target.ny; ++j) {
    for (int i = 0; i < target.nx; ++i) out.at(i, j) = source.sample(target.centre_x(i), target.centre_y(j));
  }
  return out;
}

}  // namespace repose
