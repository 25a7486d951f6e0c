#include "models/snow/snow_picture_options.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "models/core/config/fields.h"

namespace repose {
namespace {

// The key a FieldError names when `change` spoils the default options.
std::string refused_key(const std::function<void(SnowPictureOptions&)>& change) {
  SnowPictureOptions o;
  change(o);
  try {
    validate(o);
  } catch (const FieldError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line: " << e.what();
    return e.field();
  }
  return "";
}

TEST(SnowPictureOptions, DefaultsDrawNothingAndAreValid) {
  const SnowPictureOptions o;
  EXPECT_NO_THROW(validate(o));
  EXPECT_FALSE(o.any());
}

TEST(SnowPictureOptions, RefusalsNameTheKey) {
  EXPECT_EQ(refused_key([](auto& o) { o.times_s = {-1.0}; }), "picture_times_s");
  EXPECT_EQ(refused_key([](auto& o) { o.times_s = {2.0, 1.0}; }), "picture_times_s");
  EXPECT_EQ(refused_key([](auto& o) { o.times_s = {1.0, 1.0}; }), "picture_times_s");
  EXPECT_EQ(refused_key([](auto& o) { o.frame_count = -1; }), "frame_count");
  EXPECT_EQ(refused_key([](auto& o) { o.frame_count = 10001; }), "frame_count");
  EXPECT_EQ(refused_key([](auto& o) { o.width_px = 8; }), "picture_width_px");
  EXPECT_EQ(refused_key([](auto& o) { o.height_px = 5000; }), "picture_height_px");
  EXPECT_EQ(refused_key([](auto& o) { o.view_elevation_rad = 2.0 * kRadPerDeg; }), "view_elevation_deg");
  EXPECT_EQ(refused_key([](auto& o) { o.view_elevation_rad = 91.0 * kRadPerDeg; }), "view_elevation_deg");
  EXPECT_EQ(refused_key([](auto& o) { o.view_azimuth_rad = std::nan(""); }), "view_azimuth_deg");
}

TEST(SnowPictureOptions, TimesMustLieWithinTheRun) {
  SnowPictureOptions o;
  o.times_s = {0.0, 10.0};
  EXPECT_NO_THROW(validate_picture_times(o, 10.0));
  try {
    validate_picture_times(o, 5.0);
    ADD_FAILURE() << "a time after the end was accepted";
  } catch (const FieldError& e) {
    EXPECT_EQ(e.field(), "picture_times_s");
  }
}

TEST(SnowPictureOptions, FramesSpanTheRunEvenly) {
  SnowPictureOptions o;
  o.frame_count = 5;
  const std::vector<double> t = frame_times_s(o, 8.0);
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t.front(), 0.0);
  EXPECT_EQ(t.back(), 8.0);
  for (std::size_t k = 1; k < t.size(); ++k) EXPECT_DOUBLE_EQ(t[k] - t[k - 1], 2.0);
  o.frame_count = 1;
  EXPECT_EQ(frame_times_s(o, 8.0), std::vector<double>{8.0});
  o.frame_count = 0;
  EXPECT_TRUE(frame_times_s(o, 8.0).empty());
}

}  // namespace
}  // namespace repose
