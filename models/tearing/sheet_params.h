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
  double tear_strain = 0.02;

  // Throws FieldError (an InputError) naming the field: stiffness_n_per_m > 0, tear_strain
  // in (0, 10].
  void validate() const;
};

}  // namespace repose
