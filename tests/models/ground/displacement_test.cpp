// Displacement: drags without a preferred side, and the floor at the base.
#include "models/ground/displacement.h"

#include <gtest/gtest.h>

#include "tests/models/ground/ground_fixtures.h"
#include "tests/models/ground/mirrored_scene.h"

namespace repose {
namespace {

using namespace repose::testing;

constexpr double kBed = 0.05, kRadius = 0.05;

// The drag (ground_fixtures.h) in a 5 cm bed.
Scene drag_scene(const Eigen::Vector2d& dir) { return symmetric_drag_scene(dir, kBed, kRadius); }

HeightField run(const Scene& scene) {
  const GroundModel model = build_ground_model(scene);
  return run_steps(model, default_params(model), kBed, model.time.step_count()).height;
}

// A drag along an axis is mirror-symmetric about that axis, a diagonal drag
// about the diagonal, to round-off (issue 16: 15 mm and 5.7e-5 m^3 of sand
// on the +y side, following the grid's storage order).
TEST(Displacement, DragsAreMirrorSymmetricAboutTheirAxis) {
  const double d = std::sqrt(0.5);
  const struct {
    Eigen::Vector2d dir;
    Mirror mirror;
    const char* name;
  } cases[] = {{{1, 0}, Mirror::kY, "+x"}, {{-1, 0}, Mirror::kY, "-x"}, {{0, 1}, Mirror::kX, "+y"},
               {{d, d}, Mirror::kDiagonal, "diagonal"}};
  for (const auto& c : cases) {
    const HeightField h = run(drag_scene(c.dir));
    EXPECT_LT(largest_mirror_difference(h, h, c.mirror), 1e-12) << c.name;
    EXPECT_GT(h.max_height_m(), kBed + 1e-3) << c.name;  // material was pushed up
  }
}

// Dragging along -x gives the +x drag's field turned round.
TEST(Displacement, OppositeDragsGiveTurnedFields) {
  const HeightField plus = run(drag_scene({1, 0})), minus = run(drag_scene({-1, 0}));
  EXPECT_LT(largest_mirror_difference(plus, minus, Mirror::kX), 1e-12);
}

// The floor: a sphere pressed 2 cm below the base of a 1 cm bed removes
// the material down to the base, no further (issue 16: -16.5 mm); the
// ledger records the bedrock it met and still balances. Dragged on, it
// meets more (its swept path).
TEST(Displacement, TheBaseIsAFloorAndTheLedgerSaysSo) {
  const double thin = 0.01;
  // a cap of the sphere 2 cm deep lies below the base: pi d^2 (3 r - d) / 3
  const double cap_m3 = std::numbers::pi * 0.02 * 0.02 * (3 * kRadius - 0.02) / 3;
  for (const bool sweep : {true, false}) {
    ObjectSpec ball = sphere(kRadius, {at(0, 0, 0, 0.1), at(1, 0, 0, kRadius - 0.02), at(2, 0.03, 0, kRadius - 0.02)});
    ball.body = make_octasphere(kRadius, 4);
    Scene scene = flat_scene(centred_grid(48, 48, 0.0025), thin, sand(), {ball}, 2);
    scene = with_ground_options_changed(std::move(scene), [&](GroundModelSpec& o) { o.sweep = sweep; });
    const GroundModel model = build_ground_model(scene);
    GroundState state = run_steps(model, default_params(model), thin, 1);
    EXPECT_EQ(state.height.min_height_m(), 0.0) << sweep;  // reached the base, not below
    EXPECT_NEAR(state.ledger.bedrock_m3, cap_m3, 0.05 * cap_m3) << sweep;  // to the grid's resolution
    expect_balanced(state.ledger, state.height.volume_m3());
    auto renderer = make_cpu_underside_renderer();
    step(model, default_params(model), *renderer, &state);
    EXPECT_EQ(state.height.min_height_m(), 0.0) << sweep;
    EXPECT_GT(state.ledger.bedrock_m3, cap_m3 * (sweep ? 1.3 : 0.95)) << sweep;
    expect_balanced(state.ledger, state.height.volume_m3());
  }
}

// Above the base, no bedrock is met.
TEST(Displacement, NoBedrockAboveTheBase) {
  const GroundModel model = build_ground_model(drag_scene({1, 0}));
  const GroundState state = run_steps(model, default_params(model), kBed, 10);
  EXPECT_EQ(state.ledger.bedrock_m3, 0.0);
}

// A sphere already 2 cm deep, dragged 8 cm along x (every step a drag):
// with alpha 0.5 it compresses what it meets, less as the material's drag
// compaction ratio falls, nothing at 0 (the volume is then conserved).
GroundState pure_drag(double drag_compaction_ratio) {
  const double low = kBed + kRadius - 0.02;
  ObjectSpec ball = sphere(kRadius, {at(0, -0.04, 0.0011, low), at(4, 0.04, 0.0011, low)});
  Material m = sand();
  m.alpha = 0.5;
  m.drag_compaction_ratio = drag_compaction_ratio;
  const Scene scene = flat_scene(centred_grid(64, 40, 0.005), kBed, m, {ball}, 4);
  const GroundModel model = build_ground_model(scene);
  return run_steps(model, default_params(model), kBed, model.time.step_count());
}

TEST(Displacement, ADragCompressesByItsCompactionRatio) {
  const GroundState none = pure_drag(0.0), half = pure_drag(0.5), all = pure_drag(1.0);
  EXPECT_EQ(none.ledger.compressed_m3, 0.0);
  EXPECT_GT(half.ledger.compressed_m3, 0.0);
  EXPECT_GT(all.ledger.compressed_m3, 1.5 * half.ledger.compressed_m3);
  for (const GroundState* s : {&none, &half, &all}) expect_balanced(s->ledger, s->height.volume_m3());
  EXPECT_GT(none.height.volume_m3(), half.height.volume_m3());
}

// A level drag is a drag at every step, although interpolating a level
// segment between keyframes wanders by an ulp in z: counted as descents,
// those steps compressed as a press does (ref_bulldoze lost 16 of its
// 21 cm^3 that way).
TEST(Displacement, ALevelDragIsADragAtEveryStepDespiteRoundOff) {
  const double low = kBed + kRadius - 0.02;
  ObjectSpec ball = sphere(kRadius, {at(0, -0.1, 0.0011, low), at(1, 0.1, 0.0011, low)});
  Material m = sand();
  m.alpha = 0.5;
  m.drag_compaction_ratio = 0.0;  // a drag compresses nothing, a press half of what it meets
  Scene scene = flat_scene(centred_grid(64, 40, 0.005), kBed, m, {ball}, 1);
  scene.time.step_s = 0.01;
  int descents = 0;  // the round-off this test is about must be there
  for (int k = 0; k < 100; ++k) {
    const double dz = ball.pose_at(k * 0.01 + 0.01).position_m.z() - ball.pose_at(k * 0.01).position_m.z();
    descents += dz < 0.0 ? 1 : 0;
  }
  ASSERT_GT(descents, 0);
  const GroundModel model = build_ground_model(scene);
  const GroundState s = run_steps(model, default_params(model), kBed, model.time.step_count());
  EXPECT_EQ(s.ledger.compressed_m3, 0.0);
  expect_balanced(s.ledger, s.height.volume_m3());
}

// Pressing straight down is no drag: the ratio leaves it bit for bit alone.
TEST(Displacement, TheDragCompactionRatioLeavesAPressAlone) {
  HeightField pressed[2];
  const double ratios[2] = {1.0, 0.2};
  for (int k = 0; k < 2; ++k) {
    ObjectSpec ball = sphere(kRadius, {at(0, 0, 0, kBed + kRadius + 0.01), at(2, 0, 0, kBed + kRadius - 0.02)});
    Material m = sand();
    m.alpha = 0.5;
    m.drag_compaction_ratio = ratios[k];
    const GroundModel model = build_ground_model(flat_scene(centred_grid(40, 40, 0.005), kBed, m, {ball}, 2));
    pressed[k] = run_steps(model, default_params(model), kBed, model.time.step_count()).height;
  }
  EXPECT_TRUE((pressed[0].heights() == pressed[1].heights()).all());
  EXPECT_LT(pressed[0].volume_m3(), HeightField(pressed[0].grid(), kBed).volume_m3());  // it did compress
}

}  // namespace
}  // namespace repose
