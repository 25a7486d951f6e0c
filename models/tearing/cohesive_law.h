#pragma once
// A cohesive softening law for the sheet's springs (SheetSpec::tear_rule
// cohesive), the crack-band regularisation of Bazant & Oh (1983, "Crack band
// theory for fracture of concrete", Materiaux et Constructions 16, 155-177),
// which is Hillerborg, Modeer & Petersson's fictitious crack (1976, Cement and
// Concrete Research 6, 773-782) with the crack smeared over one cell.
//
// A spring of constant k and rest length L at strain e = (length - L) / L
// pulls with k L e up to the peak strain e_p; past it its force falls
// linearly to zero at the zero-force strain e_f:
//   F(e) = k L e_p (e_f - e) / (e_f - e_p),   e_p < e < e_f,
// and a cell tears (all its springs go, as in the seed) when one of its
// springs reaches e_f. Damage does not heal: a spring that has been to
// e_m > e_p unloads and reloads along the secant k L e F(e_m) / F_lin(e_m)
// (force s k L e, s = secant_factor), and, alone, is undamaged in
// compression. Of the law's area 1/2 k L^2 e_p e_f, the part behind the
// secant,
//   D(e_m) = 1/2 k L^2 e_p e_f (e_m - e_p) / (e_f - e_p),
// is dissipated as e_m grows (booked as fracture energy); the rest,
// 1/2 s k L^2 e^2, is stored and recoverable until the cell tears.
//
// In the sheet a cell softens as one (sheet_forces.cpp): its damage is the
// law's at the largest strain any of its six springs has reached (each on
// its own limits' scale), and all six springs, stretched or compressed,
// pull with that one factor s (the crack band's scalar damage, the cell
// its element). As s falls by ds at strains where the six springs' linear
// energy is Y, the cell dissipates -Y ds (for one spring alone, dD above);
// when the leading spring reaches e_f, s = 0 and the cell holds nothing:
// the tear releases no stored energy, everything the cell gave up was
// dissipated along the law. Why the whole cell: with springs softening
// each on its own (session 17), only the springs past their peak softened
// (in the tear, the one edge at the crack tip's side: 4.1 % when it went,
// the opposite edge 0.08 %); the others, the diagonals above all (median
// strain 0.25 %, 88 % of it), still held their elastic energy when the
// cell went, released in one step, about the same per cell on every mesh,
// so growing per unit tear length as the mesh was refined (0.0088 ->
// 0.0196 J/m from 100 to 200 cells, the law's own softening +3 %;
// experiments/tearing_convergence_cohesive.yaml), the fracture energy
// with it (+18 %); a band pulled in uniaxial stress dissipated 1.27,
// 1.35, 1.56 times Gamma at 1, 0.5, 0.25 mm cells (the default 40 um
// opening; 1.25, 1.70, 2.16 times with a 1 um one). With the cell damaged
// as one, a band of cells opened in uniaxial stress (cell energy
// 1/2 E t h^2 e^2 per cell) dissipates exactly 1/2 E t h^2 e_p e_f per
// cell, Gamma per unit length below, on every mesh (cohesive_law_test.cpp).
//
// The parameters (cohesive_law below): the peak is a strength, a strain
// fixed for every mesh, SheetParams::tear_strain (the seed's limit), and
// the crack band's energy fixes the fall: a band of cells of width h
// strained uniaxially (in uniaxial stress) through the law gives up
//   1/2 (E t) e_p e_f h  per unit length of crack,
// which is Gamma = SheetParams::tear_energy_j_per_m when
//   e_f = 2 Gamma / (E t e_p h),
// i.e. an edge spring (L = h) reaches zero force at the stretch
//   delta_f = e_f h = 2 Gamma / (E t e_p),
// a material length, the same on every mesh (0.16 J/m, 4e5 N/m, 0.02:
// 40 um), and the softening runs over the opening delta_f - e_p h (20 um
// on 1 mm cells, 30 um on 0.5 mm ones). The energy rule (tear_limit.h) is
// the case e_f = e_p: 1/2 E t e_c^2 h = Gamma. On cells too coarse for the
// band (h > 2 Gamma / (E t e_p^2), where e_f would fall below e_p: a snap-back)
// the peak is lowered to the energy rule's e_c and the law is the energy
// rule's snap (as Bazant & Oh lower the strength of a band too wide); on
// the default 10 cm, 0.16 J/m, 0.02 sheet that is 50 cells and coarser.
//
// Why not the energy rule's peak with a fixed opening: the energy rule's
// peak already holds Gamma per unit length at e_c ~ h^-1/2, and any fixed
// opening past it adds 1/2 F_p delta per spring, ~ h^-1/2 per unit length,
// so its fracture energy would grow as the mesh is refined.

#include <array>

#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_params.h"

namespace repose {

struct CohesiveLaw {
  double peak_strain = 0.0;  // e_p
  double zero_strain = 0.0;  // e_f >= e_p (= e_p: the snap)

  // The law of a spring whose limits are `factor` times these.
  CohesiveLaw scaled(double factor) const { return {peak_strain * factor, zero_strain * factor}; }
  // The secant factor past the largest strain max_strain, in tension: 1 up
  // to the peak, F(e_m) / (k L e_m) past it, 0 at e_f.
  double damage_factor(double max_strain) const;
  // The fraction of its linear force k L e a spring at strain e pulls with
  // after having been to the largest strain max_strain: 1 in compression
  // and below the peak, the secant F(e_m) / (k L e_m) past it, 0 at e_f.
  double secant_factor(double strain, double max_strain) const;
  // The force (N) of a spring of constant k and rest length L at strain e
  // that has been to max_strain (< e_f): s k L e.
  double force_n(double k_n_per_m, double rest_length_m, double strain, double max_strain) const;
  // The energy (J) dissipated once the spring has been to max_strain,
  // D(e_m) above (0 up to the peak, the law's area at e_f).
  double dissipated_j(double k_n_per_m, double rest_length_m, double max_strain) const;
  // The law's whole area 1/2 k L^2 e_p e_f (J).
  double area_j(double k_n_per_m, double rest_length_m) const;
  // Raises *max_strain to strain (at most e_f) when strain passes both it
  // and the peak; returns the energy that dissipates (J, >= 0).
  double soften(double k_n_per_m, double rest_length_m, double strain, double* max_strain) const;
};

// The cohesive law of a spring of relative fibre density 1 on this mesh:
// e_p = tear_strain, e_f = 2 Gamma / (E t e_p h) while tear_strain is
// below the energy rule's e_c; else e_p = e_f = e_c exactly (the energy
// rule's snap to the bit). Cell c's is scaled by its tear factor
// (cell_tear_strain).
CohesiveLaw cohesive_law(const SheetModel& model, const SheetParams& params);

}  // namespace repose
