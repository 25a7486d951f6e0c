#pragma once
// Linearised backward Euler for the sheet (Baraff & Witkin 1998): one Newton
// step of backward Euler per time step,
//   (M (1 + c dt) + dt C - dt^2 K) dv = dt (f(x_n, v_n) + dt K v_n + M g - c M v_n),
//   v_{n+1} = v_n + dv,   x_{n+1} = x_n + dt v_{n+1},
// K = df/dx at x_n from the intact springs and acting bending terms, C =
// -df/dv of their dashpots (beta times K's axial and bending parts,
// SheetSpec::stiffness_damping_s; 0 by default), f the elastic and
// dashpot forces, solved
// by Eigen's conjugate gradients over the free degrees of freedom (held axes
// of gripped vertices move with their grip and enter the right-hand side),
// preconditioned by a multigrid V-cycle over the vertex grid
// (sheet_multigrid.h) kept over several steps, or by the diagonal (Jacobi),
// the reference it is tested against (ImplicitSolverOptions). The matrix is
// refilled each step into the sparsity pattern of the whole sheet, built
// once (torn springs leave zeros), each spring's and bending term's blocks
// added at places found once. Tearing is the explicit integrator's rule,
// judged at x_n.
//
// Speed (tearing_benchmark, 10x the explicit step, CPU time, shared 2-core
// machine at load ~3.5-6, 2026-11-23; before = main at 1ab1748, the two
// binaries run in turn, median of 6): one step of the seed's twist from
// rest at 200 x 200, Jacobi 529 -> 530 ms (109 CG iterations; no change
// out of the noise), multigrid 375 -> 234 ms (4.3 steps/s, 8.8 iterations;
// the 20 steps/s is missed ~4.7x). Whole tears of the seed's twist
// to 5 cm (BM_ImplicitWholeTear*): 50 cells, 1,189 steps, Jacobi 40.1 s
// before, 31.4 and 41.6 s after (noise), multigrid 57.4 -> 13.3 and 13.8 s,
// the same tear, force and work to the digits printed; 100 cells, 2,161
// steps, multigrid 119 s against Jacobi 306 s (same outcomes). What made the
// difference: the multigrid smoother by 3 x 3 vertex blocks
// (sheet_multigrid.h), whose iterations no longer grow as the flaps turn
// (20 x 20 twist of implicit_integrator_test, steps 1-140: 8 -> 11, where
// the point smoother went 11 -> 29), and a backward sweep that reads memory
// in one direction (it had cost 5x a forward one); springs between free
// vertices are also assembled a block at a time. Left at ~230 ms (perf):
// the smoother and residual ~30 %, CG's own products ~15 %, assembly ~11 %.
//
// 2026-11-26 (tearing_benchmark, BM_ImplicitStepMultigrid/200, median of
// 3, CPU time, load 6-7; main's binary and this one in turn, twice): 379,
// 463 -> 161, 151 ms a step (2.6 -> 6.4 steps/s), by a relative
// tolerance of 1e-3 instead of 1e-8 (its error measured: relative_tolerance
// below; 8.6 -> 3.6 products a step) and products A p from the smoother's
// float block copy (4.5 ms against Eigen's ~14). Where a step goes now
// (wall, load 6; medians over 46 steps): internal forces 5 ms, assembly
// 52, the block copy's refresh 17, 4.5 V-cycles of ~25 ms (the fine
// level's three passes ~10 of them on a quiet machine) and 3.5 products of
// 4.5. Then the system went straight into the float blocks on the steps
// that keep the hierarchy (stiffness_assembly.h: no double matrix, no
// refresh; the same tear at 50 cells to the digits printed): 115 and 141
// ms against main's 415 (load 7-9, in turn), ~7-8 steps/s. The 20 steps/s
// of the issue (50 ms) is out of reach of this scheme: the V-cycles alone
// cost ~85 ms a step on a quiet machine (4.5 a step at ~19 ms; the fine
// level's three passes read 21 MB of float blocks at ~6 GB/s, ~10 ms).
// 2026-11-27 (BM_ImplicitStepMultigrid/200, 5 s, median of 3, CPU; main
// at dcd3538 and this binary in turn, four times, load 2.7-4.5): 92.0,
// 96.2, 101, 109 -> 72.9, 94.7, 82.5, 78.8 ms a step (~10.1 -> ~12.4
// steps/s; 3.8 products a step, two hierarchy builds a run). Whole tear
// at 100 cells (BM_ImplicitWholeTearMultigrid/100, in turn, load ~2.5):
// 47.5 -> 36.2 CPU s, the outcomes the same to the digits printed (2,128
// steps, 50 cells, work 50.858 mJ, fracture 1.7371 mJ, peak 24.5724 N; at
// 50 cells 64.4993 mJ, 3.34326 mJ, 32.1582 N). By: conjugate gradients
// and the V-cycle in block vectors in kept workspaces; fused passes (the
// sweep from zero scatters its residual, the fine level's last backward
// sweep A z, so A p is carried: the fine matrix read 1.5 times a cycle,
// 3 before); the fine block pattern made with the integrator, rebuilds
// gathering values only; the mass and bending blocks copied in from a
// kept base (refilled when a cell tears), the springs' constants worked
// out once. Where a step goes (scratch timers, 40 steps from rest, wall =
// CPU at that moment, before the last two changes): internal forces 3.4
// ms, assembly 19.8 (the springs; the base copy ~3), solve 38.8 (3.6
// cycles of ~10.7 ms: the block sweeps, which are scalar arithmetic more
// than memory now), the hierarchy's build ~480 ms (Galerkin products
// ~290, interpolation ~100, coarse blocks ~60), once in 40 steps, about
// every 46 steps over a whole tear. 20 steps/s (50 ms) is still missed
// ~1.6x. Rebuilding every 200 steps instead of 50 saves nothing: at 50
// cells 11 builds instead of 25, 6.01 against 6.06 CPU s (the iterations
// grow by as much).
// 2026-11-27 later (main at ee7ed6f and this binary in turn, load 2-5,
// CPU): BM_ImplicitStepMultigrid/200/iterations:40 over 8 rounds 131,
// 170, 135, 109, 100, 119, 118, 113 -> 107, 122, 109, 106, 92, 114, 95,
// 105 ms a step (medians 118.5 -> 106.5, -10 %; 4 to 20 % a round);
// /200/min (median of 3, three rounds) 148, 126, 123 -> 128, 113, 129 ms
// (noise as large as the change). Whole tear at 100 cells in three pairs
// 76.4 -> 62.0, 55.4 -> 50.2, 57.6 -> 54.4 CPU s, the same outcomes to
// the digits printed (2,128 steps, 50 cells, 50.858 mJ, 1.7371 mJ, 24.5724
// N; at 50 cells 64.4993 mJ, 3.34326 mJ, 32.1582 N). By: every multigrid level's
// sweeps in float, 4 floats at a time (vertex_block_float_sweeps.cpp: the
// sweeps went from scalar-arithmetic bound to memory bound; subnormals
// flushed inside them, which had made them 2x slower), the springs by
// vertex pair (spring_links.h, a third fewer) from n and two coefficients,
// and the coarse operators by 3 x 3 blocks (galerkin_product.h). The
// float sweeps' carried products hold the true residual to ~5e-6 of |b|,
// so below a relative tolerance of 1e-5 the double sweeps run. Where a
// step goes now (perf, 40 steps from rest, one build): the float sweeps
// ~31 % (memory bound: 21 MB of fine blocks read 1.5 times a cycle),
// springs ~7 %, level transfers ~4 %, the base copy ~3 %, the diagonal
// inverses ~3 %, the bending terms' right-hand side ~3 %, the coarsest
// solve ~3 %. 20 steps/s is still missed (~1.3-1.6x on a quiet machine):
// fewer bytes per fine block (the 4 bending blocks a row are multiples
// of I stored as 9 floats) or a matrix-free spring product are next.
// 2026-11-27 session 17 (main at 054449b and this binary in turn, load
// 7.5-11, CPU): the bending ends' blocks (k I) kept as one float each
// (vertex_block_matrix.h's scalar blocks: a fine row 392 bytes instead of
// 520), the diagonal inverses and the sweep from zero without clearing
// passes. BM_ImplicitStepMultigrid/200/iterations:40 medians 58.9 -> 51.9
// ms (7 rounds, the branch at b9b470f; per-round ratio median 0.88) and
// 57.5 -> 54.6 ms (6 rounds, this binary; 0.93); callgrind over the 40 steps 15,807.8 -> 15,785.6 M
// instructions (the two float sweeps +0.5 %: the scalar lists' loops; memset
// -289 M), so the gain is in bytes read, not instructions. Whole
// tear at 100 cells: the same 2,128 steps and 50 cells; work, fracture
// energy and peak force within 2e-8 of main's (50.858018 mJ, 1.737103 mJ,
// 24.572394 N). 20 steps/s (50 ms) still missed by ~5-10 % at this load.
//
// It is the converged yardstick, not the fast path: stable at any step,
// first-order accurate, and it damps the fast modes the explicit scheme
// keeps. Departure from exact backward Euler: a spring's geometric
// stiffness (1 - L0/L)(I - n n^T) is dropped while it is compressed
// (L < L0), so that the matrix stays positive definite (Choi & Ko 2002);
// a buckling sheet is then a little stiffer over one step than it should be.
// The grip force recorded is the one at x_n.

#include <array>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "models/tearing/conjugate_gradients.h"
#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_multigrid.h"
#include "models/tearing/sheet_params.h"
#include "models/tearing/sheet_state.h"
#include "models/tearing/spring_links.h"

namespace repose {

struct ImplicitSolverOptions {
  enum class Preconditioner { kMultigrid, kJacobi };
  // kJacobi, the diagonal: ~100-190 iterations at 1e-8, no state kept
  // between steps; kMultigrid: ~9 iterations a step at 1e-8 (3.6 at
  // the default 1e-3, 200 x 200), 8 -> 11 through the
  // 20 x 20 tear of implicit_integrator_test, and 2.4x (50 cells) and
  // 2.6x (100 cells) less CPU than Jacobi over whole tears of the seed's
  // twist (Speed above), hence the default (a point-Gauss-Seidel smoother
  // had let its iterations grow 11 -> 29 as the flaps turned, and it lost
  // to Jacobi over whole tears).
  Preconditioner preconditioner = Preconditioner::kMultigrid;
  // CG stops once |b - A dv| <= relative_tolerance |b| (kMultigrid with
  // single_precision_products: |b - A_float dv|, the residual it updates
  // recursively). In (0, 1). Why 1e-3 (1e-8 until 2026-11-26): the error
  // it costs was measured against a 1e-12 solve with double products and
  // is thousands of times below the resolution errors the ladder and the
  // convergence experiment resolve (percents): the seed's twist at 200 x
  // 200, 40 steps from rest (tearing_benchmark BM_ImplicitToleranceError):
  // the sheet within 4.1e-5 of its motion, the grips' work within 1.1e-5
  // (1e-4: 4.0e-5 and 1.1e-6); whole tears of the seed's twist at 50 cells
  // (BM_ImplicitWholeTearTolerance): the same 25 cells torn at the same
  // steps, the work within 3e-6, the fracture energy within 3e-6 and the
  // peak force unchanged to 6 digits, and at 100 cells (1e-8 with double
  // products against 1e-3: the same 50 cells, 2,128 steps, work 50.8581
  // and 50.858 mJ, fracture 1.73709 and 1.7371 mJ, 166 and 89 CPU s);
  // the 20 x 20 tear of
  // implicit_integrator_test within 1e-4 of the motion and 1.1e-5 of the
  // work. It takes 3.6 products a step at 200 x 200 where 1e-8 took 9.7.
  // Jacobi at 1e-3 strays further (2e-4 of the work on that 20 x 20 tear,
  // its residual says less about its error): give it 1e-8 as a yardstick.
  double relative_tolerance = 1e-3;
  // kMultigrid: conjugate gradients take their products A p from the
  // smoother's float 3 x 3 block copy of the system (vertex_block_matrix.h,
  // 2.7x less memory read than Eigen's double storage) instead of the
  // double matrix. The solve is then one of the float-rounded system (each
  // entry within 6e-8 of its own), exact to relative_tolerance.
  bool single_precision_products = true;
  // kMultigrid: the hierarchy is rebuilt (~1 step's cost) from the step's
  // system at the first step, after rebuild_every_steps steps, and when a
  // solve took more than rebuild_iteration_growth times the iterations of
  // the first solve after the last rebuild (tears and large rotations make
  // a kept hierarchy a slower preconditioner, never a wrong one).
  // rebuild_every_steps >= 1, rebuild_iteration_growth >= 1.
  int rebuild_every_steps = 50;
  double rebuild_iteration_growth = 1.5;
  SheetMultigridOptions multigrid;

  // Throws FieldError naming the field broken.
  void validate() const;
};

class ImplicitIntegrator {
 public:
  // Refuses (InputError naming time_step_s) a step that is not positive or
  // finite, and (naming release_time_s) a sheet whose torn cells let go
  // gradually (SheetSpec::release_time_s > 0: the explicit integrator's
  // only), and (naming tear_rule) softening springs (tear_rule cohesive).
  // model and params must outlive the integrator.
  ImplicitIntegrator(const SheetModel& model, const SheetParams& params, double time_step_s,
                     const ImplicitSolverOptions& solver = {});

  double time_step_s() const { return dt_; }

  // One step; returns the number of cells torn in it.
  int step(SheetState* state);
  // Conjugate-gradient iterations of the last step (Eigen's count for Jacobi
  // and double products; with float products, the products A p taken,
  // one more than Eigen would count).
  int last_iterations() const { return last_iterations_; }
  // Times the multigrid hierarchy was built.
  int multigrid_rebuilds() const { return rebuilds_; }

  using SolveWork = ConjugateGradientWork;

 private:
  // The system (into system_) over the free degrees of freedom; dv_all
  // holds the held ones.
  void assemble(const SheetState& state, const Eigen::VectorXd& dv_all, Eigen::VectorXd* rhs);
  // The step's mass and bending blocks into the fine blocks (block_base_).
  void fill_block_base(const SheetState& state, VertexBlockMatrix* blocks);
  template <class Assembly>
  void add_stiffness(const SheetState& state, Assembly* assembly) const;
  // Whether this step's solve rebuilds the multigrid hierarchy.
  bool rebuild_due() const;
  // dv over the free degrees of freedom (into dv_): system_ dv = rhs.
  void solve(const Eigen::VectorXd& rhs);

  const SheetModel& model_;
  const SheetParams& params_;
  double dt_ = 0.0;
  std::vector<int> free_index_;  // per degree of freedom 3 v + a: its row, or -1 when held
  int free_count_ = 0;
  Eigen::Matrix3Xd forces_;
  ImplicitSolverOptions solver_;
  std::unique_ptr<SheetMultigrid> multigrid_;  // kMultigrid only
  int steps_since_rebuild_ = 0, iterations_after_rebuild_ = 0, rebuilds_ = 0;
  // every entry the system can have (torn springs leave zeros), refilled each step
  Eigen::SparseMatrix<double> system_;
  std::vector<int> first_row_;  // per vertex: the row of its first free axis, or -1
  std::vector<char> all_free_;  // per vertex: no axis held (its rows first_row_ + 0..2)
  // per stiffness block (for_each_block_place's index), per column of
  // the block: where its first free row lies in system_'s values, or -1
  std::vector<std::array<int, 3>> block_place_;
  int last_iterations_ = 0;
  // this step's system went straight into the multigrid's fine blocks,
  // system_ is stale (assemble())
  bool assembled_in_blocks_ = false;
  std::vector<int> block_row_;    // per vertex: its block row in the fine blocks, or -1
  std::vector<int> block_index_;  // per stiffness block: its index in the fine blocks, or -1 (filled once)
  // the step's vectors, kept to spare their allocation: the held axes'
  // velocity change (all axes), the right-hand side and dv (free rows)
  Eigen::VectorXd dv_all_, rhs_, dv_;
  SolveWork work_;
  std::vector<SpringLink> spring_links_;  // the springs by vertex pair, their constants
  // the fine blocks' mass and bending values, and the torn cells they hold
  std::vector<float> block_base_;
  std::vector<int> base_torn_step_;
};

}  // namespace repose
