#include "models/snow/snow_state.h"

namespace repose {

SnowState make_snow_state(const SnowModel& model) {
  SnowState s;
  s.depth_m.assign(model.maps.size(), ArrayXXdR::Zero(model.grid.ny, model.grid.nx));
  return s;
}

double snow_on_maps_m3(const SnowState& state, const Grid& grid) {
  double sum = 0.0;
  for (const ArrayXXdR& d : state.depth_m) sum += d.sum();
  return sum * grid.cell_area_m2();
}

double snow_imbalance_m3(const SnowState& state, const Grid& grid) {
  return state.ledger.fallen_m3 - (snow_on_maps_m3(state, grid) + state.ledger.left_scene_m3);
}

}  // namespace repose
