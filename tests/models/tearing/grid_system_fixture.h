#pragma once
// A grid system shared by the multigrid's and the conjugate gradients'
// tests (sheet_multigrid_test.cpp, conjugate_gradients_test.cpp).

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace repose::testing {

// A grid system like the integrator's: per vertex mass m on the diagonal of
// its three axes, springs of random stiffness (times `stiffness_over_mass`)
// along the grid lines and diagonals, each coupling all three axes through
// a random rank-one direction plus 10 % isotropic part (positive
// semidefinite blocks [h -h; -h h]); the springs crossing the vertical cut
// x = vertices_x / 2 over the top third are removed (a tear), and the left
// column is held in all axes.
struct GridSystem {
  int vertices_x = 0, vertices_y = 0;
  std::vector<int> free_index;
  Eigen::SparseMatrix<double> matrix;
};

inline GridSystem grid_system(int vertices_x, int vertices_y, double stiffness_over_mass, std::uint64_t seed) {
  GridSystem g;
  g.vertices_x = vertices_x;
  g.vertices_y = vertices_y;
  const int vertices = vertices_x * vertices_y;
  g.free_index.assign(static_cast<std::size_t>(3 * vertices), -1);
  int count = 0;
  for (int v = 0; v < vertices; ++v) {
    for (int a = 0; a < 3; ++a) {
      if (v % vertices_x != 0) g.free_index[static_cast<std::size_t>(3 * v + a)] = count++;
    }
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> stiffness(0.2, 1.0), direction(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> triplets;
  const auto add = [&](int va, int vb, const Eigen::Matrix3d& h) {
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) {
        const int row = g.free_index[static_cast<std::size_t>(3 * va + p)];
        const int col = g.free_index[static_cast<std::size_t>(3 * vb + q)];
        if (row >= 0 && col >= 0) triplets.emplace_back(row, col, h(p, q));
      }
    }
  };
  for (int v = 0; v < vertices; ++v) add(v, v, Eigen::Matrix3d::Identity());
  const int cut = vertices_x / 2;
  for (int j = 0; j < vertices_y; ++j) {
    for (int i = 0; i < vertices_x; ++i) {
      for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{0, 1}, std::pair{1, 1}, std::pair{-1, 1}}) {
        const int ni = i + di, nj = j + dj;
        if (ni < 0 || ni >= vertices_x || nj >= vertices_y) continue;
        const bool crosses = (i < cut) != (ni < cut) && j > 2 * vertices_y / 3;
        if (crosses) continue;
        Eigen::Vector3d n(direction(rng), direction(rng), direction(rng));
        n.normalize();
        const Eigen::Matrix3d h =
            stiffness_over_mass * stiffness(rng) * (n * n.transpose() + 0.1 * Eigen::Matrix3d::Identity());
        const int a = j * vertices_x + i, b = nj * vertices_x + ni;
        add(a, a, h);
        add(b, b, h);
        add(a, b, -h);
        add(b, a, -h);
      }
    }
  }
  g.matrix.resize(count, count);
  g.matrix.setFromTriplets(triplets.begin(), triplets.end());
  g.matrix.makeCompressed();
  return g;
}

}  // namespace repose::testing
