#include "validation/particles/particle_observables.h"

#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "models/core/base/error.h"

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

// A bucket 0.1 m wide inside, 0.1 m tall: a floor box and four wall boxes, merged (overlapping at the corners).
TriangleMesh bucket() {
  const auto box = [](const Eigen::Vector3d& half, const Eigen::Vector3d& centre) {
    return transformed(make_box(half), Pose{centre, Eigen::Quaterniond::Identity()});
  };
  TriangleMesh m = box({0.06, 0.06, 0.005}, {0, 0, 0.005});   // floor: z 0 .. 0.01
  m = merged(m, box({0.005, 0.06, 0.05}, {0.055, 0, 0.05}));   // walls: z 0 .. 0.1
  m = merged(m, box({0.005, 0.06, 0.05}, {-0.055, 0, 0.05}));
  m = merged(m, box({0.06, 0.005, 0.05}, {0, 0.055, 0.05}));
  m = merged(m, box({0.06, 0.005, 0.05}, {0, -0.055, 0.05}));
  return m;
}

GrainSet grains_at(const std::vector<Eigen::Vector3d>& centres, double radius) {
  GrainSet g;
  g.position_m.resize(static_cast<Eigen::Index>(centres.size()), 3);
  for (std::size_t k = 0; k < centres.size(); ++k) g.position_m.row(static_cast<Eigen::Index>(k)) = centres[k].transpose();
  g.radius_m = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(centres.size()), radius);
  return g;
}

TEST(Observables, MassHeldByABucketCountsGrainsInsideItBelowTheRim) {
  const double r = 0.002, density = 2500.0;
  const double one = density * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const Eigen::Vector3d offset(0.3, -0.2, 0.05);  // the bucket placed away from the origin
  const TriangleMesh b = transformed(bucket(), Pose{offset, Eigen::Quaterniond::Identity()});
  const auto held = [&](const Eigen::Vector3d& c) { return mass_held_by_object_kg(grains_at({offset + c}, r), b, density); };
  // inside: resting on the floor, in a corner, just below the rim, inside a wall
  for (const Eigen::Vector3d& c : {Eigen::Vector3d(0, 0, 0.012), Eigen::Vector3d(0.048, 0.048, 0.03),
                                  Eigen::Vector3d(-0.02, 0.01, 0.099), Eigen::Vector3d(0.055, 0.0, 0.05),
                                  Eigen::Vector3d(0.0, 0.0, 0.005)}) {
    EXPECT_NEAR(held(c), one, 1e-12 * one) << c.transpose();
  }
  // not held: beside it, under it, above the rim (also right over a wall)
  for (const Eigen::Vector3d& c : {Eigen::Vector3d(0.08, 0, 0.05), Eigen::Vector3d(0, -0.2, 0.02),
                                  Eigen::Vector3d(0, 0, -0.01), Eigen::Vector3d(0, 0, 0.102),
                                  Eigen::Vector3d(0.055, 0, 0.12), Eigen::Vector3d(0.0, 0.0, 0.5)}) {
    EXPECT_EQ(held(c), 0.0) << c.transpose();
  }
  // many grains at once: two of the three are held
  const GrainSet g = grains_at({offset + Eigen::Vector3d(0, 0, 0.05), offset + Eigen::Vector3d(0.2, 0, 0.05),
                                offset + Eigen::Vector3d(0.01, 0.01, 0.02)},
                               r);
  EXPECT_NEAR(mass_held_by_object_kg(g, b, density), 2 * one, 1e-12 * one);
  EXPECT_EQ(mass_held_by_object_kg(g, TriangleMesh{}, density), 0.0);
}

TEST(Observables, AnUpsideDownBucketAndAClosedBodyHoldOnlyWhatIsInside) {
  const double r = 0.002, density = 1000.0;
  const double one = density * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  // upside down: the cavity opens downwards, so grains in it are not held
  const TriangleMesh flipped =
      transformed(bucket(), Pose{Eigen::Vector3d(0, 0, 0.1), Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi,
                                                                                                 Eigen::Vector3d::UnitX()))});
  EXPECT_EQ(mass_held_by_object_kg(grains_at({Eigen::Vector3d(0, 0, 0.05)}, r), flipped, density), 0.0);
  EXPECT_NEAR(mass_held_by_object_kg(grains_at({Eigen::Vector3d(0.055, 0, 0.05)}, r), flipped, density), one,
              1e-12 * one);  // inside a wall
  // a sphere: inside held, on top (above its top) not
  const TriangleMesh ball = make_sphere(0.05, 24);
  EXPECT_NEAR(mass_held_by_object_kg(grains_at({Eigen::Vector3d(0.01, -0.02, 0.03)}, r), ball, density), one,
              1e-12 * one);
  EXPECT_EQ(mass_held_by_object_kg(grains_at({Eigen::Vector3d(0, 0, 0.052)}, r), ball, density), 0.0);
  EXPECT_EQ(mass_held_by_object_kg(grains_at({Eigen::Vector3d(0.06, 0, 0)}, r), ball, density), 0.0);
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
