#include "validation/particles/surface_height.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/core/base/error.h"

namespace repose {

HeightField surface_height(const GrainSet& grains, const Grid& grid, const SurfaceHeightOptions& options) {
  constexpr double kUncovered = -std::numeric_limits<double>::infinity();
  ArrayXXdR top = ArrayXXdR::Constant(grid.ny, grid.nx, kUncovered);
  const double h = grid.cell_size_m;
  const int n = options.samples_per_axis;
  REPOSE_DEMAND(n >= 1);
  REPOSE_DEMAND(std::isfinite(options.probe_radius_m) && options.probe_radius_m >= 0.0);
  for (Eigen::Index g = 0; g < grains.size(); ++g) {
    const double x = grains.position_m(g, 0), y = grains.position_m(g, 1), z = grains.position_m(g, 2);
    const double r = grains.radius_m[g] + options.probe_radius_m;  // the grain as the probe's centre sees it
    // cells that overlap the grain's horizontal disk
    const int i0 = std::max(0, static_cast<int>(std::floor((x - r - grid.origin_x_m) / h)));
    const int i1 = std::min(grid.nx - 1, static_cast<int>(std::floor((x + r - grid.origin_x_m) / h)));
    const int j0 = std::max(0, static_cast<int>(std::floor((y - r - grid.origin_y_m) / h)));
    const int j1 = std::min(grid.ny - 1, static_cast<int>(std::floor((y + r - grid.origin_y_m) / h)));
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        for (int sj = 0; sj < n; ++sj) {
          for (int si = 0; si < n; ++si) {
            const double dx = grid.origin_x_m + (i + (si + 0.5) / n) * h - x;
            const double dy = grid.origin_y_m + (j + (sj + 0.5) / n) * h - y;
            const double d2 = dx * dx + dy * dy;
            if (d2 < r * r) top(j, i) = std::max(top(j, i), z + std::sqrt(r * r - d2) - options.probe_radius_m);
          }
        }
      }
    }
  }
  HeightField out(grid, 0.0);
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      if (top(j, i) != kUncovered) {
        out.at(i, j) = std::max(top(j, i), 0.0);  // a probe stops on the floor at the latest
        continue;
      }
      int covered = 0, neighbours = 0;
      double lowest = std::numeric_limits<double>::infinity();
      for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
          if ((di == 0 && dj == 0) || !grid.contains(i + di, j + dj)) continue;
          ++neighbours;
          const double t = top(j + dj, i + di);
          if (t == kUncovered) continue;
          ++covered;
          lowest = std::min(lowest, t);
        }
      }
      const bool gap = covered > 0 && covered >= options.gap_covered_fraction * neighbours;
      out.at(i, j) = gap ? lowest : 0.0;
    }
  }
  return out;
}

}  // namespace repose
