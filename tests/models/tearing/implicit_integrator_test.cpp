// The implicit integrator: rest, stability far above the explicit limit,
// statics, and agreement with the explicit integrator on a tear load.
#include "models/tearing/implicit_integrator.h"

#include <random>

#include <gtest/gtest.h>

#include "models/tearing/explicit_integrator.h"
#include "models/tearing/seeded_draw.h"
#include "models/tearing/sheet_forces.h"
#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

TEST(ImplicitIntegrator, AnUntornSheetAtRestStaysAtRest) {
  const SheetModel model = fibre_sheet(free_sheet_spec(0.03, 8), 2);
  const SheetParams params;
  ImplicitIntegrator integrator(model, params, integrator_limit_fraction(model, params, 100.0));
  SheetState state = make_sheet_state(model);
  for (int s = 0; s < 50; ++s) integrator.step(&state);
  EXPECT_LT((state.positions - model.rest_positions).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(ImplicitIntegrator, StaysFiniteAndLosesEnergyAtAHundredTimesTheExplicitLimit) {
  const SheetModel model = fibre_sheet(free_sheet_spec(0.03, 8), 3);
  SheetParams params;
  params.tear_strain = 0.03;
  ImplicitIntegrator integrator(model, params, integrator_limit_fraction(model, params, 100.0));
  SheetState state = make_sheet_state(model);
  std::mt19937_64 rng(5);
  for (int v = 0; v < model.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) state.positions(a, v) += draw_between(rng, -3e-4, 3e-4);
  }
  const double e0 = potential_energy(model, params, state);
  double previous = e0;
  for (int s = 0; s < 100; ++s) {
    integrator.step(&state);
    ASSERT_TRUE(state.positions.allFinite()) << "step " << s;
    const double e = potential_energy(model, params, state) + kinetic_energy(model, state);
    EXPECT_LE(e, previous * (1 + 1e-9)) << "step " << s;  // backward Euler only dissipates (tearing too)
    previous = e;
  }
  EXPECT_LT(previous, 0.5 * e0);
}

TEST(ImplicitIntegrator, AHangingSheetHangsFromItsGripAtAHundredTimesTheExplicitLimit) {
  SheetSpec spec = free_sheet_spec(0.03, 6);
  spec.gravity_m_per_s2 = Eigen::Vector3d(0.0, -9.81, 0.0);
  spec.grips = {column_grip(0.0, 0.03, 0.03, 0.0, {true, true, true})};
  spec.grips[0].x_max_m = 0.03;
  const SheetModel model = uniform_sheet(spec);
  const SheetParams params;
  ImplicitIntegrator integrator(model, params, integrator_limit_fraction(model, params, 100.0));
  SheetState state = make_sheet_state(model);
  for (int s = 0; s < 200; ++s) integrator.step(&state);
  const double weight = model.mass_kg.sum() * 9.81;
  EXPECT_NEAR(state.grip_force_n(1, 0), weight, 1e-6 * weight);
}

TEST(ImplicitIntegrator, SlowUniaxialPullMeetsTheAnalyticStiffness) {
  SheetSpec spec = free_sheet_spec(0.02, 8);
  const double speed = 0.01;
  add_uniaxial_grips(&spec, speed);
  const SheetModel model = uniform_sheet(spec);
  SheetParams params;
  params.tear_strain = 1.0;
  ImplicitIntegrator integrator(model, params, integrator_limit_fraction(model, params, 20.0));
  SheetState state = make_sheet_state(model);
  while (state.time_s < 2e-3) integrator.step(&state);
  // the force is read at the start of the last step
  const double strain = speed * (state.time_s - integrator.time_step_s()) / spec.width_m;
  const double expected = params.stiffness_n_per_m * spec.height_m * strain;
  EXPECT_NEAR(state.grip_force_n(0, 2), expected, 0.01 * expected);
}

// The peak force of a strip torn apart: the explicit integrator at 0.9 of
// its limit and the implicit one at 2x and 0.5x of it agree.
TEST(ImplicitIntegrator, AgreesWithTheExplicitIntegratorOnATearLoad) {
  SheetSpec spec = free_sheet_spec(0.016, 8);
  spec.damping_per_s = 2e4;
  add_uniaxial_grips(&spec, 1.0);
  const SheetModel model = fibre_sheet(spec, 1);
  SheetParams params;
  params.tear_strain = 0.01;
  const auto peak = [&](auto& integrator) {
    SheetState state = make_sheet_state(model);
    double largest = 0.0;
    while (state.time_s < 4.8e-4) {
      integrator.step(&state);
      largest = std::max(largest, state.grip_force_n(0, 2));
    }
    return largest;
  };
  const double limit = integrator_limit_fraction(model, params, 1.0);
  ExplicitIntegrator explicit_step(model, params, 0.9 * limit);
  ImplicitIntegrator implicit_coarse(model, params, 2.0 * limit), implicit_fine(model, params, 0.5 * limit);
  const double f_explicit = peak(explicit_step), f_coarse = peak(implicit_coarse), f_fine = peak(implicit_fine);
  EXPECT_NEAR(f_fine, f_explicit, 0.02 * f_explicit);
  // and the implicit load converges as its step shrinks
  EXPECT_LE(std::abs(f_fine - f_explicit), std::abs(f_coarse - f_explicit) + 1e-3 * f_explicit);
}

}  // namespace
}  // namespace repose
