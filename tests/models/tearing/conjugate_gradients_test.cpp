// The integrator's conjugate gradients with products carried from the
// multigrid cycle (conjugate_gradients.h): they reach the tolerance asked
// of the true residual, with the sweeps in float as with
// them in double, in the same iterations, and agree with Eigen's. Down to
// 1e-5: below, the float cycle's carried product held the true residual
// at ~5e-6 (measured at 1e-6 on this system), which is why the integrator
// takes the double sweeps there.
#include "models/tearing/conjugate_gradients.h"

#include <random>

#include <Eigen/IterativeLinearSolvers>

#include <gtest/gtest.h>

#include "tests/models/tearing/grid_system_fixture.h"

namespace repose {
namespace {

using testing::grid_system;
using testing::GridSystem;

struct Solve {
  Eigen::VectorXd x;
  int iterations = 0;
  // |b - A x| / |b| of the system the float blocks hold (the double one
  // rounded to float, ~1e-7 an entry), the product in double
  double true_residual = 0.0;
};

// A x = b by conjugate gradients carrying A p from the cycle's A z.
Solve carried_solve(const GridSystem& g, const Eigen::VectorXd& b, double tolerance, bool float_sweeps) {
  SheetMultigridOptions options;
  options.coarsest_unknowns = 60;
  options.single_precision_sweeps = float_sweeps;
  SheetMultigrid multigrid(g.vertices_x, g.vertices_y, g.free_index, static_cast<int>(g.matrix.rows()), options);
  multigrid.rebuild(g.matrix);
  const VertexBlockMatrix& blocks = multigrid.fine_blocks();
  ConjugateGradientWork work;
  Solve solve;
  blocks.to_blocks(b, &work.b);
  conjugate_gradients(
      work.b, tolerance, 500,
      [&](const Eigen::VectorXd& r, Eigen::VectorXd* z, Eigen::VectorXd* az) { multigrid.apply_blocks(r, z, az); },
      &work, &solve.iterations);
  blocks.from_blocks(work.x, &solve.x);
  solve.true_residual = (work.b - blocks.product(work.x)).norm() / work.b.norm();
  return solve;
}

TEST(ConjugateGradients, WithTheFloatSweepsTheyReachTheToleranceOfTheDoubleOnes) {
  const GridSystem g = grid_system(41, 29, 2000.0, 31);
  std::mt19937_64 rng(32);
  std::normal_distribution<double> normal;
  Eigen::VectorXd b(g.matrix.rows());
  for (Eigen::Index k = 0; k < b.size(); ++k) b[k] = normal(rng);
  for (const double tolerance : {1e-3, 1e-4, 1e-5}) {
    const Solve single = carried_solve(g, b, tolerance, true);
    const Solve full = carried_solve(g, b, tolerance, false);
    EXPECT_LE(single.true_residual, 1.05 * tolerance) << tolerance;
    EXPECT_LE(full.true_residual, 1.05 * tolerance) << tolerance;
    EXPECT_GE(single.iterations, 2);
    EXPECT_LE(std::abs(single.iterations - full.iterations), 1) << single.iterations << " against " << full.iterations;
  }
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> eigen;
  eigen.setTolerance(1e-10);
  eigen.compute(g.matrix);
  const Eigen::VectorXd exact = eigen.solve(b);
  const Solve tight = carried_solve(g, b, 1e-6, true);
  EXPECT_LT((tight.x - exact).norm(), 1e-3 * exact.norm());  // the float rounding of the system
}

}  // namespace
}  // namespace repose
