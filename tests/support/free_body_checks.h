#pragma once
// Free-body checks every rigid-body reference engine must pass (Bullet,
// ODE), written once: a body dropped on the bare floor, a sphere dropped
// into a small bed.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/rigid_checks.h"
#include "validation/particles/free_body_track.h"
#include "validation/rigid/rigid_simulation.h"

namespace repose::test_support {

// A free sphere of radius r (or, with box, a cube of half side r) of density
// 7800 kg/m^3 at rest with its lowest point drop_m above the floor.
inline ObjectSpec free_body(bool box, double r_m, const Eigen::Vector3d& centre_m) {
  ObjectSpec o;
  o.name = box ? "cube" : "ball";
  o.shape = box ? ObjectSpec::Shape::kBox : ObjectSpec::Shape::kSphere;
  o.radius_m = r_m;
  o.half_extents_m = Eigen::Vector3d::Constant(r_m);
  o.body = box ? make_box(o.half_extents_m) : make_sphere(r_m);
  DynamicBody d;
  d.density_kg_m3 = 7800.0;
  d.position_m = centre_m;
  o.dynamic = d;
  o.keyframes = {Keyframe{0.0, Pose{centre_m, Eigen::Quaterniond::Identity()}}};
  return o;
}

// The body dropped on the floor of a wide ground box (one 2 mm grain lies in
// a far corner): the height of its lowest point at the top of its first rebound.
inline double free_body_rebound_m(const RigidEngine& engine, bool box, double r_m, double drop_m, double restitution) {
  const RigidContactLaw law{0.5, restitution, 0.0};
  RigidWorldSpec spec = one_grain(0.002, {0.4, 0.4, 0.002}, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), law);
  spec.bodies = {free_body(box, r_m, {0.0, 0.0, r_m + drop_m})};
  const auto world = engine.make_world(spec);
  double z_prev = r_m + drop_m;
  bool rising = false;
  for (int k = 0; k < 100000; ++k) {
    world->step();
    const double z = world->free_bodies().at(0).pose.position_m.z();
    if (z > z_prev) rising = true;
    if (rising && z < z_prev) return z_prev - r_m;  // passed the top
    z_prev = z;
  }
  return -1.0;
}

// A sphere and a cube dropped on the bare floor rebound to e^2 times the drop
// (the rebound speed within 0.03 of e times the impact speed), at a step that
// resolves the impact.
inline void expect_free_bodies_rebound(const RigidEngine& engine) {
  const double r = 0.01, drop = 0.05;
  for (bool box : {false, true}) {
    for (double e : {0.3, 0.5, 0.8}) {
      const double h = free_body_rebound_m(engine, box, r, drop, e);
      EXPECT_NEAR(std::sqrt(std::max(h, 0.0) / drop), e, 0.03) << (box ? "cube" : "sphere") << ", restitution " << e;
    }
  }
}

// A free steel sphere (r 1 cm) high above the floor under a constant torque
// about z (dynamic.torque_n_m): in 0.1 s of free fall, touching nothing, its
// spin grows as tau t / I with I = 2/5 m r^2, about z only.
inline void expect_torque_spins_up_a_free_body(const RigidEngine& engine) {
  const RigidContactLaw law{0.5, 0.3, 0.0};
  RigidWorldSpec spec = one_grain(0.002, {0.4, 0.4, 0.002}, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), law);
  const double r = 0.01, tau = 1.0e-4;
  ObjectSpec ball = free_body(false, r, {0.0, 0.0, 1.0});
  ball.dynamic->torque_n_m = {0.0, 0.0, tau};
  spec.bodies = {ball};
  const auto world = engine.make_world(spec);
  const int steps = static_cast<int>(std::lround(0.1 / world->time_step_s()));
  for (int k = 0; k < steps; ++k) world->step();
  const double inertia = 0.4 * ball.mass_kg() * r * r, expected = tau * steps * world->time_step_s() / inertia;
  const Eigen::Vector3d w = world->free_bodies().at(0).angular_velocity_rad_s;
  EXPECT_NEAR(w.z(), expected, 1e-3 * expected);
  EXPECT_NEAR(w.head<2>().norm(), 0.0, 1e-9 * expected);
}

// A free mesh (a closed box mesh, 2 cm, turned 30 deg about x) dropped 2 cm
// on the bare floor lands on it and stays there: its lowest vertex within
// 1 mm of the floor after 1 s. With rests, it has also come to rest flat (a
// face down, at rest). Bullet's convex hull of it does not: it was still
// rocking on an edge at 1.7-3.7 rad/s after 1 s (measured; more contact
// points per step, multipoint GJK or polyhedral clipping, did not stop it),
// where a box primitive rests.
inline void expect_free_mesh_lands_on_the_floor(const RigidEngine& engine, bool rests) {
  const RigidContactLaw law{0.5, 0.3, 0.0};
  RigidWorldSpec spec = one_grain(0.002, {0.4, 0.4, 0.002}, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), law);
  ObjectSpec mesh = free_body(true, 0.01, {0.0, 0.0, 0.04});
  mesh.name = "mesh";
  mesh.shape = ObjectSpec::Shape::kMesh;
  mesh.keyframes[0].pose.orientation = Eigen::AngleAxisd(30.0 * std::numbers::pi / 180.0, Eigen::Vector3d::UnitX());
  spec.bodies = {mesh};
  const auto world = engine.make_world(spec);
  for (double t = 0.0; t < 1.0; t += world->time_step_s()) world->step();
  const FreeBodyState s = world->free_bodies().at(0);
  const TriangleMesh placed = transformed(mesh.body, s.pose);
  EXPECT_NEAR(placed.V.col(2).minCoeff(), 0.0, 0.001);
  if (!rests) return;
  EXPECT_NEAR(s.pose.position_m.z(), 0.01, 0.001);  // lies on a face, its centre half a side up
  EXPECT_LT(s.velocity_m_s.norm(), 0.01) << s.velocity_m_s.transpose() << ", w " << s.angular_velocity_rad_s.transpose();
}

// A steel sphere (r 6 mm, 7800 kg/m^3) dropped at 0.5 m/s into a 1 cm bed of
// 2 mm grains (3.2 cm square): it comes to rest (slow at the end), in the bed
// (its lowest point below the surface, above the floor), held by the grains
// (the mean contact force over the last fifth within 25 % of its weight), no
// grain lost; the same seed repeats bit for bit.
inline RigidReferenceResult drop_sphere_into_bed(const RigidEngine& engine, const std::string& cache_dir) {
  RigidInputs in = tiny_bed(11);
  in.grid = Grid{8, 8, 0.004, 0.0, 0.0};
  in.time = TimeSpec{0.01, 0.5};
  ObjectSpec ball = free_body(false, 0.006, {0.016, 0.016, 0.022});
  ball.dynamic->velocity_m_s = {0.0, 0.0, -0.5};
  in.objects = {ball};
  RigidReferenceOptions options;
  options.cache_dir = cache_dir;
  return run_rigid_reference(engine, in, options);
}

inline void expect_sphere_comes_to_rest_in_the_bed(const RigidEngine& engine) {
  const TempDir cache("rigid_free");
  const RigidReferenceResult r = drop_sphere_into_bed(engine, cache.path.string());
  ASSERT_EQ(r.free_bodies.size(), 1u);
  ASSERT_EQ(r.free_body_rests.size(), 1u);
  const FreeBodyTrack& track = r.free_bodies[0];
  const FreeBodyRest& rest = r.free_body_rests[0];
  EXPECT_EQ(track.samples.size(), static_cast<std::size_t>(r.run.steps + 1));
  EXPECT_EQ(r.grains_final.size(), r.grains_initial.size());
  EXPECT_LT(rest.final_speed_m_s, 0.02);
  EXPECT_GT(rest.resting_depth_m, 0.0) << "bottom " << rest.bottom_z_m << ", surface " << rest.surface_z_m;
  EXPECT_GT(rest.bottom_z_m, -0.001);
  EXPECT_LT(rest.bottom_z_m, rest.surface_z_m);
  EXPECT_NEAR(rest.resting_force_n.z(), rest.weight_n, 0.25 * rest.weight_n);
  EXPECT_GT(rest.max_force_n, rest.weight_n);  // the impact
  // the same seed: the same trajectory, bit for bit (the bed comes from the cache)
  const RigidReferenceResult again = drop_sphere_into_bed(engine, cache.path.string());
  ASSERT_EQ(again.free_bodies.size(), 1u);
  const FreeBodySample &a = track.samples.back(), &b = again.free_bodies[0].samples.back();
  EXPECT_EQ(a.state.pose.position_m, b.state.pose.position_m);
  EXPECT_EQ(a.state.velocity_m_s, b.state.velocity_m_s);
  EXPECT_EQ(rest.resting_depth_m, again.free_body_rests[0].resting_depth_m);
}

}  // namespace repose::test_support
