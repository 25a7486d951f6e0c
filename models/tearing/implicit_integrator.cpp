#include "models/tearing/implicit_integrator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Sparse>
#include <Eigen/IterativeLinearSolvers>
#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/fields.h"
#include "models/tearing/conjugate_gradients.h"
#include "models/tearing/sheet_forces.h"
#include "models/tearing/spring_links.h"
#include "models/tearing/stiffness_assembly.h"

namespace repose {

namespace {

// The bending part of add_stiffness (below).
template <class Bending>
void for_each_bending_term(const SheetModel& model, const SpringConstants& kc, const SheetState& state,
                           Bending&& bending) {
  const int bending_first = 24 * model.cell_count();
  for (std::size_t k = 0; k < model.bending.size(); ++k) {
    const BendingTerm& t = model.bending[k];
    if (!bending_acts(t, state)) continue;
    const std::array<int, 3> v = {t.a, t.b, t.c};
    bending(bending_first + 9 * static_cast<int>(k), v, kc.bending_n_per_m * t.weight);
  }
}

// The twist part of add_stiffness (below): nothing unless
// SheetSpec::twist_stiffness.
template <class Twist>
void for_each_twist_term(const SheetModel& model, const SpringConstants& kc, const SheetState& state, Twist&& twist) {
  if (kc.twist_n_per_m == 0.0) return;
  const int twist_first = 24 * model.cell_count() + 9 * static_cast<int>(model.bending.size());
  for (int c = 0; c < model.cell_count(); ++c) {
    if (state.intact(c)) twist(twist_first + 16 * c, model.corners(c), kc.twist_n_per_m * model.cell_stiffness[c]);
  }
}

// Per spring 6 c + k (cell c's spring k) its constant (N/m): fixed by
// the model and parameters, so worked out once (a cosine each when the
// fibres are anisotropic), not every step.
std::vector<double> spring_constants_of(const SheetModel& model, const SheetParams& params) {
  const SpringConstants kc = spring_constants(model, params);
  std::vector<double> constants;
  constants.reserve(6 * static_cast<std::size_t>(model.cell_count()));
  for (int c = 0; c < model.cell_count(); ++c) {
    for (const CellSpring& s : cell_springs(model, c)) {
      constants.push_back(spring_constant_n_per_m(kc, s, model.cell_stiffness[c]));
    }
  }
  return constants;
}

// Calls place(a, b) for every block add_stiffness can give, in
// the order of its index, whether or not the spring or term acts.
template <class Place>
void for_each_block_place(const SheetModel& model, Place&& place) {
  for (int c = 0; c < model.cell_count(); ++c) {
    for (const CellSpring& s : cell_springs(model, c)) {
      place(s.a, s.a);
      place(s.b, s.b);
      place(s.a, s.b);
      place(s.b, s.a);
    }
  }
  for (const BendingTerm& t : model.bending) {
    const int v[3] = {t.a, t.b, t.c};
    for (const int a : v) {
      for (const int b : v) place(a, b);
    }
  }
  if (!model.spec.twist_stiffness) return;
  for (int c = 0; c < model.cell_count(); ++c) {
    const std::array<int, 4> v = model.corners(c);
    for (const int a : v) {
      for (const int b : v) place(a, b);
    }
  }
}

// The vertex pairs whose blocks are multiples of the identity in every
// system: the ends of a bending term (kBendingCoefficient's 1 x 1), free in
// every axis, that no spring or twist term couples (those blocks are
// general); the fine blocks keep them as one float each
// (VertexBlockMatrix's scalar blocks), 4 of a fine row's 13 blocks.
std::vector<std::pair<int, int>> identity_couplings(const SheetModel& model) {
  const int bending_first = 24 * model.cell_count(), twist_first = bending_first + 9 * static_cast<int>(model.bending.size());
  std::vector<std::pair<int, int>> general, identity;
  int index = 0;
  for_each_block_place(model, [&](int a, int b) {
    if (index < bending_first || index >= twist_first) general.emplace_back(a, b);
    ++index;
  });
  std::sort(general.begin(), general.end());
  const auto all_free = [&](int v) { return model.held_axes[static_cast<std::size_t>(v)] == 0; };
  for (const BendingTerm& t : model.bending) {
    if (t.a == t.c || !all_free(t.a) || !all_free(t.c)) continue;
    if (std::binary_search(general.begin(), general.end(), std::pair<int, int>(t.a, t.c))) continue;
    if (std::binary_search(general.begin(), general.end(), std::pair<int, int>(t.c, t.a))) continue;
    identity.emplace_back(t.a, t.c);
  }
  return identity;
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
  for_each_block_place(model, add_block);
  Eigen::SparseMatrix<double> pattern(free_count, free_count);
  pattern.setFromTriplets(triplets.begin(), triplets.end());
  pattern.makeCompressed();
  return pattern;
}

// Where block (a, b) lies in the pattern's values: per column q of b, the
// place of the first free row of a (its free rows follow it in the column),
// -1 for a held column or an a without free rows.
std::array<int, 3> block_place(const Eigen::SparseMatrix<double>& pattern, const std::vector<int>& free_index,
                               const std::vector<int>& first_row, int a, int b) {
  std::array<int, 3> place = {-1, -1, -1};
  const int row0 = first_row[static_cast<std::size_t>(a)];
  if (row0 < 0) return place;
  const int* rows = pattern.innerIndexPtr();
  for (int q = 0; q < 3; ++q) {
    const int col = free_index[static_cast<std::size_t>(3 * b + q)];
    if (col < 0) continue;
    const int* begin = rows + pattern.outerIndexPtr()[col];
    const int* end = rows + pattern.outerIndexPtr()[col + 1];
    const int* at = std::lower_bound(begin, end, row0);
    place[static_cast<std::size_t>(q)] = static_cast<int>(at - rows);
    // a's free rows are consecutive in the column from there
    for (int p = 0; p < 3; ++p) {
      const int row = free_index[static_cast<std::size_t>(3 * a + p)];
      REPOSE_DEMAND(row < 0 || (at + (row - row0) < end && at[row - row0] == row));
    }
  }
  return place;
}

}  // namespace

void ImplicitSolverOptions::validate() const {
  if (!(relative_tolerance > 0.0 && relative_tolerance < 1.0)) {
    throw FieldError("relative_tolerance", "a number in (0, 1)", fmt::format("{}", relative_tolerance));
  }
  if (rebuild_every_steps < 1) {
    throw FieldError("rebuild_every_steps", "a count >= 1", fmt::format("{}", rebuild_every_steps));
  }
  if (!(rebuild_iteration_growth >= 1.0)) {
    throw FieldError("rebuild_iteration_growth", "a factor >= 1", fmt::format("{}", rebuild_iteration_growth));
  }
  multigrid.validate();
}

ImplicitIntegrator::ImplicitIntegrator(const SheetModel& model, const SheetParams& params, double time_step_s,
                                       const ImplicitSolverOptions& solver)
    : model_(model), params_(params), dt_(time_step_s), solver_(solver) {
  params.validate();
  solver.validate();
  if (!(std::isfinite(time_step_s) && time_step_s > 0.0)) {
    throw InputError(fmt::format("tearing: time_step_s = {} must be > 0", time_step_s));
  }
  if (model.spec.release_time_s > 0.0) {
    throw InputError(fmt::format(
        "tearing: release_time_s = {} s (cells let go gradually) is supported by the explicit integrator only; set "
        "integrator: explicit or release_time_s: 0",
        model.spec.release_time_s));
  }
  if (model.spec.tear_rule == TearRule::kCohesive) {
    throw InputError(
        "tearing: tear_rule: cohesive (springs softening past their peak) is supported by the explicit integrator "
        "only; set integrator: explicit or tear_rule: energy");
  }
  free_index_.assign(static_cast<std::size_t>(3 * model.vertex_count()), -1);
  for (int v = 0; v < model.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) {
      if (!(model.held_axes[static_cast<std::size_t>(v)] & (1u << a))) free_index_[3 * v + a] = free_count_++;
    }
  }
  system_ = system_pattern(model, free_index_, free_count_);
  spring_links_ = spring_links(model, spring_constants_of(model, params));
  first_row_.assign(static_cast<std::size_t>(model.vertex_count()), -1);
  all_free_.assign(static_cast<std::size_t>(model.vertex_count()), 0);
  for (int v = 0; v < model.vertex_count(); ++v) {
    for (int a = 2; a >= 0; --a) {
      if (free_index_[3 * v + a] >= 0) first_row_[static_cast<std::size_t>(v)] = free_index_[3 * v + a];
    }
    all_free_[static_cast<std::size_t>(v)] = model.held_axes[static_cast<std::size_t>(v)] == 0;
  }
  for_each_block_place(model, [&](int a, int b) {
    block_place_.push_back(block_place(system_, free_index_, first_row_, a, b));
  });
  block_row_.assign(static_cast<std::size_t>(model.vertex_count()), -1);
  for (int v = 0, rows = 0; v < model.vertex_count(); ++v) {
    if (first_row_[static_cast<std::size_t>(v)] >= 0) block_row_[static_cast<std::size_t>(v)] = rows++;
  }
  if (solver_.preconditioner == ImplicitSolverOptions::Preconditioner::kMultigrid && free_count_ > 0) {
    SheetMultigridOptions multigrid = solver_.multigrid;
    // the float sweeps' carried products hold conjugate gradients' true
    // residual to ~5e-6 of |b| (conjugate_gradients_test.cpp): below 1e-5 the
    // double sweeps
    multigrid.single_precision_sweeps = multigrid.single_precision_sweeps && solver_.relative_tolerance >= 1e-5;
    multigrid_ = std::make_unique<SheetMultigrid>(model.cells_x + 1, model.cells_y + 1, free_index_, free_count_,
                                                  multigrid);
    multigrid_->prepare_fine_pattern(system_, identity_couplings(model));  // the mesh's, like system_'s
  }
}

void ImplicitIntegrator::solve(const Eigen::VectorXd& rhs) {
  const int max_iterations = std::max(1000, 2 * free_count_);
  // no warm start: the last step's dv left a residual of 0.5-1.8 |b| on
  // the seed's twist at 200 x 200 (measured), no better than zero
  if (!multigrid_) {
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
    cg.setTolerance(solver_.relative_tolerance);
    cg.setMaxIterations(max_iterations);
    cg.compute(system_);
    dv_ = cg.solve(rhs);
    REPOSE_DEMAND(cg.info() == Eigen::Success && dv_.allFinite());
    last_iterations_ = static_cast<int>(cg.iterations());
    return;
  }
  const bool rebuilt = rebuild_due();
  if (rebuilt) {
    multigrid_->rebuild(system_);
    steps_since_rebuild_ = 0;
    ++rebuilds_;
  } else if (!assembled_in_blocks_) {
    multigrid_->update_fine(system_);
  }
  ++steps_since_rebuild_;
  if (solver_.single_precision_products && solver_.multigrid.smoother == SheetMultigridOptions::Smoother::kGaussSeidel) {
    // in the fine blocks' vectors throughout (held axes 0)
    const VertexBlockMatrix& blocks = multigrid_->fine_blocks();
    blocks.to_blocks(rhs, &work_.b);
    conjugate_gradients(
        work_.b, solver_.relative_tolerance, max_iterations,
        [&](const Eigen::VectorXd& r, Eigen::VectorXd* z, Eigen::VectorXd* az) { multigrid_->apply_blocks(r, z, az); },
        &work_, &last_iterations_);
    blocks.from_blocks(work_.x, &dv_);
    REPOSE_DEMAND(last_iterations_ < max_iterations && dv_.allFinite());
  } else if (solver_.single_precision_products) {
    const VertexBlockMatrix& blocks = multigrid_->fine_blocks();
    dv_ = conjugate_gradients(
        rhs, solver_.relative_tolerance, max_iterations,
        [&](const Eigen::VectorXd& p) { return blocks.from_blocks(blocks.product(blocks.to_blocks(p))); },
        [&](const Eigen::VectorXd& r) { return multigrid_->apply(system_, r); }, &last_iterations_);
    REPOSE_DEMAND(last_iterations_ < max_iterations && dv_.allFinite());
  } else {
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper, MultigridPreconditioner> cg;
    cg.setTolerance(solver_.relative_tolerance);
    cg.setMaxIterations(max_iterations);
    cg.compute(system_);
    cg.preconditioner().use(multigrid_.get(), &system_);
    dv_ = cg.solve(rhs);
    REPOSE_DEMAND(cg.info() == Eigen::Success && dv_.allFinite());
    last_iterations_ = static_cast<int>(cg.iterations());
  }
  if (rebuilt) iterations_after_rebuild_ = last_iterations_;
}

bool ImplicitIntegrator::rebuild_due() const {
  return !multigrid_->built() || steps_since_rebuild_ >= solver_.rebuild_every_steps ||
         last_iterations_ > solver_.rebuild_iteration_growth * iterations_after_rebuild_;
}

void ImplicitIntegrator::assemble(const SheetState& state, const Eigen::VectorXd& dv_all, Eigen::VectorXd* rhs_out) {
  const double c = model_.spec.damping_per_s;
  const Eigen::Vector3d& g = model_.spec.gravity_m_per_s2;
  Eigen::VectorXd& rhs = *rhs_out;
  rhs.resize(free_count_);
  // straight into the smoother's float blocks on the steps that keep the
  // hierarchy and need no double matrix (float products, Gauss-Seidel)
  assembled_in_blocks_ = multigrid_ && solver_.single_precision_products &&
                         solver_.multigrid.smoother == SheetMultigridOptions::Smoother::kGaussSeidel && !rebuild_due();
  VertexBlockMatrix* blocks = assembled_in_blocks_ ? &multigrid_->fine_blocks_to_fill() : nullptr;
  if (blocks && block_index_.empty()) {
    for_each_block_place(model_, [&](int a, int b) {
      const int i = block_row_[static_cast<std::size_t>(a)], j = block_row_[static_cast<std::size_t>(b)];
      // a full block k, a scalar block s as -2 - s (BlockTarget), or none
      const int k = i < 0 || j < 0 ? -1 : blocks->find_block(i, j);
      const int scalar = k < 0 && i >= 0 && j >= 0 ? blocks->find_scalar(i, j) : -1;
      block_index_.push_back(scalar >= 0 ? -2 - scalar : k);
    });
  }
  // the fixed pattern, refilled in place: no sort of millions of triplets
  // and no search for an entry each step
  if (blocks) {
    fill_block_base(state, blocks);
  } else {
    system_.coeffs().setZero();
  }
  for (int v = 0; v < model_.vertex_count(); ++v) {
    const double m = model_.mass_kg[v];
    for (int a = 0; a < 3; ++a) {
      const int row = free_index_[3 * v + a];
      if (row < 0) continue;
      if (!blocks) system_.coeffRef(row, row) += m * (1.0 + c * dt_);
      rhs[row] = dt_ * (forces_(a, v) + m * g[a] - c * m * state.velocities(a, v));
    }
  }
  const Eigen::Map<const Eigen::VectorXd> v0(state.velocities.data(), 3 * model_.vertex_count());
  const double dt2 = dt_ * dt_, dt_beta = dt_ * model_.spec.stiffness_damping_s;
  if (blocks) {
    StiffnessAssembly<BlockTarget> assembly{free_index_,
                                            first_row_,
                                            all_free_,
                                            {block_index_, blocks->values(), blocks->values() + blocks->scalar_offset()},
                                            &rhs,        v0,         dv_all,    dt2,
                                            dt_beta,     false};
    add_stiffness(state, &assembly);
    blocks->finish_values();
  } else {
    StiffnessAssembly<CscTarget> assembly{free_index_, first_row_, all_free_, {block_place_, system_.valuePtr()},
                                          &rhs,        v0,         dv_all,    dt2, dt_beta};
    add_stiffness(state, &assembly);
  }
}

// The mass, bending and twist blocks: constant while no cell tears, so kept
// (block_base_) and copied in over the last step's values until a cell
// tears (the torn cells differ from those the copy was made with).
void ImplicitIntegrator::fill_block_base(const SheetState& state, VertexBlockMatrix* blocks) {
  if (blocks->value_count() == block_base_.size() && base_torn_step_ == state.torn_step) {
    std::copy(block_base_.begin(), block_base_.end(), blocks->values());
    return;
  }
  blocks->clear_values();
  for (int v = 0; v < model_.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) {
      if (free_index_[3 * v + a] < 0) continue;
      blocks->diagonal_block(block_row_[static_cast<std::size_t>(v)])[4 * a] +=
          static_cast<float>(model_.mass_kg[v] * (1.0 + model_.spec.damping_per_s * dt_));
    }
  }
  // the bending terms' right-hand side is each step's (assemble())
  Eigen::VectorXd discarded = Eigen::VectorXd::Zero(free_count_);
  const Eigen::Map<const Eigen::VectorXd> v0(state.velocities.data(), 3 * model_.vertex_count());
  StiffnessAssembly<BlockTarget> assembly{
      free_index_, first_row_, all_free_, {block_index_, blocks->values(), blocks->values() + blocks->scalar_offset()},
      &discarded,  v0,         dv_all_,   dt_ * dt_,
      dt_ * model_.spec.stiffness_damping_s};
  const SpringConstants kc = spring_constants(model_, params_);
  for_each_bending_term(model_, kc, state,
                        [&](int first, const std::array<int, 3>& v, double kb) { assembly.add_bending(first, v, kb); });
  for_each_twist_term(model_, kc, state,
                      [&](int first, const std::array<int, 4>& v, double kt) { assembly.add_twist(first, v, kt); });
  block_base_.assign(blocks->values(), blocks->values() + blocks->value_count());
  base_torn_step_ = state.torn_step;
}

// The stiffness -K (positive) of the intact springs and acting bending
// and twist terms: per spring link (spring_links.h) the sum of its intact
// cells' constants, its blocks (a, a) = (b, b) = h, (a, b) = (b, a) = -h;
// per bending term blocks (v[p], v[q]) kb c_p c_q I (kBendingCoefficient),
// per intact cell's twist term kt c_i c_j I (kTwistCoefficient). Block
// indices: for_each_block_place's (4 (6 c + k) + 0..3 for spring k of
// cell c, then 24 cells + 9 t + 3 p + q for term t, then 24 cells + 9
// terms + 16 c for cell c's twist).
template <class Assembly>
void ImplicitIntegrator::add_stiffness(const SheetState& state, Assembly* assembly) const {
  for (const SpringLink& link : spring_links_) {
    const double ks = link.constant_in(state);
    if (ks == 0.0) continue;
    const Eigen::Vector3d d = state.positions.col(link.b) - state.positions.col(link.a);
    if (d.isZero(0.0)) continue;
    assembly->add_spring_along(link.first, link.a, link.b, d, ks, link.rest_length_m);
  }
  const SpringConstants kc = spring_constants(model_, params_);
  for_each_bending_term(model_, kc, state,
                        [&](int first, const std::array<int, 3>& v, double kb) { assembly->add_bending(first, v, kb); });
  for_each_twist_term(model_, kc, state,
                      [&](int first, const std::array<int, 4>& v, double kt) { assembly->add_twist(first, v, kt); });
}

int ImplicitIntegrator::step(SheetState* state) {
  REPOSE_DEMAND(state->positions.cols() == model_.vertex_count());
  const int torn = tear_and_internal_forces(model_, params_, static_cast<int>(state->steps + 1), state, &forces_);
  const double t_next = state->time_s + dt_;
  const Eigen::Vector3d& g = model_.spec.gravity_m_per_s2;
  // the held axes' velocity change is known
  Eigen::VectorXd& dv_all = dv_all_;
  dv_all.setZero(3 * model_.vertex_count());
  for (int v = 0; v < model_.vertex_count(); ++v) {
    const int grip = model_.grip_of_vertex[static_cast<std::size_t>(v)];
    for (int a = 0; a < 3; ++a) {
      if (free_index_[3 * v + a] >= 0) continue;
      dv_all[3 * v + a] = model_.spec.grips[static_cast<std::size_t>(grip)].velocity_m_per_s[a] - state->velocities(a, v);
    }
  }
  assemble(*state, dv_all, &rhs_);
  // the system is symmetric positive definite
  solve(rhs_);
  const Eigen::VectorXd& dv = dv_;
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
