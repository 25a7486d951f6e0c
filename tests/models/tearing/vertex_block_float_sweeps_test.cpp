// The float block passes (vertex_block_float_sweeps.cpp): the double
// passes to float rounding, held axes and the padding lane kept 0, and the
// caller's floating-point mode left as it was.
#include "models/tearing/vertex_block_matrix.h"

#include <cmath>
#include <vector>

#include <xmmintrin.h>

#include <gtest/gtest.h>

#include "tests/models/tearing/block_system_fixture.h"

namespace repose {
namespace {

using testing::block_system;
using testing::BlockSystem;
using testing::random_vector;

// a block vector (3 a row) as the float passes' (4 a row, the fourth 0), and back
AlignedFloats padded(const VertexBlockMatrix& blocks, const Eigen::VectorXd& x) {
  AlignedFloats f(blocks.float_vector_size(), 0.0f);
  for (Eigen::Index k = 0; k < x.size(); ++k) f[static_cast<std::size_t>(k + k / 3)] = static_cast<float>(x[k]);
  return f;
}

Eigen::VectorXd unpadded(const AlignedFloats& f) {
  Eigen::VectorXd x(static_cast<Eigen::Index>(3 * f.size() / 4));
  for (Eigen::Index k = 0; k < x.size(); ++k) x[k] = f[static_cast<std::size_t>(k + k / 3)];
  return x;
}

void expect_padding_zero(const AlignedFloats& f) {
  for (std::size_t k = 3; k < f.size(); k += 4) EXPECT_EQ(f[k], 0.0f) << k;
}

TEST(VertexBlockFloatSweeps, TheSweepFromZeroWithItsResidualIsTheDoublePassToFloatRounding) {
  const BlockSystem s = block_system(40, 30.0, 21);
  const VertexBlockMatrix blocks(s.matrix, s.index);
  const Eigen::VectorXd b = blocks.to_blocks(random_vector(s.matrix.rows(), 22));
  Eigen::VectorXd x, r;
  blocks.sweep_from_zero_with_residual(b, &x, &r);
  const AlignedFloats fb = padded(blocks, b);
  AlignedFloats fx(fb.size(), 1.0f), fr(fb.size(), 1.0f);  // overwritten whole
  blocks.sweep_from_zero_with_residual(fb.data(), fx.data(), fr.data());
  EXPECT_LT((unpadded(fx) - x).norm(), 1e-5 * x.norm());
  EXPECT_LT((unpadded(fr) - r).norm(), 1e-5 * r.norm());
  EXPECT_GT(r.norm(), 0.1 * b.norm());  // a residual worth comparing
  EXPECT_EQ(fx[4 + 0], 0.0f);           // block row 1 is vertex 2, its x held
  EXPECT_EQ(fr[4 + 0], 0.0f);
  expect_padding_zero(fx);
  expect_padding_zero(fr);
}

TEST(VertexBlockFloatSweeps, TheBackwardSweepWithItsProductIsTheDoublePassToFloatRounding) {
  const BlockSystem s = block_system(40, 30.0, 23);
  const VertexBlockMatrix blocks(s.matrix, s.index);
  const Eigen::VectorXd b = blocks.to_blocks(random_vector(s.matrix.rows(), 24));
  Eigen::VectorXd x = blocks.to_blocks(random_vector(s.matrix.rows(), 25)), ax;
  const AlignedFloats fb = padded(blocks, b);
  AlignedFloats fx = padded(blocks, x), fax(fb.size(), 1.0f), swept_only = fx;
  blocks.backward_sweep_with_product(b, &x, &ax);
  blocks.backward_sweep_with_product(fb.data(), fx.data(), fax.data());
  blocks.backward_sweep_with_product(fb.data(), swept_only.data(), nullptr);
  EXPECT_LT((unpadded(fx) - x).norm(), 1e-5 * x.norm());
  EXPECT_LT((unpadded(fax) - ax).norm(), 1e-5 * ax.norm());
  EXPECT_EQ(swept_only, fx);  // the product changes nothing of the sweep
  EXPECT_EQ(fax[4 + 0], 0.0f);
  expect_padding_zero(fx);
  expect_padding_zero(fax);
}

// Values far below float's normal range (~1e-38), as the sweeps meet far
// from the grips, are flushed to 0 inside the passes (they had made them 2x
// slower than the double ones), and the caller's mode is restored after.
TEST(VertexBlockFloatSweeps, SubnormalValuesAreFlushedInsideThePassesOnly) {
  const BlockSystem s = block_system(12, 30.0, 26);
  const VertexBlockMatrix blocks(s.matrix, s.index);
  const Eigen::VectorXd b = 1e-41 * blocks.to_blocks(random_vector(s.matrix.rows(), 27));
  // the control bits (rounding, flush, masks), not the sticky exception flags
  const auto control = [] { return _mm_getcsr() & ~0x3Fu; };
  const unsigned mode = control();
  const AlignedFloats fb = padded(blocks, b);  // subnormal floats
  ASSERT_NE(fb[1], 0.0f);
  AlignedFloats fx(fb.size()), fr(fb.size());
  blocks.sweep_from_zero_with_residual(fb.data(), fx.data(), fr.data());
  EXPECT_EQ(control(), mode);
  for (const float v : fx) EXPECT_EQ(v, 0.0f);
  blocks.backward_sweep_with_product(fb.data(), fx.data(), fr.data());
  EXPECT_EQ(control(), mode);
  volatile float tiny = 1e-41f;  // the caller still computes subnormals
  EXPECT_NE(tiny * 1.0f, 0.0f);
}

// With scalar blocks (identity couplings) the float passes are those of
// the copy with full blocks, to float rounding.
TEST(VertexBlockFloatSweeps, ThePassesWithScalarBlocksAreThoseWithFullBlocks) {
  const BlockSystem s = block_system(40, 30.0, 28, true);
  ASSERT_GT(s.identity_pairs.size(), 30u);
  const VertexBlockMatrix full(s.matrix, s.index), scalar(s.matrix, s.index, true, s.identity_pairs);
  const AlignedFloats fb = padded(full, full.to_blocks(random_vector(s.matrix.rows(), 29)));
  AlignedFloats x(fb.size()), r(fb.size()), fx(fb.size()), fr(fb.size());
  scalar.sweep_from_zero_with_residual(fb.data(), x.data(), r.data());
  full.sweep_from_zero_with_residual(fb.data(), fx.data(), fr.data());
  EXPECT_LT((unpadded(x) - unpadded(fx)).norm(), 1e-5 * unpadded(fx).norm());
  EXPECT_LT((unpadded(r) - unpadded(fr)).norm(), 1e-5 * unpadded(fr).norm());
  AlignedFloats ax(fb.size()), fax(fb.size());
  scalar.backward_sweep_with_product(fb.data(), x.data(), ax.data());
  full.backward_sweep_with_product(fb.data(), fx.data(), fax.data());
  EXPECT_LT((unpadded(x) - unpadded(fx)).norm(), 1e-5 * unpadded(fx).norm());
  EXPECT_LT((unpadded(ax) - unpadded(fax)).norm(), 1e-5 * unpadded(fax).norm());
  EXPECT_EQ(ax[4 + 0], 0.0f);  // the held axis
  expect_padding_zero(x);
  expect_padding_zero(ax);
  expect_padding_zero(r);
}

}  // namespace
}  // namespace repose
