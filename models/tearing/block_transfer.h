#pragma once
// The multigrid's transfers between two levels' block vectors
// (sheet_multigrid.h, vertex_block_matrix.h): the interpolation P from a
// coarser level into a finer one, and its transpose, the restriction.
//
// Why not Eigen's sparse products: the sheet's interpolation keeps the axis
// (a fine entry of axis a takes coarse entries of axis a only), so P is a
// list of coarse vertices per fine vertex, each with one weight per axis.
// Stored so, a transfer reads each link once for its three axes, and it
// reads and writes the float sweeps' vectors (4 floats a vertex) directly:
// Eigen's products took 7.7 % of the 200 x 200 implicit step's
// instructions (callgrind, 2026-11-27), and two more passes converted the
// float residual to double and the double correction back.
//
// Same arithmetic as Eigen's products of the same P, in the same order
// (a coarse entry sums its fine entries in ascending order, a fine entry its
// coarse entries in ascending order, each from 0): equal to them bit for bit.

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace repose {

class BlockTransfer {
 public:
  BlockTransfer() = default;
  // From P between block vectors (3 entries a vertex): entry (3 i + a,
  // 3 J + b) is the weight of coarse vertex J's axis b in fine vertex i's
  // axis a, and must have a == b (REPOSE_DEMAND).
  explicit BlockTransfer(const Eigen::SparseMatrix<double>& p);
  // The same from P between unknowns, entry (r, c) standing at (fine_place[r],
  // coarse_place[c]) of the block-vector P (VertexBlockMatrix::
  // block_place_of_rows of the two levels): no block-vector matrix built.
  BlockTransfer(const Eigen::SparseMatrix<double>& p, const std::vector<int>& fine_place,
                const std::vector<int>& coarse_place, int fine_rows, int coarse_rows);

  int fine_rows() const { return static_cast<int>(outer_.size()) - 1; }
  int coarse_rows() const { return coarse_rows_; }

  // *coarse = P^T fine, fine a block vector in double (3 a vertex) or in
  // float (4 a vertex, the fourth ignored: VertexBlockMatrix's float
  // passes' vectors).
  void restrict_to(const Eigen::VectorXd& fine, Eigen::VectorXd* coarse) const;
  void restrict_to(const float* fine, Eigen::VectorXd* coarse) const;
  // *fine += P coarse: in double, each product added to *fine in turn (as
  // Eigen's x += P c); in float (4 a vertex, the fourth left alone), P c
  // summed in double per entry, then added.
  void add_interpolated(const Eigen::VectorXd& coarse, Eigen::VectorXd* fine) const;
  void add_interpolated(const Eigen::VectorXd& coarse, float* fine) const;

 private:
  void restrict_doubles(const double* fine, Eigen::VectorXd* coarse) const;

  int coarse_rows_ = 0;
  std::vector<int> outer_ = {0};  // per fine vertex its first link, fine_rows + 1 entries
  std::vector<int> coarse_;       // per link its coarse vertex, ascending within a fine vertex
  std::vector<double> weight_;    // 3 per link: per axis, 0 where P has no entry
  // the same links per coarse vertex (the restriction gathers: one store a
  // coarse vertex): its first, per link the fine vertex (ascending) and weights
  std::vector<int> reverse_outer_, fine_;
  std::vector<double> reverse_weight_;
};

}  // namespace repose
