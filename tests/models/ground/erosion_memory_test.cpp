// The erosion memory: cells stay until their slopes have settled, so a
// surface left alone reaches the angle of repose whatever En and the
// memory length.
#include "models/ground/erosion_memory.h"

#include <gtest/gtest.h>

#include "models/ground/erosion.h"
#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

// A cell whose time is up stays while `settled` says no, and goes once it says yes.
TEST(ErosionMemory, AnUnsettledCellStaysPastItsTime) {
  ErosionMemory memory(16, 0);
  memory.touch(3);
  memory.touch(7);
  for (int s = 0; s < 5; ++s) memory.end_step([](std::int64_t c) { return c != 7; });
  ASSERT_EQ(memory.cells().size(), 1u);
  EXPECT_EQ(memory.cells()[0], 7);
  memory.end_step([](std::int64_t) { return true; });
  EXPECT_TRUE(memory.empty());
}

// The case at 4 mm cells: a sphere of 5 cm pressed 3 cm into sand
// (30 deg) and lifted out, then left alone. Once the memory is empty (which
// must happen in bounded time), no neighbour pair is steeper than tan(30
// deg) + the tolerance of erosion.h; before, with a short memory or few
// passes, cells were forgotten at up to 37 deg. Prints how long it took.
TEST(ErosionMemory, ASurfaceLeftAloneReachesTheAngleOfRepose) {
  const double bed = 0.05, r = 0.05, lifted_s = 0.6, step_s = 0.02;
  for (const auto& [passes, memory_steps] : {std::pair{1, 0}, std::pair{5, 5}, std::pair{5, 30}}) {
    Material m = sand();
    m.erosion_iterations = passes;
    ObjectSpec ball = sphere(r, {at(0, 0, 0, bed + r + 0.005), at(0.3, 0, 0, bed + r - 0.03),
                                 at(0.4, 0, 0, bed + r - 0.03), at(lifted_s, 0, 0, 0.2)});
    Scene scene = flat_scene(centred_grid(60, 60, 0.004), bed, m, {ball}, 1);
    scene.time.step_s = step_s;
    scene = with_ground_options_changed(std::move(scene), [&](GroundModelSpec& o) { o.erosion_memory_steps = memory_steps; });
    const GroundModel model = build_ground_model(scene);
    const GroundParams params = default_params(model);
    GroundState state = make_ground_state(model, HeightField(model.grid, bed));
    auto renderer = make_cpu_underside_renderer();
    constexpr int kMaxSteps = 20000;  // 400 s
    int s = 0;
    for (; s < kMaxSteps && (state.time_s < lifted_s || !state.erosion.empty()); ++s) {
      step(model, params, *renderer, &state);
    }
    ASSERT_TRUE(state.erosion.empty()) << "En " << passes << ", memory " << memory_steps;
    const double steepest = max_slope(state.height);
    EXPECT_LE(steepest, std::tan(m.repose_angle_rad) + 1.01 * kErosionToleranceFraction)
        << "En " << passes << ", memory " << memory_steps;
    EXPECT_GT(state.height.max_height_m(), bed);  // a rim remains
    std::cout << "En " << passes << ", memory " << memory_steps << ": settled " << state.time_s - lifted_s
              << " s after the lift-out, steepest " << std::atan(steepest) / kDeg << " deg\n";
  }
}

}  // namespace
}  // namespace repose
