// The float 3 x 3 block copy of a sheet system: its residual is the
// matrix's to float rounding, held axes stay out, its Gauss-Seidel sweeps
// solve the system, and a refresh follows new values of the pattern.
#include "models/tearing/vertex_block_matrix.h"

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/SparseCore>

#include <gtest/gtest.h>

#include "tests/models/tearing/block_system_fixture.h"

namespace repose {
namespace {

using testing::block_system;
using testing::BlockSystem;
using testing::random_vector;

TEST(VertexBlockMatrix, ItsResidualIsTheMatrixsToFloatRounding) {
  const BlockSystem s = block_system(12, 30.0, 1);
  const VertexBlockMatrix blocks(s.matrix, s.index);
  EXPECT_EQ(blocks.block_rows(), 11);  // vertex 0 has no unknown
  const Eigen::VectorXd x = random_vector(s.matrix.rows(), 2), b = random_vector(s.matrix.rows(), 3);
  EXPECT_EQ(blocks.from_blocks(blocks.to_blocks(x)), x);
  const Eigen::VectorXd exact = b - s.matrix * x;
  const Eigen::VectorXd r = blocks.from_blocks(blocks.residual(blocks.to_blocks(b), blocks.to_blocks(x)));
  EXPECT_LT((r - exact).norm(), 1e-6 * (b.norm() + s.matrix.norm() * x.norm()));
  // the held x axis of vertex 2 (block row 1) stays zero in block vectors
  EXPECT_EQ(blocks.residual(blocks.to_blocks(b), blocks.to_blocks(x))[3], 0.0);
}

TEST(VertexBlockMatrix, ItsProductIsTheMatrixsToFloatRoundingAndSymmetric) {
  const BlockSystem s = block_system(12, 30.0, 10);
  const VertexBlockMatrix blocks(s.matrix, s.index);
  const Eigen::VectorXd x = random_vector(s.matrix.rows(), 11), y = random_vector(s.matrix.rows(), 12);
  const Eigen::VectorXd ax = blocks.from_blocks(blocks.product(blocks.to_blocks(x)));
  EXPECT_LT((ax - s.matrix * x).norm(), 1e-6 * (s.matrix.norm() * x.norm()));
  // x^T A y = y^T A x: the rounded matrix stays symmetric, as conjugate gradients need
  const Eigen::VectorXd ay = blocks.from_blocks(blocks.product(blocks.to_blocks(y)));
  EXPECT_NEAR(x.dot(ay), y.dot(ax), 1e-12 * std::abs(x.dot(ay)) + 1e-12);
  EXPECT_EQ(blocks.product(blocks.to_blocks(x))[3], 0.0);  // the held axis
}

TEST(VertexBlockMatrix, SymmetricGaussSeidelSweepsSolveTheSystem) {
  const BlockSystem s = block_system(12, 30.0, 4);
  const VertexBlockMatrix blocks(s.matrix, s.index);
  const Eigen::VectorXd b = random_vector(s.matrix.rows(), 5);
  const Eigen::VectorXd bb = blocks.to_blocks(b);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(bb.size());
  blocks.gauss_seidel_sweep(bb, true, true, &x);
  for (int sweep = 0; sweep < 400; ++sweep) {
    blocks.gauss_seidel_sweep(bb, false, false, &x);
    blocks.gauss_seidel_sweep(bb, true, false, &x);
  }
  EXPECT_EQ(x[3], 0.0);  // the held axis
  // solved to the float rounding of the matrix
  EXPECT_LT((s.matrix * blocks.from_blocks(x) - b).norm(), 1e-5 * b.norm());
}

TEST(VertexBlockMatrix, ASweepFromZeroIsAFullSweepFromZero) {
  const BlockSystem s = block_system(9, 10.0, 6);
  const VertexBlockMatrix blocks(s.matrix, s.index);
  const Eigen::VectorXd bb = blocks.to_blocks(random_vector(s.matrix.rows(), 7));
  Eigen::VectorXd half = Eigen::VectorXd::Zero(bb.size()), full = half;
  blocks.gauss_seidel_sweep(bb, true, true, &half);
  blocks.gauss_seidel_sweep(bb, true, false, &full);
  EXPECT_LT((half - full).norm(), 1e-14 * full.norm());
}

// The multigrid's shortcut: after one forward sweep from zero, the upper
// blocks alone give the residual (the held axis included).
TEST(VertexBlockMatrix, AfterASweepFromZeroTheUpperBlocksGiveTheResidual) {
  const BlockSystem s = block_system(12, 30.0, 13);
  const VertexBlockMatrix blocks(s.matrix, s.index);
  const Eigen::VectorXd bb = blocks.to_blocks(random_vector(s.matrix.rows(), 14));
  Eigen::VectorXd x = Eigen::VectorXd::Zero(bb.size());
  blocks.gauss_seidel_sweep(bb, true, true, &x);
  const Eigen::VectorXd full = blocks.residual(bb, x), shortcut = blocks.residual_after_sweep_from_zero(x);
  EXPECT_GT(full.norm(), 0.1 * bb.norm());  // one sweep is far from a solve
  EXPECT_LT((shortcut - full).norm(), 1e-12 * full.norm());
  EXPECT_EQ(shortcut[3], 0.0);
}

// The fused passes the multigrid takes: a sweep from zero that scatters its
// residual, and a backward sweep that scatters the product of its result.
TEST(VertexBlockMatrix, ASweepFromZeroWithItsResidualEqualsTheSweepThenTheResidual) {
  const BlockSystem s = block_system(12, 30.0, 15);
  const VertexBlockMatrix blocks(s.matrix, s.index);
  const Eigen::VectorXd bb = blocks.to_blocks(random_vector(s.matrix.rows(), 16));
  Eigen::VectorXd x = Eigen::VectorXd::Zero(bb.size()), fused_x, fused_r;
  blocks.gauss_seidel_sweep(bb, true, true, &x);
  blocks.sweep_from_zero_with_residual(bb, &fused_x, &fused_r);
  EXPECT_EQ(fused_x, x);
  const Eigen::VectorXd full = blocks.residual(bb, x);
  EXPECT_GT(full.norm(), 0.1 * bb.norm());
  EXPECT_LT((fused_r - full).norm(), 1e-12 * full.norm());
  EXPECT_EQ(fused_r[3], 0.0);  // the held axis
}

TEST(VertexBlockMatrix, ABackwardSweepWithItsProductEqualsTheSweepThenTheProduct) {
  const BlockSystem s = block_system(12, 30.0, 17);
  const VertexBlockMatrix blocks(s.matrix, s.index);
  const Eigen::VectorXd bb = blocks.to_blocks(random_vector(s.matrix.rows(), 18));
  Eigen::VectorXd x = blocks.to_blocks(random_vector(s.matrix.rows(), 19));
  Eigen::VectorXd fused_x = x, ax;
  blocks.gauss_seidel_sweep(bb, false, false, &x);
  blocks.backward_sweep_with_product(bb, &fused_x, &ax);
  EXPECT_EQ(fused_x, x);
  const Eigen::VectorXd product = blocks.product(x);
  EXPECT_LT((ax - product).norm(), 1e-12 * product.norm());
  EXPECT_EQ(ax[3], 0.0);
}

TEST(VertexBlockMatrix, ARefreshFollowsNewValuesOfThePattern) {
  const BlockSystem s = block_system(10, 5.0, 8);
  VertexBlockMatrix blocks(s.matrix, s.index);
  const Eigen::SparseMatrix<double> doubled = 2.0 * s.matrix;
  blocks.refresh(doubled);
  const Eigen::VectorXd x = random_vector(s.matrix.rows(), 9);
  const Eigen::VectorXd ax = -blocks.from_blocks(blocks.residual(Eigen::VectorXd::Zero(3 * blocks.block_rows()),
                                                                  blocks.to_blocks(x)));
  EXPECT_LT((ax - doubled * x).norm(), 1e-6 * (doubled * x).norm());
}

// Filled in place, entry by entry at the blocks find_block names (block
// row = vertex with an unknown, here vertex - 1), it is the copy a refresh
// makes of the same matrix: the same products and sweeps.
TEST(VertexBlockMatrix, FillingItInPlaceEqualsARefreshOfTheMatrix) {
  const BlockSystem s = block_system(10, 20.0, 13);
  const VertexBlockMatrix refreshed(s.matrix, s.index);
  VertexBlockMatrix filled(s.matrix, s.index);
  filled.clear_values();
  EXPECT_EQ(filled.find_block(0, 5), -1);  // vertices 1 and 6 are not coupled
  for (int v = 1; v < 10; ++v) {
    for (int w = 1; w < 10; ++w) {
      const int k = filled.find_block(v - 1, w - 1);
      if (std::abs(v - w) > 2) {
        EXPECT_EQ(k, -1);
        continue;
      }
      ASSERT_GE(k, 0);
      for (int p = 0; p < 3; ++p) {
        for (int q = 0; q < 3; ++q) {
          const int row = s.index[static_cast<std::size_t>(3 * v + p)], col = s.index[static_cast<std::size_t>(3 * w + q)];
          if (row >= 0 && col >= 0) filled.values()[9 * k + 3 * p + q] = static_cast<float>(s.matrix.coeff(row, col));
        }
      }
    }
  }
  filled.finish_values();
  const Eigen::VectorXd x = filled.to_blocks(random_vector(s.matrix.rows(), 14));
  EXPECT_EQ(filled.product(x), refreshed.product(x));
  Eigen::VectorXd a = Eigen::VectorXd::Zero(x.size()), b = a;
  filled.gauss_seidel_sweep(x, true, true, &a);
  refreshed.gauss_seidel_sweep(x, true, true, &b);
  EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace repose
