// The tensile test of an uncut strip: a uniform strip gives the lattice's
// analytic stiffness E t (sheet_model.h) and breaks when its edge springs
// reach the tear strain (uniaxial stress with Poisson's ratio 1/3 strains
// the diagonals by a third of that), so its strength is E t x tear strain;
// options are checked by name.
#include "models/tearing/tensile_test.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/tearing/tear_limit.h"
#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

SheetModel uniform_strip(double length_m, double width_m, int cells_x, double speed_m_per_s) {
  SheetSpec spec = free_sheet_spec(length_m, cells_x);
  spec.height_m = width_m;
  spec.damping_per_s = 200.0;
  spec.grips = tensile_grips(length_m, width_m, spec.cell_size_m(), speed_m_per_s);
  return uniform_sheet(spec);
}

TEST(TensileTest, AUniformStripHasTheLatticeStiffnessAndBreaksAtTheTearStrain) {
  TensileOptions options;
  const SheetModel model = uniform_strip(0.03, 0.01, 15, options.speed_m_per_s);
  SheetParams params;
  params.stiffness_n_per_m = 3.0e5;
  params.tear_strain = 0.015;
  const TensileResult r = run_tensile_test(model, params, options);
  EXPECT_TRUE(r.broke);
  EXPECT_NEAR(r.stiffness_n_per_m, params.stiffness_n_per_m, 0.03 * params.stiffness_n_per_m);
  EXPECT_NEAR(r.strain_at_peak, params.tear_strain, 0.05 * params.tear_strain);
  EXPECT_NEAR(r.strength_n_per_m, params.stiffness_n_per_m * params.tear_strain,
              0.05 * params.stiffness_n_per_m * params.tear_strain);
  EXPECT_EQ(r.strain.size(), static_cast<std::size_t>(r.steps));
}

// Under the energy rule the uniform strip breaks at sqrt(2 Gamma / (E t h)):
// halving the cells' size raises its strength by sqrt(2).
TEST(TensileTest, UnderTheEnergyRuleTheStripsStrengthFollowsTheCellSize) {
  TensileOptions options;
  SheetParams params;
  params.tear_energy_j_per_m = 0.1;
  double strength[2];
  for (int k = 0; k < 2; ++k) {
    SheetSpec spec = free_sheet_spec(0.03, 10 * (k + 1));
    spec.height_m = 0.012;
    spec.damping_per_s = 200.0;
    spec.tear_rule = TearRule::kEnergy;
    spec.grips = tensile_grips(spec.width_m, spec.height_m, spec.cell_size_m(), options.speed_m_per_s);
    const SheetModel model = uniform_sheet(spec);
    strength[k] = run_tensile_test(model, params, options).strength_n_per_m;
    const double expected = params.stiffness_n_per_m * base_tear_strain(model, params);
    EXPECT_NEAR(strength[k], expected, 0.05 * expected) << "cells " << spec.cells_x;
  }
  EXPECT_NEAR(strength[1] / strength[0], std::sqrt(2.0), 0.05);
}

// Springs along the grain (1 + a), across it (1 - a) times stiffer: under
// uniaxial stress along x the lattice's stiffness is
// k_x + k_d - k_d^2 / (k_y + k_d) (sheet_params.h), with the grain along x
// (MD) and across it (CD).
TEST(TensileTest, TheFibreAnisotropyGivesTheLatticesStiffnessAlongAndAcrossTheGrain) {
  TensileOptions options;
  SheetParams params;
  params.fibre_anisotropy = 0.5;
  const double ke = 0.75 * params.stiffness_n_per_m, kd = 0.375 * params.stiffness_n_per_m, a = params.fibre_anisotropy;
  for (const double grain_deg : {0.0, 90.0}) {
    SheetSpec spec = free_sheet_spec(0.03, 15);
    spec.height_m = 0.01;
    spec.damping_per_s = 200.0;
    spec.fibres.grain_direction_rad = grain_deg * std::numbers::pi / 180.0;
    spec.grips = tensile_grips(spec.width_m, spec.height_m, spec.cell_size_m(), options.speed_m_per_s);
    const double kx = ke * (grain_deg == 0.0 ? 1 + a : 1 - a), ky = ke * (grain_deg == 0.0 ? 1 - a : 1 + a);
    const double expected = kx + kd - kd * kd / (ky + kd);
    const TensileResult r = run_tensile_test(uniform_sheet(spec), params, options);
    EXPECT_NEAR(r.stiffness_n_per_m, expected, 0.03 * expected) << "grain " << grain_deg << " deg";
  }
}

TEST(TensileTest, RefusesASheetWithoutTensileGripsAndNamesBadOptions) {
  SheetSpec spec = free_sheet_spec(0.01, 4);
  spec.grips = seed_twist_grips(0.01, 0.01, 0.0025, 0.0025, 1.0);
  EXPECT_THROW(run_tensile_test(uniform_sheet(spec), SheetParams{}, TensileOptions{}), InputError);
  const SheetModel model = uniform_strip(0.01, 0.005, 4, 0.5);
  for (auto [field, change] : std::initializer_list<std::pair<const char*, void (*)(TensileOptions*)>>{
           {"speed_m_per_s", [](TensileOptions* o) { o->speed_m_per_s = 0.0; }},
           {"time_step_fraction", [](TensileOptions* o) { o->time_step_fraction = 1.5; }},
           {"max_strain", [](TensileOptions* o) { o->max_strain = -1.0; }},
           {"stiffness_strain_fraction", [](TensileOptions* o) { o->stiffness_strain_fraction = 0.0; }}}) {
    TensileOptions options;
    change(&options);
    try {
      run_tensile_test(model, SheetParams{}, options);
      ADD_FAILURE() << field << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace repose
