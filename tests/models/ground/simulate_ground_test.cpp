// Whole runs of the ground model: the extremes, sweeping, multi-resolution,
// scenes from YAML and the two collision paths.
#include "models/ground/simulate_ground.h"
#include "experiments/solvers/solver_registry.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/core/config/scene_loader.h"
#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

GroundRun run_scene(const Scene& scene) {
  const GroundModel model = build_ground_model(scene);
  return simulate_ground(model, default_params(model),
                         HeightField(model.grid, scene.ground.initial.height_m));
}

void expect_sane(const GroundRun& run) {
  EXPECT_TRUE(run.final_height.all_finite());
  expect_balanced(run.ledger, run.final_volume_m3);
}

TEST(SimulateGround, ParameterExtremesStayFiniteAndBalanced) {
  for (const double theta_deg : {0.1, 30.0, 90.0}) {
    for (const double sigma : {1e-6, 0.2, kSigmaMax}) {
      for (const double alpha : {0.0, 1.0}) {
        Material m = sand();
        m.repose_angle_rad = theta_deg * kDeg;
        m.sigma = sigma;
        m.alpha = alpha;
        ObjectSpec ball = sphere(0.05, {at(0, 0, 0, 0.2), at(1, 0, 0, 0.06), at(2, 0.05, 0, 0.06), at(3, 0.05, 0, 0.3)});
        const GroundRun run = run_scene(flat_scene(centred_grid(32, 32, 0.01), 0.05, m, {ball}, 4));
        expect_sane(run);
        if (alpha == 1.0) {
          EXPECT_EQ(run.ledger.compressed_m3, 0.0);
        }
      }
    }
  }
}

TEST(SimulateGround, GridsFrom8To1024) {
  for (const int n : {8, 64, 1024}) {
    ObjectSpec ball = sphere(0.03, {at(0, 0, 0, 0.2), at(1, 0, 0, 0.05 + 0.03 - 0.01)});
    const GroundRun run = run_scene(flat_scene(centred_grid(n, n, 0.01), 0.05, sand(), {ball}, 2));
    expect_sane(run);
    EXPECT_GT(run.contact_cells, 0) << n;
  }
}

// 4096^2: one step with a small contact (the cost follows the contact; speed
// itself is measured in ground_benchmark).
TEST(SimulateGround, Grid4096OneStep) {
  ObjectSpec ball = sphere(0.03, {at(0, 0, 0, 0.2), at(1, 0, 0, 0.05 + 0.03 - 0.01)});
  const GroundModel model = build_ground_model(flat_scene(centred_grid(4096, 4096, 0.01), 0.05, sand(), {ball}, 1));
  GroundState state = make_ground_state(model, HeightField(model.grid, 0.05));
  auto renderer = make_cpu_underside_renderer();
  const StepReport r = step(model, default_params(model), *renderer, &state);
  EXPECT_GT(r.contact_cells, 0);
  EXPECT_LT(r.erosion.pair_visits, 200000);  // local, not 2 * 4096^2
  expect_balanced(state.ledger, state.height.volume_m3());
}

TEST(SimulateGround, ObjectLargerThanTheGridPushesMaterialOffIt) {
  ObjectSpec ball = sphere(0.5, {at(0, 0, 0, 0.6), at(1, 0, 0, 0.5 + 0.05 - 0.02)});
  const GroundRun run = run_scene(flat_scene(centred_grid(8, 8, 0.01), 0.05, sand(), {ball}, 2));
  expect_sane(run);
  EXPECT_GT(run.ledger.left_grid_m3, 0.0);
}

TEST(SimulateGround, ObjectWhollyBelowTheSurface) {
  ObjectSpec ball = sphere(0.05, {at(0, 0, 0, 0.2)});
  const Scene scene = flat_scene(centred_grid(32, 32, 0.01), 0.5, sand(), {ball}, 3);
  const GroundRun run = run_scene(scene);
  expect_sane(run);
  // the heights over the ball are at most its underside
  const GroundModel model = build_ground_model(scene);
  const DepthImage under = depth_image_cpu({transformed(ball.body, ball.pose_at(3))}, model.grid, ViewFrom::kBelow);
  for (int j = 0; j < 32; ++j) {
    for (int i = 0; i < 32; ++i) {
      if (under.is_covered(i, j)) {
        EXPECT_LE(run.final_height.at(i, j), under.z(i, j) + 1e-12);
      }
    }
  }
}

TEST(SimulateGround, AStepThatMovesManyCells) {
  for (const bool sweep : {true, false}) {
    ObjectSpec ball = sphere(0.05, {at(0, -0.3, 0, 0.07), at(1, 0.3, 0, 0.07)});
    Scene scene = flat_scene(centred_grid(80, 40, 0.01), 0.05, sand(), {ball}, 2);
    scene = with_ground_options_changed(std::move(scene), [&](GroundModelSpec& o) { o.sweep = sweep; });
    expect_sane(run_scene(scene));
  }
}

// Settling after the object has gone: the memory keeps eroding until every
// slope it touched is at most tan(theta) (+ the stated tolerance).
TEST(SimulateGround, SlopesSettleAfterTheObjectLeaves) {
  ObjectSpec ball = sphere(0.1, {at(0, 0, 0, 0.2), at(1, 0, 0, 0.05 + 0.1 - 0.05), at(2, 0, 0, 0.3)});
  Scene scene = flat_scene(centred_grid(64, 64, 0.01), 0.05, sand(), {ball}, 300);
  scene = with_ground_options_changed(std::move(scene), [&](GroundModelSpec& o) { o.erosion_memory_steps = 10; });
  const GroundRun run = run_scene(scene);
  expect_sane(run);
  EXPECT_LE(max_slope(run.final_height), std::tan(30 * kDeg) + 1.01 * kErosionToleranceFraction);
}

// Streakiness of a furrow: the mean absolute change of the height from cell
// to cell along the path's centre line, away from its ends (its total
// variation per cell). Streaks (bumps every frame) raise it; a smooth trend
// along the path (more erosion at the older end) barely does.
double streak_statistic(const HeightField& h, double x0, double x1) {
  const Grid& g = h.grid();
  const int j = g.ny / 2;
  auto centre = [&](int i) { return 0.5 * (h.at(i, j) + h.at(i, j - 1)); };  // the path runs between rows
  double sum = 0.0;
  int n = 0;
  for (int i = 1; i < g.nx; ++i) {
    if (g.centre_x(i - 1) < x0 || g.centre_x(i) > x1) continue;
    sum += std::abs(centre(i) - centre(i - 1));
    ++n;
  }
  return sum / n;
}

TEST(SimulateGround, SweepLeavesAContinuousFurrowNoSweepLeavesStreaks) {
  // 10 cells per frame, 3 cm deep, radius 10 cm
  auto dragged = [](bool sweep, int substeps) {
    ObjectSpec ball = sphere(0.1, {at(0, -0.5, 0, 0.12), at(10, 0.5, 0, 0.12)});
    Scene scene = flat_scene(centred_grid(160, 60, 0.01), 0.05, sand(), {ball}, 10);
    scene = with_ground_options_changed(std::move(scene), [&](GroundModelSpec& o) { o.sweep = sweep; });
    scene = with_ground_options_changed(std::move(scene), [&](GroundModelSpec& o) { o.substeps = substeps; });
    return run_scene(scene);
  };
  const GroundRun swept = dragged(true, 1), streaky = dragged(false, 1), substepped = dragged(false, 10);
  for (const GroundRun* r : {&swept, &streaky, &substepped}) expect_sane(*r);
  const double s_sweep = streak_statistic(swept.final_height, -0.3, 0.3);
  const double s_none = streak_statistic(streaky.final_height, -0.3, 0.3);
  const double s_sub = streak_statistic(substepped.final_height, -0.3, 0.3);
  // no sweep: the bottom rises ~r - sqrt(r^2 - (5 cells)^2) = 1.3 cm between
  // frames 10 cells apart, up and down: ~2.6 mm per cell
  EXPECT_GT(s_none, 0.001);
  EXPECT_LT(s_sweep, 0.2 * s_none) << s_sweep << " vs " << s_none;
  EXPECT_LT(s_sub, 0.2 * s_none) << s_sub << " vs " << s_none;
  EXPECT_NE(std::find(swept.stages.begin(), swept.stages.end(), "sweep"), swept.stages.end());
  EXPECT_NE(std::find(substepped.stages.begin(), substepped.stages.end(), "substeps:10"), substepped.stages.end());
}

TEST(SimulateGround, MultiResolutionConservesVolume) {
  for (const int factor : {2, 4}) {
    ObjectSpec ball = sphere(0.1, {at(0, -0.2, 0, 0.2), at(1, -0.2, 0, 0.11), at(5, 0.2, 0, 0.11)});
    ball.simple = true;
    Scene scene = flat_scene(centred_grid(96, 64, 0.01), 0.05, sand(), {ball}, 6);
    scene = with_ground_options_changed(std::move(scene), [&](GroundModelSpec& o) { o.coarse_factor = factor; });
    const GroundRun run = run_scene(scene);
    expect_sane(run);
    EXPECT_NE(std::find(run.stages.begin(), run.stages.end(), "multires"), run.stages.end());
    EXPECT_LT(run.final_height.min_height_m(), 0.05 - 0.02);  // it did deform
  }
}

// The coarse run tracks the full-resolution one: same furrow depth within a coarse cell's sagitta.
TEST(SimulateGround, MultiResolutionMatchesFullResolutionRoughly) {
  auto run = [](bool simple) {
    ObjectSpec ball = sphere(0.1, {at(0, 0, 0, 0.2), at(1, 0, 0, 0.11)});
    ball.simple = simple;
    return run_scene(flat_scene(centred_grid(64, 64, 0.01), 0.05, sand(), {ball}, 3));
  };
  const GroundRun fine = run(false), coarse = run(true);
  EXPECT_NEAR(coarse.final_height.min_height_m(), fine.final_height.min_height_m(), 0.005);
  EXPECT_NEAR(coarse.final_volume_m3, fine.final_volume_m3, 1e-9);  // sand: nothing compressed
}

TEST(SimulateGround, RejectsInvalidParamsNamingTheField) {
  const Scene scene = flat_scene(centred_grid(8, 8, 0.01), 0.05, sand(), {}, 1);
  const GroundModel model = build_ground_model(scene);
  GroundParams params = default_params(model);
  params.materials[0].alpha = 1.5;
  try {
    simulate_ground(model, params, HeightField(model.grid, 0.0));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("alpha"), std::string::npos);
  }
}

TEST(SimulateGround, RegionsLaterWin) {
  Scene scene = flat_scene(centred_grid(10, 10, 0.1), 0.05, sand(), {}, 1);
  Material mud, snow;
  material_preset("mud", &mud);
  material_preset("snow", &snow);
  scene.ground.regions.push_back({mud.name, -0.5, 0.0, -0.5, 0.5, ""});
  scene.ground.regions.push_back({snow.name, -0.25, 0.25, -0.5, 0.5, ""});
  const GroundModel model = build_ground_model(scene);
  ASSERT_EQ(model.materials.size(), 3u);
  EXPECT_EQ(model.material_at(model.cell(0, 5)), 1);  // x = -0.45: mud
  EXPECT_EQ(model.material_at(model.cell(4, 5)), 2);  // x = -0.05: snow wins
  EXPECT_EQ(model.material_at(model.cell(9, 5)), 0);  // x = 0.45: sand
}

TEST(SimulateGround, InlineYamlScene) {
  const std::string yaml = R"(
time: {step_s: 0.1, duration_s: 0.5}
ground:
  extent_m: [0.4, 0.4]
  cell_size_m: 0.01
  initial_height: {kind: flat, height_m: 0.05}
  material: mud
objects:
  - name: ball
    shape: sphere
    radius_m: 0.06
    motion:
      - {time_s: 0, position_m: [0, 0, 0.2]}
      - {time_s: 0.2, position_m: [0, 0, 0.08]}
ground_model: {erosion_memory_steps: 5}
)";
  const Scene scene = load_scene_from_string(yaml, "inline.yaml", solver_registry().sections());
  const GroundModel model = build_ground_model(scene);
  const GroundRun run = simulate_ground(scene, default_params(model));
  expect_sane(run);
  EXPECT_GT(run.ledger.compressed_m3, 0.0);  // mud: alpha 0.8
  EXPECT_EQ(run.steps, 5);
  EXPECT_EQ(run.step_wall_s.size(), 5u);
  EXPECT_EQ(run.stages.front(), "collision:cpu");
}

}  // namespace
}  // namespace repose

namespace repose {
namespace {

using namespace repose::testing;

TEST(SimulateGroundOsmesa, SelectableCollisionMatchesCpu) {
  try {
    make_osmesa_underside_renderer();
  } catch (const InputError& e) {
    GTEST_SKIP() << e.what();
  }
  auto run = [](GroundModelSpec::Collision c) {
    ObjectSpec ball = sphere(0.1, {at(0, -0.1, 0, 0.2), at(1, -0.1, 0, 0.11), at(3, 0.1, 0, 0.11)});
    Scene scene = flat_scene(centred_grid(64, 48, 0.01), 0.05, sand(), {ball}, 4);
    scene = with_ground_options_changed(std::move(scene), [&](GroundModelSpec& o) { o.collision = c; });
    const GroundModel model = build_ground_model(scene);
    return simulate_ground(model, default_params(model), HeightField(model.grid, 0.05));
  };
  const GroundRun cpu = run(GroundModelSpec::Collision::kCpu);
  const GroundRun gl = run(GroundModelSpec::Collision::kOsmesa);
  EXPECT_EQ(gl.stages.front(), "collision:osmesa");
  expect_balanced(gl.ledger, gl.final_volume_m3);
  // same furrow to well within a millimetre (float vertices, silhouette cells)
  EXPECT_NEAR(gl.final_height.min_height_m(), cpu.final_height.min_height_m(), 1e-3);
  EXPECT_LT((gl.final_height.heights() - cpu.final_height.heights()).abs().mean(), 1e-3);
}

}  // namespace
}  // namespace repose
