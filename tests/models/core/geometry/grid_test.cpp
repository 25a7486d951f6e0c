// Grid: the same extent on other cells, coarsened by a factor or at a given
// cell size, and refused when the cells do not divide it.
#include "models/core/geometry/grid.h"

#include <gtest/gtest.h>

namespace repose {
namespace {

TEST(Grid, ACoarsenedGridRoundsItsCellsUp) {
  const Grid g = Grid{10, 7, 0.01, -0.05, 0.02}.coarsened(3);
  EXPECT_EQ(g.nx, 4);
  EXPECT_EQ(g.ny, 3);
  EXPECT_DOUBLE_EQ(g.cell_size_m, 0.03);
  EXPECT_EQ(g.origin_x_m, -0.05);
}

TEST(Grid, WithACellSizeKeepsTheExtentExactlyOrRefuses) {
  const Grid scoop{104, 40, 0.0025, 0.0, 0.0};  // 0.26 x 0.10 m
  for (const double h : {0.005, 0.004, 0.00125, 0.0025}) {
    const auto g = scoop.with_cell_size(h);
    ASSERT_TRUE(g.has_value()) << h;
    EXPECT_NEAR(g->extent_x_m(), scoop.extent_x_m(), 1e-12) << h;
    EXPECT_NEAR(g->extent_y_m(), scoop.extent_y_m(), 1e-12) << h;
    EXPECT_EQ(g->origin_x_m, scoop.origin_x_m);
    EXPECT_EQ(g->cell_size_m, h);
  }
  EXPECT_EQ(scoop.with_cell_size(0.004)->nx, 65);
  EXPECT_FALSE(scoop.with_cell_size(0.003).has_value());  // 86.7 cells across
  EXPECT_FALSE(scoop.with_cell_size(0.3).has_value());    // not one cell
}

}  // namespace
}  // namespace repose
