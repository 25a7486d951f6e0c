#pragma once
// How the fibre-density images are drawn (the seed paper's section 3.1): per
// layer, fibre clumps are scattered at random over an empty image; each
// clump's size (width) and length are drawn from ranges set by the paper's
// quality, and it is turned to the grain direction plus a random angle
// within +-grain_spread_rad. A composite of all layers sets the sheet's
// spring constants and masses (sheet_model.h).
//
// Departures from the seed, which gives no formulas: a clump is an
// elliptical Gaussian (standard deviations clump_width_m across and
// clump_length_m along its axis); clumps add up, and a pixel's density is
// the covered fraction 1 - exp(-sum) (the chance that a point lies under at
// least one fibre, for Poisson-scattered fibres), so dense regions saturate
// at 1 instead of growing without bound; the composite is the mean of the
// layers.

#include <string>

namespace repose {

struct FibreOptions {
  // 3 to 5 in the seed; 1 to 8 accepted.
  int layers = 3;
  // Image pixel edge (m): the images cover the sheet at this resolution,
  // whatever the mesh, so a finer mesh samples the same fibres.
  double pixel_size_m = 0.25e-3;
  // Clumps per square metre of sheet, per layer. The default, with the
  // default sizes, covers each point by about one clump on average.
  double clumps_per_m2 = 1.0e5;
  // Clump width (Gaussian standard deviation across its axis), drawn
  // uniformly in [min, max].
  double clump_width_min_m = 0.3e-3;
  double clump_width_max_m = 0.7e-3;
  // Clump length (Gaussian standard deviation along its axis), drawn
  // uniformly in [min, max]; at least the width.
  double clump_length_min_m = 2.0e-3;
  double clump_length_max_m = 4.0e-3;
  // Grain (machine) direction, from +x towards +y.
  double grain_direction_rad = 0.0;
  // Each clump is turned by an angle drawn uniformly in [-spread, +spread]
  // around the grain; pi/2 gives no preferred direction.
  double grain_spread_rad = 0.35;
  // Density everywhere, clump or not (filler, fines); keeps the weakest
  // point of the sheet above zero stiffness. In [0, 1).
  double background_density = 0.2;

  // Throws FieldError (an InputError) naming the scene key and the rule.
  void validate() const;
};

}  // namespace repose
