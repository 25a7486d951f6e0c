#pragma once
// What a snow run changes: the snow depth on every map and the ledger of
// where the snow went. Snow fallen = snow on the maps + snow that left the
// scene, to round-off (snow_state_test / simulate_snow_test check it).

#include <vector>

#include "models/core/geometry/height_field.h"
#include "models/snow/snow_model.h"

namespace repose {

struct SnowLedger {
  double fallen_m3 = 0.0;      // sum over steps and cells of P * dM * cell area
  double left_scene_m3 = 0.0;  // pushed off a map with no map below it
};

struct SnowState {
  double time_s = 0.0;
  std::vector<ArrayXXdR> depth_m;  // per map, ny x nx, >= 0, 0 outside the snow-possible area
  SnowLedger ledger;
};

SnowState make_snow_state(const SnowModel& model);

// Snow on all maps (m^3).
double snow_on_maps_m3(const SnowState& state, const Grid& grid);
// fallen - (on maps + left the scene): round-off only.
double snow_imbalance_m3(const SnowState& state, const Grid& grid);

}  // namespace repose
