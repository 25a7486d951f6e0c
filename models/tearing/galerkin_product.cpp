#include "models/tearing/galerkin_product.h"

#include <algorithm>
#include <array>
#include <numeric>

#include "models/core/base/error.h"

namespace repose {

namespace {

using Weights = std::array<double, 3>;  // per axis

// Per vertex of one side, its partners on the other with their per-axis weights.
using Links = std::vector<std::vector<std::pair<int, Weights>>>;

void add_link(std::vector<std::pair<int, Weights>>* links, int partner, int axis, double w) {
  for (auto& [other, weights] : *links) {
    if (other == partner) {
      weights[static_cast<std::size_t>(axis)] = w;
      return;
    }
  }
  Weights weights = {0.0, 0.0, 0.0};
  weights[static_cast<std::size_t>(axis)] = w;
  links->emplace_back(partner, weights);
}

// Per (unknown) its (vertex, axis), from an index.
std::vector<std::pair<int, int>> vertex_axis(const std::vector<int>& index, int count) {
  std::vector<std::pair<int, int>> of(static_cast<std::size_t>(count), {-1, -1});
  for (std::size_t k = 0; k < index.size(); ++k) {
    if (index[k] >= 0) of[static_cast<std::size_t>(index[k])] = {static_cast<int>(k / 3), static_cast<int>(k % 3)};
  }
  return of;
}

// A's blocks per fine vertex (partner vertex, 3 x 3 row-major), flat: the
// blocks of vertex v at [begin[v], begin[v + 1]).
struct BlockRows {
  std::vector<int> begin, partner;
  std::vector<std::array<double, 9>> value;
};

BlockRows block_rows_of(const Eigen::SparseMatrix<double>& a, const std::vector<int>& fine_index,
                        const std::vector<std::pair<int, int>>& fine_of, int vertices) {
  BlockRows rows;
  rows.begin.assign(static_cast<std::size_t>(vertices) + 1, 0);
  rows.partner.reserve(static_cast<std::size_t>(a.nonZeros()) / 3);
  rows.value.reserve(static_cast<std::size_t>(a.nonZeros()) / 3);
  std::vector<int> slot_of(static_cast<std::size_t>(vertices), -1);
  for (int v = 0; v < vertices; ++v) {
    const std::size_t first = rows.partner.size();
    // A symmetric: column (v, p) is row (v, p)
    for (int p = 0; p < 3; ++p) {
      const int c = fine_index[static_cast<std::size_t>(3 * v + p)];
      if (c < 0) continue;
      for (int k = a.outerIndexPtr()[c]; k < a.outerIndexPtr()[c + 1]; ++k) {
        const auto [u, q] = fine_of[static_cast<std::size_t>(a.innerIndexPtr()[k])];
        int& slot = slot_of[static_cast<std::size_t>(u)];
        if (slot < 0) {
          slot = static_cast<int>(rows.partner.size());
          rows.partner.push_back(u);
          rows.value.push_back({});
        }
        rows.value[static_cast<std::size_t>(slot)][static_cast<std::size_t>(3 * p + q)] += a.valuePtr()[k];
      }
    }
    for (std::size_t k = first; k < rows.partner.size(); ++k) slot_of[static_cast<std::size_t>(rows.partner[k])] = -1;
    rows.begin[static_cast<std::size_t>(v) + 1] = static_cast<int>(rows.partner.size());
  }
  return rows;
}

// Per fine vertex its coarse vertices (forward), per coarse vertex its fine
// ones (reverse), with the per-axis weights of p.
void interpolation_links(const Eigen::SparseMatrix<double>& p, const std::vector<std::pair<int, int>>& fine_of,
                         const std::vector<std::pair<int, int>>& coarse_of, Links* forward, Links* reverse) {
  for (int c = 0; c < p.outerSize(); ++c) {
    const auto [coarse_vertex, axis] = coarse_of[static_cast<std::size_t>(c)];
    for (Eigen::SparseMatrix<double>::InnerIterator it(p, c); it; ++it) {
      const auto [fine_vertex, fine_axis] = fine_of[static_cast<std::size_t>(it.row())];
      REPOSE_DEMAND(fine_axis == axis);
      add_link(&(*forward)[static_cast<std::size_t>(fine_vertex)], coarse_vertex, axis, it.value());
      add_link(&(*reverse)[static_cast<std::size_t>(coarse_vertex)], fine_vertex, axis, it.value());
    }
  }
}

// The coarse blocks per coarse vertex (partner, 3 x 3 row-major), unsorted.
struct CoarseRows {
  std::vector<std::vector<int>> partner;
  std::vector<std::vector<std::array<double, 9>>> value;
};

// Row I of P^T A P: sum over its fine vertices i, their blocks (i, j) and
// j's coarse vertices J of diag(w_iI) A_ij diag(w_jJ), a row at a time.
CoarseRows coarse_block_rows(const BlockRows& fine, const Links& forward, const Links& reverse) {
  const std::size_t coarse_vertices = reverse.size();
  CoarseRows rows;
  rows.partner.resize(coarse_vertices);
  rows.value.resize(coarse_vertices);
  std::vector<int> slot_of(coarse_vertices, -1);
  for (std::size_t big_i = 0; big_i < coarse_vertices; ++big_i) {
    std::vector<int>& cols = rows.partner[big_i];
    std::vector<std::array<double, 9>>& vals = rows.value[big_i];
    for (const auto& [i, wi] : reverse[big_i]) {
      for (int k = fine.begin[static_cast<std::size_t>(i)]; k < fine.begin[static_cast<std::size_t>(i) + 1]; ++k) {
        const std::array<double, 9>& block = fine.value[static_cast<std::size_t>(k)];
        std::array<double, 9> left;  // diag(w_iI) A_ij, the same for every J
        for (int r = 0; r < 3; ++r) {
          for (int s = 0; s < 3; ++s) left[static_cast<std::size_t>(3 * r + s)] = wi[r] * block[3 * r + s];
        }
        for (const auto& [big_j, wj] : forward[static_cast<std::size_t>(fine.partner[static_cast<std::size_t>(k)])]) {
          int& slot = slot_of[static_cast<std::size_t>(big_j)];
          if (slot < 0) {
            slot = static_cast<int>(cols.size());
            cols.push_back(big_j);
            vals.push_back({});
          }
          std::array<double, 9>& out = vals[static_cast<std::size_t>(slot)];
          for (int r = 0; r < 3; ++r) {
            for (int s = 0; s < 3; ++s) {
              out[static_cast<std::size_t>(3 * r + s)] += left[static_cast<std::size_t>(3 * r + s)] * wj[s];
            }
          }
        }
      }
    }
    for (const int j : cols) slot_of[static_cast<std::size_t>(j)] = -1;
  }
  return rows;
}

// The scalar compressed matrix of the coarse rows (count unknowns, numbered
// by coarse_index): column (J, b) holds rows (I, a) of row J's blocks, I
// ascending (the matrix symmetric: column (J, b) is row (J, b)).
Eigen::SparseMatrix<double> scalar_matrix(const CoarseRows& rows, const std::vector<int>& coarse_index, int count) {
  std::vector<int> outer(static_cast<std::size_t>(count) + 1, 0), inner;
  std::vector<double> values;
  std::size_t blocks = 0;
  for (const std::vector<int>& cols : rows.partner) blocks += cols.size();
  inner.reserve(9 * blocks);
  values.reserve(9 * blocks);
  for (std::size_t big_j = 0; big_j < rows.partner.size(); ++big_j) {
    const std::vector<int>& cols = rows.partner[big_j];
    std::vector<int> order(cols.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](int x, int y) { return cols[static_cast<std::size_t>(x)] < cols[static_cast<std::size_t>(y)]; });
    for (int b = 0; b < 3; ++b) {
      const int column = coarse_index[3 * big_j + static_cast<std::size_t>(b)];
      if (column < 0) continue;
      for (const int o : order) {
        const int big_i = cols[static_cast<std::size_t>(o)];
        const std::array<double, 9>& block = rows.value[big_j][static_cast<std::size_t>(o)];
        for (int r = 0; r < 3; ++r) {
          const int row = coarse_index[static_cast<std::size_t>(3 * big_i + r)];
          if (row < 0) continue;
          inner.push_back(row);
          values.push_back(block[static_cast<std::size_t>(3 * b + r)]);  // C(I a, J b) = C(J b, I a)
        }
      }
      outer[static_cast<std::size_t>(column) + 1] = static_cast<int>(inner.size());
    }
  }
  Eigen::SparseMatrix<double> c(count, count);
  c.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(inner.begin(), inner.end(), c.innerIndexPtr());
  std::copy(values.begin(), values.end(), c.valuePtr());
  std::copy(outer.begin(), outer.end(), c.outerIndexPtr());
  return c;
}

}  // namespace

Eigen::SparseMatrix<double> galerkin_product(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& p,
                                             const std::vector<int>& fine_index, const std::vector<int>& coarse_index) {
  REPOSE_DEMAND(a.isCompressed() && a.rows() == a.cols() && p.rows() == a.rows());
  const int fine_vertices = static_cast<int>(fine_index.size() / 3);
  const auto fine_of = vertex_axis(fine_index, static_cast<int>(a.rows()));
  const auto coarse_of = vertex_axis(coarse_index, static_cast<int>(p.cols()));
  Links forward(static_cast<std::size_t>(fine_vertices)), reverse(coarse_index.size() / 3);
  interpolation_links(p, fine_of, coarse_of, &forward, &reverse);
  const BlockRows fine = block_rows_of(a, fine_index, fine_of, fine_vertices);
  return scalar_matrix(coarse_block_rows(fine, forward, reverse), coarse_index, static_cast<int>(p.cols()));
}

}  // namespace repose
