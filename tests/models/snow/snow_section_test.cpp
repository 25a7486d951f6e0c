#include "models/snow/snow_section.h"

#include <gtest/gtest.h>

#include <numbers>

#include "models/core/base/error.h"
#include "models/core/config/scene_loader.h"

namespace repose {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

const char* const kCommon = R"(
name: snow_section
time: {step_s: 1.0, duration_s: 2.0}
ground:
  extent_m: [0.2, 0.2]
  cell_size_m: 0.01
  initial_height: {kind: flat, height_m: 0.0}
objects:
  - {name: top, shape: box, half_extents_m: [0.04, 0.04, 0.005], motion: [{time_s: 0, position_m: [0, 0, 0.05]}]}
)";

Scene load(const std::string& snow) {
  return load_scene_from_string(std::string(kCommon) + snow, "/tmp/snow_section.yaml", {snow_section_type()});
}

std::string error_of(const std::string& snow) {
  try {
    load(snow);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SnowSection, ReadsOptionsAndParamsInSiUnits) {
  const Scene scene = load(R"(
snow:
  groups: [{name: ground, ground: true}, {name: table, objects: [top]}]
  direction_tilt_deg: 20
  direction_azimuth_deg: 90
  spread_deg: 12
  repose_angle_deg: 50
  direction_count: 32
  snowfall: [{time_s: 0, rate_m_s: 0.0}, {time_s: 2, rate_m_s: 0.002}]
  renderer: osmesa
  probability: ray_cast
)");
  const SnowSection* s = scene.section<SnowSection>();
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->spec.options.groups.size(), 2u);
  EXPECT_TRUE(s->spec.options.groups[0].ground);
  EXPECT_EQ(s->spec.options.groups[1].objects, std::vector<std::string>{"top"});
  EXPECT_NEAR(s->spec.options.main_direction.tilt_rad, 20 * kDeg, 1e-15);
  EXPECT_NEAR(s->spec.params.direction_spread_rad, 12 * kDeg, 1e-15);
  EXPECT_NEAR(s->spec.params.repose_angle_rad, 50 * kDeg, 1e-15);
  EXPECT_EQ(s->spec.options.direction_count, 32);
  EXPECT_NEAR(s->spec.options.snowfall.depth_between_m(0.0, 2.0), 0.002, 1e-15);
  EXPECT_EQ(s->spec.options.renderer, SnowRenderer::kOsmesa);
  EXPECT_EQ(s->spec.options.probability, SnowOptions::Probability::kRayCast);
}

TEST(SnowSection, WritesWhatItReads) {
  const Scene scene = load(R"(
snow:
  groups: [{name: ground, ground: true}, {name: table, objects: [top]}]
  spread_deg: 7
  snowfall_rate_m_s: 0.003
)");
  const Scene again = load_scene_from_string(scene_to_yaml(scene), "/tmp/again.yaml", {snow_section_type()});
  const SnowSpec& a = scene.section<SnowSection>()->spec;
  const SnowSpec& b = again.section<SnowSection>()->spec;
  EXPECT_EQ(a.params.direction_spread_rad, b.params.direction_spread_rad);
  EXPECT_EQ(a.options.groups.size(), b.options.groups.size());
  EXPECT_EQ(a.options.snowfall.depth_between_m(0, 1), b.options.snowfall.depth_between_m(0, 1));
  EXPECT_EQ(a.options.moved_fraction, b.options.moved_fraction);
}

TEST(SnowSection, ReadsAndWritesThePictureOptions) {
  const Scene scene = load(R"(
snow:
  groups: [{name: ground, ground: true}]
  picture_times_s: [0, 1.5]
  frame_count: 4
  picture_width_px: 320
  view_elevation_deg: 90
)");
  const SnowPictureOptions& p = scene.section<SnowSection>()->spec.options.pictures;
  EXPECT_EQ(p.times_s, (std::vector<double>{0.0, 1.5}));
  EXPECT_EQ(p.frame_count, 4);
  EXPECT_EQ(p.width_px, 320);
  EXPECT_NEAR(p.view_elevation_rad, 0.5 * std::numbers::pi, 1e-15);
  const Scene again = load_scene_from_string(scene_to_yaml(scene), "/tmp/again.yaml", {snow_section_type()});
  const SnowPictureOptions& q = again.section<SnowSection>()->spec.options.pictures;
  EXPECT_EQ(q.times_s, p.times_s);
  EXPECT_EQ(q.frame_count, 4);
}

TEST(SnowSection, PictureRefusalsNameTheKeyInOneLine) {
  const std::string groups = "  groups: [{name: ground, ground: true}]\n";
  for (const auto& [text, key] : std::vector<std::pair<std::string, std::string>>{
           {"  frame_count: -1\n", "frame_count"},
           {"  picture_times_s: [1, 0.5]\n", "picture_times_s"},
           {"  picture_times_s: [3]\n", "picture_times_s"},  // after the run's 2 s
           {"  picture_width_px: 4\n", "picture_width_px"},
           {"  view_elevation_deg: 0\n", "view_elevation_deg"}}) {
    const std::string e = error_of("snow:\n" + groups + text);
    EXPECT_NE(e.find(key), std::string::npos) << text << " -> " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
}

TEST(SnowSection, RefusalsNameTheKey) {
  const std::string groups = "  groups: [{name: ground, ground: true}]\n";
  EXPECT_NE(error_of("snow:\n" + groups + "  moved_fraction: 0.3\n").find("moved_fraction"), std::string::npos);
  EXPECT_NE(error_of("snow:\n" + groups + "  direction_tilt_deg: 89\n").find("direction_tilt_deg"), std::string::npos);
  EXPECT_NE(error_of("snow:\n" + groups + "  spread: 3\n").find("spread"), std::string::npos);
  EXPECT_NE(error_of("snow:\n  groups: [{name: t, objects: [chair]}]\n").find("chair"), std::string::npos);
  EXPECT_NE(error_of("snow:\n  direction_count: 3\n").find("groups"), std::string::npos);
  EXPECT_NE(error_of("snow:\n" + groups + "  snowfall_rate_m_s: 0.1\n  snowfall: [{time_s: 0, rate_m_s: 0}]\n")
                .find("snowfall"),
            std::string::npos);
}

}  // namespace
}  // namespace repose
