#include "models/tearing/sheet_forces.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "models/tearing/cohesive_law.h"

namespace repose {

SpringConstants spring_constants(const SheetModel& model, const SheetParams& params) {
  const double d_over_h2 = model.spec.bending_stiffness_n_m / (model.cell_size_m * model.cell_size_m);
  return {0.75 * params.stiffness_n_per_m,
          0.375 * params.stiffness_n_per_m,
          d_over_h2,
          model.spec.twist_stiffness ? 2.0 * d_over_h2 : 0.0,
          params.fibre_anisotropy,
          model.spec.fibres.grain_direction_rad};
}

Eigen::Vector3d twist_difference(const std::array<int, 4>& corners, const Eigen::Matrix3Xd& x) {
  return x.col(corners[0]) - x.col(corners[1]) + x.col(corners[2]) - x.col(corners[3]);
}

double spring_constant_n_per_m(const SpringConstants& k, const CellSpring& s, double cell_stiffness) {
  const double direction = k.anisotropy == 0.0 ? 1.0 : 1.0 + k.anisotropy * std::cos(2.0 * (s.direction_rad - k.grain_rad));
  return (s.diagonal ? k.diagonal_n_per_m : k.edge_n_per_m) * s.share * cell_stiffness * direction;
}

std::array<CellSpring, 6> cell_springs(const SheetModel& model, int cell) {
  const auto [v00, v10, v11, v01] = model.corners(cell);
  const double h = model.cell_size_m, d = h * std::numbers::sqrt2;
  constexpr double kQuarter = 0.25 * std::numbers::pi;
  return {CellSpring{v00, v10, h, 0.5, false, 0.0},          CellSpring{v10, v11, h, 0.5, false, 2 * kQuarter},
          CellSpring{v01, v11, h, 0.5, false, 0.0},          CellSpring{v00, v01, h, 0.5, false, 2 * kQuarter},
          CellSpring{v00, v11, d, 1.0, true, kQuarter}, CellSpring{v10, v01, d, 1.0, true, 3 * kQuarter}};
}

namespace {

bool edge_held(const std::array<int, 2>& cells, const SheetState& state) {
  return (cells[0] >= 0 && state.intact(cells[0])) || (cells[1] >= 0 && state.intact(cells[1]));
}

double edge_hold(const std::array<int, 2>& cells, const SheetState& state) {
  return std::max(cells[0] >= 0 ? state.hold(cells[0]) : 0.0, cells[1] >= 0 ? state.hold(cells[1]) : 0.0);
}

}  // namespace

bool bending_acts(const BendingTerm& t, const SheetState& state) {
  return edge_held(t.cells_ab, state) && edge_held(t.cells_bc, state);
}

double bending_hold(const BendingTerm& t, const SheetState& state) {
  return std::min(edge_hold(t.cells_ab, state), edge_hold(t.cells_bc, state));
}

double bending_term_energy_j(const SpringConstants& k, const BendingTerm& t, const Eigen::Matrix3Xd& x) {
  return 0.5 * k.bending_n_per_m * t.weight * (x.col(t.a) - 2.0 * x.col(t.b) + x.col(t.c)).squaredNorm();
}

double cell_twist_energy_j(const SheetModel& model, const SpringConstants& k, const Eigen::Matrix3Xd& x, int c) {
  if (k.twist_n_per_m == 0.0) return 0.0;
  return 0.5 * k.twist_n_per_m * model.cell_stiffness[c] * twist_difference(model.corners(c), x).squaredNorm();
}

namespace {

// The spring vectors of a cell and whether any is stretched past `limit`.
struct CellStretch {
  std::array<Eigen::Vector3d, 6> d;
  std::array<double, 6> length;
  bool over = false;
};

// A spring's limit from its cell's `limit`: with SheetSpec::isotropic_tear_energy
// (`isotropic`) limit / sqrt(its direction factor), else limit.
double spring_limit_of(double limit, const CellSpring& spring, const SpringConstants* isotropic) {
  if (isotropic != nullptr && isotropic->anisotropy != 0.0) {
    return limit / std::sqrt(1.0 + isotropic->anisotropy * std::cos(2.0 * (spring.direction_rad - isotropic->grain_rad)));
  }
  return limit;
}

// `limit` is the cell's tear strain; each spring's is spring_limit_of it.
CellStretch stretch_of(const std::array<CellSpring, 6>& springs, const Eigen::Matrix3Xd& x, double limit,
                       const SpringConstants* isotropic = nullptr) {
  CellStretch s;
  for (int k = 0; k < 6; ++k) {
    s.d[k] = x.col(springs[k].b) - x.col(springs[k].a);
    s.length[k] = s.d[k].norm();
    const double spring_limit = spring_limit_of(limit, springs[k], isotropic);
    s.over = s.over || s.length[k] > (1.0 + spring_limit) * springs[k].rest_length_m;
  }
  return s;
}

// Under tear_rule cohesive (cohesive_law.h), the law of one cell: the
// sheet's law times the cell's tear factor, and each spring's limits as
// stretch_of takes them (that law times scale[q]).
struct CellLaws {
  CohesiveLaw cell;
  std::array<double, 6> scale{};
};

CellLaws cell_laws(const CohesiveLaw& sheet_law, const SheetModel& model, const std::array<CellSpring, 6>& springs,
                   int c, const SpringConstants* isotropic) {
  CellLaws laws{sheet_law.scaled(model.cell_tear_factor[c]), {}};
  for (int q = 0; q < 6; ++q) laws.scale[q] = spring_limit_of(1.0, springs[q], isotropic);
  return laws;
}

// The cell's damage strain: the largest of its springs' largest strains
// (`reached`, 6 values), each on the cell law's scale.
double cell_reached(const CellLaws& laws, const double* reached) {
  double m = 0.0;
  for (int q = 0; q < 6; ++q) m = std::max(m, reached[q] / laws.scale[q]);
  return m;
}

// The fraction of its linear force each spring of a cell pulls with: the
// cell's damage factor (CohesiveLaw::damage_factor at cell_reached), the
// same for all six (cohesive_law.h: the cell softens as one).
using SpringFactors = std::array<double, 6>;
SpringFactors secant_factors(const CellLaws& laws, const double* reached) {
  SpringFactors f;
  f.fill(laws.cell.damage_factor(cell_reached(laws, reached)));
  return f;
}

// Raises each spring's largest strain (`reached`, 6 values) to its strain
// now where that passes its peak; returns the energy dissipated (J): the
// drop of the cell's damage factor times the linear energy its six
// springs hold now (the stored energy the damage takes, at these
// positions; cohesive_law.h).
double soften_cell(const std::array<CellSpring, 6>& springs, const CellStretch& s, const CellLaws& laws,
                   const SpringConstants& k, double weight, double* reached) {
  if (laws.cell.zero_strain <= laws.cell.peak_strain) return 0.0;  // the snap: no softening
  const double before = laws.cell.damage_factor(cell_reached(laws, reached));
  double linear_energy = 0.0;
  for (int q = 0; q < 6; ++q) {
    const double stretch = s.length[q] - springs[q].rest_length_m;
    const double strain = stretch / springs[q].rest_length_m;
    if (strain > laws.cell.peak_strain * laws.scale[q] && strain > reached[q]) {
      reached[q] = std::min(strain, laws.cell.zero_strain * laws.scale[q]);
    }
    linear_energy += 0.5 * spring_constant_n_per_m(k, springs[q], weight) * stretch * stretch;
  }
  return (before - laws.cell.damage_factor(cell_reached(laws, reached))) * linear_energy;
}

// factors: each spring's share of its constant (SpringFactors), or null: all 1.
double cell_spring_energy(const std::array<CellSpring, 6>& springs, const CellStretch& s, const SpringConstants& k,
                          double weight, const SpringFactors* factors = nullptr) {
  double energy = 0.0;
  for (int q = 0; q < 6; ++q) {
    const double stretch = s.length[q] - springs[q].rest_length_m;
    const double e = 0.5 * spring_constant_n_per_m(k, springs[q], weight) * stretch * stretch;
    energy += factors == nullptr ? e : (*factors)[q] * e;
  }
  return energy;
}

void add_cell_forces(const std::array<CellSpring, 6>& springs, const CellStretch& s, const SpringConstants& k,
                     double weight, Eigen::Matrix3Xd* forces, const SpringFactors* factors = nullptr) {
  for (int q = 0; q < 6; ++q) {
    if (s.length[q] == 0.0) continue;  // coincident ends: no direction to push along
    const CellSpring& sp = springs[q];
    double constant = spring_constant_n_per_m(k, sp, weight);
    if (factors != nullptr) constant *= (*factors)[q];
    const Eigen::Vector3d f = (constant * (s.length[q] - sp.rest_length_m) / s.length[q]) * s.d[q];
    forces->col(sp.a) += f;
    forces->col(sp.b) -= f;
  }
}

// The bending terms' forces -scale k_b c_p (y_a - 2 y_b + y_c) on y =
// positions (scale 1: elastic) or velocities (scale beta: the dashpots).
void add_bending_forces(const SheetModel& model, const SpringConstants& k, const SheetState& state,
                        const Eigen::Matrix3Xd& y, double scale, Eigen::Matrix3Xd* forces) {
  for (const BendingTerm& t : model.bending) {
    const double hold = bending_hold(t, state);
    if (hold == 0.0) continue;
    const Eigen::Vector3d g =
        (scale * k.bending_n_per_m * t.weight * hold) * (y.col(t.a) - 2.0 * y.col(t.b) + y.col(t.c));
    forces->col(t.a) -= g;
    forces->col(t.b) += 2.0 * g;
    forces->col(t.c) -= g;
  }
}

// Cell c's twist term's forces -scale hold k_t w c_i Delta(y) on y = positions
// (scale 1: elastic) or velocities (scale beta: its dashpot).
void add_twist_forces(const SheetModel& model, const SpringConstants& k, int c, double hold, const Eigen::Matrix3Xd& y,
                      double scale, Eigen::Matrix3Xd* forces) {
  if (k.twist_n_per_m == 0.0) return;
  const std::array<int, 4> corners = model.corners(c);
  const Eigen::Vector3d g = (scale * k.twist_n_per_m * (model.cell_stiffness[c] * hold)) * twist_difference(corners, y);
  for (int i = 0; i < 4; ++i) forces->col(corners[static_cast<std::size_t>(i)]) -= kTwistCoefficient[i] * g;
}

// The springs' dashpots (SheetSpec::stiffness_damping_s): beta k times the
// rate of stretch along each spring.
void add_cell_damping(const std::array<CellSpring, 6>& springs, const CellStretch& s, const SpringConstants& k,
                      double weight, double beta, const Eigen::Matrix3Xd& v, Eigen::Matrix3Xd* forces,
                      const SpringFactors* factors = nullptr) {
  for (int q = 0; q < 6; ++q) {
    if (s.length[q] == 0.0) continue;
    const CellSpring& sp = springs[q];
    const Eigen::Vector3d n = s.d[q] / s.length[q];
    double constant = spring_constant_n_per_m(k, sp, weight);
    if (factors != nullptr) constant *= (*factors)[q];
    const Eigen::Vector3d f = (beta * constant * n.dot(v.col(sp.b) - v.col(sp.a))) * n;
    forces->col(sp.a) += f;
    forces->col(sp.b) -= f;
  }
}

}  // namespace

double cell_springs_energy_j(const SheetModel& model, const SpringConstants& k, const Eigen::Matrix3Xd& x, int c) {
  const std::array<CellSpring, 6> springs = cell_springs(model, c);
  return cell_spring_energy(springs, stretch_of(springs, x, INFINITY), k, model.cell_stiffness[c]);
}

namespace {

// Under tear_rule cohesive, the secant factors of cell c's springs at the
// state's largest strains (SheetState::softening); else null.
const SpringFactors* state_factors(const SheetModel& model, const SheetParams& params, const SheetState& state,
                                   const std::array<CellSpring, 6>& springs, int c, SpringFactors* storage) {
  if (model.spec.tear_rule != TearRule::kCohesive) return nullptr;
  const SpringConstants k = spring_constants(model, params);
  const CellLaws laws =
      cell_laws(cohesive_law(model, params), model, springs, c, model.spec.isotropic_tear_energy ? &k : nullptr);
  *storage = secant_factors(laws, state.softening.data() + 6 * static_cast<std::size_t>(c));
  return storage;
}

}  // namespace

void internal_forces(const SheetModel& model, const SheetParams& params, const SheetState& state,
                     Eigen::Matrix3Xd* forces) {
  forces->setZero(3, model.vertex_count());
  const SpringConstants k = spring_constants(model, params);
  for (int c = 0; c < model.cell_count(); ++c) {
    const double hold = state.hold(c);
    if (hold == 0.0) continue;
    const std::array<CellSpring, 6> springs = cell_springs(model, c);
    const CellStretch s = stretch_of(springs, state.positions, INFINITY);
    SpringFactors storage;
    add_cell_forces(springs, s, k, model.cell_stiffness[c] * hold, forces,
                    state_factors(model, params, state, springs, c, &storage));
    add_twist_forces(model, k, c, hold, state.positions, 1.0, forces);
  }
  add_bending_forces(model, k, state, state.positions, 1.0, forces);
}

bool cell_overstretched(const SheetModel& model, const SheetParams& params, const SheetState& state, int c) {
  const SpringConstants k = spring_constants(model, params);
  return stretch_of(cell_springs(model, c), state.positions, cell_tear_strain(model, params, c),
                    model.spec.isotropic_tear_energy ? &k : nullptr)
      .over;
}

namespace {

// The energy (J) at the state's positions of the bending terms that the
// cells torn at step_number (snapped: hold 1 -> 0) took out: each term's
// hold with those cells still intact minus its hold now, times its energy.
double snapped_bending_energy_j(const SheetModel& model, const SpringConstants& k, int step_number,
                                const SheetState& state) {
  SheetState before;  // only torn_step and releasing are read by bending_hold
  before.torn_step = state.torn_step;
  for (int& s : before.torn_step) {
    if (s == step_number) s = -1;
  }
  before.releasing = state.releasing;
  double dropped = 0.0;
  for (const BendingTerm& t : model.bending) {
    const double lost = bending_hold(t, before) - bending_hold(t, state);
    if (lost > 0.0) dropped += lost * bending_term_energy_j(k, t, state.positions);
  }
  return dropped;
}

}  // namespace

int tear_and_internal_forces(const SheetModel& model, const SheetParams& params, int step_number, SheetState* state,
                             Eigen::Matrix3Xd* forces) {
  forces->setZero(3, model.vertex_count());
  const SpringConstants k = spring_constants(model, params);
  const double beta = model.spec.stiffness_damping_s;
  int torn = 0;
  const bool gradual = model.spec.release_time_s > 0.0;
  const bool cohesive = model.spec.tear_rule == TearRule::kCohesive;
  const SpringConstants* isotropic = model.spec.isotropic_tear_energy ? &k : nullptr;
  const CohesiveLaw sheet_law = cohesive ? cohesive_law(model, params) : CohesiveLaw{};
  for (int c = 0; c < model.cell_count(); ++c) {
    const bool intact = state->intact(c);
    if (!intact && state->hold(c) == 0.0) continue;
    const std::array<CellSpring, 6> springs = cell_springs(model, c);
    const CellStretch s = stretch_of(springs, state->positions, intact ? cell_tear_strain(model, params, c) : INFINITY,
                                     isotropic);
    SpringFactors factor_storage;
    const SpringFactors* factors = nullptr;
    if (cohesive && intact) {  // soften first: a cell that tears gives up what its springs hold after it
      double* reached = state->softening.data() + 6 * static_cast<std::size_t>(c);
      const CellLaws laws = cell_laws(sheet_law, model, springs, c, isotropic);
      const double dissipated = soften_cell(springs, s, laws, k, model.cell_stiffness[c], reached);
      state->torn_energy_j += dissipated;
      state->softening_energy_j += dissipated;
      factor_storage = secant_factors(laws, reached);
      factors = &factor_storage;
    }
    if (intact && s.over) {
      state->torn_step[static_cast<std::size_t>(c)] = step_number;
      ++torn;
      if (gradual) {  // it holds fully this step and lets go over release_time_s (cell_release.h)
        state->releasing[static_cast<std::size_t>(c)] = 1.0;
      } else {
        state->torn_energy_j += cell_spring_energy(springs, s, k, model.cell_stiffness[c], factors);
        state->torn_twist_energy_j += cell_twist_energy_j(model, k, state->positions, c);
        continue;
      }
    }
    const double weight = model.cell_stiffness[c] * state->hold(c);
    add_cell_forces(springs, s, k, weight, forces, factors);
    add_twist_forces(model, k, c, state->hold(c), state->positions, 1.0, forces);
    if (beta > 0.0) {
      add_cell_damping(springs, s, k, weight, beta, state->velocities, forces, factors);
      add_twist_forces(model, k, c, state->hold(c), state->velocities, beta, forces);
    }
  }
  if (torn > 0 && !gradual) state->torn_bending_energy_j += snapped_bending_energy_j(model, k, step_number, *state);
  add_bending_forces(model, k, *state, state->positions, 1.0, forces);
  if (beta > 0.0) add_bending_forces(model, k, *state, state->velocities, beta, forces);
  return torn;
}

ElasticEnergy elastic_energy(const SheetModel& model, const SheetParams& params, const SheetState& state) {
  const SpringConstants k = spring_constants(model, params);
  const Eigen::Matrix3Xd& x = state.positions;
  ElasticEnergy energy;
  for (int c = 0; c < model.cell_count(); ++c) {
    const double hold = state.hold(c);
    if (hold == 0.0) continue;
    const std::array<CellSpring, 6> springs = cell_springs(model, c);
    SpringFactors storage;
    const SpringFactors* factors = state_factors(model, params, state, springs, c, &storage);
    for (int q = 0; q < 6; ++q) {
      const CellSpring& s = springs[q];
      const double stretch = (x.col(s.b) - x.col(s.a)).norm() - s.rest_length_m;
      double e = 0.5 * spring_constant_n_per_m(k, s, model.cell_stiffness[c] * hold) * stretch * stretch;
      if (factors != nullptr) e *= (*factors)[q];
      (s.diagonal ? energy.shear_j : energy.structural_j) += e;
    }
    energy.twist_j += hold * cell_twist_energy_j(model, k, x, c);
  }
  for (const BendingTerm& t : model.bending) {
    const double hold = bending_hold(t, state);
    if (hold > 0.0) energy.bending_j += hold * bending_term_energy_j(k, t, x);
  }
  return energy;
}

double potential_energy(const SheetModel& model, const SheetParams& params, const SheetState& state) {
  return elastic_energy(model, params, state).total_j();
}

double kinetic_energy(const SheetModel& model, const SheetState& state) {
  return 0.5 * (state.velocities.colwise().squaredNorm().transpose().array() * model.mass_kg.array()).sum();
}

double max_spring_strain(const SheetModel& model, const SheetState& state, int cell) {
  double strain = -1.0;
  for (const CellSpring& s : cell_springs(model, cell)) {
    strain = std::max(strain, (state.positions.col(s.b) - state.positions.col(s.a)).norm() / s.rest_length_m - 1.0);
  }
  return strain;
}

}  // namespace repose
