// End-to-end runs of the `liggghts` program (skipped where it is not installed):
// a small bed settling and a sphere pressed into it, from scene to observables;
// a run killed by its wall-clock limit; a script error reported with its line.

#include "validation/liggghts/liggghts_reference.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/validation/liggghts/dem_test_scene.h"
#include "validation/liggghts/liggghts_dump.h"
#include "validation/liggghts/liggghts_thermo.h"

#include "tests/support/liggghts_test.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

class LiggghtsReference : public test_support::LiggghtsTest {};

TEST_F(LiggghtsReference, SmallBedAndIndenterFromSceneToObservables) {
  const Scene scene = testing::small_dem_scene(true);
  LiggghtsReferenceOptions options;
  options.bed.cache_dir = (dir_ / "cache").string();
  options.bed.run.wall_clock_limit_s = 120;
  options.run.wall_clock_limit_s = 120;
  fs::create_directories(dir_ / "run");
  const LiggghtsReferenceResult r = run_liggghts_reference(scene, (dir_ / "run").string(), options);

  // grains conserved: as many as asked, in the bed and at the end
  const long asked = bed_grain_count(scene, options.bed.script);
  EXPECT_EQ(r.bed.grain_count, asked);
  EXPECT_EQ(r.grain_count, asked);
  EXPECT_FALSE(r.bed.from_cache);
  EXPECT_NE(r.run.version.find("LIGGGHTS"), std::string::npos);

  // the settled surface lies near the bed depth (within a grain diameter)
  const double d = 2 * dem_of(scene)->grain_radius_m;
  const double mean_initial = r.height_initial.heights().mean();
  EXPECT_NEAR(mean_initial, dem_of(scene)->bed_depth_m, d);

  // no grain left the box; the final surface is finite and below the box top
  const auto dumps = list_dump_files((dir_ / "run" / "dumps").string());
  ASSERT_GE(dumps.size(), 2u);
  const DumpFrame last = read_last_dump_frame(dumps.back());
  for (Eigen::Index g = 0; g < last.grains.size(); ++g) {
    EXPECT_GE(last.grains.position_m(g, 0), 0.0);
    EXPECT_LE(last.grains.position_m(g, 0), 0.04);
    EXPECT_GE(last.grains.position_m(g, 1), 0.0);
    EXPECT_LE(last.grains.position_m(g, 1), 0.04);
    EXPECT_GE(last.grains.position_m(g, 2), 0.0);
  }
  EXPECT_TRUE(r.height_final.all_finite());

  // the grains pushed the sphere up while it was pressed in
  const ThermoTable thermo = read_thermo_table((dir_ / "run" / "log.liggghts").string());
  const int fz = thermo.column("obj0[3]");
  ASSERT_GE(fz, 0);
  double max_fz = 0.0;
  for (const auto& row : thermo.rows) max_fz = std::max(max_fz, row[fz]);
  EXPECT_GT(max_fz, 0.0);

  for (const char* file : {"height_initial.npy", "height_final.npy", "material_per_area_final.npy", "forces.csv",
                           "liggghts_manifest.json", "height_final.csv"}) {
    EXPECT_TRUE(fs::is_regular_file(dir_ / "run" / file)) << file;
  }
  RecordProperty("bed_particle_steps_per_s", std::to_string(r.bed.grain_count * r.bed.steps / r.bed.wall_time_s));
  RecordProperty("run_particle_steps_per_s", std::to_string(r.particle_steps_per_s));

  // the second time the bed comes from the cache, with the same key
  const SettledBed again = settled_bed(scene, options.bed);
  EXPECT_TRUE(again.from_cache);
  EXPECT_EQ(again.key, r.bed.key);
  EXPECT_EQ(again.grain_count, asked);
}

TEST_F(LiggghtsReference, RunKilledByTheWallClockLimitIsReportedAndNotCached) {
  const Scene scene = testing::small_dem_scene(false);
  BedOptions options;
  options.cache_dir = (dir_ / "cache").string();
  options.run.wall_clock_limit_s = 0.3;  // the bed needs seconds to settle
  try {
    settled_bed(scene, options);
    FAIL() << "the run was not stopped by its limit";
  } catch (const LiggghtsRunError& e) {
    EXPECT_NE(e.reason().find("wall-clock limit"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(e.log_path()), std::string::npos) << e.what();
  }
  const std::string key = bed_cache_key(bed_script(scene, options.script),
                                        liggghts_version(resolve_liggghts_executable(options.run)));
  EXPECT_FALSE(fs::exists(dir_ / "cache" / "beds" / key));
}

TEST_F(LiggghtsReference, ErrorLinesAreQuoted) {
  std::ofstream(dir_ / "bad.in") << "units si\nno_such_command 1 2 3\nprint \"REPOSE_COMPLETE\"\n";
  try {
    run_liggghts(dir_.string(), "bad.in", {});
    FAIL() << "a failing script was reported as a success";
  } catch (const LiggghtsRunError& e) {
    EXPECT_NE(e.reason().find("ERROR"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(dir_.string()), std::string::npos) << e.what();
  }
  // a script that exits cleanly before its end marker is a failure too
  std::ofstream(dir_ / "short.in") << "units si\n";
  EXPECT_THROW(run_liggghts(dir_.string(), "short.in", {}), LiggghtsRunError);
}

}  // namespace
}  // namespace repose
