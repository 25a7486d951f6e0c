#pragma once
// A geometric multigrid V-cycle over the sheet's vertex grid: the
// preconditioner of the implicit integrator's conjugate gradients
// (implicit_integrator.h).
//
// Why multigrid: the system M (1 + c dt) - dt^2 K at 10x the explicit step
// has a condition number ~ (10 x 2)^2 = 400 over the Jacobi diagonal, which
// costs Jacobi CG ~160 iterations for a relative residual of 1e-12 at
// 200 x 200. A sparse Cholesky factor kept over many steps was measured as
// a preconditioner first (2026-11-23, 200 x 200): 3.2e7 non-zeros in L
// (SimplicialLDLT, AMD; CHOLMOD supernodal the same fill), factorised in
// 2.5 s (CHOLMOD) to 17 s (Eigen), and each application 55-100 ms, more
// than a whole step's budget at 20 steps/s. The V-cycle costs a few
// matrix-vector products and cuts the iterations to ~10.
//
// Coarse levels: every second vertex of every second grid line (and the
// last line); interpolation P between them each axis on its own, weighted
// by the fine matrix's coupling between neighbours (bilinear on a uniform
// intact sheet; nothing across a tear: a plain bilinear P left the V-cycle
// a contraction of only 0.6-0.85 on the modes of the notch's flaps, and
// took 17 iterations at 200 x 200 where this takes 13, relative residual
// 1e-12); held axes have no row of P, coarse unknowns no fine row reaches
// are dropped. Coarse operators are Galerkin, A_c = P^T A P, so tears (zeros in
// A) reach the coarse levels without geometry. Smoothing: a forward
// Gauss-Seidel sweep before the coarse correction and a backward one after,
// so the cycle is a symmetric positive definite operator (required by CG);
// the coarsest level is solved by a sparse LDL^T. The sweeps go vertex by
// vertex (3 x 3 blocks) over a float copy of each level's matrix
// (vertex_block_matrix.h): they and the residual are bound by memory, and
// that copy is 2.7x smaller than Eigen's (on a 201 x 201 grid system of
// 3.2e6 non-zeros, best of 30: a sweep from zero 0.8 ms against 2.0, a
// residual 1.0 against 2.1; CG iterations on the seed's twist unchanged,
// 8.7 against 8.9). The backward sweep walks each row's blocks backward too,
// so that memory is read in one direction (tearing_benchmark: 24 ms a
// fine-level backward sweep otherwise, 3.6 ms so). apply_blocks runs the
// cycle in block vectors throughout (interpolation between the levels'
// block vectors by block_transfer.h, which reads and writes the float
// sweeps' vectors directly; workspaces kept), and its passes are fused: the sweep
// from zero scatters its residual from the lower blocks it reads (A_ji =
// A_ij^T), and the fine level's last backward sweep scatters A z from its
// upper blocks, the product conjugate gradients need (1.5 reads of the
// fine matrix a cycle, 3 before).
//
// The hierarchy is built from one system matrix and may be kept while the
// system changes: it stays a valid (symmetric positive definite)
// preconditioner, only a slower one; the fine level's smoothing uses the
// matrix last given to rebuild() or update_fine().

#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "models/tearing/vertex_block_matrix.h"

namespace repose {

struct SheetMultigridOptions {
  // Coarsening stops once a level has at most this many unknowns (or its
  // grid cannot be halved); that level is factorised directly. >= 1.
  int coarsest_unknowns = 3000;
  // Smoother sweeps before and after each coarse correction. >= 1.
  int smoothing_sweeps = 1;
  // Gauss-Seidel (forward before, backward after) or l1-Jacobi (the
  // diagonal sum_j |a_ij|: convergent without a weight, vectorises). On the
  // seed's twist l1-Jacobi took twice the iterations (23 against 12 at
  // 20 x 20, 28 against 14 at 200 x 200, relative residual 1e-12, against
  // the point Gauss-Seidel this was before its 3 x 3 blocks), more than its
  // cheaper sweep saves.
  enum class Smoother { kGaussSeidel, kL1Jacobi };
  Smoother smoother = Smoother::kGaussSeidel;
  // Gauss-Seidel with one sweep: every level's two sweeps (but the
  // coarsest's direct solve) on float vectors, 4 floats at a time
  // (vertex_block_float_sweeps.cpp), the transfers between levels in
  // double. The cycle is then the double one to float rounding of its
  // vectors (relative ~1e-6), which the conjugate gradients' own tolerance
  // (1e-3 by default) leaves no trace of: they stop on their own double
  // residual. Its carried product A z (apply_blocks) is then float too:
  // conjugate gradients carrying it reach a true residual of ~5e-6 |b|
  // at best (conjugate_gradients_test.cpp), so the implicit integrator
  // asks for it only at relative tolerances >= 1e-5. false: the double
  // sweeps.
  bool single_precision_sweeps = true;

  // Throws FieldError naming the field broken.
  void validate() const;
};

class SheetMultigrid {
 public:
  // The fine level: a grid of vertices_x x vertices_y vertices (vertex
  // j * vertices_x + i), free_index per degree of freedom 3 v + a its row in
  // the system or -1 when held, free_count rows in all.
  SheetMultigrid(int vertices_x, int vertices_y, std::vector<int> free_index, int free_count,
                 const SheetMultigridOptions& options = {});
  ~SheetMultigrid();
  SheetMultigrid(const SheetMultigrid&) = delete;
  SheetMultigrid& operator=(const SheetMultigrid&) = delete;

  // Builds the coarse operators from `system` (free_count x free_count,
  // symmetric positive definite, both triangles stored).
  void rebuild(const Eigen::SparseMatrix<double>& system);
  bool built() const;
  // Makes the fine block pattern from the pattern of the systems to come
  // (values ignored) ahead of the first rebuild(), which then gathers the
  // values only, as later ones do: the pattern is the mesh's, fixed.
  // identity_pairs: vertex pairs whose blocks are multiples of the identity
  // in every system to come, kept as one float each
  // (VertexBlockMatrix's scalar blocks).
  void prepare_fine_pattern(const Eigen::SparseMatrix<double>& pattern,
                            const std::vector<std::pair<int, int>>& identity_pairs = {});
  // Refreshes the fine level's smoother for a later system of the same
  // pattern (one pass over it); the coarse levels are kept. Required
  // before apply() whenever the fine system changed.
  void update_fine(const Eigen::SparseMatrix<double>& system);
  // The float 3 x 3 block copy of the fine matrix last given to rebuild()
  // or update_fine() (vertex_block_matrix.h). Requires built().
  const VertexBlockMatrix& fine_blocks() const { return fine_blocks_; }
  // The same, to be filled in place with a later system of the pattern
  // (VertexBlockMatrix::clear_values, finish_values): stands for
  // update_fine() with the Gauss-Seidel smoother. Requires built().
  VertexBlockMatrix& fine_blocks_to_fill() { return fine_blocks_; }
  // Number of levels, the fine one included (1 before the first rebuild).
  int level_count() const;

  // One V-cycle for system z = r, starting from z = 0; `system` is the
  // fine matrix last given to rebuild() or update_fine() (Gauss-Seidel
  // smooths with its block copy made there, l1-Jacobi with `system`
  // itself). Requires built(). Not for concurrent use (the cycle keeps its
  // vectors in this object: apply_blocks).
  Eigen::VectorXd apply(const Eigen::SparseMatrix<double>& system, const Eigen::VectorXd& r) const;
  // The same V-cycle with the Gauss-Seidel smoother, r and *z fine block
  // vectors (fine_blocks()), z distinct from r: the levels' vectors live in
  // block form throughout (interpolation between block vectors) in
  // workspaces kept here, so a cycle allocates nothing but the coarsest
  // level's small vectors. apply() with Gauss-Seidel is this one between
  // to_blocks and from_blocks. Not for concurrent use. Requires built().
  // With az, also fine_blocks() times z into *az, from the last backward
  // sweep's blocks (VertexBlockMatrix::backward_sweep_with_product): the
  // product conjugate gradients need, without a pass of its own.
  void apply_blocks(const Eigen::VectorXd& r, Eigen::VectorXd* z, Eigen::VectorXd* az = nullptr) const;

 private:
  struct Level;
  // per level above the coarsest: its coarse right-hand side, solution and
  // fine residual (block vectors)
  struct Work {
    Eigen::VectorXd residual, coarse_b, coarse_x;
    AlignedFloats b, x, float_residual, ax;  // single_precision_sweeps
  };
  Eigen::VectorXd cycle(std::size_t level, const Eigen::SparseMatrix<double>& matrix, const Eigen::VectorXd& r) const;
  void cycle_blocks(std::size_t level, const Eigen::VectorXd& b, Eigen::VectorXd* x, Eigen::VectorXd* ax) const;
  // cycle_blocks at a level above the coarsest, its sweeps in float
  void cycle_in_float(std::size_t level, const Eigen::VectorXd& b, Eigen::VectorXd* x, Eigen::VectorXd* ax) const;

  SheetMultigridOptions options_;
  // per level below the fine one: its interpolation from there, operator, grid
  std::vector<std::unique_ptr<Level>> levels_;
  // the coarsest level's factor
  std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> coarsest_;
  int vertices_x_ = 0, vertices_y_ = 0, free_count_ = 0;
  std::vector<int> free_index_;
  VertexBlockMatrix fine_blocks_;  // the fine matrix last given, float 3 x 3 blocks (Gauss-Seidel)
  mutable std::vector<Work> work_;  // per level but the coarsest (apply_blocks)
  Eigen::VectorXd fine_inverse_l1_;
};

}  // namespace repose
