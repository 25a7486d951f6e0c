#include "models/heightspan/particles.h"

#include <gtest/gtest.h>

#include "heightspan_fixtures.h"
#include "models/core/config/initial_height.h"

namespace repose {
namespace {

using testing::bed_scene;
using testing::key;
using testing::mesh_object;

struct World {
  HeightSpanModel model;
  HeightSpanState state;
  World() {
    Scene s = bed_scene(40, 40, 0.005, 0.01,
                        {mesh_object("plate", make_box({0.03, 0.03, 0.005}), {key(0.0, 0.1, 0.1, 0.05)})}, 1);
    model = build_heightspan_model(s);
    state = make_heightspan_state(model, make_initial_height(s));
  }
  void fall(double seconds) {
    for (int k = 0; k < static_cast<int>(seconds / 0.01); ++k) {
      advance_particles(0.01, model.ground, {&state.held[0].map}, &state.particles, &state.ground);
    }
  }
};

TEST(Particles, AParticleLandsOnTheGroundAndAddsItsVolumeThere) {
  World w;
  const double before = accounted_m3(w.state);
  w.state.particles.release({{0.03, 0.03, 0.1}, Eigen::Vector3d::Zero(), 2.5e-7}, 0.0, &w.state.rng);
  EXPECT_NEAR(accounted_m3(w.state) - before, 2.5e-7, 1e-18);
  w.fall(0.5);
  EXPECT_TRUE(w.state.particles.particles.empty());
  EXPECT_EQ(w.state.particles.landed_on_ground, 1);
  EXPECT_NEAR(w.state.ground.height.at(6, 6), 0.01 + 2.5e-7 / 2.5e-5, 1e-15);
  EXPECT_TRUE(w.state.ground.erosion.contains(w.model.ground.cell(6, 6)));
}

TEST(Particles, AParticleAboveAnObjectLandsOnItsSpan) {
  World w;
  w.state.particles.release({{0.1025, 0.1025, 0.2}, Eigen::Vector3d::Zero(), 2.5e-7}, 0.0, &w.state.rng);
  w.fall(0.5);
  EXPECT_EQ(w.state.particles.landed_on_spans, 1);
  EXPECT_NEAR(w.state.held[0].map.material_m3(), 2.5e-7, 1e-18);
}

TEST(Particles, ParticlesThatLeaveTheGridAreInTheLedger) {
  World w;
  const double before = accounted_m3(w.state);
  w.state.particles.release({{0.19, 0.1, 0.1}, Eigen::Vector3d(1.0, 0, 0), 1e-7}, 0.0, &w.state.rng);
  w.fall(0.5);
  EXPECT_EQ(w.state.particles.left_grid, 1);
  EXPECT_NEAR(w.state.ground.ledger.left_grid_m3, 1e-7, 1e-20);
  EXPECT_NEAR(accounted_m3(w.state), before + 1e-7, 1e-18);
}

TEST(Particles, TheSpreadIsDrawnFromTheGeneratorGiven) {
  ParticleSystem a, b, c;
  std::mt19937_64 ra(5), rb(5), rc(6);
  a.release({}, 0.1, &ra);
  b.release({}, 0.1, &rb);
  c.release({}, 0.1, &rc);
  EXPECT_EQ(a.particles[0].velocity_m_s, b.particles[0].velocity_m_s);
  EXPECT_NE(a.particles[0].velocity_m_s, c.particles[0].velocity_m_s);
  EXPECT_EQ(a.particles[0].velocity_m_s.z(), 0.0);
  EXPECT_TRUE(a.built);
}

}  // namespace
}  // namespace repose
