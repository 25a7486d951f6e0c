#include "models/tearing/vertex_block_matrix.h"

#include <algorithm>

#include <Eigen/LU>

#include "models/core/base/error.h"

namespace repose {

namespace {

// The identity pairs as sorted (block row, block column), both orders.
std::vector<std::pair<int, int>> identity_blocks(const std::vector<std::pair<int, int>>& identity_pairs,
                                                 const std::vector<int>& block_of_vertex, const std::vector<int>& index) {
  const auto all_free = [&](int v) {
    for (int axis = 0; axis < 3; ++axis) {
      if (index[static_cast<std::size_t>(3 * v + axis)] < 0) return false;
    }
    return true;
  };
  std::vector<std::pair<int, int>> blocks;
  for (const auto& [u, v] : identity_pairs) {
    REPOSE_DEMAND(u != v && std::min(u, v) >= 0 && static_cast<std::size_t>(3 * std::max(u, v) + 2) < index.size());
    REPOSE_DEMAND(all_free(u) && all_free(v));
    const int i = block_of_vertex[static_cast<std::size_t>(u)], j = block_of_vertex[static_cast<std::size_t>(v)];
    blocks.emplace_back(i, j);
    blocks.emplace_back(j, i);
  }
  std::sort(blocks.begin(), blocks.end());
  blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
  return blocks;
}

}  // namespace

VertexBlockMatrix::VertexBlockMatrix(const Eigen::SparseMatrix<double>& a, const std::vector<int>& index,
                                     bool with_values, const std::vector<std::pair<int, int>>& identity_pairs) {
  REPOSE_DEMAND(a.rows() == a.cols() && a.isCompressed() && index.size() % 3 == 0);
  // block rows: the vertices with an unknown, in order
  const int vertices = static_cast<int>(index.size() / 3);
  std::vector<int> block_of_row(static_cast<std::size_t>(a.rows()), -1);
  std::vector<int> block_of_vertex(static_cast<std::size_t>(vertices), -1);
  for (int v = 0; v < vertices; ++v) {
    bool any = false;
    for (int axis = 0; axis < 3; ++axis) any = any || index[static_cast<std::size_t>(3 * v + axis)] >= 0;
    if (!any) continue;
    const int block = static_cast<int>(row_of_.size() / 3);
    block_of_vertex[static_cast<std::size_t>(v)] = block;
    for (int axis = 0; axis < 3; ++axis) {
      const int row = index[static_cast<std::size_t>(3 * v + axis)];
      row_of_.push_back(row);
      if (row >= 0) block_of_row[static_cast<std::size_t>(row)] = block;
    }
  }
  const int rows = static_cast<int>(row_of_.size() / 3);
  scalar_rows_ = static_cast<int>(a.rows());
  scalar_outer_.assign(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1);
  scalar_inner_.assign(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros());
  // the blocks of each block row: a is symmetric, so column c's rows are row c's columns
  std::vector<std::vector<int>> columns(static_cast<std::size_t>(rows));
  for (int c = 0; c < a.cols(); ++c) {
    const int block = block_of_row[static_cast<std::size_t>(c)];
    REPOSE_DEMAND(block >= 0);
    for (int k = a.outerIndexPtr()[c]; k < a.outerIndexPtr()[c + 1]; ++k) {
      columns[static_cast<std::size_t>(block)].push_back(block_of_row[static_cast<std::size_t>(a.innerIndexPtr()[k])]);
    }
  }
  split_blocks(&columns, identity_blocks(identity_pairs, block_of_vertex, index));
  find_sources(a);
  values_.assign(value_count() + 4, 0.0f);
  if (with_values) refresh(a);
}

// Each block row's columns (sorted here) into full blocks and the scalar
// blocks `identity` names (sorted (row, column) pairs, each in the pattern).
void VertexBlockMatrix::split_blocks(std::vector<std::vector<int>>* columns,
                                     const std::vector<std::pair<int, int>>& identity) {
  outer_.assign(1, 0);
  identity_outer_.assign(1, 0);
  std::size_t named = 0;  // identity blocks met in the pattern
  for (int i = 0; i < static_cast<int>(columns->size()); ++i) {
    std::vector<int>& cols = (*columns)[static_cast<std::size_t>(i)];
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
    int upper = -1;
    for (const int j : cols) {
      if (std::binary_search(identity.begin(), identity.end(), std::pair<int, int>(i, j))) {
        if (j > i && upper < 0) upper = static_cast<int>(identity_column_.size());
        identity_column_.push_back(j);
        ++named;
        continue;
      }
      if (j == i) diagonal_.push_back(static_cast<int>(column_.size()));
      column_.push_back(j);
    }
    REPOSE_DEMAND(static_cast<int>(diagonal_.size()) == i + 1);
    identity_upper_.push_back(upper < 0 ? static_cast<int>(identity_column_.size()) : upper);
    outer_.push_back(static_cast<int>(column_.size()));
    identity_outer_.push_back(static_cast<int>(identity_column_.size()));
  }
  REPOSE_DEMAND(named == identity.size());  // every pair named is coupled in the pattern
}

// Where each entry (p, q) of block (i, j) lies in a (source_,
// identity_source_): a's column row_of_(j, q) holds rows row_of_(i, p) for
// the blocks (i, j) of block column j, which are the blocks (j, i) of block
// row j (the pattern symmetric), i ascending: one walk down each column,
// each block row's blocks met in column order (a cursor per row and list).
void VertexBlockMatrix::find_sources(const Eigen::SparseMatrix<double>& a) {
  const int rows = block_rows();
  source_.assign(9 * column_.size(), -1);
  identity_source_.assign(9 * identity_column_.size(), -1);
  std::vector<int> full_at(outer_.begin(), outer_.end() - 1), identity_at(identity_outer_.begin(), identity_outer_.end() - 1);
  std::vector<std::pair<int, int*>> column_blocks;  // per block (i, j) of column j: i, its 9 sources
  for (int j = 0; j < rows; ++j) {
    column_blocks.clear();
    for (int k = outer_[static_cast<std::size_t>(j)]; k < outer_[static_cast<std::size_t>(j) + 1]; ++k) {
      const int i = column_[static_cast<std::size_t>(k)];
      const int at = full_at[static_cast<std::size_t>(i)]++;
      REPOSE_DEMAND(column_[static_cast<std::size_t>(at)] == j);  // a symmetric pattern
      column_blocks.emplace_back(i, source_.data() + 9 * static_cast<std::ptrdiff_t>(at));
    }
    for (int k = identity_outer_[static_cast<std::size_t>(j)]; k < identity_outer_[static_cast<std::size_t>(j) + 1]; ++k) {
      const int i = identity_column_[static_cast<std::size_t>(k)];
      const int at = identity_at[static_cast<std::size_t>(i)]++;
      REPOSE_DEMAND(identity_column_[static_cast<std::size_t>(at)] == j);
      column_blocks.emplace_back(i, identity_source_.data() + 9 * static_cast<std::ptrdiff_t>(at));
    }
    std::sort(column_blocks.begin(), column_blocks.end());
    for (int q = 0; q < 3; ++q) {
      const int col = row_of_[static_cast<std::size_t>(3 * j + q)];
      if (col < 0) continue;
      const int* at = a.innerIndexPtr() + a.outerIndexPtr()[col];
      const int* end = a.innerIndexPtr() + a.outerIndexPtr()[col + 1];
      for (const auto& [i, sources] : column_blocks) {
        for (int p = 0; p < 3; ++p) {
          const int row = row_of_[static_cast<std::size_t>(3 * i + p)];
          if (row < 0) continue;
          while (at != end && *at < row) ++at;
          if (at != end && *at == row) sources[3 * p + q] = static_cast<int>(at - a.innerIndexPtr());
        }
      }
    }
  }
  for (const int source : identity_source_) REPOSE_DEMAND(source >= 0);  // free in every axis
}

bool VertexBlockMatrix::has_pattern_of(const Eigen::SparseMatrix<double>& a) const {
  return a.isCompressed() && a.rows() == scalar_rows_ && a.cols() == scalar_rows_ &&
         static_cast<std::size_t>(a.nonZeros()) == scalar_inner_.size() &&
         std::equal(scalar_outer_.begin(), scalar_outer_.end(), a.outerIndexPtr()) &&
         std::equal(scalar_inner_.begin(), scalar_inner_.end(), a.innerIndexPtr());
}

void VertexBlockMatrix::refresh(const Eigen::SparseMatrix<double>& a) {
  REPOSE_DEMAND(static_cast<std::size_t>(a.nonZeros()) == scalar_inner_.size());
  const double* from = a.valuePtr();
  for (std::size_t k = 0; k < source_.size(); ++k) {
    values_[k] = source_[k] >= 0 ? static_cast<float>(from[source_[k]]) : 0.0f;
  }
  float* identity = values_.data() + source_.size();
  for (std::size_t k = 0; k < identity_column_.size(); ++k) {
    const int* at = &identity_source_[9 * k];
    const double value = from[at[0]];
    // the caller's promise: k I
    for (int e = 1; e < 9; ++e) REPOSE_DEMAND(from[at[e]] == (e % 4 == 0 ? value : 0.0));
    identity[k] = static_cast<float>(value);
  }
  invert_diagonal();
}

// D_i^-1 of the rounded matrix, so that both sweeps use one smoother; a
// held axis is given a unit diagonal to invert, then zeroed (its x stays 0).
// Every entry is written each time (no clearing pass: the fine level's runs
// each step).
void VertexBlockMatrix::invert_diagonal() {
  const int rows = block_rows();
  inverse_.resize(9 * static_cast<std::size_t>(rows));
  inverse_columns_.resize(12 * static_cast<std::size_t>(rows));
  for (int i = 0; i < rows; ++i) {
    const float* d = &values_[9 * static_cast<std::size_t>(diagonal_[static_cast<std::size_t>(i)])];
    Eigen::Matrix3d block;
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) block(p, q) = d[3 * p + q];
    }
    for (int p = 0; p < 3; ++p) {
      if (row_of_[static_cast<std::size_t>(3 * i + p)] >= 0) continue;
      block.row(p).setZero();
      block.col(p).setZero();
      block(p, p) = 1.0;
    }
    Eigen::Matrix3d inverse = block.inverse();
    for (int p = 0; p < 3; ++p) {
      if (row_of_[static_cast<std::size_t>(3 * i + p)] < 0) inverse(p, p) = 0.0;
    }
    REPOSE_DEMAND(inverse.allFinite());
    for (int q = 0; q < 3; ++q) {
      for (int p = 0; p < 3; ++p) {
        inverse_[9 * static_cast<std::size_t>(i) + 3 * p + q] = inverse(p, q);
        inverse_columns_[12 * static_cast<std::size_t>(i) + 4 * q + p] = static_cast<float>(inverse(p, q));
      }
      inverse_columns_[12 * static_cast<std::size_t>(i) + 4 * q + 3] = 0.0f;  // the padding
    }
  }
}

Eigen::VectorXd VertexBlockMatrix::to_blocks(const Eigen::VectorXd& x) const {
  Eigen::VectorXd blocks;
  to_blocks(x, &blocks);
  return blocks;
}

Eigen::VectorXd VertexBlockMatrix::from_blocks(const Eigen::VectorXd& blocks) const {
  Eigen::VectorXd x;
  from_blocks(blocks, &x);
  return x;
}

void VertexBlockMatrix::to_blocks(const Eigen::VectorXd& x, Eigen::VectorXd* blocks_out) const {
  Eigen::VectorXd& blocks = *blocks_out;
  blocks.resize(static_cast<Eigen::Index>(row_of_.size()));
  for (std::size_t k = 0; k < row_of_.size(); ++k) {
    blocks[static_cast<Eigen::Index>(k)] = row_of_[k] >= 0 ? x[row_of_[k]] : 0.0;
  }
}

void VertexBlockMatrix::from_blocks(const Eigen::VectorXd& blocks, Eigen::VectorXd* x_out) const {
  Eigen::VectorXd& x = *x_out;
  x.resize(scalar_rows_);
  for (std::size_t k = 0; k < row_of_.size(); ++k) {
    if (row_of_[k] >= 0) x[row_of_[k]] = blocks[static_cast<Eigen::Index>(k)];
  }
}

std::vector<int> VertexBlockMatrix::block_place_of_rows() const {
  std::vector<int> place(static_cast<std::size_t>(scalar_rows_), -1);
  for (std::size_t k = 0; k < row_of_.size(); ++k) {
    if (row_of_[k] >= 0) place[static_cast<std::size_t>(row_of_[k])] = static_cast<int>(k);
  }
  return place;
}

namespace {

inline void subtract_block(const float* m, const double* xj, double s[3]) {
  s[0] -= m[0] * xj[0] + m[1] * xj[1] + m[2] * xj[2];
  s[1] -= m[3] * xj[0] + m[4] * xj[1] + m[5] * xj[2];
  s[2] -= m[6] * xj[0] + m[7] * xj[1] + m[8] * xj[2];
}

// s -= A_ij x_j for the blocks [begin, end) of a row, in two interleaved
// sums (one chains every subtraction on the last: the sweep, whose rows
// wait on each other, was then bound by latency), in the order of memory
// or against it: a backward sweep that went forward within each row while
// its rows went back was ~5x slower than a forward one at 200 x 200 (the
// hardware prefetcher lost the stream once the matrix outgrew the cache).
template <bool kDescending>
inline void subtract_blocks(const float* values, const int* column, int begin, int end, const double* x, double s[3]) {
  double t[3] = {0.0, 0.0, 0.0};
  const int count = end - begin;
  const auto block = [&](int j) { return kDescending ? end - 1 - j : begin + j; };
  int j = 0;
  for (; j + 2 <= count; j += 2) {
    const int k0 = block(j), k1 = block(j + 1);
    subtract_block(values + 9 * static_cast<std::ptrdiff_t>(k0), x + 3 * static_cast<std::ptrdiff_t>(column[k0]), s);
    subtract_block(values + 9 * static_cast<std::ptrdiff_t>(k1), x + 3 * static_cast<std::ptrdiff_t>(column[k1]), t);
  }
  if (j < count) {
    const int k = block(j);
    subtract_block(values + 9 * static_cast<std::ptrdiff_t>(k), x + 3 * static_cast<std::ptrdiff_t>(column[k]), t);
  }
  for (int p = 0; p < 3; ++p) s[p] += t[p];
}

// y_j += s A_ij^T x_i for the blocks [begin, end) of row i (x_i given)
inline void add_transposed_blocks(const float* values, const int* column, int begin, int end, const double xi[3],
                                  double scale, double* y) {
  for (int k = begin; k < end; ++k) {
    const float* m = values + 9 * static_cast<std::ptrdiff_t>(k);
    double* yj = y + 3 * static_cast<std::ptrdiff_t>(column[k]);
    yj[0] += scale * (m[0] * xi[0] + m[3] * xi[1] + m[6] * xi[2]);
    yj[1] += scale * (m[1] * xi[0] + m[4] * xi[1] + m[7] * xi[2]);
    yj[2] += scale * (m[2] * xi[0] + m[5] * xi[1] + m[8] * xi[2]);
  }
}

// The same two for scalar blocks k (k I): s -= k x_j, y_j += scale k x_i.
template <bool kDescending>
inline void subtract_scalars(const float* scalars, const int* column, int begin, int end, const double* x, double s[3]) {
  for (int j = 0; j < end - begin; ++j) {
    const int k = kDescending ? end - 1 - j : begin + j;
    const double m = scalars[k];
    const double* xj = x + 3 * static_cast<std::ptrdiff_t>(column[k]);
    for (int p = 0; p < 3; ++p) s[p] -= m * xj[p];
  }
}

inline void add_scalars(const float* scalars, const int* column, int begin, int end, const double xi[3], double scale,
                        double* y) {
  for (int k = begin; k < end; ++k) {
    double* yj = y + 3 * static_cast<std::ptrdiff_t>(column[k]);
    for (int p = 0; p < 3; ++p) yj[p] += scale * (scalars[k] * xi[p]);
  }
}

}  // namespace

void VertexBlockMatrix::subtract_part(int i, Part part, bool descending, const double* x, double s[3]) const {
  const std::size_t u = static_cast<std::size_t>(i);
  const int begin = part == Part::kUpper ? diagonal_[u] + 1 : outer_[u];
  const int end = part == Part::kLower ? diagonal_[u] : outer_[u + 1];
  const int scalar_begin = part == Part::kUpper ? identity_upper_[u] : identity_outer_[u];
  const int scalar_end = part == Part::kLower ? identity_upper_[u] : identity_outer_[u + 1];
  if (descending) {
    subtract_blocks<true>(values_.data(), column_.data(), begin, end, x, s);
    subtract_scalars<true>(scalars(), identity_column_.data(), scalar_begin, scalar_end, x, s);
  } else {
    subtract_blocks<false>(values_.data(), column_.data(), begin, end, x, s);
    subtract_scalars<false>(scalars(), identity_column_.data(), scalar_begin, scalar_end, x, s);
  }
}

void VertexBlockMatrix::add_transposed_part(int i, bool upper, const double v[3], double scale, double* y) const {
  const std::size_t u = static_cast<std::size_t>(i);
  if (upper) {
    add_transposed_blocks(values_.data(), column_.data(), diagonal_[u] + 1, outer_[u + 1], v, scale, y);
    add_scalars(scalars(), identity_column_.data(), identity_upper_[u], identity_outer_[u + 1], v, scale, y);
  } else {
    add_transposed_blocks(values_.data(), column_.data(), outer_[u], diagonal_[u], v, scale, y);
    add_scalars(scalars(), identity_column_.data(), identity_outer_[u], identity_upper_[u], v, scale, y);
  }
}

void VertexBlockMatrix::gauss_seidel_sweep(const Eigen::VectorXd& b, bool forward, bool from_zero,
                                           Eigen::VectorXd* x_out) const {
  REPOSE_DEMAND(!(from_zero && !forward));
  double* x = x_out->data();
  const int rows = block_rows();
  for (int step = 0; step < rows; ++step) {
    const int i = forward ? step : rows - 1 - step;
    double s[3] = {b[3 * i], b[3 * i + 1], b[3 * i + 2]};
    if (forward) {
      subtract_part(i, Part::kLower, false, x, s);
      if (!from_zero) subtract_part(i, Part::kUpper, false, x, s);
    } else {
      subtract_part(i, Part::kUpper, true, x, s);
      subtract_part(i, Part::kLower, true, x, s);
    }
    const double* inv = &inverse_[9 * static_cast<std::size_t>(i)];
    for (int p = 0; p < 3; ++p) x[3 * i + p] = inv[3 * p] * s[0] + inv[3 * p + 1] * s[1] + inv[3 * p + 2] * s[2];
  }
}

void VertexBlockMatrix::sweep_from_zero_with_residual(const Eigen::VectorXd& b, Eigen::VectorXd* x_out,
                                                      Eigen::VectorXd* r_out) const {
  REPOSE_DEMAND(x_out != r_out);
  x_out->resize(b.size());
  r_out->setZero(b.size());
  double* x = x_out->data();
  double* r = r_out->data();
  const int rows = block_rows();
  for (int i = 0; i < rows; ++i) {
    double s[3] = {b[3 * i], b[3 * i + 1], b[3 * i + 2]};
    subtract_part(i, Part::kLower, false, x, s);
    const double* inv = &inverse_[9 * static_cast<std::size_t>(i)];
    double* xi = x + 3 * i;
    for (int p = 0; p < 3; ++p) xi[p] = inv[3 * p] * s[0] + inv[3 * p + 1] * s[1] + inv[3 * p + 2] * s[2];
    // row j < i's residual -sum_{k > j} A_jk x_k takes A_ji x_i = A_ij^T x_i
    add_transposed_part(i, false, xi, -1.0, r);
  }
}

void VertexBlockMatrix::backward_sweep_with_product(const Eigen::VectorXd& b, Eigen::VectorXd* x_out,
                                                    Eigen::VectorXd* ax_out) const {
  REPOSE_DEMAND(x_out != ax_out && x_out->size() == b.size());
  *ax_out = b;
  double* x = x_out->data();
  double* ax = ax_out->data();
  const int rows = block_rows();
  for (int i = rows - 1; i >= 0; --i) {
    double s[3] = {b[3 * i], b[3 * i + 1], b[3 * i + 2]};
    subtract_part(i, Part::kUpper, true, x, s);
    subtract_part(i, Part::kLower, true, x, s);
    const double* inv = &inverse_[9 * static_cast<std::size_t>(i)];
    double change[3];
    for (int p = 0; p < 3; ++p) {
      const double xp = inv[3 * p] * s[0] + inv[3 * p + 1] * s[1] + inv[3 * p + 2] * s[2];
      change[p] = xp - x[3 * i + p];
      x[3 * i + p] = xp;
    }
    // rows k > i (not yet final in ax) take A_ki (x_i - x_i before) = A_ik^T change
    add_transposed_part(i, true, change, 1.0, ax);
  }
}

Eigen::VectorXd VertexBlockMatrix::residual(const Eigen::VectorXd& b, const Eigen::VectorXd& x) const {
  Eigen::VectorXd r;
  residual(b, x, &r);
  return r;
}

Eigen::VectorXd VertexBlockMatrix::residual_after_sweep_from_zero(const Eigen::VectorXd& x) const {
  Eigen::VectorXd r;
  residual_after_sweep_from_zero(x, &r);
  return r;
}

void VertexBlockMatrix::residual(const Eigen::VectorXd& b, const Eigen::VectorXd& x, Eigen::VectorXd* r_out) const {
  Eigen::VectorXd& r = *r_out;
  r.resize(b.size());
  const int rows = block_rows();
  for (int i = 0; i < rows; ++i) {
    double s[3] = {b[3 * i], b[3 * i + 1], b[3 * i + 2]};
    subtract_part(i, Part::kAll, false, x.data(), s);
    for (int p = 0; p < 3; ++p) r[3 * i + p] = s[p];
  }
}

void VertexBlockMatrix::residual_after_sweep_from_zero(const Eigen::VectorXd& x, Eigen::VectorXd* r_out) const {
  Eigen::VectorXd& r = *r_out;
  r.resize(x.size());
  const int rows = block_rows();
  for (int i = 0; i < rows; ++i) {
    double s[3] = {0.0, 0.0, 0.0};
    subtract_part(i, Part::kUpper, false, x.data(), s);
    for (int p = 0; p < 3; ++p) r[3 * i + p] = s[p];
  }
}

int VertexBlockMatrix::find_block(int i, int j) const {
  const auto begin = column_.begin() + outer_[static_cast<std::size_t>(i)];
  const auto end = column_.begin() + outer_[static_cast<std::size_t>(i) + 1];
  const auto at = std::lower_bound(begin, end, j);
  return at != end && *at == j ? static_cast<int>(at - column_.begin()) : -1;
}

int VertexBlockMatrix::find_scalar(int i, int j) const {
  const auto begin = identity_column_.begin() + identity_outer_[static_cast<std::size_t>(i)];
  const auto end = identity_column_.begin() + identity_outer_[static_cast<std::size_t>(i) + 1];
  const auto at = std::lower_bound(begin, end, j);
  return at != end && *at == j ? static_cast<int>(at - identity_column_.begin()) : -1;
}

Eigen::VectorXd VertexBlockMatrix::product(const Eigen::VectorXd& x) const {
  Eigen::VectorXd y;
  product(x, &y);
  return y;
}

void VertexBlockMatrix::product(const Eigen::VectorXd& x, Eigen::VectorXd* y_out) const {
  Eigen::VectorXd& y = *y_out;
  y.resize(x.size());
  const int rows = block_rows();
  for (int i = 0; i < rows; ++i) {
    double s[3] = {0.0, 0.0, 0.0};
    subtract_part(i, Part::kAll, false, x.data(), s);
    for (int p = 0; p < 3; ++p) y[3 * i + p] = -s[p];
  }
}

}  // namespace repose
