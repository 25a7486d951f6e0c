#include "validation/rigid/rigid_setup.h"

#include <gtest/gtest.h>

#include <set>

#include "models/core/base/error.h"
#include "validation/liggghts/liggghts_script.h"

namespace repose {
namespace {

RigidInputs bed(std::uint64_t seed) {
  RigidInputs in;
  in.grid = Grid{10, 8, 0.004, -0.01, 0.02};
  in.dem.bed_depth_m = 0.012;
  in.seed = seed;
  return in;
}

TEST(RigidSetup, TheLatticeHoldsTheLiggghtsBedsGrainCountWithoutOverlapsInsideTheBox) {
  const RigidInputs in = bed(1);
  const RigidOptions options;
  const RigidWorldSpec w = settling_world(in, options);
  const GrainSet& g = w.grains;
  const double volume = in.grid.extent_x_m() * in.grid.extent_y_m() * in.dem.bed_depth_m * options.packing_fraction;
  EXPECT_EQ(g.size(), std::lround(volume / mean_grain_volume_m3(in.dem)));
  EXPECT_EQ(g.size(), rigid_grain_count(in, options));
  for (Eigen::Index a = 0; a < g.size(); ++a) {
    const auto p = g.position_m.row(a);
    const double r = g.radius_m(a);
    EXPECT_GE(p.x() - r, w.bounds.x_min_m);
    EXPECT_LE(p.x() + r, w.bounds.x_max_m);
    EXPECT_GE(p.y() - r, w.bounds.y_min_m);
    EXPECT_LE(p.y() + r, w.bounds.y_max_m);
    EXPECT_GE(p.z() - r, 0.0);
    EXPECT_LE(p.z() + r, w.bounds.z_top_m);
    for (Eigen::Index b = a + 1; b < g.size(); ++b) {
      ASSERT_GT((g.position_m.row(b) - p).norm(), r + g.radius_m(b)) << "grains " << a << " and " << b;
    }
  }
}

TEST(RigidSetup, RadiiAreDrawnFromTheLiggghtsDistributionAndTheSeedDecides) {
  const RigidOptions options;
  const GrainSet a = grain_lattice(bed(1), options);
  const GrainSet b = grain_lattice(bed(1), options);
  const GrainSet c = grain_lattice(bed(2), options);
  EXPECT_EQ(a.position_m, b.position_m);
  EXPECT_EQ(a.radius_m, b.radius_m);
  EXPECT_NE(a.radius_m, c.radius_m);
  const std::vector<double> radii = grain_radii_m(bed(1).dem);
  std::set<double> seen(a.radius_m.begin(), a.radius_m.end());
  EXPECT_EQ(seen, std::set<double>(radii.begin(), radii.end()));
}

TEST(RigidSetup, TheGroundBoxIsAFloorAtZeroAndFourWallsOnTheGridsEdges) {
  const RigidInputs in = bed(1);
  const RigidWorldSpec w = settling_world(in, RigidOptions{});
  ASSERT_EQ(w.walls.size(), 5u);
  const StaticBox& floor = w.walls[0];
  EXPECT_DOUBLE_EQ(floor.centre_m.z() + floor.half_extents_m.z(), 0.0);
  EXPECT_DOUBLE_EQ(w.walls[1].centre_m.x() + w.walls[1].half_extents_m.x(), in.grid.origin_x_m);
  EXPECT_DOUBLE_EQ(w.walls[2].centre_m.x() - w.walls[2].half_extents_m.x(), in.grid.origin_x_m + in.grid.extent_x_m());
  EXPECT_DOUBLE_EQ(w.walls[3].centre_m.y() + w.walls[3].half_extents_m.y(), in.grid.origin_y_m);
  EXPECT_DOUBLE_EQ(w.walls[4].centre_m.y() - w.walls[4].half_extents_m.y(), in.grid.origin_y_m + in.grid.extent_y_m());
}

TEST(RigidSetup, ARoughFloorTakesItsOwnRollingFriction) {
  RigidInputs in = bed(1);
  in.dem.floor = DemSpec::Floor::kRough;
  in.dem.floor_rolling_friction = 0.7;
  const RigidWorldSpec w = settling_world(in, RigidOptions{});
  EXPECT_DOUBLE_EQ(w.walls[0].rolling_friction, 0.7);
  EXPECT_DOUBLE_EQ(w.walls[1].rolling_friction, in.dem.rolling_friction);
}

TEST(RigidSetup, TheRunsBoxReachesAboveTheHighestObject) {
  RigidInputs in = bed(1);
  ObjectSpec o;
  o.name = "high";
  o.body = make_sphere(0.01);
  Keyframe k;
  k.pose.position_m = {0.0, 0.03, 0.2};
  o.keyframes = {k};
  in.objects = {o};
  const RigidWorldSpec w = run_world(in, grain_lattice(in, RigidOptions{}));
  EXPECT_GE(w.bounds.z_top_m, 0.21);
  EXPECT_EQ(w.objects.size(), 1u);
}

TEST(RigidSetup, AGridNarrowerThanAGrainIsRefused) {
  RigidInputs in = bed(1);
  in.grid = Grid{1, 1, 0.003, 0.0, 0.0};
  EXPECT_THROW(grain_lattice(in, RigidOptions{}), InputError);
}

Scene column_scene(DemSpec::ColumnShape shape, double width_m = 0.03) {
  Scene s;
  s.ground.grid = Grid{25, 20, 0.004, 0.0, 0.0};
  DemSpec dem;
  dem.initial = DemSpec::Initial::kColumn;
  dem.column_shape = shape;
  dem.column_width_m = width_m;
  dem.column_height_m = 0.02;
  auto section = std::make_shared<DemSection>();
  section->spec = dem;
  s.sections[DemSection::kKey] = section;
  return s;
}

TEST(RigidSetup, AColumnIsLaidOutBehindItsGateWithTheLiggghtsCount) {
  for (auto shape : {DemSpec::ColumnShape::kSlot, DemSpec::ColumnShape::kCylinder}) {
    const RigidInputs in = rigid_inputs(column_scene(shape), "test");
    ASSERT_TRUE(in.column.has_value());
    const RigidOptions options;
    const RigidWorldSpec w = settling_world(in, options);
    const double volume = in.column->footprint_m2 * in.dem.column_height_m * options.packing_fraction;
    EXPECT_EQ(w.grains.size(), std::lround(volume / mean_grain_volume_m3(in.dem)));
    for (Eigen::Index g = 0; g < w.grains.size(); ++g) {
      const Eigen::Vector2d xy(w.grains.position_m(g, 0), w.grains.position_m(g, 1));
      const double r = w.grains.radius_m(g);
      if (shape == DemSpec::ColumnShape::kSlot) {
        EXPECT_LE(xy.x() + r, in.column->gate_x_m);
      } else {
        EXPECT_LE((xy - in.column->axis_xy_m).norm() + r, in.column->width_m * std::cos(M_PI / 32));
      }
    }
    // the gate is there while settling, gone in the run
    EXPECT_GT(w.walls.size(), 5u);
    EXPECT_EQ(run_world(in, w.grains).walls.size(), 5u);
  }
}

TEST(RigidSetup, AColumnThatDoesNotFitTheGridIsRefused) {
  EXPECT_THROW(rigid_inputs(column_scene(DemSpec::ColumnShape::kSlot, 0.2), "test"), InputError);
  EXPECT_THROW(rigid_inputs(Scene{}, "test"), InputError);
}

// A quarter column needs frictionless symmetry walls, which the rigid
// engines' ground box does not have: refused in one line naming the key.
TEST(RigidSetup, AQuarterColumnIsRefusedNamingTheKey) {
  try {
    rigid_inputs(column_scene(DemSpec::ColumnShape::kQuarterCylinder), "bullet");
    FAIL() << "a quarter column was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("column_shape"), std::string::npos) << what;
    EXPECT_NE(what.find("bullet"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace repose
