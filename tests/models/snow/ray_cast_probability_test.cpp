#include "models/snow/ray_cast_probability.h"

#include <gtest/gtest.h>

#include <numbers>

#include "snow_fixtures.h"

namespace repose {
namespace {

using testing::centred_grid;
using testing::plate;
using testing::plates_over_ground;

constexpr double kDeg = std::numbers::pi / 180.0;

// Vertical snow at spread 0: the rays and the shadow maps agree exactly
// (plate edges on cell borders, so no centre is near an edge).
TEST(RayCastProbability, AgreesExactlyWithShadowMapsForVerticalSnow) {
  const HeightField ground(centred_grid(20));
  const SnowModel model = plates_over_ground(ground, {plate(0.04, 0.03, 0.05)}, testing::vertical_snow_options(2));
  const auto dirs = snowfall_directions(model, SnowParams{0.5, 0.0});
  const SnowProbability rays = snow_probability_ray_cast(model, dirs);
  const SnowProbability maps = snow_probability_shadow_maps(model, dirs);
  for (std::size_t m = 0; m < 2; ++m) EXPECT_TRUE((rays.per_map[m] == maps.per_map[m]).all()) << m;
}

// Tilted, spread snow over two plates and a sphere: the two methods cast the
// same directions and differ only where a cell's point lies within a shadow
// map pixel of a shadow's edge. Stated tolerance: mean |dP| <= 0.03 over
// covered cells and no cell off by more than 0.5.
TEST(RayCastProbability, AgreesWithShadowMapsOnASmallScene) {
  HeightField ground(centred_grid(32));
  for (int j = 0; j < 32; ++j) {
    for (int i = 0; i < 32; ++i) ground.at(i, j) = 0.005 * std::sin(0.3 * i) * std::cos(0.2 * j);
  }
  Pose pose;
  pose.position_m = Eigen::Vector3d(-0.06, 0.06, 0.05);
  const TriangleMesh sphere = transformed(make_sphere(0.04, 24), pose);
  SnowOptions o = testing::vertical_snow_options(32);
  o.main_direction = {25 * kDeg, 30 * kDeg};
  std::vector<SnowGroupGeometry> groups = {{"ground", &ground, {}},
                                           {"plates", nullptr, {plate(0.05, 0.03, 0.08, 0.05, -0.04),
                                                                plate(0.04, 0.04, 0.04, 0.07, -0.07)}},
                                           {"sphere", nullptr, {sphere}}};
  o.groups = {{"ground", true, {}}, {"plates", false, {"a", "b"}}, {"sphere", false, {"s"}}};
  const SnowModel model = build_snow_model(groups, ground.grid(), o, TimeSpec{}, 3);
  const auto dirs = snowfall_directions(model, SnowParams{0.5, 10 * kDeg});
  const SnowProbability rays = snow_probability_ray_cast(model, dirs);
  const SnowProbability maps = snow_probability_shadow_maps(model, dirs);
  for (std::size_t m = 0; m < model.maps.size(); ++m) {
    const auto covered = model.maps[m].base.covered.cast<bool>();
    const ArrayXXdR diff = (rays.per_map[m] - maps.per_map[m]).abs();
    const double mean = covered.select(diff, 0.0).sum() / std::max<Eigen::Index>(1, covered.count());
    std::printf("  map %s: %ld cells, mean |dP| = %.4f, max |dP| = %.4f\n", model.maps[m].name.c_str(),
                static_cast<long>(covered.count()), mean, diff.maxCoeff());
    EXPECT_LE(mean, 0.03) << model.maps[m].name;
    EXPECT_LE(diff.maxCoeff(), 0.5) << model.maps[m].name;
  }
  // the scene does cast shadows: the comparison is not between two all-ones maps
  EXPECT_LT(maps.per_map[0].mean(), 0.9);
}

}  // namespace
}  // namespace repose
