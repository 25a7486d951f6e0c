// A tiny column collapse run by the `liggghts` program (skipped where it is
// not installed): ~250 grains settled in a cylinder, the cylinder removed,
// the grains slump. Checked by invariants: no grain lost, the front advances,
// the top comes down, a pile with flanks is left; the slot twin (~100 grains)
// spreads along +x only.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/validation/liggghts/dem_test_scene.h"
#include "validation/liggghts/liggghts_dump.h"
#include "validation/liggghts/liggghts_reference.h"

#include "tests/support/liggghts_test.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

class ColumnCollapseRun : public test_support::LiggghtsTest {
 protected:
  LiggghtsReferenceResult run(const Scene& scene) {
    LiggghtsReferenceOptions options;
    options.bed.cache_dir = (dir_ / "cache").string();
    options.bed.run.wall_clock_limit_s = 60;
    options.run.wall_clock_limit_s = 60;
    fs::create_directories(dir_ / "run");
    return run_liggghts_reference(scene, (dir_ / "run").string(), options);
  }
};

TEST_F(ColumnCollapseRun, CylinderColumnSlumpsIntoAPile) {
  const Scene scene = testing::column_dem_scene(DemSpec::ColumnShape::kCylinder, 0.03);
  const LiggghtsReferenceResult r = run(scene);
  EXPECT_EQ(r.grain_count, bed_grain_count(scene, BedScriptOptions{}));
  ASSERT_TRUE(r.column.has_value());
  ASSERT_TRUE(r.pile.has_value());
  const ColumnCollapse& c = *r.column;

  // the settled column: its grains fill it at a packing fraction between 0.4 (a narrow
  // cylinder packs loosely at its wall) and 0.65, where 0.6 was assumed to count them
  const double d = 2 * dem_of(scene)->grain_radius_m;
  EXPECT_GT(c.height_initial_m, 0.03 * 0.6 / 0.65);
  EXPECT_LT(c.height_initial_m, 0.03 * 0.6 / 0.4 + d);
  EXPECT_LE(c.front_initial_m, 0.012 + 0.1 * dem_of(scene)->grain_radius_m);  // grains press slightly into the wall
  EXPECT_GT(c.front_initial_m, 0.012 - 2 * dem_of(scene)->grain_radius_m);
  // released: the front advanced, the top came down
  EXPECT_GT(c.runout_normalised, 0.2);
  EXPECT_LT(c.height_final_m, 0.8 * c.height_initial_m);
  // a pile, highest near its axis, with flanks below 45 degrees
  EXPECT_GT(r.pile->mean_rad, 0.0);
  EXPECT_LT(r.pile->mean_rad, std::numbers::pi / 4);
  // the front over the dumps: one row per dump, ending at the final front
  const auto dumps = list_dump_files((dir_ / "run" / "dumps").string());
  ASSERT_EQ(c.front_m.size(), dumps.size());
  EXPECT_DOUBLE_EQ(c.front_m.back(), c.front_final_m);
  EXPECT_TRUE(fs::is_regular_file(dir_ / "run" / "runout.csv"));
  EXPECT_TRUE(fs::is_regular_file(dir_ / "run" / "pile_flank_angles.csv"));
  std::ifstream manifest(dir_ / "run" / "liggghts_manifest.json");
  const std::string text((std::istreambuf_iterator<char>(manifest)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"runout_normalised\""), std::string::npos);
  EXPECT_NE(text.find("\"flank_angle_mean_deg\""), std::string::npos);
}

TEST_F(ColumnCollapseRun, SlotColumnSpreadsAlongXBetweenItsWalls) {
  const Scene scene = testing::column_dem_scene(DemSpec::ColumnShape::kSlot, 0.04);
  const LiggghtsReferenceResult r = run(scene);
  ASSERT_TRUE(r.column.has_value());
  EXPECT_FALSE(r.pile.has_value());
  EXPECT_GT(r.column->runout_normalised, 0.2);
  EXPECT_LT(r.column->height_final_m, r.column->height_initial_m);
  const DumpFrame last = read_last_dump_frame(list_dump_files((dir_ / "run" / "dumps").string()).back());
  const double half_radius = 0.5 * dem_of(scene)->grain_radius_m * (1.0 - dem_of(scene)->radius_spread);
  for (Eigen::Index g = 0; g < last.grains.size(); ++g) {
    EXPECT_GE(last.grains.position_m(g, 1), half_radius);  // the walls keep every centre off them
    EXPECT_LE(last.grains.position_m(g, 1), 0.012 - half_radius);
  }
}

// Without side walls nothing keeps a grain's centre a radius off the strip's
// y edges: in a periodic strip grains lie across them, between walls none does.
TEST_F(ColumnCollapseRun, PeriodicSlotHasGrainsAcrossItsYEdges) {
  const Scene walls = testing::column_dem_scene(DemSpec::ColumnShape::kSlot, 0.04);
  const Scene periodic = with_dem_changed(walls, [](DemSpec& d) { d.sides = DemSpec::Sides::kPeriodic; });
  const LiggghtsReferenceResult r = run(periodic);
  EXPECT_EQ(r.grain_count, bed_grain_count(periodic, BedScriptOptions{}));
  ASSERT_TRUE(r.column.has_value());
  EXPECT_GT(r.column->runout_normalised, 0.2);
  EXPECT_GT(r.neighbor.builds, 0);
  EXPECT_EQ(r.neighbor.dangerous_builds, 0);
  const DumpFrame last = read_last_dump_frame(list_dump_files((dir_ / "run" / "dumps").string()).back());
  const double radius = dem_of(periodic)->grain_radius_m * (1.0 - dem_of(periodic)->radius_spread);
  int across = 0;
  for (Eigen::Index g = 0; g < last.grains.size(); ++g) {
    const double y = last.grains.position_m(g, 1);
    EXPECT_GE(y, 0.0);
    EXPECT_LT(y, 0.012);
    if (y < 0.5 * radius || y > 0.012 - 0.5 * radius) ++across;
  }
  EXPECT_GT(across, 0) << "no grain lies across the periodic edges";
}

}  // namespace
}  // namespace repose
