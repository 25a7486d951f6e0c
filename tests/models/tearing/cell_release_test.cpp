// Torn cells let go gradually (SheetSpec::release_time_s): a zero release
// time is the seed's snap to the bit; a fading cell holds a linearly falling
// share of its springs, bending and twist terms and nothing after the
// release time, the energy it gives up booked so that the energy ledger
// still closes; below the tear limit the option changes nothing.
#include "models/tearing/cell_release.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/tearing/explicit_integrator.h"
#include "models/tearing/implicit_integrator.h"
#include "models/tearing/sheet_forces.h"
#include "models/tearing/tear_run.h"
#include "models/tearing/tearing.h"
#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

// The notched sheet under the seed's twist (tearing_fixtures.h), undamped,
// cells let go over release_time_s.
SheetModel notched_twisted_sheet(double release_time_s, bool twist_stiffness = false) {
  SheetSpec spec = notched_twisted_spec(twist_stiffness);
  spec.release_time_s = release_time_s;
  return uniform_sheet(spec);
}

// A 3 x 3 sheet rolled about y and stretched 3 % along x: every cell past
// the 1 % tear strain, holding spring, bending and twist energy.
SheetState rolled_and_stretched(const SheetModel& model) {
  SheetState state = make_sheet_state(model);
  for (int v = 0; v < model.vertex_count(); ++v) {
    const double x = model.rest_positions(0, v), y = model.rest_positions(1, v);
    state.positions(0, v) = 1.03 * x;
    state.positions(2, v) = 40.0 * x * x + 30.0 * x * y;
  }
  return state;
}

SheetModel stiff_three_by_three(double release_time_s) {
  SheetSpec spec = free_sheet_spec(0.006, 3);
  spec.twist_stiffness = true;
  spec.bending_stiffness_n_m = 3e-2;  // so that bending weighs against the springs
  spec.release_time_s = release_time_s;
  return uniform_sheet(spec);
}

// The seed's rule, stepped by hand from tearing.h's tear_overstretched_cells
// (which only marks cells torn) and the elastic forces of what is left: a
// zero release time must give the same trajectory to the bit.
TEST(CellRelease, AZeroReleaseTimeIsTheSeedsSnapToTheBit) {
  const SheetModel model = notched_twisted_sheet(0.0);
  const SheetParams params;
  const double dt = 0.9 * stable_time_step_s(model, params);
  ExplicitIntegrator integrator(model, params, dt);
  SheetState run = make_sheet_state(model), by_hand = run;
  Eigen::Matrix3Xd forces;
  const Eigen::Vector3d& g = model.spec.gravity_m_per_s2;
  for (int step = 1; step <= 4000; ++step) {
    integrator.step(&run);
    tear_overstretched_cells(model, params, step, &by_hand);
    internal_forces(model, params, by_hand, &forces);
    const double t_next = by_hand.time_s + dt;
    for (int v = 0; v < model.vertex_count(); ++v) {
      const int grip = model.grip_of_vertex[static_cast<std::size_t>(v)];
      for (int a = 0; a < 3; ++a) {
        if (model.held_axes[static_cast<std::size_t>(v)] & (1u << a)) {
          const double speed = model.spec.grips[static_cast<std::size_t>(grip)].velocity_m_per_s[a];
          by_hand.velocities(a, v) = speed;
          by_hand.positions(a, v) = model.rest_positions(a, v) + speed * t_next;
        } else {
          by_hand.velocities(a, v) += dt * (forces(a, v) / model.mass_kg[v] + g[a]);
          by_hand.positions(a, v) += dt * by_hand.velocities(a, v);
        }
      }
    }
    by_hand.time_s = t_next;
  }
  ASSERT_GT(run.torn_count(), static_cast<int>(model.notch_cells.size()) + 3) << "the test must tear";
  EXPECT_EQ(run.torn_step, by_hand.torn_step);
  EXPECT_TRUE(run.positions == by_hand.positions);
  EXPECT_TRUE(run.velocities == by_hand.velocities);
  for (const double r : run.releasing) EXPECT_EQ(r, 0.0);
  EXPECT_GT(run.torn_bending_energy_j, 0.0);  // the snap books the bending terms it takes out (sheet_forces.h)
}

// A torn cell holds all of its springs on the step it tears, then a share
// falling by dt / release_time_s a step, and nothing once the release time
// has passed; at fixed positions the energy booked over the fade is what
// the sheet held (springs as fracture, twist and bending apart).
TEST(CellRelease, ATornCellFadesLinearlyAndIsFullyReleasedAfterTheReleaseTime) {
  const double release_s = 1e-6;
  const SheetModel model = stiff_three_by_three(release_s);
  SheetParams params;
  params.tear_strain = 0.01;
  SheetState state = rolled_and_stretched(model);
  const ElasticEnergy held = elastic_energy(model, params, state);
  ASSERT_GT(held.bending_j, 0.0);
  ASSERT_GT(held.twist_j, 0.0);
  Eigen::Matrix3Xd intact_forces, forces;
  internal_forces(model, params, state, &intact_forces);
  ASSERT_EQ(tear_and_internal_forces(model, params, 1, &state, &forces), model.cell_count());
  EXPECT_TRUE(forces == intact_forces) << "on the step it tears a cell still holds fully";
  const Eigen::Matrix3Xd fixed = state.positions;
  for (int k = 1; k <= 4; ++k) {
    const int still = release_torn_cells(model, params, 0.25 * release_s, fixed, &state);
    EXPECT_EQ(still, k < 4 ? model.cell_count() : 0);
    for (int c = 0; c < model.cell_count(); ++c) EXPECT_NEAR(state.hold(c), 1.0 - 0.25 * k, 1e-12);
    if (k == 2) {  // half held: half the forces and half the energy
      internal_forces(model, params, state, &forces);
      EXPECT_LT((forces - 0.5 * intact_forces).cwiseAbs().maxCoeff(), 1e-12 * intact_forces.cwiseAbs().maxCoeff());
      EXPECT_NEAR(elastic_energy(model, params, state).total_j(), 0.5 * held.total_j(), 1e-12 * held.total_j());
    }
  }
  internal_forces(model, params, state, &forces);
  EXPECT_EQ(forces.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(elastic_energy(model, params, state).total_j(), 0.0);
  EXPECT_NEAR(state.torn_energy_j, held.structural_j + held.shear_j, 1e-12 * held.total_j());
  EXPECT_NEAR(state.torn_twist_energy_j, held.twist_j, 1e-12 * held.total_j());
  EXPECT_NEAR(state.torn_bending_energy_j, held.bending_j, 1e-12 * held.total_j());
  EXPECT_EQ(release_torn_cells(model, params, 0.25 * release_s, fixed, &state), 0);  // nothing left to release
}

// Through a whole tear, the energy the fading cells give up is booked, and
// the grips' work is accounted for within 1 %, for
// a fade of a few steps and one of many.
TEST(CellRelease, TheEnergyLedgerClosesWhileTornCellsFade) {
  const SheetParams params;
  const double dt = 0.9 * stable_time_step_s(notched_twisted_sheet(0.0), params);
  for (const double release_s : {5.0 * dt, 200.0 * dt}) {
    for (const bool twist : {false, true}) {
      const TearRun run = run_tear(notched_twisted_sheet(release_s, twist), params, stop_at_24_mm());
      const EnergyLedger& e = run.ledger;
      ASSERT_GT(run.tear_length_m, 0.01) << release_s;
      EXPECT_GT(e.fracture_j, 0.0);
      EXPECT_GT(e.torn_bending_j, 0.0);
      EXPECT_EQ(e.torn_twist_j > 0.0, twist);
      EXPECT_LT(std::abs(e.residual_j), 0.01 * run.grip_work_j)
          << "release " << release_s << " s, twist " << twist << ": stored " << e.stored_j << " kinetic "
          << e.kinetic_j << " fracture " << e.fracture_j << " torn bending " << e.torn_bending_j << " grips "
          << run.grip_work_j;
    }
  }
}

// Below the tear limit nothing tears, so a release time changes nothing.
TEST(CellRelease, BelowTheLimitAReleaseTimeChangesNothing) {
  SheetParams params;
  params.tear_strain = 10.0;
  TearRunOptions options;
  options.duration_s = 1e-3;
  const TearRun snap = run_tear(notched_twisted_sheet(0.0), params, options);
  const TearRun fading = run_tear(notched_twisted_sheet(1e-5), params, options);
  EXPECT_EQ(snap.state.torn_count(), static_cast<int>(notched_twisted_sheet(0.0).notch_cells.size()));
  EXPECT_EQ(fading.state.torn_step, snap.state.torn_step);
  EXPECT_TRUE(fading.state.positions == snap.state.positions);
  EXPECT_EQ(fading.grip_work_j, snap.grip_work_j);
  EXPECT_EQ(fading.ledger.fracture_j, 0.0);
}

TEST(CellRelease, TheSpecNamesABadReleaseTimeAndTheImplicitIntegratorRefusesOne) {
  SheetSpec spec = free_sheet_spec(0.01, 4);
  for (const double bad : {-1e-6, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    spec.release_time_s = bad;
    try {
      spec.validate();
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("release_time_s"), std::string::npos) << e.what();
    }
  }
  const SheetModel model = stiff_three_by_three(1e-6);
  try {
    ImplicitIntegrator integrator(model, SheetParams{}, 1e-6);
    ADD_FAILURE() << "the implicit integrator took a release time";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("release_time_s"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace repose
