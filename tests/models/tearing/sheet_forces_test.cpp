// The tear limit of one spring under fibre anisotropy: by default one strain
// per cell (the seed's rule); with isotropic_tear_energy each spring's limit
// is scaled so that it tears holding the same energy whatever its direction.
#include "models/tearing/sheet_forces.h"

#include <cmath>

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

}  // namespace
}  // namespace repose
