// The dem_snowfall: section: defaults without it, values read, refusals naming the key.

#include "validation/liggghts/snowfall_section.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/validation/liggghts/snowfall_test_scene.h"

namespace repose {
namespace {

std::string error_of(const std::string& section) {
  std::string text = testing::kSnowfallSceneText;
  text = text.substr(0, text.find("dem_snowfall:")) + section;
  try {
    testing::snowfall_test_scene(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SnowfallSection, DefaultsAndValues) {
  std::string text = testing::kSnowfallSceneText;
  const Scene without = testing::snowfall_test_scene(text.substr(0, text.find("dem_snowfall:")));
  EXPECT_EQ(snowfall_options_of(without).stream_count, SnowfallOptions{}.stream_count);
  EXPECT_EQ(snowfall_options_of(without).fall_speed_m_s, 0.5);
  const SnowfallOptions o = snowfall_options_of(testing::snowfall_test_scene());
  EXPECT_EQ(o.stream_count, 4);
  EXPECT_EQ(o.insert_time_s, 0.1);
  EXPECT_EQ(o.max_settle_time_s, 0.5);
}

TEST(SnowfallSection, RefusalsNameTheKey) {
  EXPECT_NE(error_of("dem_snowfall: {fall_speed_m_s: 0}\n").find("fall_speed_m_s"), std::string::npos);
  EXPECT_NE(error_of("dem_snowfall: {packing_fraction: 0.9}\n").find("packing_fraction"), std::string::npos);
  EXPECT_NE(error_of("dem_snowfall: {streams: 3}\n").find("streams"), std::string::npos);
  EXPECT_NE(error_of("dem_snowfall: {insert_time_s: -1}\n").find("insert_time_s"), std::string::npos);
}

}  // namespace
}  // namespace repose
