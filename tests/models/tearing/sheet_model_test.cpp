// The sheet's description: mass, fibre weights, grips, notch, and the
// analytic stiffness of its spring lattice (sheet_model.h).
#include "models/tearing/sheet_model.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/tearing/explicit_integrator.h"
#include "models/tearing/sheet_forces.h"
#include "models/tearing/stable_time_step.h"
#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

TEST(SheetModel, MassIsGrammageTimesAreaAndWeightsAverageOne) {
  SheetSpec spec = free_sheet_spec(0.04, 16);
  spec.grammage_kg_per_m2 = 0.12;
  const SheetModel model = fibre_sheet(spec, 4);
  EXPECT_EQ(model.vertex_count(), 17 * 17);
  EXPECT_NEAR(model.mass_kg.sum(), 0.12 * 0.04 * 0.04, 1e-15);
  EXPECT_NEAR(model.cell_weight.mean(), 1.0, 1e-12);
  // the fibres make the cells differ
  EXPECT_GT(model.cell_weight.maxCoeff() / model.cell_weight.minCoeff(), 1.2);
}

TEST(SheetModel, GripsHoldTheirVerticesAndTheNotchCutsFromTheTop) {
  SheetSpec spec = free_sheet_spec(0.05, 10);
  spec.grips = seed_twist_grips(0.05, 0.05, 0.01, 0.01, 1.0);
  spec.notch_length_m = 0.012;
  spec.notch_x_m = 0.025;
  const SheetModel model = uniform_sheet(spec);
  int left = 0, right = 0;
  for (int v = 0; v < model.vertex_count(); ++v) {
    left += model.grip_of_vertex[v] == 0;
    right += model.grip_of_vertex[v] == 1;
  }
  EXPECT_EQ(left, 5 * 3);  // x in [0, 0.02], y in [0.04, 0.05]
  EXPECT_EQ(right, 5 * 3);
  // 0.012 m is 2.4 cells: three cells of column 5 from the top
  EXPECT_EQ(model.notch_cells, (std::vector<int>{model.cell(5, 9), model.cell(5, 8), model.cell(5, 7)}));
}

TEST(SheetModel, RefusesCellsThatAreNotSquareAndGripsThatHoldNothing) {
  SheetSpec spec = free_sheet_spec(0.05, 10);
  spec.height_m = 0.052;
  EXPECT_THROW(uniform_sheet(spec), InputError);
  spec = free_sheet_spec(0.05, 10);
  spec.grips = {column_grip(0.0021, 0.0, 0.05, 0.0, {true, true, true})};
  try {
    uniform_sheet(spec);
    FAIL() << "a grip holding no vertex was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("grips[0]"), std::string::npos) << e.what();
  }
}

// Uniform strain (e, -e/3) is an exact equilibrium of the free-edged sheet,
// and the load on the pulled edge is E t x width x e: E_2D = E t, nu = 1/3.
TEST(SheetModel, UniaxialStrainIsAnEquilibriumWithTheAnalyticStiffness) {
  for (const int cells : {1, 2, 7, 20}) {
    const SheetModel model = uniform_sheet(free_sheet_spec(0.05, cells));
    SheetParams params;
    const double strain = 1e-7;
    const SheetState state = affinely_stretched(model, strain, -strain / 3.0);
    Eigen::Matrix3Xd forces;
    internal_forces(model, params, state, &forces);
    double right_edge_x = 0.0, largest_elsewhere = 0.0;
    for (int j = 0; j <= model.cells_y; ++j) {
      for (int i = 0; i <= model.cells_x; ++i) {
        const Eigen::Vector3d f = forces.col(model.vertex(i, j));
        if (i == model.cells_x) right_edge_x += f.x();
        // the pulled edges carry x forces only; every other vertex is balanced
        const double unbalanced = (i == 0 || i == model.cells_x) ? std::abs(f.y()) : f.norm();
        largest_elsewhere = std::max(largest_elsewhere, unbalanced);
      }
    }
    const double expected = params.stiffness_n_per_m * 0.05 * strain;
    EXPECT_NEAR(-right_edge_x, expected, 1e-6 * expected) << cells << " cells";
    EXPECT_LT(largest_elsewhere, 1e-6 * expected) << cells << " cells";
  }
}

// The same stiffness reached dynamically: a strip pulled slowly by rollers
// through the explicit integrator.
TEST(SheetModel, SlowUniaxialPullMeetsTheAnalyticStiffness) {
  SheetSpec spec = free_sheet_spec(0.02, 8);
  spec.damping_per_s = 2.0e4;
  const double speed = 0.01;
  add_uniaxial_grips(&spec, speed);
  const SheetModel model = uniform_sheet(spec);
  SheetParams params;
  params.tear_strain = 1.0;
  ExplicitIntegrator integrator(model, params, 0.9 * stable_time_step_s(model, params));
  SheetState state = make_sheet_state(model);
  while (state.time_s < 2e-3) integrator.step(&state);
  const double strain = speed * state.time_s / spec.width_m;
  const double expected = params.stiffness_n_per_m * spec.height_m * strain;
  EXPECT_NEAR(state.grip_force_n(0, 2), expected, 0.01 * expected);
  // lateral contraction nu = 1/3 at the middle of the strip
  const int middle = model.vertex(4, 8);
  EXPECT_NEAR(state.positions(1, middle) - model.rest_positions(1, middle), -strain / 3.0 * 0.02, 0.02 * strain / 3.0 * 0.02);
}

}  // namespace
}  // namespace repose
