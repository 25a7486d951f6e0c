#pragma once
// The snow probability (the snow paper 2.2, Fig. 4 and 5): per snow-map
// cell, the fraction of snowfall directions for which the cell's surface
// point (cell centre at the map's z) is lit by that direction's shadow map
// over all groups. Cells outside a map's snow-possible area get 0.
//
// P is computed once from the snow-free scene and held constant while snow
// accumulates, as the paper does while animating (2.3): the snow's own
// shadow is ignored.
//
// Error: P from N directions is a mean of N Bernoulli draws per cell, so its
// error falls as 1/sqrt(N) (measured in snow_probability_test.cpp).

#include <vector>

#include <Eigen/Core>

#include "models/core/geometry/height_field.h"
#include "models/snow/snow_model.h"
#include "models/snow/snow_params.h"

namespace repose {

struct SnowProbability {
  std::vector<ArrayXXdR> per_map;  // ny x nx each, in [0, 1], indexed like SnowModel::maps
  int direction_count = 0;
};

// The model's directions for these params: draw_snowfall_directions seeded
// with the model's seed (the same seed and params give the same directions).
std::vector<Eigen::Vector3d> snowfall_directions(const SnowModel& model, const SnowParams& params);

// Shadow maps along each direction (rendered by the model's renderer kind).
SnowProbability snow_probability_shadow_maps(const SnowModel& model, const std::vector<Eigen::Vector3d>& directions);
SnowProbability snow_probability_shadow_maps(const SnowModel& model, const std::vector<Eigen::Vector3d>& directions,
                                             TopDownRenderer* renderer);

// The pixel side of the model's shadow maps, and the bias both probability
// methods use for a direction (shadow_map.h).
double shadow_pixel_m(const SnowModel& model);

}  // namespace repose
