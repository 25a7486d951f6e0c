#pragma once
// A tensile test of an uncut strip (in the spirit of ISO 1924-3, constant
// rate of elongation): the sheet's left edge (x = 0) is held along x, its
// right edge (x = width_m) moves along +x at speed_m_per_s; both edges roll
// freely along y (the strip narrows) and z, and the lower-left vertex is also
// held along y so that the strip cannot drift. The force on the right grip
// against the nominal strain u / width_m gives
//   stiffness  the slope (least squares through the origin) of the force per
//              unit strip width (height_m) against the strain, over strains up
//              to stiffness_strain_fraction of the strain at peak: E t of the
//              strip along x (N/m);
//   strength   the peak force per unit width (N/m), the paper tester's
//              tensile strength;
//   strain at peak.
// Which way the fibres run is the sheet's grain_direction: 0 pulls along the
// grain (MD), 90 degrees across it (CD). The run stops once the force has
// fallen below a quarter of its peak (the strip broke) or at max_strain.
// Gravity and damping are the sheet's; the default speed loads a 5 cm strip
// to 2 % in 2 ms, some forty transits of the sheet's longitudinal wave, so
// the test is quasi-static (tests/models/tearing/tensile_test_test.cpp
// checks the stiffness of a uniform strip against E t).

#include <vector>

#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_params.h"

namespace repose {

struct TensileOptions {
  double speed_m_per_s = 0.5;       // of the right grip, > 0
  double time_step_fraction = 0.9;  // of the explicit stable step, in (0, 1]
  double max_strain = 0.2;          // stop here if the strip still holds, > 0
  double stiffness_strain_fraction = 0.5;  // in (0, 1]

  void validate() const;  // throws FieldError naming the field
};

struct TensileResult {
  double stiffness_n_per_m = 0.0;
  double strength_n_per_m = 0.0;
  double strain_at_peak = 0.0;
  bool broke = false;
  // Every step: nominal strain and force per unit width (N/m) on the pulled grip.
  std::vector<double> strain, force_per_width_n_per_m;
  long steps = 0;
  double cpu_s = 0.0;
};

// The grips of the test on a width_m x height_m sheet of cells cell_size_m
// (see above): grip 0 the lower-left vertex (x, y), grip 1 the rest of the
// left edge (x), grip 2 the right edge (x, moving).
std::vector<GripSpec> tensile_grips(double width_m, double height_m, double cell_size_m, double speed_m_per_s);

// model must hold tensile_grips() at options.speed_m_per_s (InputError otherwise).
TensileResult run_tensile_test(const SheetModel& model, const SheetParams& params, const TensileOptions& options);

}  // namespace repose
