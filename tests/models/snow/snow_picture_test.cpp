#include "models/snow/snow_picture.h"

#include <gtest/gtest.h>

#include <array>
#include <set>

#include "models/core/config/fields.h"
#include "models/snow/simulate_snow.h"
#include "tests/models/snow/snow_fixtures.h"

namespace repose {
namespace {

using Colour = std::array<std::uint8_t, 3>;

// The colours of the picture's pixels other than the background.
std::set<Colour> scene_colours(const RgbImage& img) {
  std::set<Colour> colours;
  for (std::size_t p = 0; p < img.rgb.size(); p += 3) {
    const Colour c{img.rgb[p], img.rgb[p + 1], img.rgb[p + 2]};
    if (c != Colour{kSnowPictureBackground[0], kSnowPictureBackground[1], kSnowPictureBackground[2]}) colours.insert(c);
  }
  return colours;
}

SnowPictureOptions small_picture(double elevation_deg) {
  SnowPictureOptions o;
  o.width_px = 96;
  o.height_px = 64;
  o.view_elevation_rad = elevation_deg * kRadPerDeg;
  o.view_azimuth_rad = -60.0 * kRadPerDeg;
  return o;
}

TEST(SnowPicture, AFlatOpenGroundUnderUniformSnowIsOneColour) {
  const HeightField ground(testing::centred_grid(16), 0.0);
  const SnowModel model = testing::plates_over_ground(ground, {}, testing::vertical_snow_options());
  SnowState state;
  simulate_snow(model, SnowParams{}, &state);
  ASSERT_GT(state.depth_m[0].minCoeff(), 0.0);
  ASSERT_EQ(state.depth_m[0].minCoeff(), state.depth_m[0].maxCoeff()) << "the snow itself is uniform";
  for (const double elevation_deg : {35.0, 90.0}) {
    SnowPictureRenderer renderer(model, small_picture(elevation_deg), snow_picture_top_m(model, 1.0));
    const std::set<Colour> snowy = scene_colours(renderer.render(state));
    ASSERT_EQ(snowy.size(), 1u) << "elevation " << elevation_deg;
    const std::set<Colour> bare = scene_colours(renderer.render(make_snow_state(model)));
    ASSERT_EQ(bare.size(), 1u);
    const Colour s = *snowy.begin(), b = *bare.begin();
    EXPECT_GT(s[0] + s[1] + s[2], b[0] + b[1] + b[2] + 150) << "snow is far brighter than the soil";
  }
}

TEST(SnowPicture, SnowOnAPlateShowsAndTheSameStateGivesTheSameBytes) {
  const HeightField ground(testing::centred_grid(24), 0.0);
  const SnowModel model =
      testing::plates_over_ground(ground, {testing::plate(0.05, 0.05, 0.06)}, testing::vertical_snow_options());
  SnowPictureRenderer renderer(model, small_picture(90.0), snow_picture_top_m(model, 1.0));
  const SnowState bare = make_snow_state(model);
  SnowState snowy;
  simulate_snow(model, SnowParams{}, &snowy);
  const RgbImage a = renderer.render(snowy), b = renderer.render(snowy), c = renderer.render(bare);
  EXPECT_EQ(a.rgb, b.rgb);
  EXPECT_NE(a.rgb, c.rgb);
  // seen from straight above, the bare plate is grey and the snow on it white: the centre pixel brightens
  const std::size_t centre = (static_cast<std::size_t>(a.height / 2) * a.width + a.width / 2) * 3;
  EXPECT_GT(a.rgb[centre] + 0, c.rgb[centre] + 40);
}

}  // namespace
}  // namespace repose
