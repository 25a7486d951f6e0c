// The chute impact's numbers on synthetic flows with known answers: the
// Froude number and pressure coefficient by their definitions, the design
// form's limits, a slab of grains' depth, speed and mass per area, and a
// synthetic surge whose force is built from the design form (the measured
// coefficient and Froude number come back), whose slow deposit is left out
// of the impact phase and whose larger static load is not its peak.

#include "validation/particles/chute_impact.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/validation/liggghts/chute_test_scene.h"

namespace repose {
namespace {

ChuteGeometry test_geometry() {
  ChuteGeometry g;
  g.slope_rad = 30.0 * std::numbers::pi / 180.0;
  g.gravity_m_s2 = 9.81;
  g.density_kg_m3 = 2500.0;
  g.wall_face_x_m = 1.0;
  g.width_m = 0.02;
  g.window_x_min_m = 0.9;
  g.window_x_max_m = 0.96;
  return g;
}

// A slab of grains of radius r on a cubic lattice of spacing 2r: x over the
// window [x0, x1), y across the width, `layers` layers from the floor, all moving at (u, 0, 0).
GrainSet slab(double x0, double x1, double width, int layers, double r, double u) {
  const int nx = static_cast<int>(std::round((x1 - x0) / (2 * r)));
  const int ny = static_cast<int>(std::round(width / (2 * r)));
  GrainSet g;
  const Eigen::Index n = static_cast<Eigen::Index>(nx) * ny * layers;
  g.position_m.resize(n, 3);
  g.velocity_m_s.resize(n, 3);
  g.radius_m = Eigen::VectorXd::Constant(n, r);
  Eigen::Index k = 0;
  for (int l = 0; l < layers; ++l) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i, ++k) {
        g.position_m.row(k) << x0 + (2 * i + 1) * r, (2 * j + 1) * r, (2 * l + 1) * r;
        g.velocity_m_s.row(k) << u, 0.0, 0.0;
      }
    }
  }
  return g;
}

double slab_mass_per_area(const ChuteGeometry& g, int layers, double r) {
  // one grain per (2r)^2 of floor per layer
  return layers * g.density_kg_m3 * 4.0 / 3.0 * std::numbers::pi * r * r * r / (4 * r * r);
}

TEST(ChuteImpact, FroudeNumberIsSpeedOverTheShallowWaveSpeedNormalToTheBed) {
  EXPECT_NEAR(froude_number(2.0, 0.01, 9.81, 0.0), 2.0 / std::sqrt(0.0981), 1e-12);
  EXPECT_NEAR(froude_number(2.0, 0.01, 9.81, std::numbers::pi / 3), 2.0 / std::sqrt(0.0981 * 0.5), 1e-12);
}

TEST(ChuteImpact, PressureCoefficientAndTheDesignForm) {
  EXPECT_DOUBLE_EQ(pressure_coefficient(1000.0, 1500.0, 2.0), 1000.0 / 6000.0);
  // C = alpha + k / (2 Fr^2): alpha at high Froude numbers, the hydrostatic part at Fr = 1
  EXPECT_DOUBLE_EQ(design_pressure_coefficient(1.0, 1.0, 1.5), 2.0);
  EXPECT_NEAR(design_pressure_coefficient(1e4, 1.0, 1.5), 1.5, 1e-8);
  // the form's pressure divided by rho v^2 is its coefficient
  const double rho = 1500, v = 3, h = 0.02, g = 9.81, zeta = 0.5, k = 1.2, alpha = 1.7;
  const double p = 0.5 * k * rho * g * h * std::cos(zeta) + alpha * rho * v * v;
  EXPECT_NEAR(pressure_coefficient(p, rho, v), design_pressure_coefficient(froude_number(v, h, g, zeta), k, alpha),
              1e-12);
}

TEST(ChuteImpact, WindowFlowOfASlabGivesItsDepthSpeedAndMass) {
  const ChuteGeometry g = test_geometry();
  const double r = 0.002;
  GrainSet grains = slab(0.9, 0.96, 0.02, 3, r, 1.5);
  // grains outside the window are left out, whatever they do
  GrainSet outside = slab(0.5, 0.6, 0.02, 6, r, -4.0);
  const Eigen::Index n = grains.size(), m = outside.size();
  grains.position_m.conservativeResize(n + m, 3);
  grains.velocity_m_s.conservativeResize(n + m, 3);
  grains.radius_m.conservativeResize(n + m);
  grains.position_m.bottomRows(m) = outside.position_m;
  grains.velocity_m_s.bottomRows(m) = outside.velocity_m_s;
  grains.radius_m.tail(m) = outside.radius_m;

  ChuteImpactOptions options;
  options.depth_quantile = 1.0;
  const ChuteFlow f = window_flow(grains, g, options);
  EXPECT_EQ(f.grains, n);
  EXPECT_NEAR(f.speed_m_s, 1.5, 1e-12);
  EXPECT_NEAR(f.depth_m, 6 * r, 1e-12);  // the top of the third layer
  EXPECT_NEAR(f.mass_per_area_kg_m2, slab_mass_per_area(g, 3, r), 1e-9);
}

TEST(ChuteImpact, GrainsWithoutVelocitiesAreRefused) {
  GrainSet grains = slab(0.9, 0.96, 0.02, 1, 0.002, 1.0);
  grains.velocity_m_s.resize(0, 3);
  EXPECT_THROW(window_flow(grains, test_geometry()), InputError);
}

// A surge: frames every 10 ms; nothing until 0.1 s, then a 3-layer slab at
// 2 m/s for 0.2 s, then a 5-layer deposit creeping at 0.1 m/s. The force on
// the wall (1 ms samples) is the design form's with k = 1, alpha = 1.5 while
// the surge arrives (until 0.36 s) and a static 3x larger load afterwards.
TEST(ChuteImpact, SyntheticSurgeGivesBackTheDesignFormsCoefficient) {
  const ChuteGeometry g = test_geometry();
  const double r = 0.002, v = 2.0, k = 1.0, alpha = 1.5;
  const double m_a = slab_mass_per_area(g, 3, r), h = 6 * r;
  const double rho = m_a / h;
  const double fr = froude_number(v, h, g.gravity_m_s2, g.slope_rad);
  const double surge_force = g.width_m * h * rho * v * v * design_pressure_coefficient(fr, k, alpha);
  std::vector<GrainSet> frames;
  std::vector<double> frame_t, force_t, force;
  for (int i = 0; i <= 60; ++i) {
    const double t = 0.01 * i;
    frame_t.push_back(t);
    frames.push_back(t < 0.1 ? GrainSet{MatrixX3dR(0, 3), Eigen::VectorXd(0), MatrixX3dR(0, 3)}
                     : t < 0.3 ? slab(0.9, 0.96, 0.02, 3, r, v)
                               : slab(0.9, 0.96, 0.02, 5, r, 0.1));
  }
  for (int i = 0; i <= 600; ++i) {
    const double t = 0.001 * i;
    force_t.push_back(t);
    force.push_back(t < 0.1 ? 0.0 : t < 0.36 ? surge_force : 3.0 * surge_force);
  }
  ChuteImpactOptions options;
  options.depth_quantile = 1.0;
  const ChuteImpact c = measure_chute_impact(g, frames, frame_t, force_t, force, options);
  EXPECT_NEAR(c.front_arrival_s, 0.1, 1e-12);
  EXPECT_EQ(c.impact_frame_count, 20);  // 0.10 .. 0.29 s; the creeping deposit is left out
  EXPECT_NEAR(c.mean.froude, fr, 1e-9);
  EXPECT_NEAR(c.mean.coefficient, design_pressure_coefficient(fr, k, alpha), 1e-9);
  EXPECT_NEAR(c.mean.bulk_density_kg_m3, rho, 1e-9);
  EXPECT_NEAR(c.mean.pressure_pa, surge_force / (g.width_m * h), 1e-9);
  // the peak is the surge's, not the deposit's static load, which is final_force_n
  EXPECT_NEAR(c.peak.force_n, surge_force, 1e-12);
  EXPECT_NEAR(c.peak.coefficient, design_pressure_coefficient(fr, k, alpha), 1e-9);
  EXPECT_NEAR(c.final_force_n, 3.0 * surge_force, 1e-12);
  EXPECT_THROW(measure_chute_impact(g, {GrainSet{}}, {0.0}, force_t, force), InputError);  // never reached
}

TEST(ChuteImpact, GeometryFromTheScenesWallAndWindow) {
  const ChuteGeometry g = chute_geometry(testing::chute_scene(35.0));
  EXPECT_NEAR(g.slope_rad, 35.0 * std::numbers::pi / 180.0, 1e-15);
  EXPECT_NEAR(g.wall_face_x_m, 0.18, 1e-12);
  EXPECT_NEAR(g.width_m, 0.0118, 1e-12);  // the wall's own width, inside the 12 mm chute
  EXPECT_NEAR(g.window_x_max_m, 0.17, 1e-12);
  EXPECT_NEAR(g.window_x_min_m, 0.13, 1e-12);
  EXPECT_THROW(chute_geometry(testing::chute_scene(35.0, 0.0)), InputError);   // no window: not a chute
  EXPECT_THROW(testing::chute_scene(35.0, 0.3), InputError);                    // a window off the grid
}

}  // namespace
}  // namespace repose
