// Material: the presets, the rule validate() applies to every field, the
// fraction displaced while pressing and while dragging, and the erosion
// passes on other cells (what they move per step: erosion_test.cpp).
#include "models/ground/material.h"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/ground/ground_params.h"
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

// More passes than a step may take on the model's cells are refused by name.
TEST(Material, AModelRefusesMoreErosionPassesThanAStepMayTake) {
  Material m = sand();
  m.erosion_iterations = 20;
  m.erosion_iterations_cell_m = 0.5;
  const GroundModel model = make_plain_ground_model(centred_grid(4, 4, 0.005), m);
  try {
    validate(GroundParams{{m}}, model);
    FAIL() << "accepted 200,000 passes";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("erosion_iterations_cell_m"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace repose
