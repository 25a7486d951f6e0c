#include "validation/particles/free_body_track.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/temp_dir.h"

namespace repose {
namespace {

ObjectSpec ball(double r_m, double mass_kg) {
  ObjectSpec o;
  o.name = "ball";
  o.radius_m = r_m;
  o.body = make_sphere(r_m);
  DynamicBody d;
  d.mass_kg = mass_kg;
  o.dynamic = d;
  o.keyframes = {Keyframe{}};
  return o;
}

FreeBodyState at(double z_m, double vz_m_s) {
  FreeBodyState s;
  s.pose.position_m = {0.05, 0.05, z_m};
  s.velocity_m_s = {0.0, 0.0, vz_m_s};
  return s;
}

TEST(FreeBodyTrack, AFreeFallFeelsNoContactForceAndARestingBodyItsWeight) {
  const double g = 9.81, dt = 0.01, m = 2.0;
  auto tracks = start_free_body_tracks({ball(0.01, m)});
  ASSERT_EQ(tracks.size(), 1u);
  EXPECT_EQ(tracks[0].mass_kg, m);
  // falling freely for 5 steps, then at rest for 5
  for (int k = 0; k <= 5; ++k) record_free_bodies(tracks, k * dt, {at(1.0, -g * k * dt)}, g);
  for (int k = 6; k <= 10; ++k) record_free_bodies(tracks, k * dt, {at(0.5, 0.0)}, g);
  for (int k = 1; k <= 5; ++k) EXPECT_NEAR(tracks[0].samples[k].contact_force_n.norm(), 0.0, 1e-9) << k;
  // the step that stops it: the impulse m v / dt on top of its weight
  EXPECT_NEAR(tracks[0].samples[6].contact_force_n.z(), m * g * 5 * dt / dt + m * g, 1e-9);
  for (int k = 7; k <= 10; ++k) EXPECT_NEAR(tracks[0].samples[k].contact_force_n.z(), m * g, 1e-9);
}

TEST(FreeBodyTrack, TheRestingDepthIsTheSurfaceAboveTheLowestPoint) {
  const double g = 9.81, r = 0.01;
  const ObjectSpec o = ball(r, 1.0);
  auto tracks = start_free_body_tracks({o});
  record_free_bodies(tracks, 0.0, {at(0.1, 0.0)}, g);
  record_free_bodies(tracks, 0.1, {at(0.025, 0.0)}, g);
  record_free_bodies(tracks, 0.2, {at(0.025, 0.0)}, g);
  const HeightField surface(Grid{10, 10, 0.01, 0.0, 0.0}, 0.02);
  const FreeBodyRest rest = free_body_rest(o, tracks[0], surface, g, 0.15);
  EXPECT_NEAR(rest.bottom_z_m, 0.025 - r, 1e-12);  // the sphere's lowest vertex is its pole
  EXPECT_NEAR(rest.surface_z_m, 0.02, 1e-12);
  EXPECT_NEAR(rest.resting_depth_m, 0.02 - 0.015, 1e-12);
  EXPECT_NEAR(rest.resting_force_n.z(), g, 1e-9);  // the last sample only lies in the window
  EXPECT_NEAR(rest.weight_n, g, 1e-12);
  EXPECT_EQ(rest.final_speed_m_s, 0.0);
}

TEST(FreeBodyTrack, TheCsvHasAHeaderAndARowPerSample) {
  const test_support::TempDir dir("free_body_csv");
  auto tracks = start_free_body_tracks({ball(0.01, 1.0)});
  for (int k = 0; k < 4; ++k) record_free_bodies(tracks, k * 0.01, {at(0.1, 0.0)}, 9.81);
  const std::string path = (dir.path / "t.csv").string();
  write_free_body_csv(path, tracks[0]);
  std::ifstream in(path);
  std::string line;
  int lines = 0;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("time_s,x_m,y_m,z_m,qw", 0), 0u);
  while (std::getline(in, line)) ++lines;
  EXPECT_EQ(lines, 4);
}

}  // namespace
}  // namespace repose
