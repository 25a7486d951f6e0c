// Free bodies driven by ODE over the ground model's field: a box at rest
// sinks to Bekker's sinkage for its weight (heavier deeper), the ledger
// balances, runs repeat bit for bit, a dropped box leaves the imprint of its
// footprint, and without bearing it rests on the field as the heuristic
// alone leaves it; a rolling wheel leaves its track, and a torque drives it. Meshes are refused
// naming the object.
#include "models/ground/free_body_drive.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/core/config/initial_height.h"
#include "models/ground/simulate_ground.h"
#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

constexpr double kBed = 0.05, kCell = 0.005;
const Eigen::Vector3d kHalf(0.05, 0.05, 0.025);  // a 10 cm x 10 cm x 5 cm box: edges on cell edges

// A box of mass_kg with its bottom drop_m above a flat bed, 0.4 m square,
// 1/60 s steps. drop_m 0: set down 1 um into the surface, so that ODE's first
// step has contact: no step of free fall, whose energy (an impact of a
// 14 um drop) would press it past its static sinkage.
Scene box_scene(double mass_kg, double drop_m, double duration_s,
                BekkerBearing::Law law = BekkerBearing::Law::kBekker) {
  ObjectSpec box;
  box.name = "box";
  box.shape = ObjectSpec::Shape::kBox;
  box.half_extents_m = kHalf;
  box.body = make_box(kHalf);
  box.dynamic = DynamicBody{};
  box.dynamic->mass_kg = mass_kg;
  box.keyframes = {at(0.0, 0.0, 0.0, kBed + (drop_m > 0.0 ? drop_m : -1e-6) + kHalf.z())};
  Scene scene = flat_scene(centred_grid(80, 80, kCell), kBed, sand(), {box}, 1);
  scene.time = TimeSpec{1.0 / 60.0, duration_s};
  auto section = std::make_shared<GroundModelSection>(ground_model_section(scene));
  section->free_bodies.bearing.law = law;
  scene.sections[GroundModelSection::kKey] = section;
  return scene;
}

GroundRun run(const Scene& scene) {
  const GroundModel model = build_ground_model(scene);
  return simulate_ground(model, default_params(model), make_initial_height(scene));
}

// Bekker's sinkage of the box's footprint (0.01 m^2, 0.1 m wide) under its weight.
double bekker_box_sinkage_m(double mass_kg) {
  return bekker_sinkage_m(BekkerBearing{}, mass_kg * 9.81 / 0.01, 0.1);
}

TEST(FreeBodyDrive, BoxAtRestSinksToBekkersSinkageForItsWeight) {
  double previous = 0.0;
  for (const double mass : {0.5, 2.0, 8.0}) {
    const GroundRun g = run(box_scene(mass, 0.0, 1.0));
    ASSERT_EQ(g.free_bodies.size(), 1u);
    const FreeBodyReport& b = g.free_bodies[0];
    const double expected = bekker_box_sinkage_m(mass);
    EXPECT_NEAR(b.resting_depth_m, expected, 0.03 * expected + 5e-5) << mass << " kg";
    EXPECT_NEAR(b.final_load_n / b.weight_n, 1.0, 0.02) << mass << " kg";
    EXPECT_LT(b.final_speed_m_s, 1e-3);
    EXPECT_GT(b.resting_depth_m, previous) << "heavier sinks deeper";
    previous = b.resting_depth_m;
    // the field under the box's centre is its imprint's floor
    EXPECT_NEAR(kBed - g.final_height.sample(0.0, 0.0), expected, 0.03 * expected + 5e-5);
    expect_balanced(g.ledger, g.final_volume_m3);
  }
}

TEST(FreeBodyDrive, WithoutBearingTheBoxRestsOnTheField) {
  const GroundRun g = run(box_scene(8.0, 0.0, 0.5, BekkerBearing::Law::kOff));
  EXPECT_LT(std::abs(g.free_bodies[0].resting_depth_m), 2e-4);  // the heuristic alone bears any load
  EXPECT_NEAR(g.final_height.sample(0.0, 0.0), kBed, 2e-4);
}

TEST(FreeBodyDrive, DroppedBoxLeavesTheImprintOfItsFootprint) {
  const GroundRun g = run(box_scene(2.0, 0.02, 1.0));
  const FreeBodyReport& b = g.free_bodies[0];
  EXPECT_GT(b.max_load_n, 2.0 * b.weight_n) << "the impact loads more than the weight";
  // beyond the static sinkage z_s the ground's work takes up the impact's energy:
  // int_{z_s}^z (W_bekker - m g) = m g drop, W_bekker = p(z) * footprint
  const double zs = bekker_box_sinkage_m(2.0);
  auto bekker_work = [](double z) { return 0.01 * 1538330.0 * std::pow(z, 2.1) / 2.1; };
  auto work = [&](double z) { return bekker_work(z) - bekker_work(zs) - 19.62 * (z - zs) - 19.62 * 0.02; };
  double lo = zs, hi = 0.05;
  for (int k = 0; k < 100; ++k) (work(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
  EXPECT_NEAR(b.resting_depth_m / lo, 1.0, 0.05) << "energy balance " << lo;
  EXPECT_GT(b.resting_depth_m, 2.0 * bekker_box_sinkage_m(2.0)) << "the impact presses deeper than the weight";
  // lowered over the footprint (inside its edge by a cell) to the box's bottom, within its tilt
  const HeightField& h = g.final_height;
  const double floor_m = kBed - b.resting_depth_m;
  for (const double x : {-0.045, -0.02, 0.0, 0.02, 0.045}) {
    for (const double y : {-0.045, 0.0, 0.045}) {
      const double z = h.sample(b.final_position_m.x() + x, b.final_position_m.y() + y);
      EXPECT_GE(z, floor_m - 2e-4) << x << " " << y;
      EXPECT_LE(z, floor_m + 5e-4) << x << " " << y;
    }
  }
  for (const double x : {-0.15, 0.15}) EXPECT_GE(h.sample(x, 0.0), kBed - 1e-9) << x;
  EXPECT_GT(h.heights().maxCoeff(), kBed) << "displaced material heaps beside the imprint";
  expect_balanced(g.ledger, g.final_volume_m3);
}

// A wheel (r 5 cm, 4 cm wide, mass_kg), axis along y, its lowest point 1 um
// into the bed at x = x0_m, with a torque about y (N m) and an initial
// rolling speed along +x; steps of 1/60 s.
Scene wheel_scene(double mass_kg, double x0_m, double torque_n_m, double speed_m_s, double duration_s) {
  ObjectSpec wheel;
  wheel.name = "wheel";
  wheel.shape = ObjectSpec::Shape::kCylinder;
  wheel.radius_m = 0.05;
  wheel.half_height_m = 0.02;
  wheel.body = make_cylinder(0.05, 0.02);
  wheel.dynamic = DynamicBody{};
  wheel.dynamic->mass_kg = mass_kg;
  wheel.dynamic->velocity_m_s = Eigen::Vector3d(speed_m_s, 0.0, 0.0);
  wheel.dynamic->angular_velocity_rad_s = Eigen::Vector3d(0.0, speed_m_s / 0.05, 0.0);
  wheel.dynamic->torque_n_m = Eigen::Vector3d(0.0, torque_n_m, 0.0);
  Keyframe start = at(0.0, x0_m, 0.0, kBed + 0.05 - 1e-6);
  start.pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitX()));
  wheel.keyframes = {start};
  Scene scene = flat_scene(centred_grid(80, 80, kCell), kBed, sand(), {wheel}, 1);
  scene.time = TimeSpec{1.0 / 60.0, duration_s};
  return scene;
}

// The track: lowered along the path on the wheel's line, untouched beside it.
void expect_track(const GroundRun& g, double from_x_m, double to_x_m) {
  for (double x = from_x_m; x < to_x_m; x += 0.02) {
    EXPECT_LT(g.final_height.sample(x, 0.0), kBed - 5e-4) << x;
    EXPECT_GE(g.final_height.sample(x, 0.1), kBed - 1e-9) << x;
  }
}

TEST(FreeBodyDrive, RollingWheelLeavesItsTrack) {
  const GroundRun g = run(wheel_scene(0.5, -0.1, 0.0, 1.0, 0.4));
  const FreeBodyReport& b = g.free_bodies[0];
  EXPECT_GT(b.final_position_m.x(), 0.0) << "it rolled";
  expect_track(g, -0.08, b.final_position_m.x() - 0.03);
  expect_balanced(g.ledger, g.final_volume_m3);
}

// A 2 kg wheel set down at rest under 0.3 N m: rolling without slip needs a
// friction force of (tau / r) / 1.5 = 4 N, within the contact's limit
// (0.5 m g = 9.8 N), so it rolls, and on
// a rigid floor would reach a = (tau / r) / (m + I / r^2) = 2 m/s^2, 0.16 m in
// 0.4 s; climbing out of its own rut costs most of that (measured: 4 cm).
// It sinks under way to the bearing depth of its load and leaves that rut
// behind it; the opposite torque drives it the opposite way as far (the
// scene's mirror symmetry about x = 0, up to ODE's height-field triangles,
// which split each cell along one diagonal: measured 5 %).
TEST(FreeBodyDrive, AWheelUnderATorqueDrivesItselfAlongAndLeavesItsRut) {
  const GroundRun forward = run(wheel_scene(2.0, 0.0, 0.3, 0.0, 0.4));
  const GroundRun backward = run(wheel_scene(2.0, 0.0, -0.3, 0.0, 0.4));
  const FreeBodyReport &f = forward.free_bodies[0], &b = backward.free_bodies[0];
  EXPECT_GT(f.final_position_m.x(), 0.02) << "the torque drove it along +x";
  EXPECT_LT(f.final_position_m.x(), 0.16 + 1e-3) << "no faster than on a rigid floor";
  EXPECT_NEAR(b.final_position_m.x(), -f.final_position_m.x(), 0.1 * f.final_position_m.x());
  EXPECT_NEAR(f.final_position_m.y(), 0.0, 1e-3) << "straight on";
  EXPECT_NEAR(f.travel_m, f.final_position_m.head<2>().norm(), 1e-12);
  EXPECT_GT(f.bearing_sinkage_m, 1e-3);
  EXPECT_NEAR(f.resting_depth_m / f.bearing_sinkage_m, 1.0, 0.1) << "under way at its load's bearing depth";
  expect_track(forward, 0.02, f.final_position_m.x() - 0.03);
  expect_balanced(forward.ledger, forward.final_volume_m3);
}

TEST(FreeBodyDrive, RepeatsBitForBit) {
  Scene scene = box_scene(2.0, 0.02, 0.5);
  scene.objects[0].dynamic->velocity_m_s = Eigen::Vector3d(0.3, 0.1, -0.2);
  scene.objects[0].dynamic->angular_velocity_rad_s = Eigen::Vector3d(0.0, 2.0, 1.0);
  const GroundRun a = run(scene), b = run(scene);
  EXPECT_TRUE((a.final_height.heights() == b.final_height.heights()).all());
  EXPECT_EQ(a.free_bodies[0].final_position_m, b.free_bodies[0].final_position_m);
  EXPECT_EQ(a.free_bodies[0].resting_depth_m, b.free_bodies[0].resting_depth_m);
}

TEST(FreeBodyDrive, StagesSayODEDrivesAndBekkerBears) {
  const Scene scene = box_scene(2.0, 0.0, 0.1);
  const GroundModel model = build_ground_model(scene);
  const std::vector<std::string> stages = ground_stages(model, default_params(model));
  EXPECT_NE(std::find(stages.begin(), stages.end(), "free-bodies:ode"), stages.end());
  EXPECT_NE(std::find(stages.begin(), stages.end(), "bearing:bekker"), stages.end());
  const GroundModel keyframed = build_ground_model(flat_scene(centred_grid(8, 8, 0.01), 0.02, sand(),
                                                              {sphere(0.02, {at(0, 0, 0, 0.05)})}, 1));
  for (const std::string& s : ground_stages(keyframed, default_params(keyframed))) {
    EXPECT_EQ(s.find("ode"), std::string::npos);
  }
}

TEST(FreeBodyDrive, RefusesAMeshNamingIt) {
  Scene scene = box_scene(2.0, 0.0, 0.1);
  scene.objects[0].shape = ObjectSpec::Shape::kMesh;
  scene.source_path = "mesh.yaml";
  try {
    build_ground_model(scene);
    FAIL() << "drove a mesh";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("mesh.yaml: objects[0] ('box')"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace repose
