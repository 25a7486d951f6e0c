#include "validation/liggghts/grain_snow_depth.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/core/base/error.h"

namespace repose {

std::vector<int> snow_map_of_grains(const GrainSet& grains, const std::vector<SnowMap>& maps) {
  std::vector<int> out(static_cast<std::size_t>(grains.size()), -1);
  if (maps.empty()) return out;
  const Grid& g = maps.front().grid();
  const auto cell = [&](double v, double origin, int n) {
    return std::clamp(static_cast<int>(std::floor((v - origin) / g.cell_size_m)), 0, n - 1);
  };
  for (Eigen::Index k = 0; k < grains.size(); ++k) {
    const double x = grains.position_m(k, 0), y = grains.position_m(k, 1), z = grains.position_m(k, 2);
    const double r = grains.radius_m(k);
    if (x < g.origin_x_m || y < g.origin_y_m || x >= g.origin_x_m + g.extent_x_m() || y >= g.origin_y_m + g.extent_y_m()) {
      continue;
    }
    // the highest surface under the grain's footprint that is not above its centre
    double best = -std::numeric_limits<double>::infinity();
    for (int j = cell(y - r, g.origin_y_m, g.ny); j <= cell(y + r, g.origin_y_m, g.ny); ++j) {
      for (int i = cell(x - r, g.origin_x_m, g.nx); i <= cell(x + r, g.origin_x_m, g.nx); ++i) {
        for (std::size_t m = 0; m < maps.size(); ++m) {
          if (!maps[m].covered(i, j)) continue;
          const double base = maps[m].base_z(i, j);
          if (base <= z && base > best) {
            best = base;
            out[static_cast<std::size_t>(k)] = static_cast<int>(m);
          }
        }
      }
    }
  }
  return out;
}

std::vector<ArrayXXdR> grain_snow_depth(const GrainSet& grains, const std::vector<SnowMap>& maps,
                                        const SurfaceHeightOptions& surface) {
  const std::vector<int> map_of = snow_map_of_grains(grains, maps);
  std::vector<ArrayXXdR> depth;
  for (std::size_t m = 0; m < maps.size(); ++m) {
    const Grid& g = maps[m].grid();
    REPOSE_DEMAND(g.nx == maps.front().grid().nx && g.ny == maps.front().grid().ny);
    GrainSet mine;
    const auto count = std::count(map_of.begin(), map_of.end(), static_cast<int>(m));
    mine.position_m.resize(count, 3);
    mine.radius_m.resize(count);
    for (Eigen::Index k = 0, n = 0; k < grains.size(); ++k) {
      if (map_of[static_cast<std::size_t>(k)] != static_cast<int>(m)) continue;
      mine.position_m.row(n) = grains.position_m.row(k);
      mine.radius_m(n++) = grains.radius_m(k);
    }
    ArrayXXdR d = ArrayXXdR::Zero(g.ny, g.nx);
    if (count > 0) {
      const HeightField top = surface_height(mine, g, surface);
      for (int j = 0; j < g.ny; ++j) {
        for (int i = 0; i < g.nx; ++i) {
          if (maps[m].covered(i, j)) d(j, i) = std::max(0.0, top.at(i, j) - maps[m].base_z(i, j));
        }
      }
    }
    depth.push_back(std::move(d));
  }
  return depth;
}

}  // namespace repose
