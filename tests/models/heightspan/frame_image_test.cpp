#include "models/heightspan/frame_image.h"

#include <gtest/gtest.h>

#include "heightspan_fixtures.h"
#include "models/core/base/error.h"
#include "models/core/config/initial_height.h"

namespace repose {
namespace {

struct Pixel {
  int r, g, b;
};
Pixel at(const RgbImage& img, int x, int y) {
  const std::size_t k = (static_cast<std::size_t>(y) * img.width + x) * 3;
  return {img.rgb[k], img.rgb[k + 1], img.rgb[k + 2]};
}

TEST(FrameImage, TheSectionShowsGroundObjectAndCarriedMaterial) {
  Scene s = testing::bed_scene(40, 20, 0.005, 0.02,
                               {testing::mesh_object("bucket", testing::bucket_mesh(), {testing::key(0, 0.1, 0.05, 0.08)})}, 1);
  const HeightSpanModel model = build_heightspan_model(s);
  HeightSpanState state = make_heightspan_state(model, make_initial_height(s));
  testing::fill_spans(&state.held[0].map, 0.01, 0.06);
  FrameView view;
  view.section_y_m = 0.0525;
  view.z_max_m = 0.12;
  view.px_per_cell = 2;
  const RgbImage img = render_frame(model, state, view);
  ASSERT_EQ(img.width, 80);
  const int rows = 24 * 2;  // 0.12 m on 5 mm cells
  ASSERT_EQ(img.height, rows + 4 + 20 * 2);
  auto row_of = [&](double z) { return static_cast<int>((0.12 - z) / 0.12 * rows); };
  const Pixel ground = at(img, 10, row_of(0.01)), air = at(img, 10, row_of(0.1));
  const Pixel floor = at(img, 40, row_of(0.0575)), load = at(img, 40, row_of(0.065));
  EXPECT_EQ(air.r, 255);
  EXPECT_LT(ground.b, ground.r);    // sand
  EXPECT_LT(std::abs(floor.r - floor.b), 20);  // the object is grey
  EXPECT_GT(load.r, ground.r);      // the carried material is lighter than the ground
  const RgbImage again = render_frame(model, state, view);
  EXPECT_EQ(again.rgb, img.rgb);
  view.px_per_cell = 0;
  EXPECT_THROW(render_frame(model, state, view), InputError);
}

}  // namespace
}  // namespace repose
