#pragma once
// The sheet's fitted parameters: what a calibration changes between runs
// without rebuilding the sheet.

namespace repose {

struct SheetParams {
  // In-plane tensile stiffness E t (N/m) of a sheet of mean fibre density,
  // i.e. Young's modulus times thickness: 4e5 N/m is 4 GPa x 0.1 mm. The
  // springs follow from it (sheet_model.h gives the lattice's analytic
  // stiffness): k_edge = 3/4 E t, k_diagonal = 3/8 E t, times the cell's
  // relative fibre density.
  double stiffness_n_per_m = 4.0e5;
  // A cell tears when one of its edge or diagonal springs is stretched by
  // more than this fraction of its rest length (the seed's "a set length").
  // Used by the strain rule (SheetSpec::tear_rule, tear_limit.h) only.
  double tear_strain = 0.02;
  // The energy per unit tear length Gamma = G_c t (J/m) of the energy rule
  // (tear_limit.h); used by it only. 0.16 J/m gives the default tear_strain
  // (0.02) on the 2 mm cells of a 10 cm, 50-cell sheet of the default
  // stiffness: 1/2 x 4e5 x 0.02^2 x 0.002. Measured paper is nearer
  // 1 J/m (in-plane fracture energy ~ 10 kJ/m^2 x 0.1 mm).
  double tear_energy_j_per_m = 0.16;
  // How much stiffer the sheet is along its grain than across it, from the
  // fibres' mean orientation (the clumps of the fibre image set where the
  // sheet is dense, not which way its fibres pull): a spring at angle theta
  // to the grain has its constant times 1 + a cos 2 theta, so springs along
  // the grain are (1 + a) stiffer, across it (1 - a), at 45 degrees
  // unchanged. With the grain along a mesh axis the lattice's tensile
  // stiffness along the grain over that across it is
  //   (k_e (1 + a) + k_d - k_d^2 / (k_e (1 - a) + k_d)) /
  //   (k_e (1 - a) + k_d - k_d^2 / (k_e (1 + a) + k_d)),
  // 1 at a = 0, 2.0 at a = 0.5 (k_e = 3/4, k_d = 3/8 E t). In [0, 1); 0,
  // the default, is the seed's isotropic springs.
  double fibre_anisotropy = 0.0;

  // Throws FieldError (an InputError) naming the field: stiffness_n_per_m > 0, tear_strain
  // in (0, 10], tear_energy_j_per_m > 0, fibre_anisotropy in [0, 1).
  void validate() const;
};

}  // namespace repose
