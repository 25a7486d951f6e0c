#pragma once
// Physics checks every rigid-body reference engine must pass (Bullet, ODE),
// written once: tiny worlds and what they must show.



#include <algorithm>
#include <numbers>
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"
#include "validation/particles/particle_observables.h"
#include "validation/rigid/rigid_bed_cache.h"
#include "validation/rigid/rigid_engine.h"
#include "validation/rigid/rigid_reference.h"
#include "validation/rigid/rigid_setup.h"

namespace repose::test_support {

// A small bed: 2 cm x 2 cm, 1 cm deep of r = 2 mm +-10 % grains (about 70).
inline RigidInputs tiny_bed(std::uint64_t seed) {
  RigidInputs in;
  in.grid = Grid{5, 5, 0.004, 0.0, 0.0};
  in.dem.bed_depth_m = 0.01;
  in.time = TimeSpec{0.01, 0.1};
  in.seed = seed;
  return in;
}

// One grain of radius r on (or above) the floor of a wide ground box, with
// the contact law law, and the given initial velocities.
inline RigidWorldSpec one_grain(double r_m, const Eigen::Vector3d& at_m, const Eigen::Vector3d& v_m_s,
                                const Eigen::Vector3d& w_rad_s, const RigidContactLaw& law) {
  RigidInputs in;
  in.grid = Grid{10, 10, 0.1, -0.5, -0.5};  // 1 m x 1 m
  in.dem.grain_radius_m = r_m;
  in.dem.radius_spread = 0.0;
  in.dem.friction = law.friction;
  in.dem.restitution = law.restitution;
  in.dem.rolling_friction = law.rolling_friction;
  GrainSet g;
  g.position_m = at_m.transpose();
  g.radius_m = Eigen::VectorXd::Constant(1, r_m);
  RigidWorldSpec spec = run_world(in, g);
  spec.walls.front().rolling_friction = law.rolling_friction;
  spec.velocity_m_s = v_m_s.transpose();
  spec.angular_velocity_rad_s = w_rad_s.transpose();
  return spec;
}

struct Roll {
  double stop_distance_m = 0.0;
  double stop_time_s = 0.0;
};

// A grain rolling along +x without slipping at v0 (omega = v0 / r about +y):
// steps until it stops (x stops growing for 10 steps), or 2 s.
inline Roll roll_until_stopped(const RigidEngine& engine, double r_m, double v0_m_s, double mu_r) {
  const RigidContactLaw law{0.5, 0.5, mu_r};
  const auto world = engine.make_world(
      one_grain(r_m, {0.0, 0.0, r_m}, {v0_m_s, 0.0, 0.0}, {0.0, v0_m_s / r_m, 0.0}, law));
  Roll roll;
  double x_max = 0.0;
  int still = 0;
  const double dt = world->time_step_s();
  for (long k = 1; k * dt < 2.0 && still < 10; ++k) {
    world->step();
    const double x = world->grains().position_m(0, 0);
    if (x > x_max + 1e-9) {
      x_max = x;
      roll.stop_time_s = k * dt;
      still = 0;
    } else {
      ++still;
    }
  }
  roll.stop_distance_m = x_max;
  return roll;
}

// A grain dropped from rest with its bottom at drop_m above the floor: the
// height of its bottom at the top of the first rebound.
inline double rebound_height_m(const RigidEngine& engine, double r_m, double drop_m, double restitution) {
  const RigidContactLaw law{0.5, restitution, 0.0};
  const auto world = engine.make_world(one_grain(r_m, {0.0, 0.0, r_m + drop_m}, Eigen::Vector3d::Zero(),
                                                 Eigen::Vector3d::Zero(), law));
  double z_prev = r_m + drop_m;
  bool rising = false;
  for (int k = 0; k < 100000; ++k) {
    world->step();
    const double z = world->grains().position_m(0, 2);
    if (z > z_prev) rising = true;
    if (rising && z < z_prev) return z_prev - r_m;  // passed the top
    z_prev = z;
  }
  return -1.0;
}


// A grain resting on a kinematic plate (an object) pushes it down by its
// weight: the object's force is (0, 0, -m g) once the grain is at rest; and
// a grain falling freely under gravity tilted by 30 degrees (a chute) gains
// g t along the tilted direction, its velocity read back by grains().
inline void expect_object_force_and_tilted_gravity(const RigidEngine& engine) {
  const double r = 0.005, g = 9.81, rho = 2500.0;
  const double m = rho * 4.0 / 3.0 * M_PI * r * r * r;
  RigidWorldSpec spec = one_grain(r, {0.0, 0.0, 0.11 + r + 0.001}, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                  RigidContactLaw{0.5, 0.1, 0.1});
  ObjectSpec plate;
  plate.name = "plate";
  plate.shape = ObjectSpec::Shape::kBox;
  plate.half_extents_m = Eigen::Vector3d(0.05, 0.05, 0.01);
  plate.body = make_box(plate.half_extents_m);
  plate.keyframes = {{0.0, Pose{Eigen::Vector3d(0, 0, 0.1), Eigen::Quaterniond::Identity()}}};
  spec.objects = {plate};
  const auto world = engine.make_world(spec);
  const long steps = std::lround(0.5 / world->time_step_s());
  for (long k = 0; k < steps; ++k) {
    world->set_object_poses({plate.keyframes.front().pose});
    world->step();
  }
  const std::vector<Eigen::Vector3d> f = world->object_forces_n();
  ASSERT_EQ(f.size(), 1u);
  EXPECT_NEAR(f[0].z(), -m * g, 0.05 * m * g);
  EXPECT_NEAR(f[0].x(), 0.0, 0.01 * m * g);
  ASSERT_EQ(world->grains().velocity_m_s.rows(), 1);
  EXPECT_LT(world->grains().velocity_m_s.row(0).norm(), 0.01);

  RigidWorldSpec fall = one_grain(r, {0.0, 0.0, 0.5}, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                  RigidContactLaw{0.5, 0.1, 0.1});
  const double a = M_PI / 6.0;
  fall.gravity_direction = Eigen::Vector3d(std::sin(a), 0.0, -std::cos(a));
  const auto falling = engine.make_world(fall);
  const long n = std::lround(0.1 / falling->time_step_s());
  for (long k = 0; k < n; ++k) falling->step();
  const Eigen::Vector3d v = falling->grains().velocity_m_s.row(0).transpose();
  const Eigen::Vector3d expected = g * static_cast<double>(n) * falling->time_step_s() * fall.gravity_direction;
  EXPECT_NEAR((v - expected).norm(), 0.0, 1e-6 + 0.01 * expected.norm());
}

inline bool same_bits(const GrainSet& a, const GrainSet& b) {
  return a.size() == b.size() && a.position_m == b.position_m && a.radius_m == b.radius_m;
}

// A tiny bed settles: every grain asked for is there, inside the box, and
// the kinetic energy is below the threshold; a second call reads the same
// bits back from the cache.
inline void expect_bed_settles(const RigidEngine& engine) {
  const TempDir cache("rigid_bed");
  const RigidInputs in = tiny_bed(7);
  const RigidBed bed = settled_rigid_bed(engine, in, cache.path.string());
  EXPECT_FALSE(bed.from_cache);
  EXPECT_EQ(bed.grains.size(), rigid_grain_count(in, engine.rigid));
  EXPECT_GT(bed.grains.size(), 50);
  EXPECT_TRUE(lost_grains(bed.grains, settling_world(in, engine.rigid).bounds).empty());
  EXPECT_TRUE(bed.settle.settled);
  EXPECT_LT(bed.settle.kinetic_energy_j, settle_threshold_j(engine.rigid, in.dem, bed.grains));
  // settled: no grain floats above the bed's depth by more than a grain
  EXPECT_LT(bed.grains.position_m.col(2).maxCoeff(), in.dem.bed_depth_m + 2 * in.dem.grain_radius_m);
  const RigidBed again = settled_rigid_bed(engine, in, cache.path.string());
  EXPECT_TRUE(again.from_cache);
  EXPECT_TRUE(same_bits(bed.grains, again.grains));
}

// The same inputs settle to the same bits in a fresh cache; another seed does not.
inline void expect_repeats_bit_identically(const RigidEngine& engine) {
  const TempDir a("rigid_a"), b("rigid_b"), c("rigid_c");
  const RigidBed first = settled_rigid_bed(engine, tiny_bed(3), a.path.string());
  const RigidBed second = settled_rigid_bed(engine, tiny_bed(3), b.path.string());
  const RigidBed other = settled_rigid_bed(engine, tiny_bed(4), c.path.string());
  EXPECT_FALSE(second.from_cache);
  EXPECT_TRUE(same_bits(first.grains, second.grains));
  EXPECT_FALSE(same_bits(first.grains, other.grains));
}

// A sphere pressed into a tiny bed and lifted out: no grain lost, all the
// grain volume accounted for on the grid, and a dent where it pressed.
inline void expect_indentation_leaves_a_dent(const RigidEngine& engine) {
  const TempDir cache("rigid_ref");
  RigidInputs in = tiny_bed(5);
  in.grid = Grid{8, 8, 0.004, 0.0, 0.0};  // 3.2 cm square
  in.time = TimeSpec{0.01, 0.2};
  ObjectSpec ball;
  ball.name = "ball";
  ball.shape = ObjectSpec::Shape::kSphere;
  ball.radius_m = 0.008;
  ball.body = make_sphere(ball.radius_m);
  Keyframe k0, k1, k2;
  k0.time_s = 0.0, k1.time_s = 0.1, k2.time_s = 0.2;
  k0.pose.position_m = {0.016, 0.016, 0.020};
  k1.pose.position_m = {0.016, 0.016, 0.012};  // bottom 6 mm below the 1 cm surface
  k2.pose.position_m = {0.016, 0.016, 0.020};
  ball.keyframes = {k0, k1, k2};
  in.objects = {ball};
  RigidReferenceOptions options;
  options.cache_dir = cache.path.string();
  const RigidReferenceResult r = run_rigid_reference(engine, in, options);
  EXPECT_EQ(r.grains_final.size(), r.grains_initial.size());
  EXPECT_EQ(r.run.steps, std::lround(std::ceil(0.2 / engine.rigid.time_step_s)));
  const double on_grid = r.material_per_area_final.volume_m3();
  EXPECT_NEAR(on_grid, grain_volume_m3(r.grains_final), 1e-12);
  // the four centre cells: lower after the sphere pressed in
  double before = 0.0, after = 0.0;
  for (int i = 3; i <= 4; ++i) {
    for (int j = 3; j <= 4; ++j) {
      before += r.height_initial.at(i, j) / 4;
      after += r.height_final.at(i, j) / 4;
    }
  }
  EXPECT_LT(after, before - in.dem.grain_radius_m) << "before " << before << " after " << after;
  ASSERT_EQ(r.mass_held_kg.size(), 1u);
  EXPECT_EQ(r.mass_held_kg[0].first, "ball");
  EXPECT_GT(r.particle_steps_per_cpu_s, 0.0);
}


// A small cylinder column (r 1.2 cm, 1.2 cm high) released on a rough floor
// spreads: its front moves out, no grain is lost, the pile is lower than the column.
inline void expect_column_spreads(const RigidEngine& engine) {
  const TempDir cache("rigid_column");
  RigidInputs in = tiny_bed(9);
  in.grid = Grid{15, 15, 0.004, 0.0, 0.0};  // 6 cm square
  in.time = TimeSpec{0.01, 0.3};
  in.dem.initial = DemSpec::Initial::kColumn;
  in.dem.column_shape = DemSpec::ColumnShape::kCylinder;
  in.dem.column_width_m = 0.012;
  in.dem.column_height_m = 0.012;
  in.dem.floor = DemSpec::Floor::kRough;
  in.dem.dump_interval_s = 0.05;
  ColumnGeometry c;
  c.shape = DemSpec::ColumnShape::kCylinder;
  c.axis_xy_m = {0.03, 0.03};
  c.width_m = 0.012;
  c.height_m = 0.012;
  c.footprint_m2 = std::numbers::pi * 0.012 * 0.012;
  in.column = c;
  RigidReferenceOptions options;
  options.cache_dir = cache.path.string();
  const RigidReferenceResult r = run_rigid_reference(engine, in, options);
  ASSERT_TRUE(r.column.has_value());
  ASSERT_TRUE(r.pile.has_value());
  EXPECT_EQ(r.grains_final.size(), r.grains_initial.size());
  EXPECT_GT(r.column->front_final_m, r.column->front_initial_m + in.dem.grain_radius_m);
  EXPECT_LT(r.column->height_final_m, r.column->height_initial_m);
  EXPECT_EQ(r.column->time_s.size(), 6u);  // every 0.05 s over 0.3 s
}

}  // namespace repose::test_support
