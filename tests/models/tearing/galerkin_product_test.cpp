// The coarse operator by vertex blocks: P^T A P to round-off for an
// interpolation that keeps the axis, with held axes on both sides.
#include "models/tearing/galerkin_product.h"

#include <random>
#include <vector>

#include <Eigen/Core>

#include <gtest/gtest.h>

#include "tests/models/tearing/block_system_fixture.h"

namespace repose {
namespace {

using testing::block_system;
using testing::BlockSystem;

TEST(GalerkinProduct, IsTheSparseProductOfTheInterpolationAndTheSystem) {
  const int vertices = 23;
  const BlockSystem s = block_system(vertices, 30.0, 41);  // vertex 0 held, vertex 2 held in x
  // coarse vertex V = v / 2 (v even), (v - 1) / 2 and (v + 1) / 2 (v odd), weights drawn per vertex pair and axis
  const int coarse_vertices = vertices / 2 + 1;
  std::vector<int> coarse_index(static_cast<std::size_t>(3 * coarse_vertices), -1);
  std::vector<std::vector<std::pair<int, double>>> stencil(s.index.size());
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> weight(0.2, 1.0);
  for (int v = 0; v < vertices; ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      if (s.index[static_cast<std::size_t>(3 * v + axis)] < 0) continue;
      const std::vector<int> coarse = v % 2 == 0 ? std::vector<int>{v / 2} : std::vector<int>{(v - 1) / 2, (v + 1) / 2};
      for (const int c : coarse) stencil[static_cast<std::size_t>(3 * v + axis)].emplace_back(3 * c + axis, weight(rng));
    }
  }
  int count = 0;
  for (int k = 0; k < 3 * coarse_vertices; ++k) {
    bool reached = false;
    for (const auto& entries : stencil) {
      for (const auto& entry : entries) reached = reached || entry.first == k;
    }
    if (reached) coarse_index[static_cast<std::size_t>(k)] = count++;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  for (std::size_t k = 0; k < stencil.size(); ++k) {
    for (const auto& [c, w] : stencil[k]) {
      triplets.emplace_back(s.index[k], coarse_index[static_cast<std::size_t>(c)], w);
    }
  }
  Eigen::SparseMatrix<double> p(s.matrix.rows(), count);
  p.setFromTriplets(triplets.begin(), triplets.end());
  p.makeCompressed();
  const Eigen::SparseMatrix<double> expected = Eigen::SparseMatrix<double>(p.transpose()) * (s.matrix * p);
  const Eigen::SparseMatrix<double> c = galerkin_product(s.matrix, p, s.index, coarse_index);
  ASSERT_EQ(c.rows(), count);
  ASSERT_EQ(c.cols(), count);
  EXPECT_TRUE(c.isCompressed());
  const Eigen::MatrixXd difference = Eigen::MatrixXd(c) - Eigen::MatrixXd(expected);
  EXPECT_LT(difference.norm(), 1e-13 * Eigen::MatrixXd(expected).norm());
  EXPECT_GT(Eigen::MatrixXd(expected).norm(), 1.0);
  // rows ascending in every column (what Eigen's compressed storage requires)
  for (int col = 0; col < c.cols(); ++col) {
    for (int k = c.outerIndexPtr()[col] + 1; k < c.outerIndexPtr()[col + 1]; ++k) {
      EXPECT_LT(c.innerIndexPtr()[k - 1], c.innerIndexPtr()[k]);
    }
  }
}

}  // namespace
}  // namespace repose
