#include "validation/rigid/rigid_bed_cache.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/temp_dir.h"
#include "tests/validation/rigid/fake_world.h"

namespace repose {
namespace {

using test_support::fake_engine;
using test_support::TempDir;

RigidInputs small_bed(std::uint64_t seed) {
  RigidInputs in;
  in.grid = Grid{4, 4, 0.004, 0.0, 0.0};
  in.dem.bed_depth_m = 0.008;
  in.dem.settle_kinetic_energy_j = 1e-3;  // the fake's energy 0.5^10 < 1e-3 after 10 steps
  in.seed = seed;
  return in;
}

int entries(const std::filesystem::path& cache) {
  int n = 0;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(cache / "rigid_beds", ec)) n += e.is_directory() ? 1 : 0;
  return n;
}

TEST(RigidBedCache, ASettledBedIsCachedAndReadBackBitIdentical) {
  const TempDir cache;
  const RigidBed fresh = settled_rigid_bed(fake_engine(0.5), small_bed(1), cache.path.string());
  EXPECT_FALSE(fresh.from_cache);
  EXPECT_TRUE(fresh.settle.settled);
  EXPECT_LT(fresh.settle.kinetic_energy_j, 1e-3);
  const RigidBed cached = settled_rigid_bed(fake_engine(0.5), small_bed(1), cache.path.string());
  EXPECT_TRUE(cached.from_cache);
  EXPECT_EQ(cached.key, fresh.key);
  EXPECT_EQ(cached.grains.position_m, fresh.grains.position_m);
  EXPECT_EQ(cached.grains.radius_m, fresh.grains.radius_m);
  EXPECT_EQ(entries(cache.path), 1);
}

TEST(RigidBedCache, TheKeyChangesWithTheSeedTheEngineOptionsAndTheGrains) {
  const std::string base = rigid_bed_key_text(fake_engine(0.5), small_bed(1));
  EXPECT_NE(base, rigid_bed_key_text(fake_engine(0.5), small_bed(2)));
  EXPECT_NE(base, rigid_bed_key_text(fake_engine(0.4), small_bed(1)));
  RigidInputs other = small_bed(1);
  other.dem.friction = 0.6;
  EXPECT_NE(base, rigid_bed_key_text(fake_engine(0.5), other));
  RigidEngine renamed = fake_engine(0.5);
  renamed.version = "fake 2";
  EXPECT_NE(base, rigid_bed_key_text(renamed, small_bed(1)));
}

TEST(RigidBedCache, ABedThatDoesNotSettleFailsAndIsNotCached) {
  const TempDir cache;
  try {
    settled_rigid_bed(fake_engine(0.999), small_bed(1), cache.path.string());
    FAIL() << "an unsettled bed was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("did not settle"), std::string::npos) << e.what();
  }
  EXPECT_EQ(entries(cache.path), 0);
}

TEST(RigidBedCache, ABedThatLosesAGrainFailsAndIsNotCached) {
  const TempDir cache;
  try {
    settled_rigid_bed(fake_engine(0.5, true), small_bed(1), cache.path.string());
    FAIL() << "a bed that lost a grain was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("lost 1 of"), std::string::npos) << e.what();
  }
  EXPECT_EQ(entries(cache.path), 0);
}

TEST(RigidBedCache, TheSpeedThresholdIsTheBedsKineticEnergyAtThatSpeed) {
  RigidOptions o;
  o.settle_rms_speed_m_s = 0.01;
  GrainSet g;
  g.position_m = MatrixX3dR::Zero(2, 3);
  g.radius_m = Eigen::VectorXd::Constant(2, 0.002);
  DemSpec dem;
  const double mass = 2 * dem.density_kg_m3 * 4.0 / 3.0 * M_PI * 8e-9;
  EXPECT_NEAR(settle_threshold_j(o, dem, g), 0.5 * mass * 1e-4, 1e-18);
  o.settle_rms_speed_m_s = 0.0;
  EXPECT_EQ(settle_threshold_j(o, dem, g), dem.settle_kinetic_energy_j);
}

}  // namespace
}  // namespace repose
