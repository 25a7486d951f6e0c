#include "models/heightspan/simulate_heightspan.h"

#include <gtest/gtest.h>

#include "heightspan_fixtures.h"
#include "models/core/config/initial_height.h"

namespace repose {
namespace {

using testing::key;

Scene scoop_scene() {
  std::vector<Keyframe> keys = {key(0.0, 0.06, 0.06, 0.1, 80), key(0.2, 0.06, 0.06, 0.055, 80),
                                key(0.6, 0.12, 0.06, 0.055, 80), key(0.9, 0.12, 0.06, 0.12, 0),
                                key(1.2, 0.12, 0.06, 0.12, 135)};
  return testing::bed_scene(40, 24, 0.005, 0.03, {testing::mesh_object("bucket", testing::bucket_mesh(), keys)}, 45);
}

TEST(SimulateHeightSpan, ReportsTheLedgerAndTheHeldVolumeEveryStep) {
  const Scene s = scoop_scene();
  const HeightSpanModel model = build_heightspan_model(s);
  const HeightSpanRun r = simulate_heightspan(model, default_params(model.ground), make_initial_height(s));
  EXPECT_EQ(r.steps, 45);
  ASSERT_EQ(r.time_s.size(), 45u);
  ASSERT_EQ(r.held_m3.size(), 1u);
  ASSERT_EQ(r.held_m3[0].size(), 45u);
  EXPECT_LT(r.max_abs_imbalance_m3, 1e-12 * r.initial_m3);
  EXPECT_GT(*std::max_element(r.held_m3[0].begin(), r.held_m3[0].end()), 0.0);
  EXPECT_GT(r.taken_up_m3, 0.0);
  EXPECT_TRUE(r.particles_built);
  EXPECT_EQ(r.stages.back(), "particles");
  EXPECT_NE(std::find(r.stages.begin(), r.stages.end(), "span-maps:cpu"), r.stages.end());
}

TEST(SimulateHeightSpan, SameInputSameBits) {
  const Scene s = scoop_scene();
  const HeightSpanModel model = build_heightspan_model(s);
  const HeightSpanRun a = simulate_heightspan(model, default_params(model.ground), make_initial_height(s));
  const HeightSpanRun b = simulate_heightspan(model, default_params(model.ground), make_initial_height(s));
  EXPECT_TRUE((a.final_height.heights() == b.final_height.heights()).all());
  EXPECT_EQ(a.held_m3, b.held_m3);
}

TEST(SimulateHeightSpan, FramesAtTimeZeroAndEveryInterval) {
  Scene s = scoop_scene();
  HeightSpanSection section = heightspan_section(s);
  section.options.frame_interval_s = 0.5;
  s = with_heightspan(s, section);
  const HeightSpanModel model = build_heightspan_model(s);
  std::vector<int> frames;
  simulate_heightspan(model, default_params(model.ground), make_initial_height(s), {},
                      [&](int n, const HeightSpanState&) { frames.push_back(n); });
  EXPECT_EQ(frames, (std::vector<int>{0, 1, 2, 3}));  // 0, 0.5, 1.0, 1.5 s
}

TEST(SimulateHeightSpan, TheOsmesaSpanMapsGiveTheSameScoop) {
  Scene s = scoop_scene();
  const HeightSpanModel cpu_model = build_heightspan_model(s);
  HeightSpanSection section = heightspan_section(s);
  section.options.span_maps = HeightSpanSpec::SpanMaps::kOsmesa;
  const HeightSpanModel gl_model = build_heightspan_model(with_heightspan(s, section));
  const HeightSpanRun cpu = simulate_heightspan(cpu_model, default_params(cpu_model.ground), make_initial_height(s));
  const HeightSpanRun gl = simulate_heightspan(gl_model, default_params(gl_model.ground), make_initial_height(s));
  EXPECT_NE(std::find(gl.stages.begin(), gl.stages.end(), "span-maps:osmesa"), gl.stages.end());
  EXPECT_LT(gl.max_abs_imbalance_m3, 1e-12 * gl.initial_m3);
  const double held_max = *std::max_element(cpu.held_m3[0].begin(), cpu.held_m3[0].end());
  // step by step through the scoop and the carry; the tip (from 0.9 s) throws what leaves the lip with the lip's
  // velocity, and where it lands, on the ground or back on the bucket, turns on single cells of the two
  // rasterisations: there both buckets empty
  for (std::size_t k = 0; k < cpu.held_m3[0].size(); ++k) {
    if (cpu.time_s[k] <= 0.9) {
      EXPECT_NEAR(gl.held_m3[0][k], cpu.held_m3[0][k], 0.01 * held_max) << "step " << k;
    }
  }
  EXPECT_LT(cpu.held_m3[0].back(), 0.01 * held_max);
  EXPECT_LT(gl.held_m3[0].back(), 0.01 * held_max);
}

TEST(SimulateHeightSpan, NothingFallsNoParticlesAreBuilt) {
  Scene s = testing::bed_scene(40, 40, 0.005, 0.01,
                               {testing::mesh_object("bucket", testing::bucket_mesh(), {key(0, 0.1, 0.1, 0.1)})}, 5);
  const HeightSpanModel model = build_heightspan_model(s);
  const HeightSpanRun r = simulate_heightspan(model, default_params(model.ground), make_initial_height(s));
  EXPECT_FALSE(r.particles_built);
  EXPECT_EQ(std::find(r.stages.begin(), r.stages.end(), "particles"), r.stages.end());
}

}  // namespace
}  // namespace repose
