#include "models/heightspan/ground_contact.h"

#include <gtest/gtest.h>

#include "heightspan_fixtures.h"
#include "models/core/config/initial_height.h"
#include "models/heightspan/drag_wedge.h"

namespace repose {
namespace {

using testing::bed_scene;
using testing::bucket_mesh;
using testing::key;
using testing::mesh_object;

TEST(GroundContact, MapCellsStandForTheGroundCellsHoldingTheirCentres) {
  const Grid ground{10, 10, 0.01, 0.0, 0.0};
  Grid map = ground;
  map.origin_x_m = -0.0204;  // centres at -0.0154, -0.0054, 0.0046: the third is ground cell 0
  map.origin_y_m = 0.0349;
  const CellOffset off = ground_offset(map, ground);
  EXPECT_EQ(off.di, -2);
  EXPECT_EQ(off.dj, 3);
}

TEST(GroundContact, TheUndersideIsTheLowestSpanBottom) {
  Scene s = bed_scene(40, 40, 0.005, 0.03, {mesh_object("bucket", bucket_mesh(), {key(0.0, 0.1, 0.1, 0.04)})}, 1);
  const HeightSpanModel model = build_heightspan_model(s);
  const HeightSpanState state = make_heightspan_state(model, make_initial_height(s));
  const Underside u = underside_of(state.held[0].map, model.ground.grid, 0.065);
  ASSERT_FALSE(u.empty());
  EXPECT_EQ(u.footprint.ni, 16);  // 8 cm on 5 mm cells
  EXPECT_NEAR(u.at(20, 20), 0.015, 1e-12);
  EXPECT_TRUE(std::isinf(u.at(0, 0)));
  // a shear layer lowers every cell it covers by its thickness, and only those
  const Underside sheared = underside_of(state.held[0].map, model.ground.grid, 0.065, 0.002);
  EXPECT_EQ(sheared.footprint.ni, u.footprint.ni);
  EXPECT_EQ(sheared.footprint.nj, u.footprint.nj);
  EXPECT_NEAR(sheared.at(20, 20), 0.013, 1e-12);
  EXPECT_TRUE(((u.z_m - sheared.z_m).isFinite() == u.z_m.isFinite()).all());
  EXPECT_TRUE(std::isinf(sheared.at(0, 0)));
}

TEST(GroundContact, GroundAboveTheFloorGoesOntoItAndNothingIsLost) {
  // an upright bucket placed with its floor's top 1 cm under a 3 cm bed
  Scene s = bed_scene(40, 40, 0.005, 0.03, {mesh_object("bucket", bucket_mesh(), {key(0.0, 0.1, 0.1, 0.04)})}, 1);
  const HeightSpanModel model = build_heightspan_model(s);
  HeightSpanState state = make_heightspan_state(model, make_initial_height(s));
  const double before = accounted_m3(state);
  SpanMap& map = state.held[0].map;
  const double moved = take_up_ground(model.ground, &map, &state.ground);
  EXPECT_NEAR(accounted_m3(state), before, 1e-15);
  EXPECT_NEAR(map.material_m3(), moved, 1e-15);
  int i, j;
  ASSERT_TRUE(map.cell_at(0.1, 0.1, &i, &j));
  EXPECT_NEAR(map.begin(map.cell(i, j))[0].material_m, 0.01, 1e-12);  // 3 cm bed - 2 cm floor top
  EXPECT_NEAR(state.ground.height.at(20, 20), 0.02, 1e-12);             // the ground left at the floor's top
  EXPECT_TRUE(state.ground.erosion.contains(model.ground.cell(20, 20)));
}

TEST(GroundContact, GroundReachingIntoAHigherSpanGoesOntoItsTop) {
  // two plates stacked with a 1 cm gap, both under a 5 cm bed
  const TriangleMesh two = merged(make_box({0.02, 0.02, 0.0025}),
                                  transformed(make_box({0.02, 0.02, 0.0025}), Pose{{0, 0, 0.015}, Eigen::Quaterniond::Identity()}));
  Scene s = bed_scene(20, 20, 0.005, 0.05, {mesh_object("rack", two, {key(0.0, 0.05, 0.05, 0.01)})}, 1);
  const HeightSpanModel model = build_heightspan_model(s);
  HeightSpanState state = make_heightspan_state(model, make_initial_height(s));
  const double before = accounted_m3(state);
  take_up_ground(model.ground, &state.held[0].map, &state.ground);
  const SpanMap& map = state.held[0].map;
  int i, j;
  ASSERT_TRUE(map.cell_at(0.0525, 0.0525, &i, &j));
  const Span* sp = map.begin(map.cell(i, j));
  ASSERT_EQ(map.count(map.cell(i, j)), 2);
  EXPECT_NEAR(sp[0].level_m(), sp[1].bottom_m, 1e-12);  // the gap is full
  EXPECT_NEAR(sp[1].level_m(), 0.05 + 0.005, 1e-12);    // the rest, and the upper plate's own volume, on top
  EXPECT_NEAR(accounted_m3(state), before, 1e-15);
  testing::expect_spans_valid(map, "rack");
}

// The x of the centre of the material on a map's spans.
double material_centre_x(const SpanMap& map) {
  double sum = 0.0, sum_x = 0.0;
  for (int j = 0; j < map.grid.ny; ++j) {
    for (int i = 0; i < map.grid.nx; ++i) {
      const std::int64_t c = map.cell(i, j);
      for (int k = 0; k < map.count(c); ++k) {
        sum += map.begin(c)[k].material_m;
        sum_x += map.begin(c)[k].material_m * map.grid.centre_x(i);
      }
    }
  }
  return sum_x / sum;
}

TEST(GroundContact, GroundScoopedWhileMovingSidewaysIsPushedToTheBackNeverAboveItsLevel) {
  // an upright bucket (centre x = 0.1) with its floor's top at 2 cm; the bed is 3 cm
  // deep over the bucket's front half (x > 0.1) and 2 cm behind: 1 cm to scoop in front
  for (const double dx : {0.0, 0.001}) {
    Scene s = bed_scene(40, 40, 0.005, 0.02, {mesh_object("bucket", bucket_mesh(), {key(0.0, 0.1, 0.1, 0.04)})}, 1);
    const HeightSpanModel model = build_heightspan_model(s);
    HeightSpanState state = make_heightspan_state(model, make_initial_height(s));
    for (int j = 0; j < 40; ++j) {
      for (int i = 20; i < 40; ++i) state.ground.height.at(i, j) = 0.03;
    }
    const double before = accounted_m3(state);
    SpanMap& map = state.held[0].map;
    const double moved = take_up_ground(model.ground, &map, &state.ground, Eigen::Vector3d(dx, 0.0, 0.0));
    SCOPED_TRACE(dx);
    EXPECT_GT(moved, 0.0);
    EXPECT_NEAR(map.material_m3(), moved, 1e-15);
    EXPECT_NEAR(accounted_m3(state), before, 1e-15);
    double top_level = 0.0;
    for (const Span& sp : map.spans) {
      if (sp.material_m > 0.0) top_level = std::max(top_level, sp.level_m());
    }
    EXPECT_LE(top_level, 0.03 + 1e-12);
    if (dx == 0.0) {
      EXPECT_GT(material_centre_x(map), 0.105);  // stays where it was scooped
    } else {
      EXPECT_LT(material_centre_x(map), 0.095);  // pushed to the back, away from the motion
    }
  }
}

// Over the map cells whose lowest span's top is under the ground: the sum of
// what each would take in, min(the intake fraction × the ground above the top, the intake layer).
double expected_intake_m3(const HeightSpanModel& model, const HeightSpanState& state, Intake intake) {
  const SpanMap& map = state.held[0].map;
  const CellOffset off = ground_offset(map.grid, model.ground.grid);
  double sum = 0.0;
  for (int j = 0; j < map.grid.ny; ++j) {
    for (int i = 0; i < map.grid.nx; ++i) {
      const std::int64_t c = map.cell(i, j);
      if (map.count(c) == 0 || !model.ground.grid.contains(i + off.di, j + off.dj)) continue;
      const double above = state.ground.height.at(i + off.di, j + off.dj) - map.begin(c)[0].top_m;
      sum += std::clamp(intake.fraction * above, 0.0, intake.layer_m);
    }
  }
  return sum * model.ground.grid.cell_area_m2();
}

// An upright bucket (floor top at 2 cm, centre x = 0.1) in a flat bed `bed_m` deep,
// moved 1 mm along +x (dx = 0: pressed) with `intake` (its layer and fraction), keeping
// `wedge_fraction` of what its lip pushes ahead in its wedge (drag_wedge.h).
struct Taken {
  double held_m3 = 0.0, expected_m3 = 0.0, ahead_gain_m3 = 0.0, balance_m3 = 0.0, wedge_m3 = 0.0;
  std::array<int, 2> wedge_back{0, 0};
};
Taken drag_through(double bed_m, Intake intake, double dx, double wedge_fraction = 0.0) {
  Scene s = bed_scene(40, 40, 0.005, bed_m, {mesh_object("bucket", bucket_mesh(), {key(0.0, 0.1, 0.1, 0.04)})}, 1);
  const HeightSpanModel model = build_heightspan_model(s);
  HeightSpanState state = make_heightspan_state(model, make_initial_height(s));
  const double before = accounted_m3(state);
  Taken t;
  t.expected_m3 = expected_intake_m3(model, state, dx == 0.0 ? Intake{} : intake);
  const HeightField ground0 = state.ground.height;
  DragWedge& wedge = state.held[0].wedge;
  take_up_ground(model.ground, &state.held[0].map, &state.ground, Eigen::Vector3d(dx, 0.0, 0.0), intake,
                 wedge_fraction > 0.0 ? LipWedge{&wedge, wedge_fraction} : LipWedge{});
  t.held_m3 = state.held[0].map.material_m3();
  t.wedge_m3 = wedge.volume_m3;
  t.wedge_back = wedge.back;
  for (int j = 0; j < 40; ++j) {
    for (int i = 28; i < 40; ++i) {  // in front of the bucket (its outer rim ends at x = 0.14)
      t.ahead_gain_m3 += (state.ground.height.at(i, j) - ground0.at(i, j)) * model.ground.grid.cell_area_m2();
    }
  }
  t.balance_m3 = accounted_m3(state) - before;
  return t;
}

TEST(GroundContact, MovingSidewaysALipTakesInOneIntakeLayerAndPushesTheRestAhead) {
  for (const double bed : {0.022, 0.03}) {  // 2 mm and 1 cm above the floor's top
    SCOPED_TRACE(bed);
    const Taken t = drag_through(bed, {0.004}, 0.001);
    EXPECT_GT(t.held_m3, 0.0);
    EXPECT_NEAR(t.held_m3, t.expected_m3, 1e-15);
    EXPECT_NEAR(t.balance_m3, 0.0, 1e-15);
    // what the lip does not take in lies in front of the bucket
    const Taken all = drag_through(bed, {1e6}, 0.001);
    EXPECT_NEAR(t.ahead_gain_m3, all.held_m3 - t.held_m3, 1e-15);
    EXPECT_EQ(all.ahead_gain_m3, 0.0);
  }
}

TEST(GroundContact, ADraggedBucketFillsInTheRatioOfTheLayersItTakesIn) {
  // 2 mm and 10 mm of ground above the floor: without a limit the intakes are
  // in the ratio 5; with a 4 mm intake layer, 4 / 2 = 2
  const double shallow = drag_through(0.022, {1e6}, 0.001).held_m3, deep = drag_through(0.03, {1e6}, 0.001).held_m3;
  EXPECT_NEAR(deep / shallow, 5.0, 1e-9);
  const double shallow_l = drag_through(0.022, {0.004}, 0.001).held_m3, deep_l = drag_through(0.03, {0.004}, 0.001).held_m3;
  EXPECT_NEAR(shallow_l, shallow, 1e-15);  // a thinner layer than the limit goes in whole
  EXPECT_NEAR(deep_l / shallow_l, 2.0, 1e-9);
}

TEST(GroundContact, ALipWedgeCarriesItsFractionOfWhatIsPushedAheadInsteadOfTheGroundAhead) {
  for (const double bed : {0.022, 0.03}) {
    SCOPED_TRACE(bed);
    const Taken none = drag_through(bed, {0.004}, 0.001);
    for (const double f : {0.5, 1.0}) {
      SCOPED_TRACE(f);
      const Taken t = drag_through(bed, {0.004}, 0.001, f);
      EXPECT_NEAR(t.held_m3, none.held_m3, 1e-15);  // the lip takes in the same layer
      EXPECT_NEAR(t.wedge_m3, f * none.ahead_gain_m3, 1e-15);
      EXPECT_NEAR(t.ahead_gain_m3, (1.0 - f) * none.ahead_gain_m3, 1e-15);
      EXPECT_NEAR(t.balance_m3, 0.0, 1e-15);  // the wedge is in the ledger
      if (none.ahead_gain_m3 > 0.0) {
        EXPECT_EQ(t.wedge_back, (std::array<int, 2>{-1, 0}));
      }
    }
  }
  // a deeper cut pushes more ahead: the wedge grows with it (2 mm of ground over the
  // floor pushes nothing past a 4 mm layer; 10 mm pushes 6 mm per cell the lip meets)
  EXPECT_EQ(drag_through(0.022, {0.004}, 0.001, 1.0).wedge_m3, 0.0);
  EXPECT_GT(drag_through(0.03, {0.004}, 0.001, 1.0).wedge_m3, 0.0);
  EXPECT_EQ(drag_through(0.03, {0.004}, 0.0, 1.0).wedge_m3, 0.0);  // pressing pushes nothing ahead
}

TEST(GroundContact, MovingSidewaysALipTakesInItsIntakeFractionOfEveryDepthAndPushesTheRestAhead) {
  // 2 mm and 10 mm of ground above the floor: a fraction keeps the intakes in the ratio 5
  // (a layer limit does not, above), and what is not taken in lies in front
  for (const double f : {0.3, 0.7}) {
    SCOPED_TRACE(f);
    const Taken shallow = drag_through(0.022, {1e6, f}, 0.001), deep = drag_through(0.03, {1e6, f}, 0.001);
    for (const Taken& t : {shallow, deep}) {
      EXPECT_GT(t.held_m3, 0.0);
      EXPECT_NEAR(t.held_m3, t.expected_m3, 1e-15);
      EXPECT_NEAR(t.ahead_gain_m3 * f, t.held_m3 * (1.0 - f), 1e-15);
      EXPECT_NEAR(t.balance_m3, 0.0, 1e-15);
    }
    EXPECT_NEAR(deep.held_m3 / shallow.held_m3, 5.0, 1e-9);
    EXPECT_NEAR(deep.held_m3, f * drag_through(0.03, {1e6}, 0.001).held_m3, 1e-15);
    // the layer still limits what the fraction admits: 0.7 of 10 mm is above a 4 mm layer
    const double layered = drag_through(0.03, {0.004}, 0.001).held_m3;
    EXPECT_NEAR(drag_through(0.03, {0.004, f}, 0.001).held_m3, layered * (f < 0.4 ? 0.75 : 1.0), 1e-15);
  }
}

TEST(GroundContact, PressingTakesInEverythingWhateverTheIntakeLayer) {
  const Taken t = drag_through(0.03, {0.004, 0.5}, 0.0);
  EXPECT_NEAR(t.held_m3, t.expected_m3, 1e-15);
  EXPECT_NEAR(t.held_m3, drag_through(0.03, {1e6}, 0.0).held_m3, 1e-15);
  EXPECT_EQ(t.ahead_gain_m3, 0.0);
}

}  // namespace
}  // namespace repose
