// The heap laid in one pass (ground_model.heap_laying: one_pass): it keeps
// the ledger, is never steeper outwards than the angle of repose where it is
// laid nor higher than the crest, and has no preferred side.
#include "models/ground/heap_in_one_pass.h"

#include <gtest/gtest.h>

#include "models/core/config/fields.h"
#include "tests/models/ground/ground_fixtures.h"
#include "tests/models/ground/mirrored_scene.h"

namespace repose {
namespace {

using namespace repose::testing;
using Laying = GroundModelSpec::HeapLaying;

constexpr double kBed = 0.05, kRadius = 0.05;

Scene laid(Scene scene, Laying laying) {
  return with_ground_options_changed(std::move(scene), [&](GroundModelSpec& o) { o.heap_laying = laying; });
}

// The drag displacement_test.cpp checks (ground_fixtures.h), heap laid in one pass.
Scene drag_scene(const Eigen::Vector2d& dir) {
  return laid(symmetric_drag_scene(dir, kBed, kRadius), Laying::kOnePass);
}

// A box (4 cm half-sides, 4 cm half-height) pressed `depth` into the bed at the grid's centre in one step.
Scene press_scene(const Material& m, double depth_m, Laying laying) {
  ObjectSpec box;
  box.name = "box";
  box.shape = ObjectSpec::Shape::kBox;
  box.half_extents_m = Eigen::Vector3d(0.0401, 0.0401, 0.04);
  box.body = make_box(box.half_extents_m);
  const double centre = kBed - depth_m + 0.04;
  box.keyframes = {at(0, 0, 0, 0.2), at(1, 0, 0, centre)};
  return laid(flat_scene(centred_grid(64, 64, 0.005), kBed, m, {box}, 1), laying);
}

TEST(HeapInOnePass, ADragKeepsTheLedgerAndHasNoPreferredSide) {
  for (const auto& [dir, mirror] : {std::pair{Eigen::Vector2d(1, 0), Mirror::kY}, {Eigen::Vector2d(0, 1), Mirror::kX}}) {
    const Scene scene = drag_scene(dir);
    const GroundModel model = build_ground_model(scene);
    const GroundState state = run_steps(model, default_params(model), kBed, model.time.step_count());
    expect_balanced(state.ledger, state.height.volume_m3());
    EXPECT_GT(state.height.max_height_m(), kBed + 1e-3);  // material was pushed up
    EXPECT_LT(largest_mirror_difference(state.height, state.height, mirror), 1e-12);
  }
}

TEST(HeapInOnePass, OppositeDragsGiveTurnedFields) {
  auto run = [](const Scene& scene) {
    const GroundModel model = build_ground_model(scene);
    return run_steps(model, default_params(model), kBed, model.time.step_count()).height;
  };
  EXPECT_LT(largest_mirror_difference(run(drag_scene({1, 0})), run(drag_scene({-1, 0})), Mirror::kX), 1e-12);
}

// With erosion off, the heap as laid: going one cell away from the box
// along x or y, no laid cell stands more than a repose step above the next,
// and none above the crest (the box's top).
TEST(HeapInOnePass, ALaidHeapIsNeverSteeperOutwardsThanTheAngleOfRepose) {
  for (const double theta_deg : {30.0, 60.0, 90.0}) {
    Material m = sand();
    m.repose_angle_rad = theta_deg * kDeg;
    const Scene scene = press_scene(m, 0.03, Laying::kOnePass);
    const GroundModel model = build_ground_model(scene);
    GroundParams params = default_params(model);
    params.materials.front().erosion_iterations = 0;  // erode() left out: only the laying
    const GroundState state = run_steps(model, params, kBed, 1);
    expect_balanced(state.ledger, state.height.volume_m3());
    const Grid& g = model.grid;
    const double step = g.cell_size_m * std::tan(m.repose_angle_rad), tol = 1e-12;
    const int half = 8;  // the box covers cells [32 - 8, 32 + 8)
    double raised = 0.0;
    for (int j = 0; j < g.ny; ++j) {
      for (int i = 0; i < g.nx; ++i) {
        const double h = state.height.at(i, j);
        raised = std::max(raised, h - kBed);
        if (i >= 32 - half && i < 32 + half && j >= 32 - half && j < 32 + half) continue;  // under the box
        EXPECT_LE(h, kBed - 0.03 + 0.08 + tol) << theta_deg;  // the crest
        const int oi = i >= 32 + half ? 1 : i < 32 - half ? -1 : 0, oj = j >= 32 + half ? 1 : j < 32 - half ? -1 : 0;
        for (const auto& [di, dj] : {std::pair{oi, 0}, {0, oj}}) {
          if ((di == 0 && dj == 0) || !g.contains(i + di, j + dj) || !(h > kBed)) continue;
          EXPECT_LE(h - state.height.at(i + di, j + dj), step + tol) << theta_deg << " at " << i << ", " << j;
        }
      }
    }
    EXPECT_GT(raised, 1e-3) << theta_deg;
    EXPECT_LT(largest_mirror_difference(state.height, state.height, Mirror::kX), 1e-12) << theta_deg;
    EXPECT_LT(largest_mirror_difference(state.height, state.height, Mirror::kDiagonal), 1e-12) << theta_deg;
  }
}

// The default lays in portions (the committed calibrations' heap): the two differ.
TEST(HeapInOnePass, TheDefaultIsThePortionsAndTheOnePassHeapDiffers) {
  EXPECT_EQ(GroundModelSpec{}.heap_laying, Laying::kPortions);
  auto run = [](Laying laying) {
    const GroundModel model = build_ground_model(press_scene(sand(), 0.03, laying));
    GroundParams params = default_params(model);
    params.materials.front().erosion_iterations = 0;
    return run_steps(model, params, kBed, 1).height;
  };
  const HeightField portions = run(Laying::kPortions), one_pass = run(Laying::kOnePass);
  EXPECT_GT((portions.heights() - one_pass.heights()).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(HeapInOnePass, AnUnknownLayingIsRefusedByName) {
  GroundModelSpec spec;
  spec.heap_laying = static_cast<Laying>(7);
  try {
    validate(spec);
    FAIL() << "accepted";
  } catch (const FieldError& e) {
    EXPECT_NE(std::string(e.what()).find("heap_laying"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace repose
