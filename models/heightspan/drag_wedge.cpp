#include "models/heightspan/drag_wedge.h"

#include <cmath>
#include <vector>

#include "models/core/base/error.h"
#include "models/ground/displacement.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_state.h"
#include "models/heightspan/ground_contact.h"

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
  const bool along_x = back[0] != 0;
  const int lanes = along_x ? map.grid.ny : map.grid.nx, length = along_x ? map.grid.nx : map.grid.ny;
  const int ahead = along_x ? -back[0] : -back[1];  // +1 or -1 along the axis
  std::vector<std::array<int, 2>> cells;
  for (int l = 0; l < lanes; ++l) {
    for (int s = 0; s < length; ++s) {
      const int a = ahead > 0 ? length - 1 - s : s;  // from the front end backwards
      const int i = along_x ? a : l, j = along_x ? l : a;
      if (map.count(map.cell(i, j)) == 0) continue;
      const int gi = i + off.di + (along_x ? ahead : 0), gj = j + off.dj + (along_x ? 0 : ahead);
      if (ground.contains(gi, gj)) {
        cells.push_back({gi, gj});
      } else {
        ++*off_grid;
      }
      break;
    }
  }
  return cells;
}

}  // namespace

double keep_in_wedge(const GroundModel& model, double compressed_m3, double fraction, const Eigen::Vector3d& motion_m,
                     DragWedge* wedge, GroundState* state) {
  if (!(fraction > 0.0) || !(compressed_m3 > 0.0) || !drags(model, motion_m)) return 0.0;
  const double kept = fraction * compressed_m3;
  state->ledger.compressed_m3 -= kept;
  wedge->volume_m3 += kept;
  wedge->back = back_step(motion_m);  // not {0, 0}: a drag moves sideways
  return kept;
}

void keep_pushed_ahead(double volume_m3, std::array<int, 2> back, DragWedge* wedge) {
  REPOSE_DEMAND(back[0] != 0 || back[1] != 0);  // pushed ahead only while moving sideways
  wedge->volume_m3 += volume_m3;
  wedge->back = back;
}

double lay_wedge(const GroundModel& model, const SpanMap& map, const Eigen::Vector3d& motion_m, DragWedge* wedge,
                 GroundState* state) {
  if (!(wedge->volume_m3 > 0.0) || drags(model, motion_m)) return 0.0;
  REPOSE_DEMAND(wedge->back[0] != 0 || wedge->back[1] != 0);  // a wedge is only kept while dragging
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
