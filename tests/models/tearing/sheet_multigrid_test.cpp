// The multigrid V-cycle: a symmetric positive definite operator (what
// conjugate gradients require), exact when the fine level is the coarsest,
// and a preconditioner that cuts the iterations of a mass-plus-stiffness
// system on a grid with held and torn parts; options checked.
#include "models/tearing/sheet_multigrid.h"

#include <random>
#include <vector>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/models/tearing/grid_system_fixture.h"

namespace repose {
namespace {

using testing::grid_system;
using testing::GridSystem;

SheetMultigridOptions small_coarsest() {
  SheetMultigridOptions options;
  options.coarsest_unknowns = 60;  // several levels on the small grids here
  return options;
}

TEST(SheetMultigrid, TheCycleIsSymmetricAndPositiveDefiniteForBothSmoothers) {
  const GridSystem g = grid_system(17, 13, 50.0, 1);
  for (const auto smoother : {SheetMultigridOptions::Smoother::kGaussSeidel, SheetMultigridOptions::Smoother::kL1Jacobi}) {
    SheetMultigridOptions options = small_coarsest();
    options.smoother = smoother;
    options.smoothing_sweeps = 2;
    SheetMultigrid multigrid(g.vertices_x, g.vertices_y, g.free_index, static_cast<int>(g.matrix.rows()), options);
    multigrid.rebuild(g.matrix);
    ASSERT_GE(multigrid.level_count(), 3);
    std::mt19937_64 rng(2);
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::VectorXd x(g.matrix.rows()), y(g.matrix.rows());
      for (Eigen::Index k = 0; k < x.size(); ++k) x[k] = normal(rng), y[k] = normal(rng);
      const Eigen::VectorXd bx = multigrid.apply(g.matrix, x), by = multigrid.apply(g.matrix, y);
      EXPECT_NEAR(y.dot(bx), x.dot(by), 1e-10 * std::abs(x.dot(by)) + 1e-14) << "trial " << trial;
      EXPECT_GT(x.dot(bx), 0.0) << "trial " << trial;
    }
  }
}

TEST(SheetMultigrid, ASystemNoLargerThanTheCoarsestLevelIsSolvedExactly) {
  const GridSystem g = grid_system(4, 3, 50.0, 3);
  SheetMultigrid multigrid(g.vertices_x, g.vertices_y, g.free_index, static_cast<int>(g.matrix.rows()));
  multigrid.rebuild(g.matrix);
  EXPECT_EQ(multigrid.level_count(), 1);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(g.matrix.rows(), -1.0, 2.0);
  const Eigen::VectorXd x = multigrid.apply(g.matrix, b);
  EXPECT_LT((g.matrix * x - b).norm(), 1e-12 * b.norm());
}

// Conjugate gradients to a relative residual of 1e-10 on a 65 x 65 grid
// whose stiffness is 400 times its mass (the integrator's system at 10x the
// explicit step): the V-cycle needs a fifth of the Jacobi iterations or fewer.
TEST(SheetMultigrid, CutsTheConjugateGradientIterationsOfAStiffTornSystem) {
  const GridSystem g = grid_system(65, 65, 400.0, 4);
  SheetMultigrid multigrid(g.vertices_x, g.vertices_y, g.free_index, static_cast<int>(g.matrix.rows()));
  multigrid.rebuild(g.matrix);
  ASSERT_GE(multigrid.level_count(), 3);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(g.matrix.rows());
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> jacobi;
  jacobi.setTolerance(1e-10);
  jacobi.compute(g.matrix);
  const Eigen::VectorXd x_jacobi = jacobi.solve(b);
  // preconditioned CG written out: Eigen's adapter lives in the integrator
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size()), r = b;
  Eigen::VectorXd z = multigrid.apply(g.matrix, r), p = z;
  double rz = r.dot(z);
  int iterations = 0;
  while (r.norm() > 1e-10 * b.norm() && iterations < 1000) {
    const Eigen::VectorXd ap = g.matrix * p;
    const double alpha = rz / p.dot(ap);
    x += alpha * p;
    r -= alpha * ap;
    z = multigrid.apply(g.matrix, r);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
    ++iterations;
  }
  EXPECT_LE(5 * iterations, jacobi.iterations()) << iterations << " against " << jacobi.iterations();
  EXPECT_LT((x - x_jacobi).norm(), 1e-6 * x_jacobi.norm());
}

// The block-vector cycle keeps its levels' vectors between calls: a cycle
// after others of other right-hand sides gives the bits of the first, and
// apply() is it between the scalar and block vectors.
TEST(SheetMultigrid, TheBlockCycleReusingItsWorkspacesGivesTheBitsOfAFreshOne) {
  const GridSystem g = grid_system(33, 21, 400.0, 5);
  SheetMultigrid multigrid(g.vertices_x, g.vertices_y, g.free_index, static_cast<int>(g.matrix.rows()), small_coarsest());
  multigrid.rebuild(g.matrix);
  ASSERT_GE(multigrid.level_count(), 3);
  const VertexBlockMatrix& blocks = multigrid.fine_blocks();
  std::mt19937_64 rng(6);
  std::normal_distribution<double> normal;
  Eigen::VectorXd r(g.matrix.rows()), other(g.matrix.rows());
  for (Eigen::Index k = 0; k < r.size(); ++k) r[k] = normal(rng), other[k] = normal(rng);
  Eigen::VectorXd first, again, between;
  multigrid.apply_blocks(blocks.to_blocks(r), &first);
  for (int k = 0; k < 3; ++k) multigrid.apply_blocks(blocks.to_blocks(other), &between);
  multigrid.apply_blocks(blocks.to_blocks(r), &again);
  EXPECT_EQ(first, again);
  const Eigen::VectorXd scalar = multigrid.apply(g.matrix, r);
  EXPECT_EQ(blocks.from_blocks(first), scalar);
  // the held column's axes stay 0 in block form
  std::vector<char> free_place(static_cast<std::size_t>(first.size()), 0);
  for (const int place : blocks.block_place_of_rows()) free_place[static_cast<std::size_t>(place)] = 1;
  for (Eigen::Index k = 0; k < first.size(); ++k) {
    if (!free_place[static_cast<std::size_t>(k)]) {
      EXPECT_EQ(first[k], 0.0) << k;
    }
  }
}

// The sweeps in float (the default) give the double cycle to
// float rounding of the levels' vectors, and are what runs: the two differ.
TEST(SheetMultigrid, TheFloatSweepsCycleIsTheDoubleOneToFloatRounding) {
  const GridSystem g = grid_system(33, 21, 400.0, 8);
  SheetMultigridOptions in_double = small_coarsest();
  in_double.single_precision_sweeps = false;
  ASSERT_TRUE(small_coarsest().single_precision_sweeps);
  SheetMultigrid single(g.vertices_x, g.vertices_y, g.free_index, static_cast<int>(g.matrix.rows()), small_coarsest());
  SheetMultigrid full(g.vertices_x, g.vertices_y, g.free_index, static_cast<int>(g.matrix.rows()), in_double);
  single.rebuild(g.matrix);
  full.rebuild(g.matrix);
  ASSERT_GE(single.level_count(), 3);
  std::mt19937_64 rng(9);
  std::normal_distribution<double> normal;
  Eigen::VectorXd r(g.matrix.rows());
  for (Eigen::Index k = 0; k < r.size(); ++k) r[k] = normal(rng);
  const Eigen::VectorXd rb = single.fine_blocks().to_blocks(r);
  Eigen::VectorXd z_single, az_single, z_full, az_full;
  single.apply_blocks(rb, &z_single, &az_single);
  full.apply_blocks(rb, &z_full, &az_full);
  EXPECT_LT((z_single - z_full).norm(), 1e-5 * z_full.norm());
  EXPECT_LT((az_single - az_full).norm(), 1e-5 * az_full.norm());
  EXPECT_NE(z_single, z_full);
  // the carried product is the fine blocks' product of z to float rounding
  EXPECT_LT((az_single - single.fine_blocks().product(z_single)).norm(), 1e-5 * az_single.norm());
}

// A rebuild from a later system of the same pattern (or after the pattern
// was prepared) keeps the fine block pattern and gathers the values only:
// the same cycle, to the bit, as a hierarchy built fresh from that system.
TEST(SheetMultigrid, ARebuildKeepingOrPreparingTheFinePatternEqualsAFreshBuild) {
  const GridSystem g = grid_system(33, 21, 400.0, 7);
  Eigen::SparseMatrix<double> later = 0.5 * g.matrix;
  for (int k = 0; k < later.outerSize(); ++k) later.coeffRef(k, k) += 1.0;
  ASSERT_EQ(later.nonZeros(), g.matrix.nonZeros());
  later.makeCompressed();
  SheetMultigrid kept(g.vertices_x, g.vertices_y, g.free_index, static_cast<int>(g.matrix.rows()), small_coarsest());
  SheetMultigrid fresh(g.vertices_x, g.vertices_y, g.free_index, static_cast<int>(g.matrix.rows()), small_coarsest());
  kept.rebuild(g.matrix);
  ASSERT_TRUE(kept.fine_blocks().has_pattern_of(later));
  kept.rebuild(later);
  fresh.rebuild(later);
  // the pattern made ahead of the first rebuild, from a matrix of zeros
  SheetMultigrid prepared(g.vertices_x, g.vertices_y, g.free_index, static_cast<int>(g.matrix.rows()), small_coarsest());
  Eigen::SparseMatrix<double> zeros = g.matrix;
  zeros.coeffs().setZero();
  prepared.prepare_fine_pattern(zeros);
  EXPECT_FALSE(prepared.built());
  prepared.rebuild(later);
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(g.matrix.rows(), -1.0, 3.0);
  EXPECT_EQ(kept.apply(later, r), fresh.apply(later, r));
  EXPECT_EQ(prepared.apply(later, r), fresh.apply(later, r));
}

TEST(SheetMultigrid, OptionsOutsideTheirRangesAreRefusedByName) {
  SheetMultigridOptions options;
  options.coarsest_unknowns = 0;
  EXPECT_THROW(
      {
        try {
          options.validate();
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("coarsest_unknowns"), std::string::npos);
          throw;
        }
      },
      InputError);
  options = {};
  options.smoothing_sweeps = 0;
  EXPECT_THROW(options.validate(), InputError);
}

}  // namespace
}  // namespace repose
