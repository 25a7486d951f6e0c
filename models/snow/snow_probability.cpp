#include "models/snow/snow_probability.h"

#include <random>

#include "models/snow/shadow_map.h"

namespace repose {

std::vector<Eigen::Vector3d> snowfall_directions(const SnowModel& model, const SnowParams& params) {
  std::mt19937_64 rng(model.seed);
  return draw_snowfall_directions(model.options.main_direction, params.direction_spread_rad,
                                  model.options.direction_count, &rng);
}

double shadow_pixel_m(const SnowModel& model) {
  return model.grid.cell_size_m / model.options.shadow_oversampling;
}

SnowProbability snow_probability_shadow_maps(const SnowModel& model, const std::vector<Eigen::Vector3d>& directions) {
  TopDownRenderer renderer(model.options.renderer);
  return snow_probability_shadow_maps(model, directions, &renderer);
}

SnowProbability snow_probability_shadow_maps(const SnowModel& model, const std::vector<Eigen::Vector3d>& directions,
                                             TopDownRenderer* renderer) {
  const Grid& g = model.grid;
  SnowProbability p;
  p.direction_count = static_cast<int>(directions.size());
  std::vector<Eigen::Array<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> lit_count(
      model.maps.size(), Eigen::Array<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>::Zero(g.ny, g.nx));
  for (const Eigen::Vector3d& travel : directions) {
    const ShadowMap shadow = render_shadow_map(model.occluders, model.maps, travel, shadow_pixel_m(model),
                                               model.options.shadow_bias_cells, renderer);
    for (std::size_t m = 0; m < model.maps.size(); ++m) {
      const SnowMap& map = model.maps[m];
      for (int j = 0; j < g.ny; ++j) {
        for (int i = 0; i < g.nx; ++i) {
          if (map.covered(i, j) && shadow.is_lit({g.centre_x(i), g.centre_y(j), map.base_z(i, j)})) {
            ++lit_count[m](j, i);
          }
        }
      }
    }
  }
  const double n = std::max<std::size_t>(1, directions.size());
  for (const auto& c : lit_count) p.per_map.push_back(c.cast<double>() / n);
  return p;
}

}  // namespace repose
