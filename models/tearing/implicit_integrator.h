#pragma once
// Linearised backward Euler for the sheet (Baraff & Witkin 1998): one Newton
// step of backward Euler per time step,
//   (M (1 + c dt) - dt^2 K) dv = dt (f(x_n) + dt K v_n + M g - c M v_n),
//   v_{n+1} = v_n + dv,   x_{n+1} = x_n + dt v_{n+1},
// K = df/dx at x_n from the intact springs and acting bending terms, solved
// by Eigen's conjugate gradients (relative residual 1e-12, Jacobi
// preconditioner, warm-started from the last step's dv) over the free
// degrees of freedom (held axes of gripped vertices move with their grip and
// enter the right-hand side). The matrix is refilled each step into the
// sparsity pattern of the whole sheet, built once (torn springs leave zeros),
// each spring's and bending term's blocks added at places found once.
// Tearing is the explicit integrator's rule, judged at x_n.
//
// It is the converged yardstick, not the fast path: stable at any step,
// first-order accurate, and it damps the fast modes the explicit scheme
// keeps. Departure from exact backward Euler: a spring's geometric
// stiffness (1 - L0/L)(I - n n^T) is dropped while it is compressed
// (L < L0), so that the matrix stays positive definite (Choi & Ko 2002);
// a buckling sheet is then a little stiffer over one step than it should be.
// The grip force recorded is the one at x_n.

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_params.h"
#include "models/tearing/sheet_state.h"

namespace repose {

class ImplicitIntegrator {
 public:
  // Refuses (InputError naming time_step_s) a step that is not positive or
  // finite. model and params must outlive the integrator.
  ImplicitIntegrator(const SheetModel& model, const SheetParams& params, double time_step_s);

  double time_step_s() const { return dt_; }

  // One step; returns the number of cells torn in it.
  int step(SheetState* state);
  // Conjugate-gradient iterations of the last step.
  int last_iterations() const { return last_iterations_; }

 private:
  // The system (into system_) over the free degrees of freedom; dv_all
  // holds the held ones.
  void assemble(const SheetState& state, const Eigen::VectorXd& dv_all, Eigen::VectorXd* rhs);

  const SheetModel& model_;
  const SheetParams& params_;
  double dt_ = 0.0;
  std::vector<int> free_index_;  // per degree of freedom 3 v + a: its row, or -1 when held
  int free_count_ = 0;
  Eigen::Matrix3Xd forces_;
  Eigen::VectorXd last_dv_;  // the last step's solution: the next solve's first guess
  // every entry the system can have (torn springs leave zeros), refilled each step
  Eigen::SparseMatrix<double> system_;
  std::vector<int> first_row_;  // per vertex: the row of its first free axis, or -1
  // per stiffness block (for_each_stiffness_block's index), per column of
  // the block: where its first free row lies in system_'s values, or -1
  std::vector<std::array<int, 3>> block_place_;
  int last_iterations_ = 0;
};

}  // namespace repose
