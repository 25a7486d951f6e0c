#include "models/heightspan/span_motion.h"

#include <gtest/gtest.h>

#include "heightspan_fixtures.h"
#include "models/core/config/initial_height.h"

namespace repose {
namespace {

using testing::bed_scene;
using testing::bucket_mesh;
using testing::key;
using testing::mesh_object;

struct Bucket {
  HeightSpanModel model;
  HeightSpanState state;
  Bucket() {
    Scene s = bed_scene(60, 60, 0.005, 0.01, {mesh_object("bucket", bucket_mesh(), {key(0.0, 0.15, 0.15, 0.1)})}, 1);
    model = build_heightspan_model(s);
    state = make_heightspan_state(model, make_initial_height(s));
    testing::fill_spans(&state.held[0].map, 0.01, 0.08);
  }
  MotionReport move(const Pose& to, const RigidVelocity& velocity = {}) {
    return move_spans(model, model.held[0], to, velocity, *state.peeler, &state.held[0], &state.particles, &state.rng);
  }
};

TEST(SpanMotion, TranslationCarriesEveryCellsMaterialExactly) {
  Bucket b;
  const SpanMap before = b.state.held[0].map;
  Pose to = b.state.held[0].pose;
  to.position_m += Eigen::Vector3d(0.0123, -0.0071, 0.02);  // not a whole number of cells
  EXPECT_FALSE(b.move(to).resampled);
  const SpanMap& after = b.state.held[0].map;
  ASSERT_EQ(after.spans.size(), before.spans.size());
  for (std::size_t k = 0; k < before.spans.size(); ++k) {
    EXPECT_EQ(after.spans[k].material_m, before.spans[k].material_m);
    EXPECT_NEAR(after.spans[k].top_m, before.spans[k].top_m + 0.02, 1e-15);
  }
  EXPECT_NEAR(after.grid.origin_x_m, before.grid.origin_x_m + 0.0123, 1e-15);
  // the map is the body peeled where it now is
  const SpanMap fresh = peel_spans(transformed(bucket_mesh(), to), after.grid);
  ASSERT_EQ(fresh.spans.size(), after.spans.size());
  for (std::size_t k = 0; k < fresh.spans.size(); ++k) EXPECT_NEAR(fresh.spans[k].top_m, after.spans[k].top_m, 1e-12);
}

TEST(SpanMotion, RotationConservesVolumeBetweenSpansAndParticles) {
  Bucket b;
  const double before = b.state.held[0].map.material_m3();
  Pose to = b.state.held[0].pose;
  for (int k = 1; k <= 36; ++k) {  // half a turn in 5 deg substeps
    to.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(5.0 * k * testing::kDeg, Eigen::Vector3d::UnitY()));
    EXPECT_TRUE(b.move(to).resampled);
    testing::expect_spans_valid(b.state.held[0].map, "turned");
    EXPECT_NEAR(b.state.held[0].map.material_m3() + b.state.particles.in_flight_m3(), before, 1e-15);
  }
  // most of it fell: what stays was re-sampled into the solid and left it
  // over the top (erosion, not run here, empties the rest: heightspan_step_test.cpp)
  EXPECT_GT(b.state.particles.in_flight_m3(), 0.5 * before);
}

TEST(SpanMotion, WhatATurnLetsGoOfMovesAsTheObjectsPointThereMoves) {
  Bucket b;
  b.model.options.particle_spread_m_s = 0.0;
  Pose to = b.state.held[0].pose;
  RigidVelocity velocity;
  for (int k = 1; k <= 36; ++k) {  // half a turn about the bucket's centre at 5 deg per 10 ms: 8.7 rad/s
    const Pose from = to;
    to.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(5.0 * k * testing::kDeg, Eigen::Vector3d::UnitY()));
    velocity = rigid_velocity(from, to, 0.01);
    b.move(to, velocity);
  }
  ASSERT_FALSE(b.state.particles.particles.empty());
  double fastest_m_s = 0.0;
  for (const Particle& p : b.state.particles.particles) {  // every substep turned alike: one velocity field
    EXPECT_TRUE(p.velocity_m_s.isApprox(velocity.at(p.position_m), 1e-12));
    fastest_m_s = std::max(fastest_m_s, p.velocity_m_s.norm());
  }
  EXPECT_GT(fastest_m_s, 0.1);  // the load lay centimetres from the centre
}

TEST(SpanMotion, ASmallTurnKeepsTheLoad) {
  Bucket b;
  const double before = b.state.held[0].map.material_m3();
  Pose to = b.state.held[0].pose;
  to.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(3.0 * testing::kDeg, Eigen::Vector3d::UnitX()));
  b.move(to);
  EXPECT_NEAR(b.state.held[0].map.material_m3(), before, 1e-15);
  EXPECT_FALSE(b.state.particles.built);
}

}  // namespace
}  // namespace repose
