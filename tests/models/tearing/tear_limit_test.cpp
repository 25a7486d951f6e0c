// The two tear rules: the strain rule's limit is the same on every mesh; the
// energy rule's holds Gamma per unit crack length in a cell strained to it
// (1/2 E t eps^2 h = Gamma), so it grows as h^-1/2; and torn under the
// seed's twist, the energy rule's work per unit tear length stays within
// 15 % between two meshes a factor 2 apart where the strain rule's does
// not (the numbers for 25 to 100 cells: experiments/tearing_convergence.yaml).
#include "models/tearing/tear_limit.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/tearing/tear_run.h"
#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

TEST(TearLimit, TheStrainRuleIsTheSameOnEveryMesh) {
  SheetParams params;
  params.tear_strain = 0.03;
  for (const int cells : {2, 7, 40}) {
    EXPECT_DOUBLE_EQ(base_tear_strain(uniform_sheet(free_sheet_spec(0.02, cells)), params), 0.03);
  }
}

TEST(TearLimit, TheEnergyRuleHoldsGammaPerUnitCrackLengthInACellAtItsLimit) {
  SheetParams params;
  params.stiffness_n_per_m = 5.0e5;
  params.tear_energy_j_per_m = 0.7;
  double previous = 0.0;
  for (const int cells : {5, 20}) {
    SheetSpec spec = free_sheet_spec(0.02, cells);
    spec.tear_rule = TearRule::kEnergy;
    const SheetModel model = uniform_sheet(spec);
    const double eps = base_tear_strain(model, params);
    EXPECT_NEAR(0.5 * params.stiffness_n_per_m * eps * eps * model.cell_size_m, params.tear_energy_j_per_m, 1e-12);
    EXPECT_NEAR(equivalent_tear_energy_j_per_m(params.stiffness_n_per_m, eps, model.cell_size_m),
                params.tear_energy_j_per_m, 1e-12);
    if (previous > 0.0) {
      EXPECT_NEAR(eps / previous, 2.0, 1e-12);  // cells 4x smaller: limit 2x larger
    }
    previous = eps;
    // every cell's limit is the rule's strain times its tear factor
    for (int c = 0; c < model.cell_count(); ++c) EXPECT_DOUBLE_EQ(cell_tear_strain(model, params, c), eps);
  }
}

TEST(TearLimit, TearEnergyIsValidatedByName) {
  SheetParams params;
  params.tear_energy_j_per_m = 0.0;
  try {
    params.validate();
    FAIL() << "a zero tear energy was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tear_energy_j_per_m"), std::string::npos) << e.what();
  }
}

// The seed's twist on a uniform sheet (tear_run_test.cpp) at two meshes.
double work_per_tear_length(TearRule rule, int cells) {
  const double w = 0.048;
  SheetSpec spec = free_sheet_spec(w, cells);
  spec.damping_per_s = 100.0;  // light, so that the work goes into the tear
  spec.tear_rule = rule;
  spec.grips = seed_twist_grips(w, w, 0.006, 0.006, 4.0);  // grips, gap and notch on vertices of both meshes
  spec.notch_length_m = 0.006;
  spec.notch_x_m = 0.5 * w;
  const SheetModel model = uniform_sheet(spec);
  SheetParams params;
  params.tear_energy_j_per_m = equivalent_tear_energy_j_per_m(params.stiffness_n_per_m, params.tear_strain, w / 32);
  TearRunOptions options;
  options.duration_s = 0.02;
  options.stop_at_depth_m = 0.028;
  const TearRun run = run_tear(model, params, options);
  EXPECT_GE(run.path.depth_m, 0.028 - 1e-12) << "cells " << cells;
  return run.work_per_tear_length_j_per_m;
}

TEST(TearLimit, UnderTheEnergyRuleTheWorkPerTearLengthDoesNotDependOnTheMesh) {
  const double energy_coarse = work_per_tear_length(TearRule::kEnergy, 16);
  const double energy_fine = work_per_tear_length(TearRule::kEnergy, 32);
  const double strain_coarse = work_per_tear_length(TearRule::kStrain, 16);
  const double strain_fine = work_per_tear_length(TearRule::kStrain, 32);
  std::printf("work per tear length, 16 and 32 cells: energy rule %.4g, %.4g J/m; strain rule %.4g, %.4g J/m\n",
              energy_coarse, energy_fine, strain_coarse, strain_fine);
  EXPECT_NEAR(energy_fine / energy_coarse, 1.0, 0.15);
  // the seed's rule: the finer mesh tears more easily
  EXPECT_LT(strain_fine / strain_coarse, 0.85);
}

}  // namespace
}  // namespace repose
