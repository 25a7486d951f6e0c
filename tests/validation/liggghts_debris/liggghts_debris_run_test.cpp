#include "validation/liggghts_debris/liggghts_debris_run.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/validation/rigid/debris_test_world.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;


// A tiny LIGGGHTS run (one element on the house's roof, 0.6 s of 1 ms
// steps): the house, a fixed mesh, carries the element's weight.
TEST(LiggghtsDebrisRun, AnElementRestingOnABuildingWeighsOnIt) {
  DebrisSetup setup = test_support::house_on_flat_ground(1.0e6);
  std::size_t top = 0;
  for (std::size_t p = 0; p < setup.spec.parts.size(); ++p) {
    if (setup.spec.parts[p].centre_m.z() > setup.spec.parts[top].centre_m.z()) top = p;
  }
  const DebrisPart& roof = setup.spec.parts[top];
  DebrisElement rock;
  rock.centre_m = roof.centre_m + Eigen::Vector3d(0, 0, roof.half_extents_m.z() + rock.radius_m);
  setup.spec.elements = {rock};
  const double weight_n = rock.density_kg_m3 * 4.0 / 3.0 * M_PI * std::pow(rock.radius_m, 3) * setup.spec.gravity_m_s2;
  LiggghtsDebrisOptions options;
  options.force_interval_s = 0.1;
  const test_support::TempDir temp;
  const LiggghtsDebrisResult r = run_liggghts_debris(setup, 0.6, options, (temp.path / "run").string());
  ASSERT_EQ(r.run.buildings.size(), 1u);
  const BuildingOutcome& house = r.run.buildings[0];
  ASSERT_EQ(r.run.force_time_s.size(), 6u);
  EXPECT_NEAR(r.run.force_time_s.back(), 0.6, 1e-9);
  EXPECT_NEAR(house.force_n.back(), weight_n, 0.02 * weight_n);
  EXPECT_EQ(house.parts, 4);
  EXPECT_EQ(house.parts_moved, 0);
  // the element stays on the roof: it neither falls through nor slides off
  const DebrisFrame& last = r.run.frames.back();
  EXPECT_NEAR(last.elements.position_m(0, 2), rock.centre_m.z(), 0.05 * rock.radius_m);
  EXPECT_NEAR(last.time_s, 0.6, 1e-9);
  EXPECT_FALSE(r.version.empty());
}

TEST(LiggghtsDebrisRun, MalformedForcesAreRefusedNamingTheFile) {
  const test_support::TempDir temp;
  const fs::path& dir = temp.path;
  const std::string path = (dir / "building_forces.txt").string();
  std::ofstream(path) << "# Time-averaged data\n# TimeStep f_part0[1] f_part0[2] f_part0[3]\n100 1 2\n";
  DebrisRunResult r;
  r.buildings.emplace_back().name = "house";
  try {
    read_debris_forces(path, 1e-3, {0}, r);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("building_forces.txt:3"), std::string::npos) << e.what();
  }
}

// Parts 0 and 2 are the house's, part 1 the barn's.
TEST(LiggghtsDebrisRun, ABuildingsForceIsTheMagnitudeOfItsPartsSumAtEachStep) {
  const test_support::TempDir temp;
  const fs::path& dir = temp.path;
  const std::string path = (dir / "building_forces.txt").string();
  std::ofstream(path) << "# Time-averaged data\n# TimeStep f_part0[1] ...\n"
                      << "50 3 0 0  1 1 1  0 4 0\n100 0 0 -2  0 0 0  0 0 2\n";
  DebrisRunResult r;
  r.buildings.emplace_back().name = "house";
  r.buildings.emplace_back().name = "barn";
  read_debris_forces(path, 1e-3, {0, 1, 0}, r);
  EXPECT_EQ(r.force_time_s, (std::vector<double>{0.05, 0.1}));
  EXPECT_EQ(r.buildings[0].force_n, (std::vector<double>{5.0, 0.0}));
  EXPECT_NEAR(r.buildings[1].force_n[0], std::sqrt(3.0), 1e-15);
}

}  // namespace
}  // namespace repose
