// Scripts for scenes that start from a column of grains (dem.initial:
// column): the gate holds the column while it settles and is gone in the run;
// the grain count fills the column's footprint; columns that do not fit are refused.

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "validation/particles/dem_section.h"
#include "tests/validation/liggghts/dem_test_scene.h"
#include "validation/liggghts/liggghts_script.h"

namespace repose {
namespace {

using Shape = DemSpec::ColumnShape;

TEST(ColumnScript, SlotGeometryLeansOnTheGridsXMinEdgeAndSpansItsY) {
  const Scene s = testing::column_dem_scene(Shape::kSlot, 0.03);
  const ColumnGeometry c = column_geometry(s);
  EXPECT_EQ(c.back_wall_x_m, 0.0);
  EXPECT_DOUBLE_EQ(c.gate_x_m, 0.016);
  EXPECT_DOUBLE_EQ(c.gap_m, 0.012);
  EXPECT_DOUBLE_EQ(c.footprint_m2, 0.016 * 0.012);
  EXPECT_DOUBLE_EQ(settled_height_m(*dem_of(s)), 0.03);
}

TEST(ColumnScript, CylinderStandsOnTheGridsCentre) {
  const Scene s = testing::column_dem_scene(Shape::kCylinder, 0.03);
  const ColumnGeometry c = column_geometry(s);
  EXPECT_DOUBLE_EQ(c.axis_xy_m.x(), 0.06);
  EXPECT_DOUBLE_EQ(c.axis_xy_m.y(), 0.06);
  EXPECT_DOUBLE_EQ(c.footprint_m2, std::numbers::pi * 0.012 * 0.012);
}

// A quarter column: its axis is the grid's (x_min, y_min) corner, its grains
// a quarter of the cylinder's, its front measured over the quadrant.
TEST(ColumnScript, QuarterCylinderStandsInTheGridsCorner) {
  const Scene s = testing::column_dem_scene(Shape::kQuarterCylinder, 0.03);
  const ColumnGeometry c = column_geometry(s);
  EXPECT_EQ(c.axis_xy_m, Eigen::Vector2d(0.0, 0.0));
  EXPECT_DOUBLE_EQ(c.footprint_m2, 0.25 * std::numbers::pi * 0.012 * 0.012);
  EXPECT_DOUBLE_EQ(c.azimuth_begin_rad, 0.0);
  EXPECT_DOUBLE_EQ(c.azimuth_span_rad, 0.5 * std::numbers::pi);
  const Scene whole = testing::column_dem_scene(Shape::kCylinder, 0.03);
  EXPECT_NEAR(static_cast<double>(bed_grain_count(s, {})), 0.25 * static_cast<double>(bed_grain_count(whole, {})), 1.0);
  EXPECT_EQ(column_shape_name(c.shape), "quarter_cylinder");
}

// The quarter's two planes of symmetry are the x_min and y_min walls, of a
// third atom type with neither sliding nor rolling friction against grains;
// the far walls stay of the grains' material, the floor rough.
TEST(ColumnScript, QuarterCylinderLeansOnFrictionlessSymmetryWalls) {
  const Scene s = testing::column_dem_scene(Shape::kQuarterCylinder, 0.03);
  for (const std::string& script : {bed_script(s), run_script(s).text}) {
    EXPECT_NE(script.find("coefficientFriction peratomtypepair 3 0.5 0.5 0 0.5 0.5 0 0 0 0\n"), std::string::npos)
        << script;
    EXPECT_NE(script.find("coefficientRollingFriction peratomtypepair 3 0.1 1 0 1 1 0 0 0 0\n"), std::string::npos)
        << script;
    EXPECT_NE(script.find("youngsModulus peratomtype 5e+06 5e+06 5e+06\n"), std::string::npos) << script;
    EXPECT_NE(script.find("primitive type 3 xplane 0\n"), std::string::npos) << script;
    EXPECT_NE(script.find("primitive type 3 yplane 0\n"), std::string::npos) << script;
    EXPECT_NE(script.find("primitive type 1 xplane 0.12\n"), std::string::npos) << script;
    EXPECT_NE(script.find("primitive type 2 zplane 0\n"), std::string::npos) << script;
  }
  const std::string bed = bed_script(s);
  EXPECT_NE(bed.find("create_box 3 domain\n"), std::string::npos);
  EXPECT_NE(bed.find("primitive type 1 zcylinder 0.012 0 0\n"), std::string::npos) << bed;
  EXPECT_NE(bed.find("region fill intersect 2 fill_cylinder fill_quadrant units box\n"), std::string::npos) << bed;
  EXPECT_NE(bed.find("region fill_quadrant block 0 0.012 0 0.012 0 "), std::string::npos) << bed;
  // a whole cylinder keeps two types and walls of the grains' own material
  const std::string whole = bed_script(testing::column_dem_scene(Shape::kCylinder, 0.03));
  EXPECT_NE(whole.find("create_box 2 domain\n"), std::string::npos);
  EXPECT_EQ(whole.find("primitive type 3"), std::string::npos);
}

TEST(ColumnScript, GrainCountFillsTheFootprintToTheColumnHeight) {
  for (Shape shape : {Shape::kSlot, Shape::kCylinder, Shape::kQuarterCylinder}) {
    const Scene s = testing::column_dem_scene(shape, 0.04);
    const BedScriptOptions o;
    const double expected = column_geometry(s).footprint_m2 * 0.04 * o.packing_fraction / mean_grain_volume_m3(*dem_of(s));
    EXPECT_NEAR(static_cast<double>(bed_grain_count(s, o)), expected, 0.5);
    // twice as tall: twice the grains
    const Scene tall = testing::column_dem_scene(shape, 0.08);
    EXPECT_NEAR(static_cast<double>(bed_grain_count(tall, o)), 2 * expected, 1.0);
  }
}

TEST(ColumnScript, SlotBedHasAGatePlaneAndInsertsBehindIt) {
  const Scene s = testing::column_dem_scene(Shape::kSlot, 0.03);
  const std::string script = bed_script(s);
  EXPECT_NE(script.find("fix gate all wall/gran model hertz tangential history rolling_friction cdt primitive type 1 "
                        "xplane 0.016\n"),
            std::string::npos)
      << script;
  EXPECT_NE(script.find("region fill block 0 0.016 0 0.012 0 "), std::string::npos) << script;
  EXPECT_EQ(script.find("zcylinder"), std::string::npos);
}

// A periodic strip: y repeats, so neither script has side walls, and the
// slot's grains are inserted over its whole gap (no wall keeps them off it).
TEST(ColumnScript, PeriodicSidesDropTheSideWallsInBothScripts) {
  const Scene walls = testing::column_dem_scene(Shape::kSlot, 0.03);
  const Scene periodic = with_dem_changed(walls, [](DemSpec& d) { d.sides = DemSpec::Sides::kPeriodic; });
  for (const std::string& script : {bed_script(periodic), run_script(periodic).text}) {
    EXPECT_NE(script.find("boundary f p f\n"), std::string::npos) << script;
    EXPECT_EQ(script.find("yplane"), std::string::npos) << script;
    EXPECT_NE(script.find("fix wall_xmin"), std::string::npos) << script;
    EXPECT_NE(script.find("fix wall_floor"), std::string::npos) << script;
  }
  for (const std::string& script : {bed_script(walls), run_script(walls).text}) {
    EXPECT_NE(script.find("boundary f f f\n"), std::string::npos) << script;
    EXPECT_NE(script.find("fix wall_ymin"), std::string::npos) << script;
  }
  // the same grains fill a wider open area, so the insertion region is lower
  EXPECT_LT(bed_domain(periodic, {}).z_max_m, bed_domain(walls, {}).z_max_m);
  EXPECT_EQ(bed_grain_count(periodic, {}), bed_grain_count(walls, {}));
}

TEST(ColumnScript, CylinderBedHasACylinderGateAndInsertsInsideIt) {
  const Scene s = testing::column_dem_scene(Shape::kCylinder, 0.03);
  const std::string script = bed_script(s);
  EXPECT_NE(script.find("primitive type 1 zcylinder 0.012 0.06 0.06\n"), std::string::npos) << script;
  EXPECT_NE(script.find("region fill cylinder z 0.06 0.06 0.012 0 "), std::string::npos) << script;
  // the insertion region is taller than the column (grains are inserted loosely) and fits the box
  const BedScriptOptions o;
  const DemDomain d = bed_domain(s, o);
  EXPECT_GT(d.z_max_m, 0.03 * o.packing_fraction / o.insert_volume_fraction);
}

TEST(ColumnScript, RunScriptHasNoGateAndRoomAboveTheColumn) {
  for (Shape shape : {Shape::kSlot, Shape::kCylinder, Shape::kQuarterCylinder}) {
    const Scene s = testing::column_dem_scene(shape, 0.05);
    const RunScript run = run_script(s);
    EXPECT_EQ(run.text.find("gate"), std::string::npos) << run.text;
    EXPECT_EQ(run.text.find("zcylinder"), std::string::npos);
    EXPECT_GE(run.domain.z_max_m, 1.25 * 0.05);
    EXPECT_EQ(run.total_steps, std::lround(s.time.duration_s / dem_of(s)->time_step_s));
  }
}

TEST(ColumnScript, BedScenesAreUnchangedByTheColumnFields) {
  Scene bed = testing::small_dem_scene(false);
  const std::string before = bed_script(bed);
  bed = with_dem_changed(std::move(bed), [&](DemSpec& d) { d.column_width_m = 0.5; });  // unused for a bed
  bed = with_dem_changed(std::move(bed), [&](DemSpec& d) { d.column_height_m = 0.5; });
  EXPECT_EQ(bed_script(bed), before);
  EXPECT_EQ(before.find("gate"), std::string::npos);
}

TEST(ColumnScript, RoughFloorIsASecondAtomTypeWithItsOwnRollingFriction) {
  Scene s = testing::column_dem_scene(Shape::kCylinder, 0.03);
  s = with_dem_changed(std::move(s), [&](DemSpec& d) { d.rolling_friction = 0.1; });
  s = with_dem_changed(std::move(s), [&](DemSpec& d) { d.floor_rolling_friction = 0.7; });
  for (const std::string& script : {bed_script(s), run_script(s).text}) {
    EXPECT_NE(script.find("coefficientRollingFriction peratomtypepair 2 0.1 0.7 0.7 0.7\n"), std::string::npos)
        << script;
    EXPECT_NE(script.find("youngsModulus peratomtype 5e+06 5e+06\n"), std::string::npos) << script;
    EXPECT_NE(script.find("primitive type 2 zplane 0\n"), std::string::npos) << script;
    EXPECT_NE(script.find("primitive type 1 xplane 0\n"), std::string::npos) << script;  // side walls: grain material
  }
  EXPECT_NE(bed_script(s).find("create_box 2 domain\n"), std::string::npos);
  // the grains themselves are all of type 1
  EXPECT_EQ(bed_script(s).find("atom_type 2"), std::string::npos);

  s = with_dem_changed(std::move(s), [&](DemSpec& d) { d.floor = DemSpec::Floor::kSmooth; });  // one type; the floor rolling friction is unused
  const std::string smooth = bed_script(s);
  EXPECT_NE(smooth.find("create_box 1 domain\n"), std::string::npos);
  EXPECT_NE(smooth.find("coefficientRollingFriction peratomtypepair 1 0.1\n"), std::string::npos);
  s = with_dem_changed(std::move(s), [&](DemSpec& d) { d.floor_rolling_friction = 0.2; });
  EXPECT_EQ(bed_script(s), smooth);
}

TEST(ColumnScript, RefusesColumnsThatDoNotFitTheGrid) {
  Scene slot = testing::column_dem_scene(Shape::kSlot, 0.03);
  slot = with_dem_changed(std::move(slot), [&](DemSpec& d) { d.column_width_m = 0.2; });  // longer than the 16 cm grid
  EXPECT_THROW(bed_script(slot), InputError);
  EXPECT_THROW(run_script(slot), InputError);

  Scene cylinder = testing::column_dem_scene(Shape::kCylinder, 0.03);
  cylinder = with_dem_changed(std::move(cylinder), [&](DemSpec& d) { d.column_width_m = 0.07; });  // wider than the 12 cm grid
  EXPECT_THROW(bed_script(cylinder), InputError);
  try {
    run_script(cylinder);
    FAIL() << "a cylinder wider than the grid was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("column_width_m"), std::string::npos) << e.what();
  }

  Scene quarter = testing::column_dem_scene(Shape::kQuarterCylinder, 0.03);
  quarter = with_dem_changed(std::move(quarter), [&](DemSpec& d) { d.column_width_m = 0.12; });  // as wide as the grid
  EXPECT_THROW(bed_script(quarter), InputError);
  quarter = with_dem_changed(std::move(quarter), [&](DemSpec& d) { d.column_width_m = 0.07; });  // fits in the corner
  EXPECT_NO_THROW(bed_script(quarter));

  Scene narrow = testing::column_dem_scene(Shape::kSlot, 0.03);
  narrow.ground.grid = Grid{40, 1, 0.004, 0.0, 0.0};  // a slot 4 mm wide: one grain diameter
  EXPECT_THROW(bed_script(narrow), InputError);
}

}  // namespace
}  // namespace repose
