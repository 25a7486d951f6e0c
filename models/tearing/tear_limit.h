#pragma once
// How far a cell's springs may stretch before the cell tears (tearing.h),
// under one of three rules chosen in the scene (SheetSpec::tear_rule):
//
// - strain (the seed paper's rule, section 3.2, and the default): one strain
//   for every spring, params.tear_strain, whatever the cell size. The energy
//   a cell holds when it tears is about 1/2 E t eps^2 h^2, so the energy
//   released per unit length of crack, 1/2 E t eps^2 h, falls with the cell
//   size h and the tear gets easier as the mesh is refined (measured in
//   experiments/tearing_convergence.yaml).
// - energy (the crack-band rule of Bazant & Oh 1983, the fix issue 15 asks
//   for): the limit is set by the energy per unit tear length
//   params.tear_energy_j_per_m (Gamma = G_c t, J/m) so that a cell of width h
//   strained uniaxially to its limit holds Gamma per unit length of crack,
//     1/2 E t eps_c^2 h = Gamma,   eps_c = sqrt(2 Gamma / (E t h)).
//   The limit grows as the mesh is refined (eps_c ~ h^-1/2), as the strain
//   at one cell from a crack tip does (~ K / sqrt(h)), so the load at which
//   a crack runs stays put. Measured on the seed's twist
//   (experiments/tearing_convergence.yaml, 25 to 200 cells): the peak grip
//   force changes by +8, +4, +3.5 % per halving of the cells, the grips'
//   work per unit tear length by +5, +8, +13 % (the strain rule: -28, -28,
//   -18 %), the energy the torn cells held per unit tear length by +1.1,
//   +2.5, -0.7 % (the rest of the grips' work is the flaps' motion, drag
//   and strain still stored; the experiment file splits it).
//   The price: an uncut strip's strength, E t eps_c, now grows as h^-1/2
//   (one brittle limit cannot hold both a strength and a fracture energy
//   fixed), so a tensile fit holds for the mesh it was made on.
// - cohesive (cohesive_law.h): the springs soften past a fixed peak strain
//   (tear_strain) and the cell tears when one reaches the zero-force strain
//   set by tear_energy_j_per_m (the crack band of Bazant & Oh 1983 over a
//   fixed opening); the limit below is that zero-force strain.
//
// Any way a cell's limit is the rule's strain times its tear factor
// w^q (SheetModel::cell_tear_factor, q = tear_strain_density_exponent).

#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_params.h"

namespace repose {

// The energy rule's tear strain sqrt(2 Gamma / (E t h)).
double energy_rule_tear_strain(double stiffness_n_per_m, double tear_energy_j_per_m, double cell_size_m);

// The tear strain of a cell of relative fibre density 1 under the sheet's rule.
double base_tear_strain(const SheetModel& model, const SheetParams& params);

// The strain past which cell c tears: base_tear_strain x its tear factor.
inline double cell_tear_strain(const SheetModel& model, const SheetParams& params, int c) {
  return base_tear_strain(model, params) * model.cell_tear_factor[c];
}

// The energy per unit tear length (J/m) that the energy rule gives the same
// tear strain as `tear_strain` on cells of size cell_size_m: 1/2 E t eps^2 h.
double equivalent_tear_energy_j_per_m(double stiffness_n_per_m, double tear_strain, double cell_size_m);

}  // namespace repose
