#pragma once
// A single-precision copy of a sheet system stored as 3 x 3 blocks, one
// per pair of coupled vertices: the multigrid smoother's matrix
// (sheet_multigrid.h).
//
// Why: the smoother's sweeps and residuals read the whole matrix once each
// and are bound by memory, not arithmetic. Eigen's scalar storage costs
// 12 bytes a non-zero (a double and a row index); 3 x 3 float blocks with
// one column index a block cost 4.4. A preconditioner may be inexact, so
// the rounding to float (7 digits, against a condition number ~400) only
// changes the iterations, never the converged answer, and the rounded
// matrix is still exactly symmetric (both triangles round alike), so the
// V-cycle stays a symmetric operator as conjugate gradients require.
//
// Vectors here ("block vectors") hold 3 entries per block row (vertex with
// a free axis), in the order of the vertices; a held axis holds 0.
//
// Identity couplings: blocks the caller names as multiples of the identity
// (the sheet's bending couplings between a vertex and the one two along a
// mesh line, 4 of the 13 blocks of a fine row, kept as 9 floats they were
// ~27 % of the matrix's bytes) are kept as one float each ("scalar
// blocks"), in a list of their own per row. Only between vertices free in
// every axis. Every pass, product and sweep treats a scalar block k as the
// block k I.

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace repose {

// A float vector 16-byte aligned (the float passes' block vectors).
using AlignedFloats = std::vector<float, Eigen::aligned_allocator<float>>;

class VertexBlockMatrix {
 public:
  VertexBlockMatrix() = default;
  // The pattern and values of `a` (square, symmetric, both triangles
  // stored, compressed); index per (vertex, axis) 3 v + axis: its row in a,
  // or -1 when that axis is not an unknown. Every row of a must be named.
  // with_values false: the pattern only (values 0, no sweep before a
  // refresh() or a fill). identity_pairs: vertex pairs (either order, both
  // blocks meant) whose blocks are multiples of the identity in every
  // matrix this copy takes, kept as scalar blocks; each pair's vertices must
  // be distinct, free in every axis and coupled in a's pattern
  // (REPOSE_DEMAND), and refresh() checks each such block of a is k I.
  VertexBlockMatrix(const Eigen::SparseMatrix<double>& a, const std::vector<int>& index, bool with_values = true,
                    const std::vector<std::pair<int, int>>& identity_pairs = {});

  // The values of a later matrix of a's pattern (one gather).
  void refresh(const Eigen::SparseMatrix<double>& a);

  int block_rows() const { return static_cast<int>(outer_.size()) - 1; }
  // Whether a has the pattern of the matrix it was made from (refresh()
  // then takes a's values).
  bool has_pattern_of(const Eigen::SparseMatrix<double>& a) const;

  // Filling the values in place (the pattern kept): clear_values(), then
  // add into values() (9 floats a block, row-major; held axes' entries
  // left 0; then one float per scalar block, from scalar_offset()), then
  // finish_values() before any sweep.
  void clear_values() { std::fill(values_.begin(), values_.end(), 0.0f); }
  float* values() { return values_.data(); }
  std::size_t value_count() const { return source_.size() + identity_column_.size(); }
  // Block (i, j)'s index (values() + 9 index), -1 when not in the pattern
  // as a full block.
  int find_block(int i, int j) const;
  // Scalar block (i, j)'s index (values() + scalar_offset() + index), -1
  // when it is not one.
  int find_scalar(int i, int j) const;
  std::size_t scalar_offset() const { return source_.size(); }
  // Full blocks and scalar blocks.
  std::size_t block_count() const { return column_.size(); }
  std::size_t scalar_count() const { return identity_column_.size(); }
  float* diagonal_block(int i) { return values_.data() + 9 * static_cast<std::ptrdiff_t>(diagonal_[static_cast<std::size_t>(i)]); }
  void finish_values() { invert_diagonal(); }
  // x (a's rows) as a block vector, and back (held axes dropped); the
  // pointer forms write into a vector kept by the caller (resized only
  // when its size differs: no allocation once it has the size).
  Eigen::VectorXd to_blocks(const Eigen::VectorXd& x) const;
  Eigen::VectorXd from_blocks(const Eigen::VectorXd& blocks) const;
  void to_blocks(const Eigen::VectorXd& x, Eigen::VectorXd* blocks) const;
  void from_blocks(const Eigen::VectorXd& blocks, Eigen::VectorXd* x) const;
  // Per row of a, its place in a block vector.
  std::vector<int> block_place_of_rows() const;

  // One block Gauss-Seidel sweep for A x = b (block vectors): per vertex
  // in turn (forward or backward), x_i = D_i^-1 (b_i - sum_{j != i} A_ij x_j)
  // with D_i the vertex's diagonal block over its free axes. from_zero: a
  // forward sweep from x = 0, which reads only the blocks left of the
  // diagonal. A forward sweep and a backward one make a symmetric smoother.
  void gauss_seidel_sweep(const Eigen::VectorXd& b, bool forward, bool from_zero, Eigen::VectorXd* x) const;
  // Fused passes for the multigrid (A's blocks symmetric across the
  // diagonal, A_ji = A_ij^T, as a symmetric matrix's are): each reads every
  // block it touches once from memory, the second use from the cache.
  // A forward sweep from zero into *x and, from the same lower blocks
  // scattered transposed, its residual b - A x into *r (equal to
  // residual_after_sweep_from_zero to round-off, without its pass over the
  // upper blocks).
  void sweep_from_zero_with_residual(const Eigen::VectorXd& b, Eigen::VectorXd* x, Eigen::VectorXd* r) const;
  // A backward sweep of *x and, from the same upper blocks scattered
  // transposed, A x of the swept x into *ax (equal to product() to
  // round-off, without its pass): (A x)_i = b_i + sum_{j<i} A_ij (x_j - x_j
  // before the sweep).
  void backward_sweep_with_product(const Eigen::VectorXd& b, Eigen::VectorXd* x, Eigen::VectorXd* ax) const;
  // b - A x (block vectors).
  Eigen::VectorXd residual(const Eigen::VectorXd& b, const Eigen::VectorXd& x) const;
  // The same for an x left by one forward sweep from zero (and nothing
  // else): that sweep made each row's b_i - sum_{j <= i} A_ij x_j zero, so
  // the residual is -sum_{j > i} A_ij x_j, read from the blocks right of
  // the diagonal only (half the memory of residual(); equal to it to
  // round-off).
  Eigen::VectorXd residual_after_sweep_from_zero(const Eigen::VectorXd& x) const;
  // A x (block vectors; 0 on held axes).
  Eigen::VectorXd product(const Eigen::VectorXd& x) const;
  // The same three into a vector kept by the caller (x and the output
  // distinct).
  void residual(const Eigen::VectorXd& b, const Eigen::VectorXd& x, Eigen::VectorXd* r) const;
  void residual_after_sweep_from_zero(const Eigen::VectorXd& x, Eigen::VectorXd* r) const;
  void product(const Eigen::VectorXd& x, Eigen::VectorXd* y) const;

  // The two fused passes in single precision on float block vectors
  // (vertex_block_float_sweeps.cpp): the multigrid's fine level, where
  // double vectors and a float-to-double conversion per entry made the
  // sweeps bound by scalar arithmetic. Each vector holds
  // float_vector_size() floats, 4 per block row (its 3 axes, then 0),
  // 16-byte aligned (AlignedFloats). Same results as the double passes to float
  // rounding of the vectors (relative ~1e-6). ax may be null (the sweep
  // alone).
  std::size_t float_vector_size() const { return 4 * static_cast<std::size_t>(block_rows()); }
  void sweep_from_zero_with_residual(const float* b, float* x, float* r) const;
  void backward_sweep_with_product(const float* b, float* x, float* ax) const;

 private:
  void invert_diagonal();
  // s -= row i's blocks (full and scalar) left of the diagonal, right of
  // it, or all, times x, in memory order or against it; y_j += scale
  // A_ij^T v over row i's blocks right of the diagonal (upper) or left
  enum class Part { kLower, kUpper, kAll };
  void subtract_part(int i, Part part, bool descending, const double* x, double s[3]) const;
  void add_transposed_part(int i, bool upper, const double v[3], double scale, double* y) const;
  void split_blocks(std::vector<std::vector<int>>* columns, const std::vector<std::pair<int, int>>& identity);
  void find_sources(const Eigen::SparseMatrix<double>& a);
  const float* scalars() const { return values_.data() + source_.size(); }

  int scalar_rows_ = 0;          // a's rows
  std::vector<int> scalar_outer_, scalar_inner_;  // a's pattern
  std::vector<int> row_of_;       // 3 per block row: a's row of each axis, or -1
  std::vector<int> outer_;        // per block row its first block, block_rows + 1 entries
  std::vector<int> column_;       // per block: its block column
  std::vector<int> diagonal_;     // per block row: its diagonal block
  // 9 per full block, row-major, then 1 per scalar block, then 4 of padding
  // (0) for 4-wide loads
  std::vector<float> values_;
  std::vector<int> source_;       // 9 per full block: where in a's values, or -1
  // the scalar blocks: per block row its first (block_rows + 1 entries) and
  // its first right of the diagonal; per scalar block its block column and
  // where in a's values its 9 entries lie
  std::vector<int> identity_outer_, identity_upper_, identity_column_, identity_source_;
  std::vector<double> inverse_;   // 9 per block row: D_i^-1, zero on held axes
  std::vector<float> inverse_columns_;  // 12 per block row: D_i^-1's columns in float, each padded by a 0
};

}  // namespace repose
