// The layered tear edge: cuts follow the thinnest fibres near the tear, and
// each layer's cut is shifted from the one above.
#include "models/tearing/tear_edge_layers.h"

#include <cmath>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

// A 10 x 10 sheet (1 mm cells) torn straight down column 4, and 3 layers.
struct Torn {
  SheetModel model;
  SheetState state;
};

Torn torn_column(const FibreImages& images) {
  Torn t{build_sheet_model(free_sheet_spec(0.01, 10), images), {}};
  t.state = make_sheet_state(t.model);
  for (int j = 9; j >= 3; --j) t.state.torn_step[t.model.cell(4, j)] = 1;
  return t;
}

TEST(TearEdgeLayers, OnAUniformImageEachLayerIsShiftedByTheOffset) {
  FibreImages images = uniform_fibre_images(0.01, 0.01, 0.1e-3, 0.5);
  images.layers = {images.composite, images.composite, images.composite};
  const Torn t = torn_column(images);
  TearEdgeOptions options;
  options.layer_offset_m = 0.3e-3;
  const LayerCuts cuts = trace_layer_cuts(t.model, t.state, images, options);
  ASSERT_EQ(cuts.cut_x_m.size(), 3u);
  int rows_cut = 0;
  for (int r = 0; r < images.ny(); ++r) {
    if (std::isnan(cuts.cut_x_m[0][r])) continue;
    ++rows_cut;
    EXPECT_NEAR(cuts.cut_x_m[0][r], 4.55e-3, 1e-12) << r;  // the tear column's centre pixel
    EXPECT_NEAR(cuts.cut_x_m[1][r] - cuts.cut_x_m[0][r], 0.3e-3, 1e-12) << r;
    EXPECT_NEAR(cuts.cut_x_m[2][r] - cuts.cut_x_m[1][r], 0.3e-3, 1e-12) << r;
  }
  EXPECT_EQ(rows_cut, 70);  // 7 cells of 10 pixels
}

TEST(TearEdgeLayers, CutsRunThroughTheThinnestFibresNearTheTear) {
  std::mt19937_64 rng(4);
  FibreOptions fibres;
  fibres.pixel_size_m = 0.1e-3;
  const FibreImages images = draw_fibre_images(fibres, 0.01, 0.01, rng);
  const Torn t = torn_column(images);
  const TearEdgeOptions options;
  const LayerCuts cuts = trace_layer_cuts(t.model, t.state, images, options);
  const double px = 0.1e-3;
  const int search = static_cast<int>(std::lround(options.search_half_width_m / px));
  const int shift = static_cast<int>(std::lround(options.layer_offset_m / px));
  double previous = std::nan("");
  for (int r = images.ny() - 1; r >= 0; --r) {
    if (std::isnan(cuts.cut_x_m[0][r])) continue;
    // the top layer's cut stays near the tear column and moves at most
    // `search` pixels from row to row
    EXPECT_LE(std::abs(cuts.cut_x_m[0][r] - 4.5e-3), 1.5e-3 + px) << r;
    if (!std::isnan(previous)) {
      EXPECT_LE(std::abs(cuts.cut_x_m[0][r] - previous), search * px + 1e-12) << r;
    }
    previous = cuts.cut_x_m[0][r];
    // a lower layer cuts where it is thinnest around the shifted cut above
    for (std::size_t k = 1; k < 3; ++k) {
      const int from = static_cast<int>(std::lround(cuts.cut_x_m[k - 1][r] / px - 0.5)) + shift;
      const int c = static_cast<int>(std::lround(cuts.cut_x_m[k][r] / px - 0.5));
      EXPECT_LE(std::abs(c - from), search) << k << ", " << r;
      for (int n = std::max(0, from - search); n <= std::min(images.nx() - 1, from + search); ++n) {
        EXPECT_LE(images.layers[k](r, c), images.layers[k](r, n)) << k << ", " << r;
      }
    }
  }
  const RgbImage picture = draw_layered_tear_edge(images, cuts, options);
  EXPECT_EQ(picture.width, 100);
  EXPECT_EQ(picture.height, 100);
}

TEST(TearEdgeLayers, RefusesANonUnitOffsetDirection) {
  TearEdgeOptions options;
  options.offset_direction = Eigen::Vector2d(2.0, 0.0);
  EXPECT_THROW(options.validate(), InputError);
}

}  // namespace
}  // namespace repose
