// A tiny chute run by the `liggghts` program (~330 grains, a few CPU
// seconds): the block released down a 35 degree rough chute reaches the
// wall; the force on the wall is positive, of the order of the incoming
// flow's momentum flux plus its hydrostatic thrust while the surge arrives,
// and at the end at most the weight of all the grains along the slope.

#include <cmath>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>

#include "tests/support/liggghts_test.h"
#include "tests/validation/liggghts/chute_test_scene.h"
#include "validation/liggghts/liggghts_reference.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

class ChuteRun : public test_support::LiggghtsTest {};

TEST_F(ChuteRun, FlowReachesTheWallAndLoadsItByItsMomentumFlux) {
  const Scene scene = testing::chute_scene(35.0);
  LiggghtsReferenceOptions options;
  options.bed.cache_dir = (dir_ / "cache").string();
  options.bed.run.wall_clock_limit_s = 120;
  options.run.wall_clock_limit_s = 120;
  fs::create_directories(dir_ / "run");
  const LiggghtsReferenceResult r = run_liggghts_reference(scene, (dir_ / "run").string(), options);
  ASSERT_TRUE(r.chute.has_value());
  const ChuteImpact& c = *r.chute;
  EXPECT_GT(c.front_arrival_s, 0.0);
  EXPECT_GE(c.impact_frame_count, 2);
  EXPECT_TRUE(fs::is_regular_file(dir_ / "run" / "chute_impact.csv"));

  const double zeta = 35.0 * std::numbers::pi / 180.0, g = 9.81;
  const ChuteLoad& m = c.mean;
  EXPECT_GT(m.speed_m_s, 0.3);
  EXPECT_GT(m.depth_m, 2 * 0.0018);  // at least a grain deep
  EXPECT_GT(m.force_n, 0.0);
  // momentum flux plus hydrostatic thrust of the incoming flow across the wall's width
  const double flux = c.geometry.width_m * m.mass_per_area_kg_m2 * (m.speed_m_s * m.speed_m_s + 0.5 * g * m.depth_m * std::cos(zeta));
  EXPECT_GT(m.force_n, 0.2 * flux);
  EXPECT_LT(m.force_n, 5.0 * flux);
  EXPECT_GE(c.peak.force_n, m.force_n);
  // at rest the wall holds at most the whole mass's weight along the slope
  double mass = 0.0;
  const double rho = dem_of(scene)->density_kg_m3;
  for (double a : {0.0018, 0.0019, 0.002, 0.0021, 0.0022}) mass += rho * 4.0 / 3.0 * std::numbers::pi * a * a * a;
  mass *= static_cast<double>(r.grain_count) / 5.0;
  EXPECT_GT(c.final_force_n, 0.0);
  EXPECT_LT(c.final_force_n, mass * g * std::sin(zeta));
}

}  // namespace
}  // namespace repose
