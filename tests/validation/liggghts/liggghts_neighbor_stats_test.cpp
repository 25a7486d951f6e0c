#include "validation/liggghts/liggghts_neighbor_stats.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

TEST(LiggghtsNeighborStats, SumsEveryRunBlockOfTheLog) {
  const test_support::TempDir dir;
  const fs::path log = dir.path / "log.liggghts";
  std::ofstream(log) << "LIGGGHTS (Version LIGGGHTS-PUBLIC 3.8.0)\n"
                        "Loop time of 0.1 on 1 procs for 0 steps with 10 atoms\n"
                        "Neighbor list builds = 0\nDangerous builds = 0\n"
                        "Step Atoms KinEng\n0 10 0\n"
                        "Neighbor list builds = 19\nDangerous builds = 2\n"
                        "Neighbor list builds = 15\nDangerous builds = 1\n"
                        "Total # of neighbors = 1234\n";
  const NeighborStats stats = read_neighbor_stats(log.string());
  EXPECT_EQ(stats.builds, 34);
  EXPECT_EQ(stats.dangerous_builds, 3);
}

TEST(LiggghtsNeighborStats, AMissingLogIsAnErrorNamingIt) {
  try {
    read_neighbor_stats("/nonexistent/log.liggghts");
    FAIL() << "read a missing log";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/log.liggghts"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace repose
