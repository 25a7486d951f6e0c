#include "models/snow/snow_picture_series.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "models/core/config/fields.h"
#include "models/snow/simulate_snow.h"
#include "tests/models/snow/snow_fixtures.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

// The number of pixels at least as bright as `level` in every channel.
long bright_pixels(const RgbImage& img, int level) {
  long n = 0;
  for (std::size_t p = 0; p < img.rgb.size(); p += 3) {
    if (img.rgb[p] >= level && img.rgb[p + 1] >= level && img.rgb[p + 2] >= level) ++n;
  }
  return n;
}

TEST(SnowPictureSeries, WritesTheRequestedFramesAndPicturesAsSnowGrows) {
  const HeightField ground(testing::centred_grid(20), 0.0);
  SnowOptions options = testing::vertical_snow_options(4);
  options.pictures.frame_count = 6;
  options.pictures.times_s = {0.0, 2.5};
  options.pictures.width_px = 80;
  options.pictures.height_px = 60;
  options.snowfall = SnowfallRate(0.0005);  // a quarter cell in 5 s: the ground whitens gradually
  SnowModel model = testing::plates_over_ground(ground, {testing::plate(0.04, 0.03, 0.05)}, options);
  model.time.duration_s = 5.0;
  const test_support::TempDir temp;
  const fs::path dir = temp.path / "series";  // made by the series
  SnowPictureSeries series(model, 1.0, dir.string());
  series.on_state(make_snow_state(model));
  SnowState state;
  simulate_snow(model, SnowParams{}, &state, [&](int, const SnowState& s) { series.on_state(s); });
  std::vector<std::string> frames;
  for (const std::string& f : series.files()) {
    ASSERT_TRUE(fs::is_regular_file(dir / f)) << f;
    if (f.rfind("frames/", 0) == 0) frames.push_back(f);
  }
  ASSERT_EQ(frames.size(), 6u);
  EXPECT_EQ(series.files().size(), 8u);
  EXPECT_TRUE(fs::is_regular_file(dir / "pictures/snow_t00002.500s.png"));
  long before = -1;
  for (const std::string& f : frames) {
    const long bright = bright_pixels(read_png_rgb((dir / f).string()), 230);
    EXPECT_GE(bright, before) << f << ": snow never shrinks under steady snowfall";
    before = bright;
  }
  EXPECT_GT(before, 0);
}

TEST(SnowPictureSeries, APictureTimeAfterTheRunIsRefused) {
  const HeightField ground(testing::centred_grid(4), 0.0);
  SnowOptions options = testing::vertical_snow_options();
  options.pictures.times_s = {3.0};
  const SnowModel model = testing::plates_over_ground(ground, {}, options);  // runs 1 s
  const test_support::TempDir temp;
  EXPECT_THROW(SnowPictureSeries(model, 1.0, (temp.path / "series").string()), FieldError);
}

}  // namespace
}  // namespace repose
