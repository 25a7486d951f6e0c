// A tiny cohesive snowfall run with the real `liggghts` program (~280
// grains, a few seconds): every grain rained is in the final dump, grains
// land on the plate and under it as the maps say, and the run's depth maps
// come out of the shared particle path.

#include "validation/liggghts/snowfall_reference.h"

#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/snow/snow_model.h"
#include "models/snow/snow_section.h"
#include "tests/support/liggghts_test.h"
#include "tests/validation/liggghts/snowfall_test_scene.h"
#include "validation/liggghts/grain_snow_depth.h"
#include "validation/liggghts/liggghts_dump.h"
#include "validation/liggghts/snowfall_script.h"

namespace repose {
namespace {

class SnowfallReference : public test_support::LiggghtsTest {};

TEST_F(SnowfallReference, TinySnowfallConservesGrainsAndCoversThePlate) {
  const Scene scene = testing::snowfall_test_scene();
  LiggghtsRunOptions options;
  options.wall_clock_limit_s = 120;
  const repose::Run run = run_liggghts_snowfall(scene, dir_.string(), options);
  const SnowfallScript script = snowfall_script(scene);
  ASSERT_GT(script.plan.grain_count, 200);
  // grain count conserved: every grain rained is in the settled dump
  const DumpFrame last = read_last_dump_frame((dir_ / kSnowfallDumpFile).string());
  EXPECT_EQ(static_cast<long>(last.grains.size()), script.plan.grain_count);
  EXPECT_EQ(run.measure("grain_count").value, static_cast<double>(script.plan.grain_count));
  // every grain rests inside the box, none above the layer it entered from
  EXPECT_GE(last.grains.position_m.col(2).minCoeff(), 0.0);
  EXPECT_LT(last.grains.position_m.col(2).maxCoeff(), script.plan.layer_bottom_m);
  // about the plate's share of the grains lands on it (area 4 x 2.4 cm of
  // 6.4 x 4.8 cm: 31 %), some spill off its edges
  const SnowModel model = build_snow_model(scene, scene.section<SnowSection>()->spec.options);
  const std::vector<int> map_of = snow_map_of_grains(last.grains, model.maps);
  const double on_plate = static_cast<double>(std::count(map_of.begin(), map_of.end(), 1)) / static_cast<double>(map_of.size());
  EXPECT_GT(on_plate, 0.15);
  EXPECT_LT(on_plate, 0.4);
  EXPECT_EQ(std::count(map_of.begin(), map_of.end(), -1), 0);
  // depth maps: snow on the plate's middle and on open ground, none where the plate has no surface
  const ArrayXXdR& plate = run.field("snow_depth_final.plate").heights();
  const ArrayXXdR& ground = run.field("snow_depth_final.ground").heights();
  EXPECT_GT(plate(6, 8), 0.002);
  EXPECT_EQ(plate(0, 0), 0.0);
  EXPECT_GT(ground(0, 0) + ground(0, 1) + ground(1, 0), 0.0);
  EXPECT_TRUE((run.field("height_final").heights() == ground).all());  // the ground is flat at 0
  EXPECT_GT(run.cpu_s, 0.0);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "liggghts_manifest.json"));
}

}  // namespace
}  // namespace repose
