#pragma once
// How a debris flow on generated terrain (validation/rigid/debris_setup.h)
// runs in LIGGGHTS: the contact stiffness and step a DEM needs and the rigid
// engines do not, and how often it reports. A terrain scene has no dem:
// section; these defaults are the run's (documented, not fitted).
//
// Young's modulus is softened as DEM practice does: 5e7 Pa lets a 0.5 m
// element under a few layers of its neighbours overlap about 3 % of its
// radius, and its Rayleigh time (~17 ms at 2,000 kg/m^3) is about 17 steps
// of 1 ms; a Hertz impact at 20 m/s lasts ~30 ms (30 steps).

namespace repose {

struct LiggghtsDebrisOptions {
  double youngs_modulus_pa = 5.0e7;   // elements and walls alike
  double poisson_ratio = 0.25;
  double time_step_s = 1.0e-3;
  double frame_interval_s = 0.0;      // element dumps every this; 0: duration / 20 (as the rigid engines)
  double force_interval_s = 0.05;     // the building forces averaged over bins of this (as debris_run.h)
  double box_margin_m = 60.0;         // the box reaches this far beyond the terrain and buildings in x and y
  double box_top_margin_m = 30.0;     // and this far above the highest element or building
  double neighbor_skin_radii = 0.5;   // the neighbour skin in radii of the largest element
  double front_quantile = 0.98;       // as debris_run.h's
  void validate() const;              // InputError naming the field
};

}  // namespace repose
