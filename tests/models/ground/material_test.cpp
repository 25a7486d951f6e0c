// Material: the presets, the rule validate() applies to every field, the
// fraction displaced while pressing and while dragging, and the erosion
// passes on other cells.
#include "models/ground/material.h"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/ground/erosion.h"
#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

TEST(Material, PresetsDisplaceAlikeWhetherPressedOrDragged) {
  for (const char* name : {"sand", "mud", "snow"}) {
    Material m;
    ASSERT_TRUE(material_preset(name, &m)) << name;
    EXPECT_EQ(m.drag_compaction_ratio, 1.0) << name;
    EXPECT_EQ(m.displaced_fraction(true), m.displaced_fraction(false)) << name;
    EXPECT_NO_THROW(validate(m)) << name;
  }
}

// Dragging compresses drag_compaction_ratio times what pressing does.
TEST(Material, DraggingCompressesTheRatioOfWhatPressingDoes) {
  Material m;
  m.alpha = 0.4;
  m.drag_compaction_ratio = 0.5;
  EXPECT_DOUBLE_EQ(m.displaced_fraction(false), 0.4);
  EXPECT_DOUBLE_EQ(1.0 - m.displaced_fraction(true), 0.5 * (1.0 - 0.4));
  m.drag_compaction_ratio = 0.0;  // a drag displaces everything it meets
  EXPECT_EQ(m.displaced_fraction(true), 1.0);
  m.drag_compaction_ratio = 10.0;  // compresses more than there is: nothing displaced, never negative
  EXPECT_EQ(m.displaced_fraction(true), 0.0);
}

TEST(Material, ValidateNamesTheFieldOutsideItsInterval) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double bad : {-0.1, 10.5, nan}) {
    Material m;
    m.drag_compaction_ratio = bad;
    try {
      validate(m);
      FAIL() << "accepted drag_compaction_ratio " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("drag_compaction_ratio"), std::string::npos) << e.what();
    }
  }
  Material m;
  m.alpha = 1.5;
  EXPECT_THROW(validate(m), InputError);
}

// En counts passes on any cell (the paper) unless the material names the
// cell size it holds at; then the passes follow the cells' area, at least one.
TEST(Material, ErosionPassesScaleWithTheCellsOnlyWhenGivenTheirCellSize) {
  Material m;
  m.erosion_iterations = 20;
  EXPECT_EQ(m.erosion_passes(0.0025), 20);
  EXPECT_EQ(m.erosion_passes(0.01), 20);
  m.erosion_iterations_cell_m = 0.0025;
  EXPECT_EQ(m.erosion_passes(0.0025), 20);
  EXPECT_EQ(m.erosion_passes(0.005), 5);
  EXPECT_EQ(m.erosion_passes(0.00125), 80);
  EXPECT_EQ(m.erosion_passes(0.003), 14);  // 13.9 rounded
  EXPECT_EQ(m.erosion_passes(0.5), 1);     // never none
  for (const double bad : {-0.001, 1.5, std::numeric_limits<double>::quiet_NaN()}) {
    m.erosion_iterations_cell_m = bad;
    try {
      validate(m);
      FAIL() << "accepted erosion_iterations_cell_m " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("erosion_iterations_cell_m"), std::string::npos) << e.what();
    }
  }
}

// The volume (m^3) that one step's erosion carries out of a 6 cm square
// column 5 cm high.
double one_step_outflow_m3(double cell_m, int erosion_iterations, double erosion_iterations_cell_m) {
  Material m = sand();
  m.erosion_iterations = erosion_iterations;
  m.erosion_iterations_cell_m = erosion_iterations_cell_m;
  const int cells = static_cast<int>(std::lround(0.4 / cell_m)), half = static_cast<int>(std::lround(0.03 / cell_m));
  const GroundModel model = make_plain_ground_model(centred_grid(cells, cells, cell_m), m);
  GroundState state = make_ground_state(model, HeightField(model.grid, 0.0));
  for (int j = cells / 2 - half; j < cells / 2 + half; ++j) {
    for (int i = cells / 2 - half; i < cells / 2 + half; ++i) {
      state.height.at(i, j) = 0.05;
      state.erosion.touch(model.cell(i, j));
    }
  }
  const double before = state.height.volume_m3();
  erode(model, GroundParams{{m}}, Ceiling{}, &state);
  double inside = 0.0;
  for (int j = cells / 2 - half; j < cells / 2 + half; ++j) {
    for (int i = cells / 2 - half; i < cells / 2 + half; ++i) inside += state.height.at(i, j) * model.grid.cell_area_m2();
  }
  return before - inside;
}

// A pass moves sigma times a pair's excess across the face between two
// cells, a diffusion of about sigma h^2 per pass: with En given at a cell
// size (passes scaled with the cells' area) a step sheds about the same
// volume on any grid; as a count of passes (the paper's En) finer cells
// shed less, and passes scaled with the cell size alone are not enough.
TEST(Material, ErosionPassesGivenAtACellSizeMoveAlikePerStepOnAnyGrid) {
  const double coarse = one_step_outflow_m3(0.01, 4, 0.0);
  EXPECT_NEAR(one_step_outflow_m3(0.005, 4, 0.01) / coarse, 1.0, 0.05);   // 16 passes
  EXPECT_NEAR(one_step_outflow_m3(0.0025, 4, 0.01) / coarse, 1.0, 0.05);  // 64 passes
  EXPECT_LT(one_step_outflow_m3(0.005, 4, 0.0) / coarse, 0.6);            // 4 passes
  EXPECT_LT(one_step_outflow_m3(0.005, 8, 0.0) / coarse, 0.8);            // 8: scaled with the cell size
}

}  // namespace
}  // namespace repose
