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

}  // namespace

Eigen::SparseMatrix<double> galerkin_product(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& p,
                                             const std::vector<int>& fine_index, const std::vector<int>& coarse_index) {
  REPOSE_DEMAND(a.isCompressed() && a.rows() == a.cols() && p.rows() == a.rows());
  const int fine_vertices = static_cast<int>(fine_index.size() / 3);
  const int coarse_vertices = static_cast<int>(coarse_index.size() / 3);
  const auto fine_of = vertex_axis(fine_index, static_cast<int>(a.rows()));
  const auto coarse_of = vertex_axis(coarse_index, static_cast<int>(p.cols()));
  // per fine vertex its coarse vertices (forward), per coarse vertex its fine ones (reverse)
  Links forward(static_cast<std::size_t>(fine_vertices)), reverse(static_cast<std::size_t>(coarse_vertices));
  for (int c = 0; c < p.outerSize(); ++c) {
    const auto [coarse_vertex, axis] = coarse_of[static_cast<std::size_t>(c)];
    for (Eigen::SparseMatrix<double>::InnerIterator it(p, c); it; ++it) {
      const auto [fine_vertex, fine_axis] = fine_of[static_cast<std::size_t>(it.row())];
      REPOSE_DEMAND(fine_axis == axis);
      add_link(&forward[static_cast<std::size_t>(fine_vertex)], coarse_vertex, axis, it.value());
      add_link(&reverse[static_cast<std::size_t>(coarse_vertex)], fine_vertex, axis, it.value());
    }
  }
  const BlockRows fine = block_rows_of(a, fine_index, fine_of, fine_vertices);
  // coarse block rows, one at a time; then the scalar columns (C symmetric: column (J, b) is row (J, b))
  std::vector<int> slot_of(static_cast<std::size_t>(coarse_vertices), -1);
  std::vector<std::vector<int>> partner(static_cast<std::size_t>(coarse_vertices));
  std::vector<std::vector<std::array<double, 9>>> value(static_cast<std::size_t>(coarse_vertices));
  for (int big_i = 0; big_i < coarse_vertices; ++big_i) {
    std::vector<int>& cols = partner[static_cast<std::size_t>(big_i)];
    std::vector<std::array<double, 9>>& vals = value[static_cast<std::size_t>(big_i)];
    for (const auto& [i, wi] : reverse[static_cast<std::size_t>(big_i)]) {
      for (int k = fine.begin[static_cast<std::size_t>(i)]; k < fine.begin[static_cast<std::size_t>(i) + 1]; ++k) {
        const std::array<double, 9>& block = fine.value[static_cast<std::size_t>(k)];
        for (const auto& [big_j, wj] : forward[static_cast<std::size_t>(fine.partner[static_cast<std::size_t>(k)])]) {
          int& slot = slot_of[static_cast<std::size_t>(big_j)];
          if (slot < 0) {
            slot = static_cast<int>(cols.size());
            cols.push_back(big_j);
            vals.push_back({});
          }
          std::array<double, 9>& out = vals[static_cast<std::size_t>(slot)];
          for (int r = 0; r < 3; ++r) {
            for (int s = 0; s < 3; ++s) out[static_cast<std::size_t>(3 * r + s)] += wi[r] * block[3 * r + s] * wj[s];
          }
        }
      }
    }
    for (const int j : cols) slot_of[static_cast<std::size_t>(j)] = -1;
  }
  // scalar CSC: column (J, b) holds rows (I, a) of row J's blocks, I ascending
  std::vector<Eigen::Index> outer(static_cast<std::size_t>(p.cols()) + 1, 0);
  std::vector<int> inner;
  std::vector<double> values;
  std::size_t blocks = 0;
  for (const std::vector<int>& cols : partner) blocks += cols.size();
  inner.reserve(9 * blocks);
  values.reserve(9 * blocks);
  for (int big_j = 0; big_j < coarse_vertices; ++big_j) {
    const std::vector<int>& cols = partner[static_cast<std::size_t>(big_j)];
    std::vector<int> order(cols.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int x, int y) { return cols[static_cast<std::size_t>(x)] < cols[static_cast<std::size_t>(y)]; });
    for (int b = 0; b < 3; ++b) {
      const int column = coarse_index[static_cast<std::size_t>(3 * big_j + b)];
      if (column < 0) continue;
      for (const int o : order) {
        const int big_i = cols[static_cast<std::size_t>(o)];
        const std::array<double, 9>& block = value[static_cast<std::size_t>(big_j)][static_cast<std::size_t>(o)];
        for (int r = 0; r < 3; ++r) {
          const int row = coarse_index[static_cast<std::size_t>(3 * big_i + r)];
          if (row < 0) continue;
          inner.push_back(row);
          values.push_back(block[static_cast<std::size_t>(3 * b + r)]);  // C(I a, J b) = C(J b, I a)
        }
      }
      outer[static_cast<std::size_t>(column) + 1] = static_cast<Eigen::Index>(inner.size());
    }
  }
  Eigen::SparseMatrix<double> c(p.cols(), p.cols());
  c.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(inner.begin(), inner.end(), c.innerIndexPtr());
  std::copy(values.begin(), values.end(), c.valuePtr());
  for (std::size_t k = 0; k < outer.size(); ++k) c.outerIndexPtr()[k] = static_cast<int>(outer[k]);
  return c;
}

}  // namespace repose
