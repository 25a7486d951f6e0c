// The torn sheet rendered in 3-D: a flat sheet seen face on covers the
// pixels its size and the camera give, the lower fibre layers show (white)
// only where the sheet is torn and as wide as the layers' offsets, and bad
// options are refused by name.
#include "experiments/tearing/tear_render.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

bool is_background(const RgbImage& img, std::size_t p) {
  return std::abs(img.rgb[3 * p] - 33) <= 2 && std::abs(img.rgb[3 * p + 1] - 33) <= 2 &&
         std::abs(img.rgb[3 * p + 2] - 43) <= 2;
}

// A lit lower layer: bright and grey (the top layer is green).
bool is_white(const RgbImage& img, std::size_t p) {
  const int r = img.rgb[3 * p], g = img.rgb[3 * p + 1], b = img.rgb[3 * p + 2];
  return r > 150 && std::abs(r - g) < 20 && std::abs(g - b) < 20;
}

int count(const RgbImage& img, bool (*what)(const RgbImage&, std::size_t)) {
  int n = 0;
  for (std::size_t p = 0; p < img.rgb.size() / 3; ++p) n += what(img, p);
  return n;
}

TearRenderOptions face_on(int px) {
  TearRenderOptions o;
  o.width_px = o.height_px = px;
  o.azimuth_deg = o.elevation_deg = 0.0;
  o.supersample = 1;
  return o;
}

// Pixels per metre at the target's distance.
double pixels_per_m(const CameraSpec& c) {
  return c.height_px / (2.0 * (c.position_m - c.target_m).norm() * std::tan(c.fov_y_rad / 2));
}

FibreImages three_uniform_layers(double side_m, double pixel_m) {
  FibreImages images = uniform_fibre_images(side_m, side_m, pixel_m, 0.5);
  images.layers = {images.composite, images.composite, images.composite};
  return images;
}

TEST(TearRender, AFlatSheetSeenFaceOnCoversItsShareOfTheImage) {
  const FibreImages images = three_uniform_layers(0.1, 0.5e-3);
  const SheetModel model = build_sheet_model(free_sheet_spec(0.1, 20), images);
  const SheetState state = make_sheet_state(model);
  const TearRenderOptions o = face_on(200);
  const RgbImage img = render_tear(model, state, images, TearEdgeOptions{}, o);
  ASSERT_EQ(img.width, 200);
  ASSERT_EQ(img.height, 200);
  const double side_px = 0.1 * pixels_per_m(tear_camera(model, state, o));
  const double expected = side_px * side_px / (200.0 * 200.0);  // about 0.42
  const double covered = 1.0 - static_cast<double>(count(img, is_background)) / (200.0 * 200.0);
  EXPECT_GT(expected, 0.3);
  EXPECT_NEAR(covered, expected, 0.02);
  EXPECT_EQ(count(img, is_white), 0);  // no tear: only the (green) top layer shows
  EXPECT_EQ(img.rgb, render_tear(model, state, images, TearEdgeOptions{}, o).rgb);  // same input, same bytes
}

TEST(TearRender, TheLowerLayersShowOnlyAlongTheTearAsWideAsTheirOffsets) {
  // a 1 cm sheet of 10 cells torn down column 4 from the top to row 3, the
  // pieces moved 0.5 mm apart each
  const FibreImages images = three_uniform_layers(0.01, 0.05e-3);
  const SheetModel model = build_sheet_model(free_sheet_spec(0.01, 10), images);
  SheetState state = make_sheet_state(model);
  for (int j = 9; j >= 3; --j) state.torn_step[model.cell(4, j)] = 1;
  for (int v = 0; v < model.vertex_count(); ++v) {
    state.positions(0, v) += model.rest_positions(0, v) < 4.5e-3 ? -0.5e-3 : 0.5e-3;
  }
  TearEdgeOptions edge;
  edge.layer_offset_m = 0.2e-3;
  const TearRenderOptions o = face_on(400);
  const RgbImage torn = render_tear(model, state, images, edge, o);
  const double ppm = pixels_per_m(tear_camera(model, state, o));
  // the left piece's two lower layers reach 0.2 and 0.4 mm past its top
  // layer's cut (the torn column's middle, so still inside the torn cell)
  // over the 7 torn rows: a 0.4 mm white fringe, 7 mm long
  const double expected_px = 0.4e-3 * 7e-3 * ppm * ppm;
  EXPECT_GT(expected_px, 300.0);
  EXPECT_NEAR(count(torn, is_white), expected_px, 0.1 * expected_px);

  edge.layer_offset_m = 0.0;  // every layer cut at the same place: no fringe
  EXPECT_LT(count(render_tear(model, state, images, edge, o), is_white), 0.05 * expected_px);
}

TEST(TearRender, RefusesBadOptionsNamingTheField) {
  const auto message = [](TearRenderOptions o) -> std::string {
    try {
      o.validate();
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  TearRenderOptions o;
  o.width_px = 0;
  EXPECT_NE(message(o).find("width_px"), std::string::npos);
  o = {};
  o.elevation_deg = 95.0;
  EXPECT_NE(message(o).find("elevation_deg"), std::string::npos);
  o = {};
  o.layer_spacing_m = -1e-4;
  EXPECT_NE(message(o).find("layer_spacing_m"), std::string::npos);
  o = {};
  o.supersample = 9;
  EXPECT_NE(message(o).find("supersample"), std::string::npos);
  EXPECT_EQ(message(TearRenderOptions{}), "");
}

TEST(TearRender, AColouredMeshNeedsAColourPerVertex) {
  ColouredMesh m;
  m.mesh.V = MatrixX3dR::Zero(3, 3);
  m.mesh.F = MatrixX3iR(1, 3);
  m.mesh.F << 0, 1, 2;
  m.vertex_rgb.resize(2);
  CameraSpec c;
  c.width_px = c.height_px = 8;
  EXPECT_THROW(render_coloured_meshes({m}, c), InputError);
}

}  // namespace
}  // namespace repose
