#pragma once
// A small block system shared by the tests of the float 3 x 3 block copy
// (vertex_block_matrix_test.cpp, vertex_block_float_sweeps_test.cpp).

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace repose::testing {

// A chain of `vertices` vertices coupled to the next two by random positive
// semidefinite blocks, unit mass; vertex 0 held in all axes, vertex 2 in x
// only (index -1), so some blocks are partly held. With identity_second,
// a vertex and the one two along are coupled by a random multiple of the
// identity instead (as the sheet's bending ends are), and
// identity_pairs names those pairs whose vertices are free in every axis.
struct BlockSystem {
  std::vector<int> index;
  Eigen::SparseMatrix<double> matrix;
  std::vector<std::pair<int, int>> identity_pairs;
};

inline BlockSystem block_system(int vertices, double stiffness, std::uint64_t seed, bool identity_second = false) {
  BlockSystem s;
  s.index.assign(static_cast<std::size_t>(3 * vertices), -1);
  int count = 0;
  for (int v = 0; v < vertices; ++v) {
    for (int a = 0; a < 3; ++a) {
      if (v != 0 && !(v == 2 && a == 0)) s.index[static_cast<std::size_t>(3 * v + a)] = count++;
    }
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> triplets;
  const auto add = [&](int va, int vb, const Eigen::Matrix3d& h) {
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) {
        const int row = s.index[static_cast<std::size_t>(3 * va + p)], col = s.index[static_cast<std::size_t>(3 * vb + q)];
        if (row >= 0 && col >= 0) triplets.emplace_back(row, col, h(p, q));
      }
    }
  };
  for (int v = 0; v < vertices; ++v) add(v, v, Eigen::Matrix3d::Identity());
  for (int v = 0; v < vertices; ++v) {
    for (int step = 1; step <= 2 && v + step < vertices; ++step) {
      const Eigen::Vector3d n = Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng)).normalized();
      Eigen::Matrix3d h = stiffness * (n * n.transpose() + 0.1 * Eigen::Matrix3d::Identity());
      if (identity_second && step == 2) {
        h = stiffness * (0.6 + 0.5 * uniform(rng)) * Eigen::Matrix3d::Identity();
        if (v != 0 && v != 2 && v + step != 2) s.identity_pairs.emplace_back(v, v + step);
      }
      add(v, v, h);
      add(v + step, v + step, h);
      add(v, v + step, -h);
      add(v + step, v, -h);
    }
  }
  s.matrix.resize(count, count);
  s.matrix.setFromTriplets(triplets.begin(), triplets.end());
  s.matrix.makeCompressed();
  return s;
}

inline Eigen::VectorXd random_vector(Eigen::Index n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i) x[i] = uniform(rng);
  return x;
}

}  // namespace repose::testing
