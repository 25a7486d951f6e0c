#pragma once
// A debris world the engine tests share: flat ground (a 200 m square of two
// triangles at z = 0, the plain at 0), an L-shaped house of two storeys
// (two convex pieces per storey: 6 joints), and, when asked, one heavy
// element thrown at the ground floor.

#include <algorithm>
#include <cmath>
#include <memory>

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

}  // namespace repose::test_support
