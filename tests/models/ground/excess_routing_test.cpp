// Where displaced material heaps: never higher than what pushed it (or the
// ground it leans on), never a column in a single cell.
#include "models/ground/excess_routing.h"

#include <gtest/gtest.h>

#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

constexpr double kBed = 0.05;

// Runs every step of the scene; the highest any cell stood after a step.
double highest_at_any_step(const Scene& scene) {
  const GroundModel model = build_ground_model(scene);
  const GroundParams params = default_params(model);
  GroundState state = make_ground_state(model, HeightField(model.grid, kBed));
  auto renderer = make_cpu_underside_renderer();
  double highest = 0.0;
  for (int s = 0; s < model.time.step_count(); ++s) {
    step(model, params, *renderer, &state);
    highest = std::max(highest, state.height.max_height_m());
    EXPECT_GE(state.height.min_height_m(), 0.0);
  }
  expect_balanced(state.ledger, state.height.volume_m3());
  return highest;
}

// The drag (4 mm cells here): a sphere of 5 cm pressed 2 cm into a
// 5 cm bed and dragged 0.2 m once raised 0.3 m columns beside it, above its
// top. Now no cell rises above the sphere's top at any step.
TEST(ExcessRouting, ADragRaisesNoCellAboveTheObject) {
  const double r = 0.05, low = kBed + r - 0.02;
  ObjectSpec ball = sphere(r, {at(0, -0.1, 0, low + 0.025), at(0.3, -0.1, 0, low), at(1.3, 0.1, 0, low),
                               at(1.5, 0.1, 0, 0.2)});
  Scene scene = flat_scene(centred_grid(100, 100, 0.004), kBed, sand(), {ball}, 2);
  scene.time.step_s = 0.02;
  EXPECT_LE(highest_at_any_step(scene), low + r + 1e-12);
}

// A material that stands at 90 deg does not erode, so whatever displacement
// heaps stays: a box pressed 4 cm into it heaps a wall up to the box's top
// (the crest), then a plateau outwards, not columns of 0.2 m above it.
TEST(ExcessRouting, AtNinetyDegreesTheHeapStopsAtTheCrest) {
  Material m = sand();
  m.repose_angle_rad = 90 * kDeg;
  ObjectSpec box;
  box.name = "box";
  box.shape = ObjectSpec::Shape::kBox;
  box.half_extents_m = Eigen::Vector3d(0.05, 0.05, 0.04);
  box.body = make_box(box.half_extents_m);
  const double centre = kBed;  // bottom 4 cm below the surface, top 4 cm above it
  box.keyframes = {at(0, 0, 0, 0.2), at(1, 0, 0, centre)};
  const Scene scene = flat_scene(centred_grid(64, 64, 0.005), kBed, m, {box}, 2);
  EXPECT_LE(highest_at_any_step(scene), centre + 0.04 + 1e-12);  // the crest: the box's top
}

// A blade pushed through sand drives a heap ahead of it, as the DEM
// references do (ref_bulldoze: a crescent ahead of the blade, levees
// beside the trench of a millimetre or two). Shedding the heap's material
// sideways as readily as forwards left most of it beside the trench, where
// the advancing blade never met it again: twice as much beside as ahead.
// While dragging, a heap now sheds forwards first.
TEST(ExcessRouting, ADraggedBladePushesItsHeapAheadNotAside) {
  const double half_x = 0.0075, half_y = 0.02, low = kBed - 0.01 + 0.015;  // bottom 1 cm below the surface
  ObjectSpec blade;
  blade.name = "blade";
  blade.shape = ObjectSpec::Shape::kBox;
  blade.half_extents_m = Eigen::Vector3d(half_x, half_y, 0.015);
  blade.body = make_box(blade.half_extents_m);
  const double from_x = -0.06, to_x = 0.04;
  blade.keyframes = {at(0, from_x, 0, low + 0.02), at(1, from_x, 0, low), at(11, to_x, 0, low)};
  Scene scene = flat_scene(centred_grid(60, 40, 0.005), kBed, sand(), {blade}, 11);
  const GroundModel model = build_ground_model(scene);
  const GroundState state = run_steps(model, default_params(model), kBed, 11);
  double ahead_m3 = 0.0, beside_m3 = 0.0;
  const Grid& g = model.grid;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const double x = g.origin_x_m + (i + 0.5) * g.cell_size_m, y = g.origin_y_m + (j + 0.5) * g.cell_size_m;
      const double raised_m3 = std::max(0.0, state.height.at(i, j) - kBed) * g.cell_area_m2();
      if (x > to_x + half_x) ahead_m3 += raised_m3;
      if (x < to_x - half_x && std::abs(y) > half_y) beside_m3 += raised_m3;
    }
  }
  EXPECT_GT(ahead_m3, 3.0 * beside_m3) << "ahead " << ahead_m3 << " m^3, beside " << beside_m3 << " m^3";
  expect_balanced(state.ledger, state.height.volume_m3());
}

}  // namespace
}  // namespace repose
