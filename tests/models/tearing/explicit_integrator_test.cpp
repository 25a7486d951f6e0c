// The explicit integrator by its invariants: rest stays rest, momentum and
// angular momentum are conserved without external forces, energy does not
// grow below the stable step, and a step above it is refused.
#include "models/tearing/explicit_integrator.h"

#include <numbers>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/tearing/seeded_draw.h"
#include "models/tearing/sheet_forces.h"
#include "models/tearing/stable_time_step.h"
#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

// The fibre sheet with every vertex displaced and moving at random.
SheetState shaken(const SheetModel& model, double amplitude_m, double speed_m_per_s, std::uint64_t seed) {
  SheetState state = make_sheet_state(model);
  std::mt19937_64 rng(seed);
  for (int v = 0; v < model.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) {
      state.positions(a, v) += draw_between(rng, -amplitude_m, amplitude_m);
      state.velocities(a, v) = draw_between(rng, -speed_m_per_s, speed_m_per_s);
    }
  }
  return state;
}

Eigen::Vector3d momentum(const SheetModel& model, const SheetState& state) {
  return state.velocities * model.mass_kg;
}

Eigen::Vector3d angular_momentum(const SheetModel& model, const SheetState& state) {
  Eigen::Vector3d l = Eigen::Vector3d::Zero();
  for (int v = 0; v < model.vertex_count(); ++v) {
    l += model.mass_kg[v] * state.positions.col(v).cross(state.velocities.col(v));
  }
  return l;
}

TEST(ExplicitIntegrator, AnUntornSheetAtRestStaysAtRest) {
  const SheetModel model = fibre_sheet(free_sheet_spec(0.03, 12), 2);
  const SheetParams params;
  ExplicitIntegrator integrator(model, params, integrator_limit_fraction(model, params, 1.0));
  SheetState state = make_sheet_state(model);
  for (int s = 0; s < 2000; ++s) integrator.step(&state);
  EXPECT_LT((state.positions - model.rest_positions).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_EQ(state.torn_count(), 0);
}

TEST(ExplicitIntegrator, ConservesMomentumAndAngularMomentumWhileTearing) {
  const SheetModel model = fibre_sheet(free_sheet_spec(0.03, 12), 3);
  SheetParams params;
  params.tear_strain = 0.03;
  ExplicitIntegrator integrator(model, params, integrator_limit_fraction(model, params, 1.0));
  SheetState state = shaken(model, 2e-4, 5.0, 17);
  const Eigen::Vector3d p0 = momentum(model, state), l0 = angular_momentum(model, state);
  const double p_scale = model.mass_kg.sum() * 5.0, l_scale = p_scale * 0.03;
  for (int s = 0; s < 3000; ++s) integrator.step(&state);
  EXPECT_GT(state.torn_count(), 0);  // the shaking tore cells, and still:
  EXPECT_LT((momentum(model, state) - p0).norm(), 1e-12 * p_scale);
  EXPECT_LT((angular_momentum(model, state) - l0).norm(), 1e-12 * l_scale);
}

// Symplectic Euler conserves a modified energy, not the energy: on an
// oscillator of frequency w with step dt the energy swings within a factor
// 1 / (1 - dt w / 2) of it, so at the limit the swing is large but it does
// not drift; at half the bound (dt w <= 1) it stays within a factor 2.
TEST(ExplicitIntegrator, EnergyDoesNotGrowAtTheStableStep) {
  const SheetModel model = fibre_sheet(free_sheet_spec(0.03, 12), 5);
  SheetParams params;
  params.tear_strain = 1.0;
  for (const double fraction : {1.0, 0.5}) {
    ExplicitIntegrator integrator(model, params, integrator_limit_fraction(model, params, fraction));
    SheetState state = shaken(model, 5e-5, 0.0, 23);
    const double e0 = potential_energy(model, params, state);
    double first_half_max = 0.0, second_half_max = 0.0;
    for (int s = 0; s < 20000; ++s) {
      integrator.step(&state);
      double& largest = s < 10000 ? first_half_max : second_half_max;
      largest = std::max(largest, potential_energy(model, params, state) + kinetic_energy(model, state));
    }
    EXPECT_LT(second_half_max, 1.01 * first_half_max) << fraction;
    if (fraction == 0.5) {
      EXPECT_LT(first_half_max, 2.0 * e0);
    }
  }
}

TEST(ExplicitIntegrator, DampingRemovesEnergy) {
  SheetSpec spec = free_sheet_spec(0.03, 12);
  spec.damping_per_s = 1e4;
  const SheetModel model = fibre_sheet(spec, 5);
  SheetParams params;
  params.tear_strain = 1.0;
  ExplicitIntegrator integrator(model, params, integrator_limit_fraction(model, params, 1.0));
  SheetState state = shaken(model, 5e-5, 0.0, 23);
  const double e0 = potential_energy(model, params, state);
  for (int s = 0; s < 5000; ++s) integrator.step(&state);
  EXPECT_LT(potential_energy(model, params, state) + kinetic_energy(model, state), 1e-3 * e0);
}

// The energy a uniform 12 x 12 sheet keeps after 20 undamped stable steps
// of time (20 x 2 / w_max), started at rest in shape with the x velocity of
// its fastest in-plane mode (neighbouring vertices moving against each
// other) or of its slowest (cos(pi x / width)), at a tenth of the stable
// step (the symplectic energy swing then stays within ~10 %).
double energy_kept(double stiffness_damping_s, bool fastest) {
  SheetSpec spec = free_sheet_spec(0.03, 12);
  const SheetParams params;
  const double time_s = 20.0 * stable_time_step_s(uniform_sheet(spec), params);
  spec.stiffness_damping_s = stiffness_damping_s;
  const SheetModel model = uniform_sheet(spec);
  const double dt = 0.1 * stable_time_step_s(model, params);
  ExplicitIntegrator integrator(model, params, dt);
  SheetState state = make_sheet_state(model);
  for (int v = 0; v < model.vertex_count(); ++v) {
    const int i = v % (spec.cells_x + 1), j = v / (spec.cells_x + 1);
    state.velocities(0, v) = fastest ? ((i + j) % 2 == 0 ? 1.0 : -1.0)
                                     : std::cos(std::numbers::pi * model.rest_positions(0, v) / spec.width_m);
  }
  const double e0 = kinetic_energy(model, state);
  while (state.time_s < time_s) integrator.step(&state);
  return (kinetic_energy(model, state) + potential_energy(model, params, state)) / e0;
}

// Rayleigh's stiffness-proportional damping (SheetSpec::stiffness_damping_s
// = beta, dashpots beta k in the springs) damps a mode w at the rate
// beta w^2 / 2: with beta = 1 / (2 w_max) the fastest mode's energy decays
// as ~exp(-w_max t / 2), to ~e^-20 here, the slowest's (w ~ w_max / 8)
// by a few tens of percent; without the dashpots both keep theirs.
TEST(ExplicitIntegrator, TheSpringsDashpotsDampTheFastestModeMoreThanTheSlowest) {
  const double beta = 0.25 * stable_time_step_s(uniform_sheet(free_sheet_spec(0.03, 12)), SheetParams{});
  EXPECT_GT(energy_kept(0.0, true), 0.85);
  EXPECT_GT(energy_kept(0.0, false), 0.85);
  const double fastest = energy_kept(beta, true), slowest = energy_kept(beta, false);
  EXPECT_LT(fastest, 0.01);
  EXPECT_GT(slowest, 0.3);
  EXPECT_LT(slowest, 0.99);  // it is damped too, only less
}

// With the dashpots the energy of a shaken sheet decreases, at the step
// they shrink the stable limit to (stable_time_step.h): beta = 2 / w_max
// (damping ratio 1 on the fastest mode, the limit 0.41 of the undamped one).
TEST(ExplicitIntegrator, TheSpringsDashpotsRemoveEnergyAtTheirStableStep) {
  SheetSpec spec = free_sheet_spec(0.03, 12);
  SheetParams params;
  params.tear_strain = 1.0;
  spec.stiffness_damping_s = stable_time_step_s(fibre_sheet(spec, 5), params);
  const SheetModel model = fibre_sheet(spec, 5);
  ExplicitIntegrator integrator(model, params, integrator_limit_fraction(model, params, 1.0));
  SheetState state = shaken(model, 5e-5, 0.0, 23);
  const double e0 = potential_energy(model, params, state);
  double previous = e0;
  for (int block = 0; block < 20; ++block) {
    for (int s = 0; s < 250; ++s) integrator.step(&state);
    const double e = potential_energy(model, params, state) + kinetic_energy(model, state);
    EXPECT_LT(e, previous) << "block " << block;
    previous = e;
  }
  EXPECT_LT(previous, 0.1 * e0);
}

TEST(ExplicitIntegrator, RefusesAStepAboveTheStableLimitNamingIt) {
  const SheetModel model = uniform_sheet(free_sheet_spec(0.03, 12));
  const SheetParams params;
  const double limit = stable_time_step_s(model, params);
  EXPECT_NO_THROW(ExplicitIntegrator(model, params, limit));
  try {
    ExplicitIntegrator(model, params, 1.01 * limit);
    FAIL() << "a step above the stable limit was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("time_step_s"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ExplicitIntegrator(model, params, 0.0), InputError);
}

TEST(ExplicitIntegrator, GripsMoveTheirVerticesAndFeelTheSheetsWeight) {
  SheetSpec spec = free_sheet_spec(0.03, 6);
  spec.gravity_m_per_s2 = Eigen::Vector3d(0.0, -9.81, 0.0);
  spec.damping_per_s = 3e4;
  spec.grips = {column_grip(0.0, 0.03, 0.03, 0.0, {true, true, true})};
  spec.grips[0].x_max_m = 0.03;  // the whole top edge
  const SheetModel model = uniform_sheet(spec);
  const SheetParams params;
  ExplicitIntegrator integrator(model, params, integrator_limit_fraction(model, params, 1.0));
  SheetState state = make_sheet_state(model);
  while (state.time_s < 0.02) integrator.step(&state);
  // hanging at rest: the grip carries the weight of the sheet
  EXPECT_NEAR(state.grip_force_n(1, 0), model.mass_kg.sum() * 9.81, 1e-3 * model.mass_kg.sum() * 9.81);
}

}  // namespace
}  // namespace repose
