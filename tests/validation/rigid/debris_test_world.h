#pragma once
// A debris world the engine tests share: flat ground (a 200 m square of two
// triangles at z = 0, the plain at 0), an L-shaped house of two storeys
// (two convex pieces per storey: 6 joints), and, when asked, one heavy
// element thrown at the ground floor.

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include <gtest/gtest.h>

#include "models/terrain/building.h"
#include "models/terrain/terrain_surface.h"
#include "validation/rigid/debris_setup.h"
#include "validation/rigid/debris_world.h"

namespace repose::test_support {

inline TriangleMesh flat_ground_mesh() {
  TriangleMesh m;
  m.V.resize(4, 3);
  m.V << -100, -100, 0, 100, -100, 0, 100, 100, 0, -100, 100, 0;
  m.F.resize(2, 3);
  m.F << 0, 1, 2, 0, 2, 3;
  return m;
}

// An 8 x 6 m L (arms 3 m wide) of two 3 m storeys at 300 kg/m^3.
inline DebrisSetup house_on_flat_ground(double joint_break_force_n) {
  DebrisSetup setup;
  setup.spec.terrain = flat_ground_mesh();
  setup.scenery.terrain.mesh = setup.spec.terrain;
  setup.scenery.terrain.height_field =
      sample_height_field(TerrainSurface(setup.spec.terrain), covering_grid(setup.spec.terrain, 4.0), 0.0);
  BuildingFootprint house{"house", {{0, 0}, {8, 0}, {8, 3}, {3, 3}, {3, 6}, {0, 6}}, 2, 3.0, 0.02};
  house.joint_break_force_n = joint_break_force_n;
  append_building(house, building_parts(house, TerrainSurface(setup.spec.terrain)), setup);
  // one element at rest far from the house, so the world has elements
  setup.spec.elements.push_back({Eigen::Vector3d(-50, -50, 0.5), Eigen::Vector3d::Zero(), 0.5});
  return setup;
}

// A 1 m element of 20 t/m^3 (84 t) at speed_m_s towards the house's long
// wall (y = 0) at the ground floor's mid height, starting 2 m from it.
inline void throw_at_house(DebrisSetup& setup, double speed_m_s) {
  setup.spec.elements.push_back(
      {Eigen::Vector3d(4.0, -3.0, 1.6), Eigen::Vector3d(0, speed_m_s, 0), 1.0, 20000.0, 0.5, 0.1, 0.1});
}

struct HouseOutcome {
  int joints_broken = 0;
  double max_part_displacement_m = 0.0;
};

inline HouseOutcome run_house(DebrisWorld& world, const DebrisSetup& setup, double duration_s) {
  const long steps = std::lround(duration_s / world.time_step_s());
  for (long s = 0; s < steps; ++s) world.step();
  HouseOutcome out;
  for (bool b : world.joints_broken()) out.joints_broken += b ? 1 : 0;
  const std::vector<Pose> poses = world.part_poses();
  for (std::size_t p = 0; p < poses.size(); ++p) {
    out.max_part_displacement_m =
        std::max(out.max_part_displacement_m, (poses[p].position_m - setup.spec.parts[p].centre_m).norm());
  }
  return out;
}

// The house checks every rigid engine passes, given how it makes its world.
using MakeDebrisWorld = std::function<std::unique_ptr<DebrisWorld>(const DebrisWorldSpec&)>;

// The house weighs 8 x 6 - 5 x 3 = 33 m^2 x 2.98 m x 300 kg/m^3 x 2 storeys
// = 58 t (5.8e5 N); a ground joint carries at most that.
constexpr double kStrongJointN = 2.0e6;

inline void expect_an_untouched_house_stands(const MakeDebrisWorld& make_world) {
  const DebrisSetup setup = house_on_flat_ground(kStrongJointN);
  ASSERT_EQ(setup.spec.joints.size(), 6u);
  const auto world = make_world(setup.spec);
  const HouseOutcome out = run_house(*world, setup, 3.0);
  EXPECT_EQ(out.joints_broken, 0);
  EXPECT_LT(out.max_part_displacement_m, 1e-3);
  // the ground joints carry the house's weight (the parts start clear of the ground)
  double max_force_n = 0.0;
  for (double f : world->joint_forces_n()) max_force_n = std::max(max_force_n, f);
  EXPECT_GT(max_force_n, 0.1 * 5.8e5);
  EXPECT_LT(max_force_n, kStrongJointN);
}

inline void expect_a_heavy_fast_body_breaks_the_house(const MakeDebrisWorld& make_world) {
  DebrisSetup setup = house_on_flat_ground(kStrongJointN);
  throw_at_house(setup, 30.0);  // 84 t at 30 m/s: 2.5e6 N s, far beyond 2e6 N over a step
  const auto world = make_world(setup.spec);
  const HouseOutcome out = run_house(*world, setup, 1.0);
  EXPECT_GT(out.joints_broken, 0);
  EXPECT_GT(out.max_part_displacement_m, 0.1);
}

inline void expect_a_slow_body_leaves_a_strong_house_standing(const MakeDebrisWorld& make_world) {
  DebrisSetup setup = house_on_flat_ground(1.0e9);
  throw_at_house(setup, 1.0);
  const auto world = make_world(setup.spec);
  EXPECT_EQ(run_house(*world, setup, 1.0).joints_broken, 0);
}

// An element resting on the roof of the house's highest part: after it
// settles, the elements' force on that part is the element's weight
// (straight down), on every other part nothing.
inline void expect_a_resting_element_weighs_on_its_part(const MakeDebrisWorld& make_world) {
  DebrisSetup setup = house_on_flat_ground(kStrongJointN);
  std::size_t top = 0;
  for (std::size_t p = 0; p < setup.spec.parts.size(); ++p) {
    if (setup.spec.parts[p].centre_m.z() > setup.spec.parts[top].centre_m.z()) top = p;
  }
  const DebrisPart& roof = setup.spec.parts[top];
  DebrisElement rock;
  rock.radius_m = 0.5;
  rock.centre_m = roof.centre_m + Eigen::Vector3d(0, 0, roof.half_extents_m.z() + rock.radius_m + 0.01);
  setup.spec.elements.push_back(rock);
  const double weight_n = rock.density_kg_m3 * 4.0 / 3.0 * M_PI * std::pow(rock.radius_m, 3) * setup.spec.gravity_m_s2;
  const auto world = make_world(setup.spec);
  const long steps = std::lround(1.0 / world->time_step_s());
  Eigen::Vector3d mean_n = Eigen::Vector3d::Zero();  // over the last fifth of a second
  const long averaged = std::lround(0.2 / world->time_step_s());
  double others_n = 0.0;
  for (long s = 1; s <= steps; ++s) {
    world->step();
    if (s <= steps - averaged) continue;
    const std::vector<Eigen::Vector3d> f = world->part_element_forces_n();
    mean_n += f[top] / static_cast<double>(averaged);
    for (std::size_t p = 0; p < f.size(); ++p) others_n = std::max(others_n, p == top ? 0.0 : f[p].norm());
  }
  EXPECT_NEAR(mean_n.z(), -weight_n, 0.02 * weight_n);
  EXPECT_LT(mean_n.head<2>().norm(), 0.02 * weight_n);
  EXPECT_EQ(others_n, 0.0);
}

// A 10.5 t element (r = 1 m) launched at 3 m/s along flat ground, far from
// the house: it slides until it rolls (at 5/7 of its speed, a solid
// sphere), then rolling resistance (torque mu_r r N) decelerates it at
// mu_r g / 1.4; it stops within 1.4 v_roll^2 / (2 mu_r g) plus the short
// slide (here 0.45 m). Rolling resistance must hold at tonne scale too.
inline void expect_rolling_resistance_stops_a_heavy_element(const MakeDebrisWorld& make_world) {
  DebrisSetup setup = house_on_flat_ground(kStrongJointN);
  DebrisElement rock;
  rock.radius_m = 1.0;
  rock.friction = 0.5;
  rock.rolling_friction = 0.1;
  rock.restitution = 0.1;
  rock.centre_m = Eigen::Vector3d(-40, 40, rock.radius_m);
  rock.velocity_m_s = Eigen::Vector3d(3.0, 0, 0);
  setup.spec.elements = {rock};
  const double v_roll = 3.0 * 5.0 / 7.0;
  const double expected_m = 0.45 + 1.4 * v_roll * v_roll / (2.0 * rock.rolling_friction * setup.spec.gravity_m_s2);
  const auto world = make_world(setup.spec);
  const long steps = std::lround(6.0 / world->time_step_s());
  for (long s = 0; s < steps; ++s) world->step();
  const GrainSet g = world->elements();
  EXPECT_NEAR(g.position_m(0, 0) - rock.centre_m.x(), expected_m, 0.2 * expected_m);
  EXPECT_LT(g.velocity_m_s.row(0).norm(), 0.05);
}

}  // namespace repose::test_support
