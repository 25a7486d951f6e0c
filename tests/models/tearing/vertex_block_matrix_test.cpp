// The float 3 x 3 block copy of a sheet system: its residual is the
// matrix's to float rounding, held axes stay out, its Gauss-Seidel sweeps
// solve the system, and a refresh follows new values of the pattern.
#include "models/tearing/vertex_block_matrix.h"

#include <cmath>
#include <random>
#include <stdexcept>
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

// Block (i, j)'s entry (p, q) is a's entry in row (i, p) and column (j, q),
// not its mirror: values made unsymmetric (the pattern kept) tell them
// apart; scalar blocks and held axes included.
TEST(VertexBlockMatrix, ItsBlocksHoldTheEntriesOfTheirRowsAndColumns) {
  const BlockSystem s = block_system(14, 30.0, 51, true);
  Eigen::SparseMatrix<double> a = s.matrix;
  for (int c = 0; c < a.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, c); it; ++it) it.valueRef() += 1e-3 * (it.row() - 2 * c);
  }
  const VertexBlockMatrix pattern(a, s.index, false, s.identity_pairs);
  VertexBlockMatrix blocks(a, s.index);  // no scalar blocks: a's are not k I now
  blocks.refresh(a);
  const std::vector<int> place = blocks.block_place_of_rows();
  std::vector<int> row_at(3 * static_cast<std::size_t>(blocks.block_rows()), -1);
  for (int r = 0; r < a.rows(); ++r) row_at[static_cast<std::size_t>(place[static_cast<std::size_t>(r)])] = r;
  int checked = 0;
  for (int i = 0; i < blocks.block_rows(); ++i) {
    for (int j = 0; j < blocks.block_rows(); ++j) {
      const int k = blocks.find_block(i, j);
      if (k < 0) continue;
      for (int e = 0; e < 9; ++e) {
        const int row = row_at[static_cast<std::size_t>(3 * i + e / 3)], col = row_at[static_cast<std::size_t>(3 * j + e % 3)];
        const double expected = row < 0 || col < 0 ? 0.0 : a.coeff(row, col);
        EXPECT_EQ(blocks.values()[9 * k + e], static_cast<float>(expected)) << i << " " << j << " " << e;
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 9 * static_cast<int>(blocks.block_count()));
  // the pattern-only copy with scalar blocks finds them all, none full
  EXPECT_GT(pattern.scalar_count(), 0u);
  EXPECT_EQ(pattern.block_count() + pattern.scalar_count(), blocks.block_count());
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

// Blocks named as identity couplings (the sheet's bending ends) are kept as
// one float each, and every pass treats them as the full blocks they stand
// for: the same results as the copy with full blocks, to round-off.
TEST(VertexBlockMatrix, ScalarBlocksActAsTheFullBlocksTheyStandFor) {
  const BlockSystem s = block_system(14, 30.0, 31, true);
  ASSERT_EQ(s.identity_pairs.size(), 10u);  // vertex v and v + 2, both free in every axis
  const VertexBlockMatrix full(s.matrix, s.index), scalar(s.matrix, s.index, true, s.identity_pairs);
  EXPECT_EQ(scalar.scalar_count(), 20u);
  EXPECT_EQ(scalar.block_count() + scalar.scalar_count(), full.block_count());
  EXPECT_EQ(scalar.value_count() + 8 * scalar.scalar_count(), full.value_count());
  EXPECT_EQ(scalar.find_block(0, 2), -1);  // vertices 1 and 3
  EXPECT_GE(scalar.find_scalar(0, 2), 0);
  EXPECT_EQ(scalar.find_scalar(0, 1), -1);
  const Eigen::VectorXd b = full.to_blocks(random_vector(s.matrix.rows(), 32));
  const Eigen::VectorXd x0 = full.to_blocks(random_vector(s.matrix.rows(), 33));
  const auto expect_same = [](const Eigen::VectorXd& got, const Eigen::VectorXd& want, const char* what) {
    EXPECT_LT((got - want).norm(), 1e-12 * want.norm()) << what;
    EXPECT_EQ(got[3], 0.0) << what;  // the held axis
  };
  expect_same(scalar.product(x0), full.product(x0), "product");
  expect_same(scalar.residual(b, x0), full.residual(b, x0), "residual");
  for (const bool forward : {true, false}) {
    Eigen::VectorXd a = x0, c = x0;
    scalar.gauss_seidel_sweep(b, forward, false, &a);
    full.gauss_seidel_sweep(b, forward, false, &c);
    expect_same(a, c, forward ? "forward sweep" : "backward sweep");
  }
  Eigen::VectorXd x, r, fx, fr;
  scalar.sweep_from_zero_with_residual(b, &x, &r);
  full.sweep_from_zero_with_residual(b, &fx, &fr);
  expect_same(x, fx, "sweep from zero");
  expect_same(r, fr, "its residual");
  expect_same(scalar.residual_after_sweep_from_zero(x), full.residual_after_sweep_from_zero(fx), "upper residual");
  Eigen::VectorXd ax, fax;
  scalar.backward_sweep_with_product(b, &x, &ax);
  full.backward_sweep_with_product(b, &fx, &fax);
  expect_same(x, fx, "backward sweep with product");
  expect_same(ax, fax, "its product");
}

// A pair named that is not a multiple of the identity in the matrix, has
// a held axis, or is not coupled is refused.
TEST(VertexBlockMatrix, APairThatCannotBeAScalarBlockIsRefused) {
  const BlockSystem s = block_system(8, 30.0, 34);  // general blocks between v and v + 2
  const std::vector<std::pair<int, int>> general = {{3, 5}}, held = {{2, 4}}, apart = {{1, 5}};
  EXPECT_NO_THROW(VertexBlockMatrix(s.matrix, s.index, false, general));  // the pattern alone
  EXPECT_THROW(VertexBlockMatrix(s.matrix, s.index, true, general), std::logic_error);
  EXPECT_THROW(VertexBlockMatrix(s.matrix, s.index, false, held), std::logic_error);
  EXPECT_THROW(VertexBlockMatrix(s.matrix, s.index, false, apart), std::logic_error);
}

// Filled in place, scalar blocks at the index find_scalar names, it is the
// copy a refresh makes of the same matrix.
TEST(VertexBlockMatrix, FillingScalarBlocksInPlaceEqualsARefresh) {
  const BlockSystem s = block_system(10, 20.0, 35, true);
  const VertexBlockMatrix refreshed(s.matrix, s.index, true, s.identity_pairs);
  VertexBlockMatrix filled(s.matrix, s.index, false, s.identity_pairs);
  for (int v = 1; v < 10; ++v) {
    for (int w = 1; w < 10; ++w) {
      const int k = filled.find_block(v - 1, w - 1), scalar = filled.find_scalar(v - 1, w - 1);
      if (scalar >= 0) {
        EXPECT_EQ(k, -1);
        const int row = s.index[static_cast<std::size_t>(3 * v)], col = s.index[static_cast<std::size_t>(3 * w)];
        filled.values()[filled.scalar_offset() + static_cast<std::size_t>(scalar)] =
            static_cast<float>(s.matrix.coeff(row, col));
        continue;
      }
      if (k < 0) continue;
      for (int p = 0; p < 3; ++p) {
        for (int q = 0; q < 3; ++q) {
          const int row = s.index[static_cast<std::size_t>(3 * v + p)], col = s.index[static_cast<std::size_t>(3 * w + q)];
          if (row >= 0 && col >= 0) filled.values()[9 * k + 3 * p + q] = static_cast<float>(s.matrix.coeff(row, col));
        }
      }
    }
  }
  filled.finish_values();
  const Eigen::VectorXd x = filled.to_blocks(random_vector(s.matrix.rows(), 36));
  EXPECT_EQ(filled.product(x), refreshed.product(x));
  const Eigen::VectorXd exact = s.matrix * filled.from_blocks(x);
  EXPECT_LT((filled.from_blocks(filled.product(x)) - exact).norm(), 1e-6 * exact.norm());
}

}  // namespace
}  // namespace repose
