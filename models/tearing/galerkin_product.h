#pragma once
// The multigrid's coarse operator P^T A P (sheet_multigrid.h) by 3 x 3
// vertex blocks: the sheet's interpolation keeps the axis (a fine unknown
// of axis a takes coarse unknowns of axis a only, with weights per vertex
// pair), so each fine block A_ij adds diag(w_iI) A_ij diag(w_jJ) to coarse
// block (I, J), accumulated a coarse block row at a time (Gustavson's
// order). Why: Eigen's two general sparse products (A P, then P^T (A P))
// took ~290 of a rebuild's ~480 ms at 200 x 200, sorting scalar columns.
// Measured 2026-11-27 (both in one process, wall, load ~5): the first
// coarse level 280 against Eigen's 438 ms, the second 102 against 128: a
// third off the products, not the 3x hoped (the blocks' per-vertex
// gathers cost about what Eigen's sorting did).

#include <vector>

#include <Eigen/SparseCore>

namespace repose {

// P^T A P with A (fine unknowns, symmetric, both triangles stored,
// compressed) and P (fine x coarse unknowns) numbered by fine_index and
// coarse_index (per (vertex, axis) 3 v + axis: the unknown, or -1; the
// unknowns in the order of 3 v + axis). P must keep the axis
// (REPOSE_DEMAND). Equal to P^T A P to round-off; its pattern holds every
// entry of each coarse block some fine block reaches (zeros included),
// symmetric.
Eigen::SparseMatrix<double> galerkin_product(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& p,
                                             const std::vector<int>& fine_index, const std::vector<int>& coarse_index);

}  // namespace repose
