// The tear path measures on torn sets drawn by hand.
#include "models/tearing/tear_path.h"

#include <cmath>

#include <gtest/gtest.h>

#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

TEST(TearPath, NothingTornHasNoPath) {
  const SheetModel model = uniform_sheet(free_sheet_spec(0.01, 10));
  const TearPath path = measure_tear_path(model, make_sheet_state(model));
  EXPECT_TRUE(path.points.empty());
  EXPECT_EQ(path.depth_m, 0.0);
}

TEST(TearPath, AStraightTearIsStraightAndSmooth) {
  const SheetModel model = uniform_sheet(free_sheet_spec(0.01, 10));
  SheetState state = make_sheet_state(model);
  for (int j = 9; j >= 4; --j) state.torn_step[model.cell(3, j)] = 1;
  const TearPath path = measure_tear_path(model, state);
  ASSERT_EQ(path.points.size(), 6u);
  EXPECT_DOUBLE_EQ(path.tortuosity, 1.0);
  EXPECT_NEAR(path.roughness_m, 0.0, 1e-15);
  EXPECT_NEAR(path.deviation_m, 0.0, 1e-15);
  EXPECT_NEAR(path.depth_m, 0.006, 1e-15);
  EXPECT_EQ(path.tear_cells, 6);
}

TEST(TearPath, AZigZagIsLongerAndRougherThanItsChord) {
  const SheetModel model = uniform_sheet(free_sheet_spec(0.01, 10));
  SheetState state = make_sheet_state(model);
  // columns 4, 5, 4, 5, ... from the top row down: steps of (1, 1) mm
  for (int j = 9; j >= 0; --j) state.torn_step[model.cell(j % 2 == 1 ? 4 : 5, j)] = 1;
  state.torn_step[model.cell(0, 0)] = 2;  // a stray cell, not diagonal-connected to the tear
  const TearPath path = measure_tear_path(model, state);
  ASSERT_EQ(path.points.size(), 10u);
  EXPECT_NEAR(path.path_length_m, 9 * std::sqrt(2.0) * 1e-3, 1e-15);
  EXPECT_NEAR(path.tortuosity, 9 * std::sqrt(2.0) / std::hypot(1.0, 9.0), 1e-12);
  // the points alternate +-0.5 mm about a nearly vertical line
  EXPECT_NEAR(path.roughness_m, 0.5e-3, 0.02e-3);
  EXPECT_NEAR(path.deviation_m, std::sqrt(0.5) * 1e-3, 1e-15);
  EXPECT_EQ(path.stray_cells, 1);
  EXPECT_EQ(path.tear_cells, 10);
}

TEST(TearPath, TheLargestTornSetIsTheTearEvenAwayFromTheNotch) {
  SheetSpec spec = free_sheet_spec(0.01, 10);
  spec.notch_length_m = 0.002;
  spec.notch_x_m = 0.0055;
  const SheetModel model = uniform_sheet(spec);
  SheetState state = make_sheet_state(model);
  for (int j = 9; j >= 5; --j) state.torn_step[model.cell(1, j)] = 3;
  const TearPath path = measure_tear_path(model, state);
  EXPECT_FALSE(path.holds_notch);
  EXPECT_EQ(path.tear_cells, 5);
  EXPECT_EQ(path.stray_cells, 2);
  EXPECT_NEAR(path.points.front().x(), 0.0015, 1e-15);
}

}  // namespace
}  // namespace repose
