#include "models/tearing/implicit_integrator.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Sparse>
#include <Eigen/IterativeLinearSolvers>
#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/tearing/sheet_forces.h"

namespace repose {

namespace {

// Calls add(a, b, block) for every 3 x 3 block (a, b) of -K (the stiffness,
// positive) of the intact springs and acting bending terms; a pair may come
// several times, its blocks add up.
template <class Add>
void for_each_stiffness_block(const SheetModel& model, const SheetParams& params, const SheetState& state, Add&& add) {
  const SpringConstants kc = spring_constants(model, params);
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  for (int c = 0; c < model.cell_count(); ++c) {
    if (!state.intact(c)) continue;
    for (const CellSpring& s : cell_springs(model, c)) {
      const Eigen::Vector3d d = state.positions.col(s.b) - state.positions.col(s.a);
      const double length = d.norm();
      if (length == 0.0) continue;
      const Eigen::Vector3d n = d / length;
      const double ks = spring_constant_n_per_m(kc, s, model.cell_stiffness[c]);
      const double geometric = std::max(0.0, 1.0 - s.rest_length_m / length);
      const Eigen::Matrix3d h = ks * (n * n.transpose() + geometric * (identity - n * n.transpose()));
      add(s.a, s.a, h);
      add(s.b, s.b, h);
      add(s.a, s.b, -h);
      add(s.b, s.a, -h);
    }
  }
  constexpr double kCoefficient[3] = {1.0, -2.0, 1.0};
  for (const BendingTerm& t : model.bending) {
    if (!bending_acts(t, state)) continue;
    const int v[3] = {t.a, t.b, t.c};
    const double kb = kc.bending_n_per_m * t.weight;
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) add(v[p], v[q], kb * kCoefficient[p] * kCoefficient[q] * identity);
    }
  }
}

// Every (row, col) of the free system any intact sheet can fill: the mass
// diagonal, each spring's four blocks and each bending term's nine.
Eigen::SparseMatrix<double> system_pattern(const SheetModel& model, const std::vector<int>& free_index, int free_count) {
  std::vector<Eigen::Triplet<double>> triplets;
  auto add_block = [&](int va, int vb) {
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) {
        const int row = free_index[3 * va + p], col = free_index[3 * vb + q];
        if (row >= 0 && col >= 0) triplets.emplace_back(row, col, 0.0);
      }
    }
  };
  for (int v = 0; v < model.vertex_count(); ++v) add_block(v, v);
  for (int c = 0; c < model.cell_count(); ++c) {
    for (const CellSpring& s : cell_springs(model, c)) {
      add_block(s.a, s.b);
      add_block(s.b, s.a);
    }
  }
  for (const BendingTerm& t : model.bending) {
    const int v[3] = {t.a, t.b, t.c};
    for (const int a : v) {
      for (const int b : v) add_block(a, b);
    }
  }
  Eigen::SparseMatrix<double> pattern(free_count, free_count);
  pattern.setFromTriplets(triplets.begin(), triplets.end());
  pattern.makeCompressed();
  return pattern;
}

}  // namespace

ImplicitIntegrator::ImplicitIntegrator(const SheetModel& model, const SheetParams& params, double time_step_s)
    : model_(model), params_(params), dt_(time_step_s) {
  params.validate();
  if (!(std::isfinite(time_step_s) && time_step_s > 0.0)) {
    throw InputError(fmt::format("tearing: time_step_s = {} must be > 0", time_step_s));
  }
  free_index_.assign(static_cast<std::size_t>(3 * model.vertex_count()), -1);
  for (int v = 0; v < model.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) {
      if (!(model.held_axes[static_cast<std::size_t>(v)] & (1u << a))) free_index_[3 * v + a] = free_count_++;
    }
  }
  pattern_ = system_pattern(model, free_index_, free_count_);
}

void ImplicitIntegrator::assemble(const SheetState& state, const Eigen::VectorXd& dv_all, Eigen::SparseMatrix<double>* matrix,
                                  Eigen::VectorXd* rhs_out) const {
  const double c = model_.spec.damping_per_s;
  const Eigen::Vector3d& g = model_.spec.gravity_m_per_s2;
  // the fixed pattern, refilled: no sort of millions of triplets each step
  Eigen::SparseMatrix<double>& a_matrix = *matrix;
  a_matrix = pattern_;
  a_matrix.coeffs().setZero();
  Eigen::VectorXd& rhs = *rhs_out;
  rhs.resize(free_count_);
  for (int v = 0; v < model_.vertex_count(); ++v) {
    const double m = model_.mass_kg[v];
    for (int a = 0; a < 3; ++a) {
      const int row = free_index_[3 * v + a];
      if (row < 0) continue;
      a_matrix.coeffRef(row, row) += m * (1.0 + c * dt_);
      rhs[row] = dt_ * (forces_(a, v) + m * g[a] - c * m * state.velocities(a, v));
    }
  }
  const Eigen::Map<const Eigen::VectorXd> v0(state.velocities.data(), 3 * model_.vertex_count());
  const double dt2 = dt_ * dt_;
  for_each_stiffness_block(model_, params_, state, [&](int va, int vb, const Eigen::Matrix3d& block) {
    for (int p = 0; p < 3; ++p) {
      const int row = free_index_[3 * va + p];
      if (row < 0) continue;
      for (int q = 0; q < 3; ++q) {
        const double kpq = block(p, q);  // of -K
        // dt K v_n on the right; -dt^2 K dv on the left, held dv moved right
        rhs[row] -= dt2 * kpq * v0[3 * vb + q];
        const int col = free_index_[3 * vb + q];
        if (col >= 0) {
          a_matrix.coeffRef(row, col) += dt2 * kpq;
        } else {
          rhs[row] -= dt2 * kpq * dv_all[3 * vb + q];
        }
      }
    }
  });
}

int ImplicitIntegrator::step(SheetState* state) {
  REPOSE_DEMAND(state->positions.cols() == model_.vertex_count());
  const int torn = tear_and_internal_forces(model_, params_, static_cast<int>(state->steps + 1), state, &forces_);
  const double t_next = state->time_s + dt_;
  const Eigen::Vector3d& g = model_.spec.gravity_m_per_s2;
  // the held axes' velocity change is known
  Eigen::VectorXd dv_all = Eigen::VectorXd::Zero(3 * model_.vertex_count());
  for (int v = 0; v < model_.vertex_count(); ++v) {
    const int grip = model_.grip_of_vertex[static_cast<std::size_t>(v)];
    for (int a = 0; a < 3; ++a) {
      if (free_index_[3 * v + a] >= 0) continue;
      dv_all[3 * v + a] = model_.spec.grips[static_cast<std::size_t>(grip)].velocity_m_per_s[a] - state->velocities(a, v);
    }
  }
  Eigen::SparseMatrix<double> system;
  Eigen::VectorXd rhs;
  assemble(*state, dv_all, &system, &rhs);
  // conjugate gradients: the system is symmetric positive definite, and a
  // direct factorisation of a 200 x 200 sheet took 18 s a step (measured)
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> solver;
  solver.setTolerance(1e-12);
  solver.setMaxIterations(std::max(1000, 2 * free_count_));
  solver.compute(system);
  // warm start from the last step's dv: the velocity change varies slowly
  if (last_dv_.size() != free_count_) last_dv_ = Eigen::VectorXd::Zero(free_count_);
  const Eigen::VectorXd dv = solver.solveWithGuess(rhs, last_dv_);
  REPOSE_DEMAND(solver.info() == Eigen::Success && dv.allFinite());
  last_dv_ = dv;
  last_iterations_ = static_cast<int>(solver.iterations());
  state->grip_force_n.setZero();
  for (int v = 0; v < model_.vertex_count(); ++v) {
    const int grip = model_.grip_of_vertex[static_cast<std::size_t>(v)];
    for (int a = 0; a < 3; ++a) {
      const int row = free_index_[3 * v + a];
      if (row < 0) {
        state->grip_force_n(a, grip) -= forces_(a, v) + model_.mass_kg[v] * g[a];
        state->velocities(a, v) += dv_all[3 * v + a];
        state->positions(a, v) = model_.rest_positions(a, v) + state->velocities(a, v) * t_next;
      } else {
        state->velocities(a, v) += dv[row];
        state->positions(a, v) += dt_ * state->velocities(a, v);
      }
    }
  }
  for (std::size_t k2 = 0; k2 < model_.spec.grips.size(); ++k2) {
    state->grip_work_j += dt_ * state->grip_force_n.col(static_cast<Eigen::Index>(k2)).dot(
                                    model_.spec.grips[k2].velocity_m_per_s);
  }
  state->time_s = t_next;
  ++state->steps;
  return torn;
}

}  // namespace repose
