// Tearing: no tear below the limit, every cell over it at once, the weakest
// place first, symmetric and seed-deterministic, and the tear load under
// mesh refinement.
#include "models/tearing/tearing.h"

#include <gtest/gtest.h>

#include "models/tearing/explicit_integrator.h"
#include "models/tearing/sheet_forces.h"
#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

TEST(Tearing, NothingTearsBelowTheLimitAndEveryCellOverItTearsAtOnce) {
  const SheetModel model = uniform_sheet(free_sheet_spec(0.05, 9));
  SheetParams params;
  params.tear_strain = 0.02;
  SheetState below = affinely_stretched(model, 0.0199, -0.0066);
  EXPECT_EQ(tear_overstretched_cells(model, params, 1, &below), 0);
  SheetState above = affinely_stretched(model, 0.0201, -0.0067);
  EXPECT_EQ(tear_overstretched_cells(model, params, 1, &above), model.cell_count());
  for (int c = 0; c < model.cell_count(); ++c) EXPECT_EQ(above.torn_step[c], 1);
  // a torn cell exerts nothing, and its vertices stay
  Eigen::Matrix3Xd forces;
  internal_forces(model, params, above, &forces);
  EXPECT_EQ(forces.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(above.positions.cols(), model.vertex_count());
}

// The energy a tear takes out of the sheet is the elastic energy its cells'
// springs held: with no bending terms, the sheet's potential energy before
// the tear less that after it, to rounding; cells that did not tear add
// nothing, and the notch cut before the run is not counted.
TEST(Tearing, TheTornEnergyIsWhatTheTornCellsSpringsHeld) {
  SheetSpec spec = free_sheet_spec(0.05, 9);
  spec.bending_stiffness_n_m = 0.0;
  spec.notch_length_m = 0.012;
  const SheetModel model = uniform_sheet(spec);
  SheetParams params;
  params.tear_strain = 0.02;
  SheetState state = affinely_stretched(model, 0.005, -0.0017);
  EXPECT_EQ(state.torn_energy_j, 0.0);
  for (int i = 0; i < 4; ++i) state.positions(0, model.vertex(i + 1, 4)) += 0.01 * model.cell_size_m;  // cells (i..i+1, 3..4) over
  Eigen::Matrix3Xd forces;
  EXPECT_EQ(tear_and_internal_forces(model, params, 1, &state, &forces), 0) << "below the limit nothing tears";
  EXPECT_EQ(state.torn_energy_j, 0.0);
  for (int i = 0; i < 4; ++i) state.positions(0, model.vertex(i + 1, 4)) += 0.03 * model.cell_size_m;
  const double before = potential_energy(model, params, state);
  const int torn = tear_and_internal_forces(model, params, 2, &state, &forces);
  ASSERT_GT(torn, 0);
  ASSERT_LT(torn, model.cell_count() - static_cast<int>(model.notch_cells.size()));
  EXPECT_GT(state.torn_energy_j, 0.0);
  EXPECT_NEAR(state.torn_energy_j, before - potential_energy(model, params, state), 1e-12 * before);
}

// A pulled strip whose one soft cell is the first to go.
TEST(Tearing, TearStartsWhereTheStrainFirstExceedsTheLimit) {
  SheetSpec spec = free_sheet_spec(0.02, 10);
  spec.damping_per_s = 2e4;
  add_uniaxial_grips(&spec, 0.5);
  FibreImages images = uniform_fibre_images(0.02, 0.02, 0.0005, 0.8);
  const int soft_i = 6, soft_j = 3;  // cell (6, 3): pixels [24, 28) x [12, 16)
  images.composite.block(12, 24, 4, 4).setConstant(0.4);
  const SheetModel model = build_sheet_model(spec, images);
  SheetParams params;
  params.tear_strain = 0.01;
  ExplicitIntegrator integrator(model, params, integrator_limit_fraction(model, params, 0.9));
  SheetState state = make_sheet_state(model);
  double largest_strain_elsewhere = 0.0;
  int torn = 0;
  while (torn == 0 && state.time_s < 0.01) {
    for (int c = 0; c < model.cell_count(); ++c) {
      const int distance = std::abs(c % model.cells_x - soft_i) + std::abs(c / model.cells_x - soft_j);
      if (distance > 1) largest_strain_elsewhere = std::max(largest_strain_elsewhere, max_spring_strain(model, state, c));
    }
    torn = integrator.step(&state);
  }
  ASSERT_GT(torn, 0);
  EXPECT_GE(state.torn_step[model.cell(soft_i, soft_j)], 1);
  // the first tear is the soft cell and those sharing its stretched edges, nothing farther
  for (int c = 0; c < model.cell_count(); ++c) {
    if (state.intact(c)) continue;
    EXPECT_LE(std::abs(c % model.cells_x - soft_i) + std::abs(c / model.cells_x - soft_j), 1) << "cell " << c;
  }
  // cells beyond the soft one's neighbours never came near the limit
  EXPECT_LT(largest_strain_elsewhere, 0.9 * params.tear_strain);
}

// Mirror-symmetric sheet, notch and pull: the torn set stays mirror-symmetric.
TEST(Tearing, ASymmetricPullTearsSymmetricallyAndStraightAlongTheNotch) {
  SheetSpec spec = free_sheet_spec(0.022, 11);
  spec.damping_per_s = 1e4;
  spec.notch_length_m = 0.006;
  spec.notch_x_m = 0.011;
  spec.grips = {column_grip(0.0, 0.0, 0.022, -0.5, {true, true, true}),
                column_grip(0.022, 0.0, 0.022, 0.5, {true, true, true})};
  const SheetModel model = uniform_sheet(spec);
  SheetParams params;
  params.tear_strain = 0.01;
  ExplicitIntegrator integrator(model, params, integrator_limit_fraction(model, params, 0.9));
  SheetState state = make_sheet_state(model);
  while (state.time_s < 1e-3) integrator.step(&state);
  EXPECT_GT(state.torn_count(), static_cast<int>(model.notch_cells.size()));
  for (int j = 0; j < model.cells_y; ++j) {
    for (int i = 0; i < model.cells_x; ++i) {
      EXPECT_EQ(state.intact(model.cell(i, j)), state.intact(model.cell(model.cells_x - 1 - i, j))) << i << ", " << j;
      // straight down the notch's column: only column 5 tears
      if (i != 5) {
        EXPECT_TRUE(state.intact(model.cell(i, j))) << i << ", " << j;
      }
    }
  }
}

TEST(Tearing, TheSameSeedTearsTheSameBits) {
  SheetSpec spec = free_sheet_spec(0.03, 15);
  spec.damping_per_s = 2e3;
  spec.grips = seed_twist_grips(0.03, 0.03, 0.006, 0.004, 2.0);
  spec.notch_length_m = 0.004;
  spec.notch_x_m = 0.015;
  SheetParams params;
  const auto run = [&](std::uint64_t seed) {
    const SheetModel model = fibre_sheet(spec, seed);
    ExplicitIntegrator integrator(model, params, integrator_limit_fraction(model, params, 0.9));
    SheetState state = make_sheet_state(model);
    for (int s = 0; s < 1500; ++s) integrator.step(&state);
    return state;
  };
  const SheetState a = run(8), b = run(8);
  EXPECT_GT(a.torn_count(), 0);
  EXPECT_EQ(a.torn_step, b.torn_step);
  EXPECT_TRUE((a.positions.array() == b.positions.array()).all());
}

}  // namespace
}  // namespace repose

namespace repose {
namespace {

using namespace repose::testing;

// Peak force of a strip of fibre sheet pulled apart along x.
double tear_load(int cells, std::uint64_t seed) {
  SheetSpec spec = free_sheet_spec(0.016, cells);
  spec.damping_per_s = 2e4;
  spec.fibres.pixel_size_m = 0.25e-3;
  add_uniaxial_grips(&spec, 1.0);
  const SheetModel model = fibre_sheet(spec, seed);
  SheetParams params;
  params.tear_strain = 0.01;
  ExplicitIntegrator integrator(model, params, integrator_limit_fraction(model, params, 0.9));
  SheetState state = make_sheet_state(model);
  double peak = 0.0;
  while (state.time_s < 0.016 * 0.03 / 1.0) {
    integrator.step(&state);
    peak = std::max(peak, state.grip_force_n(0, 2));
  }
  return peak;
}

// The seed's rule (one strain limit per spring) on a fibre image: the first
// cell goes where the image is softest, and a finer mesh resolves softer
// spots, so the load falls as the mesh is refined. Measured (seeds 1, 2):
// 50.7, 48.0, 47.5 N and 53.1, 51.2, 49.9 N at 8, 16, 32 cells: changes of
// 5.4 %, 1.0 % and 3.6 %, 2.6 %. The bound is loose on purpose: the change
// from 16 to 32 cells is under 4 % and not larger than from 8 to 16, and no
// load exceeds the uniform sheet's E t W tear_strain (64 N; the mean
// stiffness is E t, and a heterogeneous sheet is softer and strains
// unevenly).
TEST(Tearing, TearLoadConvergesLooselyUnderMeshRefinement) {
  for (const std::uint64_t seed : {1u, 2u}) {
    const double f8 = tear_load(8, seed), f16 = tear_load(16, seed), f32 = tear_load(32, seed);
    EXPECT_LT(std::abs(f32 - f16), 0.04 * f32) << "seed " << seed << ": " << f8 << ", " << f16 << ", " << f32 << " N";
    EXPECT_LE(std::abs(f32 - f16), std::abs(f16 - f8)) << "seed " << seed;
    for (const double f : {f8, f16, f32}) EXPECT_LT(f, 4e5 * 0.016 * 0.01) << "seed " << seed;
    EXPECT_GT(f32, 0.5 * 4e5 * 0.016 * 0.01) << "seed " << seed;
  }
}

}  // namespace
}  // namespace repose
