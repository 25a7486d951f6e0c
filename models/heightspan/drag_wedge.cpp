#include "models/heightspan/drag_wedge.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "models/core/base/error.h"
#include "models/ground/displacement.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_state.h"
#include "models/heightspan/ground_contact.h"
#include "models/heightspan/span_lanes.h"

namespace repose {

bool drags(const GroundModel& model, const Eigen::Vector3d& motion_m) {
  return is_drag(motion_m, 1e-3 * model.grid.cell_size_m);  // as the displacement decides (displacement.cpp)
}

namespace {

// The ground cells in front of the map's frontmost span of every lane along
// -back (one per lane that has a span and a cell ahead on the grid); lanes
// with a span but no cell on the grid count in *off_grid.
std::vector<std::array<int, 2>> cells_ahead(const SpanMap& map, const Grid& ground, std::array<int, 2> back,
                                            int* off_grid) {
  const CellOffset off = ground_offset(map.grid, ground);
  std::vector<std::array<int, 2>> cells;
  for (const LaneFront& f : lane_fronts(map, back)) {
    const int gi = f.i + off.di - back[0], gj = f.j + off.dj - back[1];
    if (ground.contains(gi, gj)) {
      cells.push_back({gi, gj});
    } else {
      ++*off_grid;
    }
  }
  return cells;
}

}  // namespace

double keep_in_wedge(const GroundModel& model, double compressed_m3, WedgeFractions fractions,
                     const Eigen::Vector3d& motion_m, DragWedge* wedge, GroundState* state) {
  const bool drag = drags(model, motion_m);
  if (drag) wedge->back = back_step(motion_m);  // not {0, 0}: a drag moves sideways; it drives what a press kept too
  const double fraction = drag ? fractions.drag : fractions.press;
  if (!(fraction > 0.0) || !(compressed_m3 > 0.0)) return 0.0;
  const double kept = fraction * compressed_m3;
  state->ledger.compressed_m3 -= kept;
  wedge->volume_m3 += kept;
  return kept;
}

void keep_pushed_ahead(double volume_m3, std::array<int, 2> back, DragWedge* wedge) {
  REPOSE_DEMAND(back[0] != 0 || back[1] != 0);  // pushed ahead only while moving sideways
  wedge->volume_m3 += volume_m3;
  wedge->back = back;
}

double feed_over_lip(const Grid& ground, double kept_m3, double fraction, DragWedge* wedge, SpanMap* map) {
  if (!(fraction > 0.0) || !(kept_m3 > 0.0)) return 0.0;
  REPOSE_DEMAND(wedge->back[0] != 0 || wedge->back[1] != 0);  // kept only while dragging
  const std::vector<LaneFront> fronts = lane_fronts(*map, wedge->back);
  if (fronts.empty()) return 0.0;
  const double fed_m3 = std::min(fraction * kept_m3, wedge->volume_m3);
  const double share_m = fed_m3 / static_cast<double>(fronts.size()) / ground.cell_area_m2();
  for (const LaneFront& f : fronts) {
    const std::int64_t c = map->cell(f.i, f.j);
    map->begin(c)[0].material_m += share_m;
    push_overflow_up(map, c);
  }
  wedge->volume_m3 -= fed_m3;
  return fed_m3;
}

double lay_wedge(const GroundModel& model, const SpanMap& map, const Eigen::Vector3d& motion_m, DragWedge* wedge,
                 GroundState* state) {
  if (!(wedge->volume_m3 > 0.0) || drags(model, motion_m)) return 0.0;
  if (wedge->back[0] == 0 && wedge->back[1] == 0) {  // only pressed material, no drag yet to drive it
    if (motion_m.z() > 0.0) {  // the object leaves without dragging: what it pressed stays compressed
      state->ledger.compressed_m3 += wedge->volume_m3;
      wedge->volume_m3 = 0.0;
    }
    return 0.0;
  }
  int off_grid = 0;
  const std::vector<std::array<int, 2>> cells = cells_ahead(map, model.grid, wedge->back, &off_grid);
  const int lanes = static_cast<int>(cells.size()) + off_grid;
  if (lanes == 0) {  // no span left on the map: nothing to lay it in front of
    state->ledger.left_grid_m3 += wedge->volume_m3;
    wedge->volume_m3 = 0.0;
    return 0.0;
  }
  const double share_m3 = wedge->volume_m3 / lanes;
  for (const auto& c : cells) {
    state->height.at(c[0], c[1]) += share_m3 / model.grid.cell_area_m2();
    state->erosion.touch(model.cell(c[0], c[1]));
  }
  state->ledger.left_grid_m3 += share_m3 * off_grid;
  const double laid = share_m3 * static_cast<double>(cells.size());
  wedge->volume_m3 = 0.0;
  return laid;
}

}  // namespace repose
