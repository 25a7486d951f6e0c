#include "models/snow/simulate_snow.h"

#include <gtest/gtest.h>

#include <numbers>

#include "models/core/base/error.h"
#include "models/core/config/scene_loader.h"
#include "snow_fixtures.h"

namespace repose {
namespace {

using testing::centred_grid;
using testing::plate;
using testing::plates_over_ground;

constexpr double kDeg = std::numbers::pi / 180.0;

SnowModel with_time(SnowModel model, double step_s, double duration_s) {
  model.time.step_s = step_s;
  model.time.duration_s = duration_s;
  return model;
}

TEST(SimulateSnow, FlatOpenGroundGetsUniformSnowEqualToTheIntegralOfM) {
  const HeightField ground(centred_grid(12), 0.1);
  SnowOptions o = testing::vertical_snow_options(8);
  o.snowfall = SnowfallRate({{0.0, 1e-3}, {10.0, 3e-3}});
  const SnowModel model = with_time(plates_over_ground(ground, {}, o), 1.0, 10.0);
  SnowState state;
  const SnowRunSummary summary = simulate_snow(model, SnowParams{30 * kDeg, 10 * kDeg}, &state);
  EXPECT_EQ(summary.steps, 10);
  EXPECT_NEAR(state.depth_m[0].minCoeff(), 0.02, 1e-15);
  EXPECT_NEAR(state.depth_m[0].maxCoeff(), 0.02, 1e-15);
  EXPECT_NEAR(summary.imbalance_m3, 0.0, 1e-15);
}

// The paper's Fig. 7: under straight-down snow, stabilisation and falling
// bring snow under the table, where none falls directly.
TEST(SimulateSnow, StraightDownSnowReachesUnderATableByFallingAndSliding) {
  const HeightField ground(centred_grid(24));
  SnowOptions o = testing::vertical_snow_options(1);
  o.snowfall = SnowfallRate(5e-3);
  o.max_stabilisation_passes = 200;
  const SnowModel model = with_time(plates_over_ground(ground, {plate(0.05, 0.05, 0.05)}, o), 1.0, 12.0);
  SnowState state;
  const SnowRunSummary summary = simulate_snow(model, SnowParams{40 * kDeg, 0.0}, &state);
  const Grid& g = model.grid;
  double under_table = 0.0;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      if (model.maps[1].covered(i, j)) {
        EXPECT_EQ(summary.probability.per_map[0](j, i), 0.0);
        under_table += state.depth_m[0](j, i);
      }
    }
  }
  EXPECT_GT(under_table, 0.0);
  EXPECT_NEAR(summary.imbalance_m3, 0.0, 1e-12 * state.ledger.fallen_m3);
  EXPECT_EQ(state.ledger.left_scene_m3, 0.0);
  EXPECT_NEAR(state.time_s, 12.0, 1e-12);
}

// A pedestal (a plate 20 cells wide, high above the ground) under vertical
// snowfall deeper than the heap it can hold: the heap's flank along the
// axis through its middle rises at the angle from the edge (the rule's
// tolerance allows tan(theta) + 1e-6 m / 1 cm; the bound 0.005 on tan is
// 0.3 deg at 25 deg), and the snow that fell is on the maps to round-off.
// Snow piled on a 4-neighbour grid is steeper along the diagonals
// (Stabilisation.PointSnowfallBuilds...): only the axis flank is the angle.
TEST(SimulateSnow, APedestalUnderVerticalSnowfallHoldsAHeapWhoseAxisFlankIsAtTheAngle) {
  const HeightField ground(centred_grid(30));
  SnowOptions o = testing::vertical_snow_options(1);
  o.snowfall = SnowfallRate(5e-3);
  o.max_stabilisation_passes = 2000;
  const SnowModel model = with_time(plates_over_ground(ground, {plate(0.1, 0.1, 0.3)}, o), 1.0, 14.0);
  for (double angle_deg : {18.5, 25.0, 35.0}) {
    SnowState state;
    const SnowRunSummary summary = simulate_snow(model, SnowParams{angle_deg * kDeg, 0.0}, &state);
    EXPECT_EQ(summary.unsettled_steps, 0);
    EXPECT_NEAR(summary.imbalance_m3, 0.0, 1e-12 * state.ledger.fallen_m3);
    // the middle row (j = 15) from the plate's west edge (i = 5) inwards: depth 0 there, then the flank
    const ArrayXXdR& top = state.depth_m[1];
    ASSERT_TRUE(model.maps[1].covered(5, 15) && !model.maps[1].covered(4, 15));
    const double tan_theta = std::tan(angle_deg * kDeg), h = model.grid.cell_size_m;
    const int flank_cells = std::min(9, static_cast<int>(0.07 / (h * tan_theta)));  // below 7 cm of snowfall
    for (int k = 1; k <= flank_cells; ++k) {
      EXPECT_NEAR((top(15, 5 + k) - top(15, 5 + k - 1)) / h, tan_theta, 0.005) << angle_deg << " deg, cell " << k;
      EXPECT_NEAR(top(15, 5 + k), top(5 + k, 15), 1e-12);  // the same along y: the square plate's symmetry
    }
  }
}

TEST(SimulateSnow, BuildsFromASceneAndRefusesUnknownObjects) {
  const std::string yaml = R"(
name: snow_table
seed: 4
time: {step_s: 1.0, duration_s: 3.0}
ground:
  extent_m: [0.2, 0.2]
  cell_size_m: 0.01
  initial_height: {kind: flat, height_m: 0.0}
objects:
  - name: top
    shape: box
    half_extents_m: [0.04, 0.04, 0.005]
    motion: [{time_s: 0, position_m: [0, 0, 0.05]}]
)";
  const Scene scene = load_scene_from_string(yaml, "/tmp/snow_table.yaml", {});
  SnowOptions o;
  o.groups = {{"ground", true, {}}, {"table", false, {"top"}}};
  o.direction_count = 4;
  const SnowModel model = build_snow_model(scene, o);
  ASSERT_EQ(model.maps.size(), 2u);
  EXPECT_EQ(model.maps[1].base.covered.cast<int>().sum(), 64);
  EXPECT_EQ(model.seed, 4u);
  SnowState state;
  const SnowRunSummary summary = simulate_snow(model, SnowParams{}, &state);
  EXPECT_EQ(summary.steps, 3);
  EXPECT_NEAR(summary.imbalance_m3, 0.0, 1e-12 * state.ledger.fallen_m3);
  o.groups[1].objects = {"chair"};
  try {
    build_snow_model(scene, o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("chair"), std::string::npos) << e.what();
  }
}

// Conservation over seeded random runs: fallen = on maps + left, to round-off.
TEST(SimulateSnow, ConservesSnowOverRandomRuns) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    HeightField ground(centred_grid(14));
    for (int j = 0; j < 14; ++j) {
      for (int i = 0; i < 14; ++i) ground.at(i, j) = 0.03 * u(rng);
    }
    SnowOptions o = testing::vertical_snow_options(8);
    o.main_direction = {40 * kDeg * u(rng), 6.28 * u(rng)};
    o.snowfall = SnowfallRate(1e-2 * u(rng));
    o.moved_fraction = 0.05 + 0.2 * u(rng);
    const SnowModel model =
        with_time(plates_over_ground(ground, {plate(0.03, 0.02, 0.06 + 0.03 * u(rng))}, o, seed, u(rng) < 0.7), 0.5, 3.0);
    SnowState state;
    const SnowRunSummary s = simulate_snow(model, SnowParams{(5 + 80 * u(rng)) * kDeg, 30 * kDeg * u(rng)}, &state);
    EXPECT_NEAR(s.imbalance_m3, 0.0, 1e-12 * std::max(1e-12, state.ledger.fallen_m3)) << "seed " << seed;
    for (const ArrayXXdR& d : state.depth_m) EXPECT_TRUE(d.allFinite() && d.minCoeff() >= 0.0) << "seed " << seed;
  }
}

}  // namespace
}  // namespace repose

namespace repose {
namespace {

// The issue's extremes: angle 0 and 90 deg, spread 0 and 180 deg, one
// direction, a single-cell map, no objects: finite, non-negative, conserved.
TEST(SimulateSnow, ExtremesStayFiniteAndConservative) {
  for (int n : {1, 9}) {
    for (bool with_plate : {false, true}) {
      for (double angle : {0.0, 90 * kDeg}) {
        for (double spread : {0.0, 180 * kDeg}) {
          const HeightField ground(centred_grid(n), 0.01);
          SnowOptions o = testing::vertical_snow_options(1);
          o.snowfall = SnowfallRate(1e-2);
          std::vector<TriangleMesh> plates;
          if (with_plate) plates.push_back(plate(0.01, 0.01, 0.05));
          const SnowModel model = with_time(plates_over_ground(ground, plates, o), 1.0, 2.0);
          SnowState state;
          const SnowRunSummary s = simulate_snow(model, SnowParams{angle, spread}, &state);
          const std::string where = "n " + std::to_string(n) + " plate " + std::to_string(with_plate) + " angle " +
                                    std::to_string(angle) + " spread " + std::to_string(spread);
          for (const ArrayXXdR& d : state.depth_m) EXPECT_TRUE(d.allFinite() && d.minCoeff() >= 0.0) << where;
          EXPECT_NEAR(s.imbalance_m3, 0.0, 1e-12 * state.ledger.fallen_m3) << where;
          EXPECT_GT(state.ledger.fallen_m3, 0.0) << where;
        }
      }
    }
  }
}

}  // namespace
}  // namespace repose

namespace repose {
namespace {

// The ray-cast probability drives the same run; on a scene whose shadows
// have no partly covered pixel (vertical snow, edges on cell borders) both
// methods give the same snow, bit for bit.
TEST(SimulateSnow, RayCastProbabilityGivesTheSameRunOnAnExactScene) {
  const HeightField ground(centred_grid(16));
  SnowOptions o = testing::vertical_snow_options(2);
  o.snowfall = SnowfallRate(4e-3);
  SnowModel model = with_time(plates_over_ground(ground, {plate(0.03, 0.02, 0.04)}, o), 1.0, 4.0);
  SnowState a, b;
  simulate_snow(model, SnowParams{35 * kDeg, 0.0}, &a);
  model.options.probability = SnowOptions::Probability::kRayCast;
  simulate_snow(model, SnowParams{35 * kDeg, 0.0}, &b);
  for (std::size_t m = 0; m < a.depth_m.size(); ++m) EXPECT_TRUE((a.depth_m[m] == b.depth_m[m]).all()) << m;
}

}  // namespace
}  // namespace repose
