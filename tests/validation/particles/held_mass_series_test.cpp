#include "validation/particles/held_mass_series.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "validation/particles/particle_observables.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

// A bucket 0.1 m wide inside, 0.1 m tall, its origin at the middle of its floor.
TriangleMesh bucket() {
  const auto box = [](const Eigen::Vector3d& half, const Eigen::Vector3d& centre) {
    return transformed(make_box(half), Pose{centre, Eigen::Quaterniond::Identity()});
  };
  TriangleMesh m = box({0.06, 0.06, 0.005}, {0, 0, 0.005});
  m = merged(m, box({0.005, 0.06, 0.05}, {0.055, 0, 0.05}));
  m = merged(m, box({0.005, 0.06, 0.05}, {-0.055, 0, 0.05}));
  m = merged(m, box({0.06, 0.005, 0.05}, {0, 0.055, 0.05}));
  m = merged(m, box({0.06, 0.005, 0.05}, {0, -0.055, 0.05}));
  return m;
}

Keyframe key(double t, const Eigen::Vector3d& p, double tilt_deg) {
  Keyframe k;
  k.time_s = t;
  k.pose = Pose{p, Eigen::Quaterniond(Eigen::AngleAxisd(tilt_deg * std::numbers::pi / 180, Eigen::Vector3d::UnitY()))};
  return k;
}

// A bucket that moves 1 m along +x from t = 0 to 1 s, then is turned upside down by t = 2 s.
ObjectSpec moving_bucket() {
  ObjectSpec o;
  o.name = "bucket";
  o.shape = ObjectSpec::Shape::kMesh;
  o.body = bucket();
  o.keyframes = {key(0.0, {0, 0, 0}, 0), key(1.0, {1, 0, 0}, 0), key(2.0, {1, 0, 0.2}, 180)};
  return o;
}

GrainFrame frame_at(double t, const std::vector<Eigen::Vector3d>& centres) {
  GrainFrame f;
  f.time_s = t;
  f.grains.position_m.resize(static_cast<Eigen::Index>(centres.size()), 3);
  for (std::size_t k = 0; k < centres.size(); ++k) f.grains.position_m.row(static_cast<Eigen::Index>(k)) = centres[k];
  f.grains.radius_m = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(centres.size()), 0.002);
  return f;
}

TEST(HeldMassSeries, CountsTheGrainsInsideTheBucketAtItsPoseInEachFrame) {
  const double one = 2500.0 * 4.0 / 3.0 * std::numbers::pi * 0.002 * 0.002 * 0.002;
  // two grains that ride inside the bucket, one that stays behind at the start
  const auto riding = [](double x) {
    return std::vector<Eigen::Vector3d>{{x, 0, 0.03}, {x + 0.02, 0.01, 0.03}, {0, 0, 0.03}};
  };
  std::vector<GrainFrame> frames = {frame_at(0.0, riding(0.0)), frame_at(0.5, riding(0.5)), frame_at(1.0, riding(1.0))};
  // upside down at t = 2: the grains that were in it now lie below its mouth
  frames.push_back(frame_at(2.0, {{1, 0, 0.05}, {1.02, 0, 0.05}, {0, 0, 0.03}}));
  const HeldMassSeries s = held_mass_series({moving_bucket()}, frames, 2500.0);
  ASSERT_EQ(s.objects, std::vector<std::string>{"bucket"});
  ASSERT_EQ(s.time_s, (std::vector<double>{0.0, 0.5, 1.0, 2.0}));
  EXPECT_NEAR(s.mass_kg[0][0], 3 * one, 1e-12);  // all three at the start
  EXPECT_NEAR(s.mass_kg[0][1], 2 * one, 1e-12);  // the one left behind is out
  EXPECT_NEAR(s.mass_kg[0][2], 2 * one, 1e-12);
  EXPECT_EQ(s.mass_kg[0][3], 0.0);               // tipped out
}

TEST(HeldMassSeries, LeavesOutFreeBodiesAndNamesUnnamedObjects) {
  ObjectSpec unnamed = moving_bucket();
  unnamed.name.clear();
  ObjectSpec free = moving_bucket();
  free.dynamic = DynamicBody{};
  const HeldMassSeries s = held_mass_series({free, unnamed}, {frame_at(0.0, {{0, 0, 0.03}})}, 2500.0);
  EXPECT_EQ(s.objects, std::vector<std::string>{"object_1"});
}

TEST(HeldMassSeries, CsvRoundTripsAndReadsTheHeightSpanModelsColumns) {
  const test_support::TempDir temp;
  const std::filesystem::path& dir = temp.path;
  HeldMassSeries s;
  s.time_s = {0.0, 0.05, 0.1};
  s.objects = {"bucket", "plate"};
  s.mass_kg = {{0.0, 0.1 / 3.0, 0.2}, {1e-3, 2e-3, 3e-3}};
  write_held_mass_csv((dir / "held_mass.csv").string(), s);
  const auto tracks = read_held_mass_csv((dir / "held_mass.csv").string());
  ASSERT_EQ(tracks.size(), 2u);
  EXPECT_EQ(tracks.at("bucket").time_s, s.time_s);
  EXPECT_EQ(tracks.at("bucket").mass_kg, s.mass_kg[0]);  // round-trip exact
  EXPECT_EQ(tracks.at("plate").mass_kg, s.mass_kg[1]);
  // the height-span solver's file: volume, mass, in-flight and ledger columns
  std::ofstream(dir / "hs.csv") << "time_s,bucket_volume_m3,bucket_mass_kg,in_flight_m3,ledger_imbalance_m3\n"
                                << "0,0,0,0,0\n0.02,1e-6,0.0015,0,1e-20\n";
  const auto hs = read_held_mass_csv((dir / "hs.csv").string());
  ASSERT_EQ(hs.size(), 1u);
  EXPECT_EQ(hs.at("bucket").mass_kg, (std::vector<double>{0.0, 0.0015}));
  std::ofstream(dir / "bad.csv") << "time_s,bucket_mass_kg\n0,0\n0.1,x\n";
  try {
    read_held_mass_csv((dir / "bad.csv").string());
    FAIL() << "a non-number was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:3"), std::string::npos) << e.what();
  }
  std::ofstream(dir / "ragged.csv") << "time_s,bucket_mass_kg\n0\n";
  EXPECT_THROW(read_held_mass_csv((dir / "ragged.csv").string()), InputError);
}

}  // namespace
}  // namespace repose
