#pragma once
// The runout of a granular column collapse (Lube et al. 2004; Lajeunesse et
// al. 2004; Balmforth & Kerswell 2005), measured on grain sets:
//   slot (quasi-2-D): the front along +x from the back wall;
//   cylinder (axisymmetric): the radial front from the axis, per azimuth
//     sector, averaged.
// Both fronts leave out grains thrown ahead of the deposit (deposit_front_m).
// The normalised runout is (L_inf - L_0) / L_0 with L_0 the column's width
// (slot length or cylinder radius); L_inf - L_0 is taken as the final front
// minus the initial front, both measured the same way, so that the
// measurement's offset of about a grain radius cancels.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "validation/particles/grain_set.h"
#include "validation/particles/column_geometry.h"
#include "validation/particles/particle_observables.h"

namespace repose {

struct ColumnCollapse {
  ColumnGeometry geometry;
  double height_initial_m = 0.0;   // H0 measured: the top of the settled column (grain_top_m)
  double aspect_ratio = 0.0;       // H0 measured / width
  double front_initial_m = 0.0;    // from the back wall (slot) or the axis (cylinder)
  double front_final_m = 0.0;
  double front_final_spread_m = 0.0;  // cylinder: std over azimuth sectors; slot: 0
  double height_final_m = 0.0;     // top of the deposit
  double runout_normalised = 0.0;  // (front_final - front_initial) / width
  std::vector<double> time_s;      // the front over the run's frames
  std::vector<double> front_m;
};

struct ColumnCollapseOptions {
  double max_gap_grain_diameters = 2.0;  // a gap wider than this many mean grain diameters ends the deposit
  int sector_count = 16;                 // cylinder: azimuth sectors
};

// The front of one grain set, measured as described above.
double column_front_m(const ColumnGeometry& geometry, const GrainSet& grains, double max_gap_m,
                      int sector_count, double* spread_m = nullptr);

// frames: the grains at frame_time_s (the last is the final deposit); initial:
// the settled column before the gate was removed. InputError for no frames
// or an empty grain set.
ColumnCollapse measure_column_collapse(const ColumnGeometry& geometry, const GrainSet& initial,
                                       const std::vector<GrainSet>& frames, const std::vector<double>& frame_time_s,
                                       double grain_diameter_m, const ColumnCollapseOptions& options = {});

// CSV "time_s,front_m" of the front over the frames.
void write_runout_csv(const std::string& path, const ColumnCollapse& collapse);

// A particle reference's column and pile results as JSON members "column"
// and "pile" (each left out when absent; angles in degrees, as in files),
// written alike by every engine.
nlohmann::json column_results_json(const std::optional<ColumnCollapse>& column, const std::optional<FlankAngles>& pile);

}  // namespace repose
