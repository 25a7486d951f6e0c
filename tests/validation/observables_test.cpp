#include "validation/observables.h"

#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "models/core/error.h"

namespace repose {
namespace {

GrainSet random_grains(int count, double extent, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, extent), r(0.001, 0.002);
  GrainSet g;
  g.position_m.resize(count, 3);
  g.radius_m.resize(count);
  for (int k = 0; k < count; ++k) {
    g.position_m.row(k) << u(rng), u(rng), u(rng);
    g.radius_m[k] = r(rng);
  }
  return g;
}

TEST(Observables, MaterialPerAreaConservesGrainVolume) {
  const GrainSet g = random_grains(500, 0.05, 1);
  const Grid grid{10, 10, 0.005, 0.0, 0.0};
  const HeightField m = material_per_area(g, grid);
  EXPECT_NEAR(m.volume_m3(), grain_volume_m3(g), 1e-12 * grain_volume_m3(g) + 1e-18);
  const HeightField h = equivalent_height(g, grid, 0.6);
  EXPECT_NEAR(h.volume_m3() * 0.6, grain_volume_m3(g), 1e-9 * grain_volume_m3(g));
  EXPECT_THROW(equivalent_height(g, grid, 0.0), InputError);
  // grains outside the grid are left out
  const Grid half{5, 10, 0.005, 0.0, 0.0};
  EXPECT_LT(material_per_area(g, half).volume_m3(), grain_volume_m3(g));
}

TEST(Observables, MassInBoxCountsGrainsByCentre) {
  GrainSet g;
  g.position_m.resize(3, 3);
  g.position_m << 0.1, 0.1, 0.1, 0.5, 0.5, 0.5, 0.9, 0.9, 0.9;
  g.radius_m = Eigen::VectorXd::Constant(3, 0.01);
  Aabb box;
  box.extend(Eigen::Vector3d(0, 0, 0));
  box.extend(Eigen::Vector3d(0.6, 0.6, 0.6));
  const double one = 2500.0 * 4.0 / 3.0 * std::numbers::pi * 1e-6;
  EXPECT_NEAR(mass_in_box_kg(g, box, 2500.0), 2 * one, 1e-15);
}

TEST(Observables, FrontPositionIsTheQuantileAlongTheDirection) {
  GrainSet g;
  const int n = 101;
  g.position_m.resize(n, 3);
  g.radius_m = Eigen::VectorXd::Constant(n, 0.001);
  for (int k = 0; k < n; ++k) g.position_m.row(k) << 0.0, 0.01 * k, 0.0;  // 0 .. 1 m along y
  EXPECT_NEAR(front_position_m(g, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 2, 0), 0.99), 0.99, 1e-12);
  EXPECT_NEAR(front_position_m(g, Eigen::Vector3d(0, 0.5, 0), Eigen::Vector3d::UnitY(), 1.0), 0.5, 1e-12);
  EXPECT_NEAR(front_position_m(g, Eigen::Vector3d::Zero(), -Eigen::Vector3d::UnitY(), 1.0), 0.0, 1e-12);
  EXPECT_THROW(front_position_m(GrainSet{}, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()), InputError);
}

// A cone of known slope: every ray's fitted angle is the cone's.
TEST(Observables, FlankAnglesOfAnAnalyticCone) {
  const double angle = 32.0 * std::numbers::pi / 180.0, peak = 0.05;
  const Grid grid{200, 200, 0.001, -0.1, -0.1};
  HeightField h(grid, 0.0);
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      const double r = std::hypot(grid.centre_x(i), grid.centre_y(j));
      h.at(i, j) = std::max(0.0, peak - std::tan(angle) * r);
    }
  }
  const FlankAngles a = pile_flank_angles(h, Eigen::Vector2d::Zero());
  EXPECT_EQ(a.angle_rad.size(), 16u);
  EXPECT_NEAR(a.mean_rad, angle, 0.01);
  EXPECT_LT(a.std_rad, 0.01);
  EXPECT_THROW(pile_flank_angles(HeightField(grid, 0.0), Eigen::Vector2d::Zero()), InputError);
}

}  // namespace
}  // namespace repose
