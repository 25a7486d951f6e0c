// The tear limit of one spring under fibre anisotropy: by default one strain
// per cell (the seed's rule); with isotropic_tear_energy each spring's limit
// is scaled so that it tears holding the same energy whatever its direction.
// The elastic energy's parts against the plate's (stretch, roll, twist), and
// the forces against its gradient.
#include "models/tearing/sheet_forces.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

// Whether every cell of a uniform 4 x 4 sheet (grain along x) is
// overstretched under a uniaxial strain along x or y.
bool tears(bool isotropic, double strain_x, double strain_y) {
  SheetSpec spec = free_sheet_spec(0.004, 4);
  spec.isotropic_tear_energy = isotropic;
  const SheetModel model = uniform_sheet(spec);
  SheetParams params;
  params.tear_strain = 0.02;
  params.fibre_anisotropy = 0.5;
  const SheetState state = affinely_stretched(model, strain_x, strain_y);
  int over = 0;
  for (int c = 0; c < model.cell_count(); ++c) over += cell_overstretched(model, params, state, c);
  EXPECT_TRUE(over == 0 || over == model.cell_count()) << over;
  return over > 0;
}

TEST(SheetForces, OneTearStrainPerCellByDefault) {
  EXPECT_FALSE(tears(false, 0.0199, 0.0));
  EXPECT_TRUE(tears(false, 0.0201, 0.0));
  EXPECT_FALSE(tears(false, 0.0, 0.0199));
  EXPECT_TRUE(tears(false, 0.0, 0.0201));
}

// Along the grain the springs are 1.5 times stiffer, across it 0.5 times:
// their limits become 0.02 / sqrt(1.5) and 0.02 / sqrt(0.5), where each
// holds 1/2 k 0.02^2 (the diagonals, direction factor 1, keep 0.02 and are
// stretched less under a uniaxial strain).
TEST(SheetForces, WithIsotropicTearEnergyEachSpringTearsAtTheSameEnergy) {
  const double along = 0.02 / std::sqrt(1.5), across = 0.02 / std::sqrt(0.5);
  EXPECT_FALSE(tears(true, 0.999 * along, 0.0));
  EXPECT_TRUE(tears(true, 1.001 * along, 0.0));
  EXPECT_FALSE(tears(true, 0.0, 0.999 * across));
  EXPECT_TRUE(tears(true, 0.0, 1.001 * across));
}

// Stretched affinely along x, a uniform sheet stores energy in its edges
// along x (structural) and its diagonals (shear) as the springs' constants
// say, none in bending (the second difference of an affine map is 0), and
// the parts sum to the potential energy.
TEST(SheetForces, TheElasticEnergySplitsAnAffineStretchIntoStructuralAndShear) {
  const SheetModel model = uniform_sheet(free_sheet_spec(0.008, 8));
  const SheetParams params;
  const double strain = 0.01, h = model.cell_size_m, cells = model.cell_count();
  const ElasticEnergy e = elastic_energy(model, params, affinely_stretched(model, strain, 0.0));
  const double k_edge = 0.75 * params.stiffness_n_per_m, k_diagonal = 0.375 * params.stiffness_n_per_m;
  // per cell: two half edges along x stretched by strain h, two diagonals
  const double diagonal_stretch = h * std::sqrt((1.0 + strain) * (1.0 + strain) + 1.0) - h * std::numbers::sqrt2;
  EXPECT_NEAR(e.structural_j, cells * 0.5 * k_edge * strain * strain * h * h, 1e-12 * e.structural_j);
  EXPECT_NEAR(e.shear_j, cells * k_diagonal * diagonal_stretch * diagonal_stretch, 1e-9 * e.shear_j);
  EXPECT_LT(std::abs(e.bending_j), 1e-12 * e.total_j());
  EXPECT_NEAR(e.total_j(), potential_energy(model, params, affinely_stretched(model, strain, 0.0)),
              1e-14 * e.total_j());
}

// The bending energy of a sheet rolled to curvature 1 / R (lengths along
// the roll kept) is the plate's 1/2 D kappa^2 A whatever the mesh: the
// bending terms' constant D / h^2 scales with the cell size so that D does
// not (a constant fixed per term would quadruple the energy from 20 to 40
// cells a side).
TEST(SheetForces, ARolledSheetStoresThePlatesBendingEnergyAtAnyMesh) {
  const double width = 0.1, radius = 0.1;
  std::vector<double> bending;
  for (const int cells : {20, 40}) {
    const SheetModel model = uniform_sheet(free_sheet_spec(width, cells));
    SheetState state = make_sheet_state(model);
    for (int v = 0; v < model.vertex_count(); ++v) {
      const double x = model.rest_positions(0, v);
      state.positions(0, v) = radius * std::sin(x / radius);
      state.positions(2, v) = radius * (1.0 - std::cos(x / radius));
    }
    const double plate = 0.5 * model.spec.bending_stiffness_n_m * width * width / (radius * radius);
    bending.push_back(elastic_energy(model, SheetParams{}, state).bending_j);
    EXPECT_NEAR(bending.back(), plate, 0.01 * plate) << cells << " cells";
  }
  EXPECT_NEAR(bending[1], bending[0], 0.005 * bending[0]);
}

// The sheet displaced out of its plane by w(x, y) (z only).
template <class W>
SheetState displaced(const SheetModel& model, W&& w) {
  SheetState state = make_sheet_state(model);
  for (int v = 0; v < model.vertex_count(); ++v) state.positions(2, v) = w(model.rest_positions(0, v), model.rest_positions(1, v));
  return state;
}

// A twist w = kappa x y is linear along every mesh line: the bending terms
// see nothing. With SheetSpec::twist_stiffness the cells' twist terms hold
// the plate's (Poisson's ratio 0) D/2 2 w_xy^2 A = D kappa^2 A at any mesh;
// without them the twist is a zero-energy mode of the sheet's bending.
TEST(SheetForces, ATwistedSheetStoresThePlatesTwistEnergyOnlyWithTheTwistTerms) {
  const double width = 0.1, kappa = 2.0;
  for (const int cells : {20, 40}) {
    SheetSpec spec = free_sheet_spec(width, cells);
    spec.twist_stiffness = true;
    const SheetModel model = uniform_sheet(spec);
    const SheetState state = displaced(model, [&](double x, double y) { return kappa * x * y; });
    const ElasticEnergy with = elastic_energy(model, SheetParams{}, state);
    const double plate = spec.bending_stiffness_n_m * kappa * kappa * width * width;
    EXPECT_NEAR(with.twist_j, plate, 0.01 * plate) << cells << " cells";
    EXPECT_LT(std::abs(with.bending_j), 1e-9 * plate) << cells << " cells";
    spec.twist_stiffness = false;
    const ElasticEnergy without = elastic_energy(uniform_sheet(spec), SheetParams{}, state);
    EXPECT_EQ(without.twist_j, 0.0);
    EXPECT_LT(std::abs(without.bending_j), 1e-9 * plate) << cells << " cells";
  }
}

// A roll about a diagonal, w = kappa/2 ((x + y) / sqrt 2)^2: an isotropic
// plate stores 1/2 D kappa^2 A as for a roll about a mesh line. The
// bending terms alone hold half of it (w_xx = w_yy = kappa / 2); the twist
// terms the other half (w_xy = kappa / 2): the sheet is isotropic only
// with them.
TEST(SheetForces, ARollAboutADiagonalCostsThePlatesEnergyOnlyWithTheTwistTerms) {
  const double width = 0.1, kappa = 2.0;
  const double plate = 0.5 * 3e-4 * kappa * kappa * width * width;
  for (const int cells : {20, 40}) {
    for (const bool twist : {false, true}) {
      SheetSpec spec = free_sheet_spec(width, cells);
      spec.twist_stiffness = twist;
      const SheetModel model = uniform_sheet(spec);
      const SheetState state = displaced(model, [&](double x, double y) { return 0.25 * kappa * (x + y) * (x + y); });
      const ElasticEnergy e = elastic_energy(model, SheetParams{}, state);
      EXPECT_NEAR(e.bending_j, 0.5 * plate, 0.01 * plate) << cells << " cells";
      EXPECT_NEAR(e.bending_j + e.twist_j, twist ? plate : 0.5 * plate, 0.01 * plate) << cells << " cells";
    }
  }
}

// Any affine map of the sheet (a rotation, shear and stretch in 3-D plus a
// shift) leaves every cell a parallelogram: no twist energy.
TEST(SheetForces, AnAffineMapStoresNoTwistEnergy) {
  SheetSpec spec = free_sheet_spec(0.02, 6);
  spec.twist_stiffness = true;
  const SheetModel model = fibre_sheet(spec, 3);
  Eigen::Matrix3d map;
  map << 0.9, 0.3, -0.2, -0.4, 1.1, 0.5, 0.6, -0.7, 0.8;
  SheetState state = make_sheet_state(model);
  state.positions = (map * model.rest_positions).colwise() + Eigen::Vector3d(0.01, -0.02, 0.03);
  const ElasticEnergy e = elastic_energy(model, SheetParams{}, state);
  EXPECT_GT(e.structural_j, 0.0);
  EXPECT_LT(e.twist_j, 1e-20 * e.structural_j);
  EXPECT_LT(e.bending_j, 1e-20 * e.structural_j);
}

// The seed's snap takes out the bending terms no intact cell holds any more
// (a term across the torn column), and books what they held: on a rolled
// 3 x 3 sheet whose middle column alone is stretched past its limit, the
// energy before the tear is the energy after it plus the springs' fracture
// energy plus the dropped bending terms', and a later step books nothing
// again.
TEST(SheetForces, ASnappedColumnBooksTheBendingTermsItTakesOut) {
  SheetSpec spec = free_sheet_spec(0.006, 3);
  spec.bending_stiffness_n_m = 3e-2;  // so that bending weighs against the springs
  const SheetModel model = uniform_sheet(spec);
  SheetParams params;
  params.tear_strain = 0.01;
  const double h = model.cell_size_m;
  SheetState state = displaced(model, [](double x, double y) { return 4.0 * x * x + 3.0 * x * y; });
  for (int v = 0; v < model.vertex_count(); ++v) {  // the middle column stretched 3 % along x
    state.positions(0, v) += 0.03 * std::clamp(model.rest_positions(0, v) - h, 0.0, h);
  }
  const ElasticEnergy before = elastic_energy(model, params, state);
  Eigen::Matrix3Xd forces;
  ASSERT_EQ(tear_and_internal_forces(model, params, 1, &state, &forces), 3);
  const ElasticEnergy after = elastic_energy(model, params, state);
  EXPECT_GT(after.bending_j, 0.0) << "the flaps still bend";
  EXPECT_GT(state.torn_bending_energy_j, 0.05 * before.bending_j);
  EXPECT_NEAR(before.total_j(), after.total_j() + state.torn_energy_j + state.torn_bending_energy_j,
              1e-12 * before.total_j());
  const double booked = state.torn_bending_energy_j;
  EXPECT_EQ(tear_and_internal_forces(model, params, 2, &state, &forces), 0);
  EXPECT_EQ(state.torn_bending_energy_j, booked);
}

// A twisted cell torn apart takes its twist term with it: the energy it
// held goes to SheetState::torn_twist_energy_j, none stays stored, and the
// springs' energy alone is the fracture energy.
TEST(SheetForces, ATornCellsTwistEnergyIsKeptApartFromTheFractureEnergy) {
  SheetSpec spec = free_sheet_spec(0.004, 1);
  spec.twist_stiffness = true;
  const SheetModel model = uniform_sheet(spec);
  SheetParams params;
  params.tear_strain = 0.01;
  SheetState state = displaced(model, [](double x, double y) { return 50.0 * x * y; });
  state.positions.row(0) *= 1.02;  // past the tear strain
  const ElasticEnergy before = elastic_energy(model, params, state);
  ASSERT_GT(before.twist_j, 0.0);
  Eigen::Matrix3Xd forces;
  ASSERT_EQ(tear_and_internal_forces(model, params, 1, &state, &forces), 1);
  EXPECT_NEAR(state.torn_twist_energy_j, before.twist_j, 1e-12 * before.twist_j);
  EXPECT_NEAR(state.torn_energy_j, before.structural_j + before.shear_j, 1e-12 * state.torn_energy_j);
  EXPECT_EQ(elastic_energy(model, params, state).total_j(), 0.0);
  EXPECT_EQ(forces.cwiseAbs().maxCoeff(), 0.0);
}

// The forces are minus the gradient of the elastic energy (springs, bending
// and twist terms of a fibre sheet with a torn cell), by central
// differences at a random state.
TEST(SheetForces, TheForcesAreMinusTheEnergysGradientWithTheTwistTerms) {
  SheetSpec spec = free_sheet_spec(0.012, 4);
  spec.twist_stiffness = true;
  spec.bending_stiffness_n_m = 3e-2;  // so that bending and twist weigh against the springs
  const SheetModel model = fibre_sheet(spec, 5);
  const SheetParams params;
  SheetState state = make_sheet_state(model);
  state.torn_step[5] = 0;
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> jitter(-3e-4, 3e-4);
  for (int v = 0; v < model.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) state.positions(a, v) += jitter(rng);
  }
  Eigen::Matrix3Xd forces;
  internal_forces(model, params, state, &forces);
  const ElasticEnergy e = elastic_energy(model, params, state);
  ASSERT_GT(e.twist_j, 0.01 * e.total_j());
  const double delta = 1e-8;
  for (int v = 0; v < model.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) {
      SheetState moved = state;
      moved.positions(a, v) += delta;
      const double plus = potential_energy(model, params, moved);
      moved.positions(a, v) -= 2 * delta;
      const double minus = potential_energy(model, params, moved);
      EXPECT_NEAR(forces(a, v), -(plus - minus) / (2 * delta), 1e-6 * forces.cwiseAbs().maxCoeff())
          << "vertex " << v << " axis " << a;
    }
  }
  // the twist terms' own share: their forces alone against their energy alone
  SheetSpec plain_spec = spec;
  plain_spec.twist_stiffness = false;
  Eigen::Matrix3Xd plain;
  internal_forces(fibre_sheet(plain_spec, 5), params, state, &plain);
  EXPECT_GT((forces - plain).cwiseAbs().maxCoeff(), 0.01 * forces.cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace repose
