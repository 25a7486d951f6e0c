#pragma once
// The sheet's internal forces and energy (springs of intact cells, bending
// terms whose edges still hold; sheet_model.h), and the springs' strains.

#include <array>

#include <Eigen/Core>

#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_params.h"
#include "models/tearing/sheet_state.h"
#include "models/tearing/tear_limit.h"

namespace repose {

// Spring constants of a cell of relative fibre density 1 (N/m).
struct SpringConstants {
  double edge_n_per_m = 0.0;      // a full (interior) edge: 3/4 E t
  double diagonal_n_per_m = 0.0;  // 3/8 E t
  double bending_n_per_m = 0.0;   // D / h^2
  double twist_n_per_m = 0.0;     // 2 D / h^2 with SheetSpec::twist_stiffness, else 0
  double anisotropy = 0.0;        // SheetParams::fibre_anisotropy
  double grain_rad = 0.0;         // the fibres' grain direction
};
SpringConstants spring_constants(const SheetModel& model, const SheetParams& params);

// One of a cell's six springs: vertices, rest length, the fraction of the
// edge/diagonal constant the cell holds (1/2 for an edge, 1 for a
// diagonal), and its direction in the rest sheet (0, pi/2, pi/4 or 3 pi/4).
struct CellSpring {
  int a = 0, b = 0;
  double rest_length_m = 0.0;
  double share = 0.0;
  bool diagonal = false;
  double direction_rad = 0.0;
};
std::array<CellSpring, 6> cell_springs(const SheetModel& model, int cell);

// The constant (N/m) of spring s of a cell of stiffness factor
// cell_stiffness (SheetModel::cell_stiffness): the edge or diagonal constant
// x share x cell_stiffness x (1 + anisotropy cos 2(direction - grain))
// (sheet_params.h).
double spring_constant_n_per_m(const SpringConstants& k, const CellSpring& s, double cell_stiffness);

// The twist term's stencil over a cell's corners in SheetModel::corners'
// order (00, 10, 11, 01): Delta = sum c_i x_i, the mixed second difference
// (sheet_model.h); its energy 1/2 k_t w |Delta|^2, its Hessian blocks
// k_t w c_i c_j I.
constexpr double kTwistCoefficient[4] = {1.0, -1.0, 1.0, -1.0};
Eigen::Vector3d twist_difference(const std::array<int, 4>& corners, const Eigen::Matrix3Xd& x);

// Whether bending term t acts: both its edges have an intact cell.
bool bending_acts(const BendingTerm& t, const SheetState& state);
// How much of bending term t acts, in [0, 1]: the smaller over its two
// edges of the larger SheetState::hold of the edge's cells (1 or 0 with
// bending_acts under the seed's snap; in between while a cell is released,
// SheetSpec::release_time_s).
double bending_hold(const BendingTerm& t, const SheetState& state);

// At full strength (hold 1), at positions x (J): the energy of cell c's six
// springs, of its twist term (0 without SheetSpec::twist_stiffness), and
// of bending term t.
double cell_springs_energy_j(const SheetModel& model, const SpringConstants& k, const Eigen::Matrix3Xd& x, int c);
double cell_twist_energy_j(const SheetModel& model, const SpringConstants& k, const Eigen::Matrix3Xd& x, int c);
double bending_term_energy_j(const SpringConstants& k, const BendingTerm& t, const Eigen::Matrix3Xd& x);

// Elastic internal forces (N) on every vertex, 3 x vertex_count,
// overwritten (no dashpots: those are tear_and_internal_forces'); each
// cell's springs and twist term scaled by its SheetState::hold, each
// bending term by its bending_hold; under tear_rule cohesive each spring
// by its secant factor at SheetState::softening (cohesive_law.h).
void internal_forces(const SheetModel& model, const SheetParams& params, const SheetState& state,
                     Eigen::Matrix3Xd* forces);

// The tear rule of tearing.h and internal_forces in one pass over the
// springs (each cell's verdict depends on its own springs only, so tearing
// a cell before the next is judged changes nothing): cells over their limit
// are marked torn at step_number; under the seed's snap (release_time_s 0)
// the energy their springs held is added to state->torn_energy_j (their
// twist terms' to state->torn_twist_energy_j, that of the bending terms
// they took out, whose edges no intact cell holds any more, to
// state->torn_bending_energy_j) and they act no more; with
// release_time_s > 0 they start letting go (SheetState::releasing = 1;
// cell_release.h fades them and books the energy). The forces of every
// cell still holding are accumulated, scaled by its hold: elastic, plus
// the dashpots of SheetSpec::stiffness_damping_s at state->velocities.
// Under tear_rule cohesive every intact cell's springs first soften
// (SheetState::softening raised to their strains past the peak, the work
// dissipated added to torn_energy_j and softening_energy_j) and pull with
// their secant factors; a cell tears when one reaches its zero-force strain.
// Returns the number of cells torn.
int tear_and_internal_forces(const SheetModel& model, const SheetParams& params, int step_number, SheetState* state,
                             Eigen::Matrix3Xd* forces);

// Whether cell c has a spring past its tear strain: the one
// rule both tear_and_internal_forces and tearing.h apply.
bool cell_overstretched(const SheetModel& model, const SheetParams& params, const SheetState& state, int c);

// The elastic energy (J) split by kind (under tear_rule cohesive, each
// spring's secant factor times its linear energy: what it would give back): the structural springs (the cells'
// edges: stretching along the mesh lines), the shear springs (their
// diagonals) and the acting bending terms (out-of-plane folding). The
// bending part of a sheet bent to curvature kappa over area A tends to
// 1/2 D kappa^2 A whatever the cell size (k_b = D / h^2 on a second
// difference ~ kappa h^2, one term per h^2 of sheet per mesh direction).
// twist_j: the intact cells' twist terms (SheetSpec::twist_stiffness; 0
// without), the plate's D kappa^2 A for a twist w = kappa x y.
struct ElasticEnergy {
  double structural_j = 0.0;
  double shear_j = 0.0;
  double bending_j = 0.0;
  double twist_j = 0.0;
  double total_j() const { return structural_j + shear_j + bending_j + twist_j; }
};
ElasticEnergy elastic_energy(const SheetModel& model, const SheetParams& params, const SheetState& state);

// Elastic energy of the intact springs, acting bending terms and intact
// cells' twist terms, those of released cells scaled by their hold (J):
// elastic_energy(...).total_j().
double potential_energy(const SheetModel& model, const SheetParams& params, const SheetState& state);
// Kinetic energy of all vertices (J).
double kinetic_energy(const SheetModel& model, const SheetState& state);

// The largest strain (L - L0) / L0 of a cell's springs.
double max_spring_strain(const SheetModel& model, const SheetState& state, int cell);

}  // namespace repose
