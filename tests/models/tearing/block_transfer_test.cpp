// The multigrid's transfers between block vectors: the restriction and the
// interpolation are Eigen's products with the same P bit for bit, in double
// and from and into the float passes' vectors (4 floats a vertex); a P that
// mixes axes is refused.
#include "models/tearing/block_transfer.h"

#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <gtest/gtest.h>

#include "tests/models/tearing/block_system_fixture.h"

namespace repose {
namespace {

using testing::random_vector;

// P between block vectors of `fine` and `coarse` vertices: fine vertex v
// takes coarse vertices v / 2 and, when odd, (v + 1) / 2 and a third
// further off (as the sheet's cell middles take four), random weights per
// axis; some axes without an entry (held on either side).
Eigen::SparseMatrix<double> random_interpolation(int fine, int coarse, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> weight(-0.3, 1.0);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int v = 0; v < fine; ++v) {
    std::vector<int> targets = {v / 2};
    if (v % 2 == 1 && (v + 1) / 2 < coarse) targets.push_back((v + 1) / 2);
    if (v % 3 == 0) targets.push_back((v / 2 + 5) % coarse);
    for (const int c : targets) {
      for (int axis = 0; axis < 3; ++axis) {
        if ((v + c + axis) % 7 == 0) continue;  // no entry
        triplets.emplace_back(3 * v + axis, 3 * c + axis, weight(rng));
      }
    }
  }
  Eigen::SparseMatrix<double> p(3 * fine, 3 * coarse);
  p.setFromTriplets(triplets.begin(), triplets.end());
  p.makeCompressed();
  return p;
}

std::vector<float> to_float4(const Eigen::VectorXd& x) {
  std::vector<float> f(static_cast<std::size_t>(4 * (x.size() / 3)), 0.0f);
  for (Eigen::Index v = 0; v < x.size() / 3; ++v) {
    for (int a = 0; a < 3; ++a) f[static_cast<std::size_t>(4 * v + a)] = static_cast<float>(x[3 * v + a]);
  }
  return f;
}

TEST(BlockTransfer, TheRestrictionIsTheTransposedProductBitForBit) {
  const int fine = 41, coarse = 21;
  const Eigen::SparseMatrix<double> p = random_interpolation(fine, coarse, 1);
  const Eigen::SparseMatrix<double> restriction = p.transpose();
  const BlockTransfer transfer(p);
  EXPECT_EQ(transfer.fine_rows(), fine);
  EXPECT_EQ(transfer.coarse_rows(), coarse);
  const Eigen::VectorXd r = random_vector(3 * fine, 2);
  Eigen::VectorXd expected, got = Eigen::VectorXd::Constant(5, 7.0);  // resized and overwritten
  expected.noalias() = restriction * r;
  transfer.restrict_to(r, &got);
  ASSERT_EQ(got.size(), expected.size());
  for (Eigen::Index k = 0; k < got.size(); ++k) EXPECT_EQ(got[k], expected[k]) << k;
  // from float vectors: the product of the residual as the floats hold it
  const std::vector<float> r4 = to_float4(r);
  Eigen::VectorXd r_rounded(3 * fine);
  for (int v = 0; v < fine; ++v) {
    for (int a = 0; a < 3; ++a) r_rounded[3 * v + a] = r4[static_cast<std::size_t>(4 * v + a)];
  }
  expected.noalias() = restriction * r_rounded;
  transfer.restrict_to(r4.data(), &got);
  for (Eigen::Index k = 0; k < got.size(); ++k) EXPECT_EQ(got[k], expected[k]) << k;
}

TEST(BlockTransfer, TheInterpolationIsTheProductBitForBit) {
  const int fine = 41, coarse = 21;
  const Eigen::SparseMatrix<double> p = random_interpolation(fine, coarse, 3);
  const BlockTransfer transfer(p);
  const Eigen::VectorXd c = random_vector(3 * coarse, 4), x0 = random_vector(3 * fine, 5);
  Eigen::VectorXd expected = x0, got = x0;
  expected.noalias() += p * c;
  transfer.add_interpolated(c, &got);
  for (Eigen::Index k = 0; k < got.size(); ++k) EXPECT_EQ(got[k], expected[k]) << k;
  // into float vectors: P c in double, rounded, added; lane 3 left alone
  std::vector<float> x4 = to_float4(x0);
  for (int v = 0; v < fine; ++v) x4[static_cast<std::size_t>(4 * v + 3)] = 0.5f;
  const Eigen::VectorXd correction = p * c;
  transfer.add_interpolated(c, x4.data());
  for (int v = 0; v < fine; ++v) {
    for (int a = 0; a < 3; ++a) {
      const float expected_float = static_cast<float>(x0[3 * v + a]) + static_cast<float>(correction[3 * v + a]);
      EXPECT_EQ(x4[static_cast<std::size_t>(4 * v + a)], expected_float) << v << " " << a;
    }
    EXPECT_EQ(x4[static_cast<std::size_t>(4 * v + 3)], 0.5f);
  }
}

// Made from P between unknowns (held axes dropped) and the places of the
// unknowns in the block vectors, it transfers what the block-vector P does.
TEST(BlockTransfer, MadeFromThePlacesOfTheUnknownsItIsTheBlockVectorOne) {
  const int fine = 29, coarse = 15;
  Eigen::SparseMatrix<double> blocks = random_interpolation(fine, coarse, 6);
  // fine axes with (v + axis) % 5 == 0 and coarse ones with (V + axis) % 4 == 1 held
  const auto held_fine = [](int k) { return (k / 3 + k % 3) % 5 == 0; };
  const auto held_coarse = [](int k) { return (k / 3 + k % 3) % 4 == 1; };
  blocks.prune([&](Eigen::Index r, Eigen::Index c, double) { return !held_fine(static_cast<int>(r)) && !held_coarse(static_cast<int>(c)); });
  std::vector<int> fine_place, coarse_place, fine_unknown(3 * fine, -1), coarse_unknown(3 * coarse, -1);
  for (int k = 0; k < 3 * fine; ++k) {
    if (!held_fine(k)) fine_unknown[static_cast<std::size_t>(k)] = static_cast<int>(fine_place.size()), fine_place.push_back(k);
  }
  for (int k = 0; k < 3 * coarse; ++k) {
    if (!held_coarse(k)) coarse_unknown[static_cast<std::size_t>(k)] = static_cast<int>(coarse_place.size()), coarse_place.push_back(k);
  }
  std::vector<Eigen::Triplet<double>> triplets;
  for (int c = 0; c < blocks.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(blocks, c); it; ++it) {
      triplets.emplace_back(fine_unknown[static_cast<std::size_t>(it.row())], coarse_unknown[static_cast<std::size_t>(c)], it.value());
    }
  }
  Eigen::SparseMatrix<double> p(static_cast<Eigen::Index>(fine_place.size()), static_cast<Eigen::Index>(coarse_place.size()));
  p.setFromTriplets(triplets.begin(), triplets.end());
  const BlockTransfer from_blocks(blocks), from_places(p, fine_place, coarse_place, fine, coarse);
  EXPECT_EQ(from_places.fine_rows(), fine);
  EXPECT_EQ(from_places.coarse_rows(), coarse);
  const Eigen::VectorXd r = random_vector(3 * fine, 7), c = random_vector(3 * coarse, 8);
  Eigen::VectorXd a, b, x = random_vector(3 * fine, 9), y = x;
  from_blocks.restrict_to(r, &a);
  from_places.restrict_to(r, &b);
  EXPECT_EQ(a, b);
  from_blocks.add_interpolated(c, &x);
  from_places.add_interpolated(c, &y);
  EXPECT_EQ(x, y);
  EXPECT_GT((x - random_vector(3 * fine, 9)).norm(), 0.1);
}

TEST(BlockTransfer, AnInterpolationMixingAxesIsRefused) {
  Eigen::SparseMatrix<double> p(6, 3);
  p.insert(4, 1) = 0.5;  // fine vertex 1's y from coarse vertex 0's y: kept
  EXPECT_NO_THROW(BlockTransfer{p});
  p.insert(3, 2) = 0.5;  // fine vertex 1's x from coarse vertex 0's z
  p.makeCompressed();
  EXPECT_THROW(BlockTransfer{p}, std::logic_error);
}

}  // namespace
}  // namespace repose
