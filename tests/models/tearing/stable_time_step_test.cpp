// The stable step bound against the exact largest frequency of small sheets.
#include "models/tearing/stable_time_step.h"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "models/tearing/sheet_forces.h"
#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

// Exact 2 / w_max at rest: the stiffness matrix by central differences of
// the (linear at rest) internal forces, then the eigenvalues of M^-1/2 K M^-1/2.
double exact_stable_step(const SheetModel& model, const SheetParams& params) {
  const int n = 3 * model.vertex_count();
  Eigen::MatrixXd k(n, n);
  SheetState state = make_sheet_state(model);
  Eigen::Matrix3Xd plus, minus;
  const double delta = 1e-9;
  for (int col = 0; col < n; ++col) {
    state.positions(col % 3, col / 3) += delta;
    internal_forces(model, params, state, &plus);
    state.positions(col % 3, col / 3) -= 2 * delta;
    internal_forces(model, params, state, &minus);
    state.positions(col % 3, col / 3) += delta;
    k.col(col) = -(plus - minus).reshaped() / (2 * delta);
  }
  Eigen::VectorXd inv_sqrt_m(n);
  for (int i = 0; i < n; ++i) inv_sqrt_m[i] = 1.0 / std::sqrt(model.mass_kg[i / 3]);
  const Eigen::MatrixXd a = inv_sqrt_m.asDiagonal() * (0.5 * (k + k.transpose())) * inv_sqrt_m.asDiagonal();
  const double omega2 = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
  return 2.0 / std::sqrt(omega2);
}

TEST(StableTimeStep, IsBelowTheExactLimitAndWithinAFactorOfTwoOfIt) {
  for (const bool twist : {false, true}) {
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
      for (const int cells : {1, 3, 6}) {
        SheetSpec spec = free_sheet_spec(0.02, cells);
        spec.bending_stiffness_n_m = 3e-4 * seed * seed * 100;  // make bending matter too
        spec.twist_stiffness = twist;
        const SheetModel model = fibre_sheet(spec, seed);
        const SheetParams params;
        const double bound = stable_time_step_s(model, params), exact = exact_stable_step(model, params);
        EXPECT_LE(bound, exact * (1 + 1e-6)) << "seed " << seed << ", " << cells << " cells, twist " << twist;
        EXPECT_GE(bound, 0.5 * exact) << "seed " << seed << ", " << cells << " cells, twist " << twist;
      }
    }
  }
}

TEST(StableTimeStep, ScalesAsOneOverTheSquareRootOfStiffness) {
  const SheetModel model = uniform_sheet(free_sheet_spec(0.02, 5));
  SheetParams soft, stiff;
  stiff.stiffness_n_per_m = 100.0 * soft.stiffness_n_per_m;
  // bending does not scale with the fitted stiffness, so allow its small share
  EXPECT_NEAR(stable_time_step_s(model, soft) / stable_time_step_s(model, stiff), 10.0, 0.01);
}

}  // namespace
}  // namespace repose

namespace repose {
namespace {

// The springs' dashpots (beta) shrink the limit to
// (2 / w) (sqrt(1 + z^2) - z), z = beta w / 2, w = 2 / (the undamped limit).
TEST(StableTimeStep, ShrinksWithTheSpringsDashpotsAsTheDampedOscillatorsLimit) {
  SheetSpec spec = testing::free_sheet_spec(0.03, 12);
  const SheetParams params;
  const double undamped = stable_time_step_s(testing::uniform_sheet(spec), params);
  for (const double beta : {0.1 * undamped, undamped, 10.0 * undamped}) {
    spec.stiffness_damping_s = beta;
    const double z = beta / undamped;  // beta w_max / 2
    EXPECT_NEAR(stable_time_step_s(testing::uniform_sheet(spec), params),
                undamped * (std::sqrt(1.0 + z * z) - z), 1e-12 * undamped) << beta;
  }
}

}  // namespace
}  // namespace repose
