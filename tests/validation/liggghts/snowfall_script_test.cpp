// The snowfall script (dem.initial: snowfall): its key lines from an inline
// scene, the grain count from the snow section's depth, the refusals, and
// the streams' directions (seeded, bit-identical, the distribution's mean and spread).

#include "validation/liggghts/snowfall_script.h"

#include <cmath>
#include <numbers>
#include <regex>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/validation/liggghts/snowfall_test_scene.h"

namespace repose {
namespace {

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

std::string error_of(const std::string& text) {
  try {
    snowfall_script(testing::snowfall_test_scene(text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SnowfallScript, KeyLines) {
  const Scene scene = testing::snowfall_test_scene();
  const SnowfallScript s = snowfall_script(scene);
  const std::string& t = s.text;
  if (std::getenv("REPOSE_PRINT_SCRIPT") != nullptr) std::cout << t;
  EXPECT_NE(t.find("boundary p p f\n"), std::string::npos);  // open ground gets snow everywhere
  EXPECT_NE(t.find("region domain block 0 0.064 0 0.048 0 "), std::string::npos);
  EXPECT_NE(t.find("create_box 2 domain\n"), std::string::npos);  // a rough floor: type 2
  // cohesion between grains, in LIGGGHTS' sub-model order; none with walls
  EXPECT_NE(t.find("pair_style gran model hertz tangential history cohesion sjkr rolling_friction cdt\n"), std::string::npos);
  EXPECT_NE(t.find("cohesionEnergyDensity peratomtypepair 2 50000 0 0 0\n"), std::string::npos);
  // terminal speed: no gravity fix; m g only on grains slower than 0.5 m/s
  EXPECT_EQ(t.find("fix gravity"), std::string::npos);
  EXPECT_NE(t.find("variable fall_gz atom -mass*9.81*((vx*vx+vy*vy+vz*vz)<0.25)\n"), std::string::npos);
  EXPECT_NE(t.find("fix fall all addforce 0 0 v_fall_gz\n"), std::string::npos);
  EXPECT_NE(t.find("fix obj0 all mesh/surface file object_0.stl type 2\n"), std::string::npos);
  EXPECT_NE(t.find("meshes obj0\n"), std::string::npos);
  ASSERT_EQ(s.meshes.size(), 1u);
  // one stream per direction, velocity = speed * direction, grain counts summing to the plan's
  const std::regex stream(R"(fix snow(\d+) all insert/rate/region seed \d+ distributiontemplate pdd nparticles (\d+) )"
                          R"(particlerate \S+ insert_every (\d+) start (\d+) .* vel constant (\S+) (\S+) (\S+) region snow_layer)");
  long total = 0;
  int streams = 0;
  std::set<long> starts;
  for (auto it = std::sregex_iterator(t.begin(), t.end(), stream); it != std::sregex_iterator(); ++it, ++streams) {
    const auto& m = *it;
    total += std::stol(m[2]);
    starts.insert(std::stol(m[4]));
    const Eigen::Vector3d v(std::stod(m[5]), std::stod(m[6]), std::stod(m[7]));
    EXPECT_NEAR(v.norm(), 0.5, 1e-12);
    EXPECT_TRUE(v.isApprox(0.5 * s.directions[static_cast<std::size_t>(std::stoi(m[1]))], 1e-12));
  }
  EXPECT_EQ(streams, 4);
  EXPECT_EQ(starts.size(), 4u);  // staggered: no two streams insert on one step
  EXPECT_EQ(total, s.plan.grain_count);
  // 4 mm of snow over the grid at packing 0.58, grains of mean volume (5 radii 1.8-2.2 mm)
  const double mean_volume = mean_grain_volume_m3(*dem_of(scene));
  EXPECT_EQ(s.plan.grain_count, std::lround(0.004 * 0.064 * 0.048 * 0.58 / mean_volume));
  EXPECT_NEAR(s.plan.open_depth_m, 0.004, 1e-15);
  // the layer is above the plate's top (0.022 m), inside the box
  EXPECT_GT(s.plan.layer_bottom_m, 0.022);
  EXPECT_LT(s.plan.layer_top_m, s.plan.domain.z_max_m);
  EXPECT_NE(t.find("dump snow all custom 1 snow.dump id type x y z radius\n"), std::string::npos);
  EXPECT_NE(t.find("REPOSE_COMPLETE"), std::string::npos);
  EXPECT_EQ(t, snowfall_script(scene).text);  // deterministic text
}

TEST(SnowfallScript, DryGrainsHaveNoCohesion) {
  const SnowfallScript s = snowfall_script(
      testing::snowfall_test_scene(replaced(testing::kSnowfallSceneText, "cohesion_energy_density_j_m3: 50000", "cohesion_energy_density_j_m3: 0")));
  EXPECT_EQ(s.text.find("cohesion"), std::string::npos);
}

TEST(SnowfallScript, RefusalsNameTheKey) {
  const std::string text = testing::kSnowfallSceneText;
  EXPECT_NE(error_of(replaced(text, "initial_height: {kind: flat, height_m: 0.0}", "initial_height: {kind: flat, height_m: 0.01}"))
                .find("flat ground at height 0"),
            std::string::npos);
  const std::string no_snow = text.substr(0, text.find("snow:\n")) + text.substr(text.find("dem:\n"));
  EXPECT_NE(error_of(no_snow).find("snow: section"), std::string::npos);
  EXPECT_NE(error_of(replaced(text, "snowfall_rate_m_s: 0.004", "snowfall_rate_m_s: 10")).find("grain_radius_m"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(text, "stream_count: 4", "stream_count: 0")).find("stream_count"), std::string::npos);
}

TEST(SnowfallStreamDirections, SeededBitIdenticalAndDistributedAsTheSnowSection) {
  const std::string text =
      replaced(replaced(testing::kSnowfallSceneText, "direction_tilt_deg: 0", "direction_tilt_deg: 20\n  direction_azimuth_deg: 90"),
               "spread_deg: 10", "spread_deg: 5");
  const Scene scene = testing::snowfall_test_scene(text);
  constexpr int kCount = 4000;
  const auto a = snowfall_stream_directions(scene, kCount);
  const auto b = snowfall_stream_directions(scene, kCount);
  ASSERT_EQ(a.size(), static_cast<std::size_t>(kCount));
  for (int k = 0; k < kCount; ++k) EXPECT_EQ(a[k], b[k]) << k;  // same bits
  Scene other = scene;
  other.seed = 4;
  EXPECT_NE(snowfall_stream_directions(other, 1)[0], a[0]);
  // mean direction: the main one (20 deg from down, towards +y); each
  // angular deviation has standard deviation 5 deg, so the angle from the
  // main direction has mean spread * sqrt(pi / 2) (a Rayleigh distribution)
  const double deg = std::numbers::pi / 180.0;
  const Eigen::Vector3d main(0.0, std::sin(20 * deg), -std::cos(20 * deg));
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double angle_sum = 0.0;
  for (const Eigen::Vector3d& d : a) {
    EXPECT_NEAR(d.norm(), 1.0, 1e-12);
    mean += d;
    angle_sum += std::acos(std::clamp(d.dot(main), -1.0, 1.0));
  }
  EXPECT_LT(std::acos(mean.normalized().dot(main)), 0.3 * deg);
  EXPECT_NEAR(angle_sum / kCount, 5 * deg * std::sqrt(std::numbers::pi / 2), 0.15 * deg);
}

}  // namespace
}  // namespace repose
