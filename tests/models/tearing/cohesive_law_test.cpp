// The cohesive softening law (SheetSpec::tear_rule cohesive): the force of
// one spring against its strain (linear to the peak, a linear fall to zero,
// never negative, secant unloading); the energy it dissipates is the law's
// area; the law's opening is a material length and its area per unit tear
// length the tear energy on every mesh fine enough for it; in a sheet it
// changes nothing below the peak, is the energy rule's snap to the bit on a
// mesh too coarse for it, and the energy ledger closes through a tear.
#include "models/tearing/cohesive_law.h"

#include <cmath>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/tearing/implicit_integrator.h"
#include "models/tearing/sheet_forces.h"
#include "models/tearing/tear_limit.h"
#include "models/tearing/tear_run.h"
#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

constexpr double kK = 3.0e5, kL = 1.0e-3;  // a spring: N/m, m
const CohesiveLaw kLaw{0.02, 0.06};

TEST(CohesiveLaw, BelowThePeakTheSpringIsLinearAndUnchanged) {
  for (const double e : {-0.05, -0.01, 0.0, 0.01, 0.02}) {
    EXPECT_EQ(kLaw.force_n(kK, kL, e, 0.0), kK * kL * e) << e;
    EXPECT_EQ(kLaw.secant_factor(e, e), 1.0) << e;
  }
  double reached = 0.0;
  EXPECT_EQ(kLaw.soften(kK, kL, 0.02, &reached), 0.0);
  EXPECT_EQ(reached, 0.0);
}

TEST(CohesiveLaw, PastThePeakTheForceFallsLinearlyToZeroAndNeverBelow) {
  const double peak = kK * kL * 0.02;
  EXPECT_NEAR(kLaw.force_n(kK, kL, 0.02, 0.02), peak, 1e-12 * peak);
  EXPECT_NEAR(kLaw.force_n(kK, kL, 0.03, 0.0), 0.75 * peak, 1e-12 * peak);
  EXPECT_NEAR(kLaw.force_n(kK, kL, 0.04, 0.0), 0.5 * peak, 1e-12 * peak);
  EXPECT_NEAR(kLaw.force_n(kK, kL, 0.05, 0.0), 0.25 * peak, 1e-12 * peak);
  EXPECT_EQ(kLaw.force_n(kK, kL, 0.06, 0.0), 0.0);
  for (int i = 0; i <= 2000; ++i) {  // never negative, however far it is pulled
    const double e = 1e-4 * i;
    EXPECT_GE(kLaw.force_n(kK, kL, e, 0.0), 0.0) << e;
    EXPECT_LE(kLaw.force_n(kK, kL, e, 0.0), peak * (1 + 1e-12)) << e;
  }
}

TEST(CohesiveLaw, ADamagedSpringUnloadsAlongItsSecantAndPushesUndamaged) {
  const double at_reached = kLaw.force_n(kK, kL, 0.04, 0.04);  // half the peak
  EXPECT_NEAR(kLaw.force_n(kK, kL, 0.02, 0.04), 0.5 * at_reached, 1e-12 * at_reached);
  EXPECT_NEAR(kLaw.force_n(kK, kL, 0.01, 0.04), 0.25 * at_reached, 1e-12 * at_reached);
  EXPECT_EQ(kLaw.force_n(kK, kL, -0.01, 0.04), -kK * kL * 0.01);  // compression: undamaged
  EXPECT_EQ(kLaw.force_n(kK, kL, 0.05, 0.06), 0.0);                 // fully open: nothing
}

// Pulled quasi-statically through the law (and let back once on the way),
// the work done on the spring is at every point what it stores plus what it
// dissipated, and at the end the law's area 1/2 k L^2 e_p e_f, all of it
// dissipated.
TEST(CohesiveLaw, OneSpringPulledThroughTheLawDissipatesTheLawsArea) {
  std::vector<double> path;
  for (int i = 0; i <= 4000; ++i) path.push_back(1e-5 * i);        // 0 .. 0.04
  for (int i = 1; i <= 3000; ++i) path.push_back(0.04 - 1e-5 * i);  // back to 0.01
  for (int i = 1; i <= 6000; ++i) path.push_back(0.01 + 1e-5 * i);  // on to 0.07
  double reached = 0.0, dissipated = 0.0, work = 0.0;
  double force = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double e = path[i];
    dissipated += kLaw.soften(kK, kL, e, &reached);
    const double next = kLaw.force_n(kK, kL, e, reached);
    work += 0.5 * (force + next) * (e - path[i - 1]) * kL;
    force = next;
    const double stored = 0.5 * kLaw.secant_factor(e, reached) * kK * kL * kL * e * e;
    ASSERT_NEAR(work, stored + dissipated, 1e-6 * kLaw.area_j(kK, kL)) << "at strain " << e;
  }
  EXPECT_NEAR(kLaw.area_j(kK, kL), 0.5 * kK * kL * kL * 0.02 * 0.06, 1e-20);
  EXPECT_EQ(reached, 0.06);
  EXPECT_NEAR(dissipated, kLaw.area_j(kK, kL), 1e-12 * kLaw.area_j(kK, kL));
  EXPECT_NEAR(work, kLaw.area_j(kK, kL), 1e-6 * kLaw.area_j(kK, kL));
}

// The crack band: on every mesh fine enough, the peak is tear_strain, an
// edge spring reaches zero force at the same stretch 2 Gamma / (E t e_p)
// (40 um here), and a cell strained through the law gives up Gamma per
// unit tear length; on coarser meshes the law is the energy rule's snap.
TEST(CohesiveLaw, TheOpeningIsAMaterialLengthAndTheAreaPerTearLengthTheTearEnergy) {
  SheetParams params;  // E t 4e5 N/m, 0.02, 0.16 J/m
  SheetSpec spec = free_sheet_spec(0.1, 100);
  spec.tear_rule = TearRule::kCohesive;
  for (const int cells : {100, 200, 400}) {
    spec.cells_x = cells;
    const SheetModel model = uniform_sheet(spec);
    const CohesiveLaw law = cohesive_law(model, params);
    const double h = model.cell_size_m;
    EXPECT_EQ(law.peak_strain, params.tear_strain) << cells;
    EXPECT_NEAR(law.zero_strain * h, 4.0e-5, 1e-15) << cells;
    EXPECT_NEAR(0.5 * params.stiffness_n_per_m * law.peak_strain * law.zero_strain * h, params.tear_energy_j_per_m,
                1e-12)
        << cells;
    EXPECT_EQ(base_tear_strain(model, params), law.zero_strain);
  }
  params.tear_strain = 0.03;  // above the energy rule's 0.0283 at 100 cells and 0.02 at 50
  for (const int cells : {25, 50, 100}) {
    spec.cells_x = cells;
    const SheetModel model = uniform_sheet(spec);
    const CohesiveLaw law = cohesive_law(model, params);
    const double energy_rule = energy_rule_tear_strain(params.stiffness_n_per_m, params.tear_energy_j_per_m, model.cell_size_m);
    EXPECT_EQ(law.peak_strain, energy_rule) << cells;
    EXPECT_EQ(law.zero_strain, energy_rule) << cells;
  }
}

SheetModel sheet_with_rule(SheetSpec spec, TearRule rule) {
  spec.tear_rule = rule;
  return uniform_sheet(spec);
}

TEST(CohesiveLaw, BelowThePeakASheetsForcesAndEnergyAreTheOtherRulesToTheBit) {
  const SheetSpec spec = free_sheet_spec(0.01, 10);  // 1 mm cells: peak 0.02, zero force at 0.04
  const SheetModel cohesive = sheet_with_rule(spec, TearRule::kCohesive);
  const SheetModel strain = sheet_with_rule(spec, TearRule::kStrain);
  const SheetParams params;
  SheetState a = affinely_stretched(cohesive, 0.015, -0.004), b = affinely_stretched(strain, 0.015, -0.004);
  for (int v = 0; v < a.positions.cols(); ++v) {  // and bent, so that every spring has its own strain
    a.positions(2, v) = b.positions(2, v) = 0.5 * a.positions(0, v) * a.positions(0, v);
  }
  Eigen::Matrix3Xd fa, fb;
  EXPECT_EQ(tear_and_internal_forces(cohesive, params, 1, &a, &fa), 0);
  EXPECT_EQ(tear_and_internal_forces(strain, params, 1, &b, &fb), 0);
  EXPECT_TRUE(fa == fb);
  EXPECT_EQ(elastic_energy(cohesive, params, a).total_j(), elastic_energy(strain, params, b).total_j());
  EXPECT_EQ(a.torn_energy_j, 0.0);
  for (const double m : a.softening) EXPECT_EQ(m, 0.0);
  EXPECT_TRUE(b.softening.empty()) << "the other rules keep no softening state";
}

// One 1 mm cell stretched along x by its right edge (its left edge held),
// quasi-statically: its x edges soften past 2 % and it tears at 4 %; the
// work done on it is at every step what it stores (its springs' secant
// energy) plus what it dissipated, and once torn all booked as fracture.
TEST(CohesiveLaw, ACellPulledApartBooksTheWorkDoneOnItAsFracture) {
  const SheetModel model = sheet_with_rule(free_sheet_spec(0.001, 1), TearRule::kCohesive);
  const SheetParams params;
  SheetState state = make_sheet_state(model);
  const std::array<int, 4> corners = model.corners(0);  // 00, 10, 11, 01
  const double h = model.cell_size_m;
  Eigen::Matrix3Xd forces;
  double work = 0.0, pulled_with = 0.0;
  int step = 1, torn = 0;
  for (; torn == 0 && step < 100000; ++step) {
    const double u = 1e-6 * step * h;
    state.positions(0, corners[1]) = state.positions(0, corners[2]) = h + u;
    torn = tear_and_internal_forces(model, params, step, &state, &forces);
    const double pull = -(forces(0, corners[1]) + forces(0, corners[2]));  // what holds the edge there
    work += 0.5 * (pulled_with + pull) * 1e-6 * h;
    pulled_with = pull;
    if (torn == 0) {
      ASSERT_NEAR(elastic_energy(model, params, state).total_j() + state.torn_energy_j, work, 1e-4 * work + 1e-18)
          << "at stretch " << u / h;
    }
  }
  ASSERT_EQ(torn, 1);
  const double u_torn = 1e-6 * (step - 1) * h;
  EXPECT_NEAR(u_torn, 0.04 * h, 2e-6 * h) << "the x edges reach zero force at 4 %";
  EXPECT_GT(state.softening_energy_j, 0.3 * state.torn_energy_j);
  EXPECT_NEAR(state.torn_energy_j, work, 1e-4 * work);
  EXPECT_EQ(elastic_energy(model, params, state).total_j(), 0.0);
}

// The sum over every step of -f . dx: the work done on the sheet's vertices
// against its internal forces (the trapezoid rule over each step).
double work_done_j(const Eigen::Matrix3Xd& f0, const Eigen::Matrix3Xd& f1, const Eigen::Matrix3Xd& x0,
                   const Eigen::Matrix3Xd& x1) {
  return -0.5 * ((f0 + f1).array() * (x1 - x0).array()).sum();
}

// The crack band's energy balance: a sheet of n x n cells (4 mm a side;
// 1, 0.5, 0.25 mm cells, all fine enough for the band) pulled along x in
// uniaxial stress (x stretched by e, y by -e/3: the lattice's Poisson
// ratio) until its cells tear. Every cell is a band: it dissipates
// 1/2 E t h^2 e_p e_f, so the fracture energy per unit band length (n^2
// cells of h each) is the tear energy on every mesh, all of it dissipated
// along the law (softening) and nothing released when the cells go; the
// work done on the sheet is at every step what it stores plus that. (A
// small peak, 0.05 %, and a 1 um opening keep the strains small, e_f 0.1 to
// 0.4 %, where the lattice is linear: its finite-strain terms add about
// e_f / 5 to the energy, 2 % at e_f 16 %.)
TEST(CohesiveLaw, ABandPulledApartDissipatesTheTearEnergyPerLengthOnEveryMesh) {
  SheetParams params;  // E t 4e5 N/m
  params.tear_strain = 0.0005;
  params.tear_energy_j_per_m = 1e-4;  // zero force at a 1 um stretch
  for (const int n : {4, 8, 16}) {
    const SheetModel model = sheet_with_rule(free_sheet_spec(0.004, n), TearRule::kCohesive);
    const double h = model.cell_size_m, e_f = cohesive_law(model, params).zero_strain;
    ASSERT_NEAR(e_f * h, 1e-6, 1e-15) << n;
    SheetState state = make_sheet_state(model);
    const Eigen::Matrix3Xd rest = state.positions;
    Eigen::Matrix3Xd forces, before_forces = Eigen::Matrix3Xd::Zero(3, rest.cols()), before_x = rest;
    double work = 0.0;
    for (int step = 1; state.torn_count() < n * n && step < 10000; ++step) {
      const double e = 5e-4 * e_f * step;
      state.positions = rest;
      state.positions.row(0) *= 1.0 + e;
      state.positions.row(1) *= 1.0 - e / 3.0;
      tear_and_internal_forces(model, params, step, &state, &forces);
      work += work_done_j(before_forces, forces, before_x, state.positions);
      before_forces = forces;
      before_x = state.positions;
      ASSERT_NEAR(elastic_energy(model, params, state).total_j() + state.torn_energy_j, work, 2e-3 * work + 1e-18)
          << n << " cells at strain " << e;
    }
    ASSERT_EQ(state.torn_count(), n * n);
    const double per_length = state.torn_energy_j / (n * n * h);
    EXPECT_NEAR(per_length, params.tear_energy_j_per_m, 2e-3 * params.tear_energy_j_per_m) << n << " cells";
    EXPECT_NEAR(state.softening_energy_j, state.torn_energy_j, 1e-9 * state.torn_energy_j)
        << "the cells must hold nothing when they go";
  }
}

// The uniform 21-cell sheet notched in its middle column under the seed's
// twist (as tear_run_test.cpp's), undamped, with a tear energy for which
// its 2 mm cells are fine enough for the band (e_c 0.028 > 0.02).
SheetModel notched_twisted_sheet(TearRule rule) {
  SheetSpec spec = free_sheet_spec(0.042, 21);
  spec.grips = seed_twist_grips(0.042, 0.042, 0.006, 0.006, 4.0);
  spec.notch_length_m = 0.004;
  spec.notch_x_m = 0.021;
  spec.tear_rule = rule;
  return uniform_sheet(spec);
}

TearRunOptions stop_at_24_mm() {
  TearRunOptions options;
  options.duration_s = 0.02;
  options.stop_at_depth_m = 0.024;
  return options;
}

// Through a softening tear the ledger books everything the grips did (the
// cells' softening as fracture energy, the bending terms the snapped cells
// take out as torn bending) but the explicit step's own error, which on
// the springs' falling branch is first order in the step: halving the step
// halves the residual (session 18: -3.4, -1.1, -0.55, -0.28 % of the
// grips' work at 0.9, 0.45, 0.225, 0.1125 of the stable step), and at a
// quarter of the stable step it is under 1 %.
TEST(CohesiveLaw, TheEnergyLedgerClosesThroughASofteningTear) {
  SheetParams params;
  params.tear_energy_j_per_m = 0.32;
  const SheetModel model = notched_twisted_sheet(TearRule::kCohesive);
  ASSERT_LT(cohesive_law(model, params).peak_strain, cohesive_law(model, params).zero_strain);
  TearRunOptions options = stop_at_24_mm();
  options.time_step_fraction = 0.225;
  const TearRun run = run_tear(model, params, options);
  const EnergyLedger& e = run.ledger;
  ASSERT_GT(run.tear_length_m, 0.01);
  EXPECT_NEAR(e.softening_j, e.fracture_j, 1e-9 * e.fracture_j) << "a softened cell holds nothing when it goes";
  EXPECT_GT(e.torn_bending_j, 0.0);
  EXPECT_LT(std::abs(e.residual_j), 0.01 * run.grip_work_j)
      << "stored " << e.stored_j << " kinetic " << e.kinetic_j << " fracture " << e.fracture_j << " torn bending "
      << e.torn_bending_j << " grips " << run.grip_work_j;
  options.time_step_fraction = 0.1125;
  const TearRun finer = run_tear(model, params, options);
  EXPECT_LT(std::abs(finer.ledger.residual_j / finer.grip_work_j), 0.6 * std::abs(e.residual_j / run.grip_work_j))
      << "the ledger's residual must be the step's error, shrinking with the step";
}

// On a mesh too coarse for the band (tear_strain above the energy rule's
// strain) the cohesive rule is the energy rule, to the bit.
TEST(CohesiveLaw, OnAMeshTooCoarseForTheBandItIsTheEnergyRuleToTheBit) {
  SheetParams params;
  params.tear_strain = 0.05;
  const TearRun energy = run_tear(notched_twisted_sheet(TearRule::kEnergy), params, stop_at_24_mm());
  const TearRun cohesive = run_tear(notched_twisted_sheet(TearRule::kCohesive), params, stop_at_24_mm());
  ASSERT_GT(energy.tear_length_m, 0.01);
  EXPECT_EQ(cohesive.state.torn_step, energy.state.torn_step);
  EXPECT_TRUE(cohesive.state.positions == energy.state.positions);
  EXPECT_EQ(cohesive.grip_work_j, energy.grip_work_j);
  EXPECT_EQ(cohesive.ledger.fracture_j, energy.ledger.fracture_j);
  EXPECT_EQ(cohesive.ledger.softening_j, 0.0);
}

TEST(CohesiveLaw, AReleaseTimeAndTheImplicitIntegratorAreRefusedByName) {
  SheetSpec spec = free_sheet_spec(0.01, 4);
  spec.tear_rule = TearRule::kCohesive;
  spec.release_time_s = 1e-6;
  try {
    spec.validate();
    ADD_FAILURE() << "accepted a release time with the cohesive rule";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("release_time_s"), std::string::npos) << e.what();
  }
  spec.release_time_s = 0.0;
  const SheetModel model = uniform_sheet(spec);
  try {
    ImplicitIntegrator integrator(model, SheetParams{}, 1e-6);
    ADD_FAILURE() << "the implicit integrator took the cohesive rule";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tear_rule"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace repose
