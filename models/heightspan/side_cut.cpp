#include "models/heightspan/side_cut.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "models/ground/ground_model.h"
#include "models/ground/ground_state.h"
#include "models/heightspan/ground_contact.h"
#include "models/heightspan/span_lanes.h"

namespace repose {

namespace {

// Cuts the cells beside lane front f, going `outward` across the lanes, down to level_m.
double cut_cells(const GroundModel& model, bool x, const LaneFront& f, CellOffset off, int outward, double level_m,
                 double width_m, GroundState* state) {
  const Grid& g = model.grid;
  const double cells = width_m / g.cell_size_m;
  const int n = static_cast<int>(std::ceil(cells - 1e-9));
  double cut_m3 = 0.0;
  for (int d = 1; d <= n; ++d) {
    const int l = f.lane + outward * d;
    const int gi = (x ? f.i : l) + off.di, gj = (x ? l : f.j) + off.dj;
    if (!g.contains(gi, gj)) break;
    double& h = state->height.at(gi, gj);
    if (!(h > level_m)) continue;
    const double dz = std::min(1.0, cells - (d - 1)) * (h - level_m);
    h -= dz;
    cut_m3 += dz * g.cell_area_m2();
    state->erosion.touch(model.cell(gi, gj));
  }
  return cut_m3;
}

// The object's lowest point: the depth its lip cuts to (+inf without spans).
double lowest_bottom(const SpanMap& map) {
  double lowest_m = std::numeric_limits<double>::infinity();
  for (std::int64_t c = 0; c < static_cast<std::int64_t>(map.grid.cell_count()); ++c) {
    if (map.count(c) > 0) lowest_m = std::min(lowest_m, map.begin(c)[0].bottom_m);
  }
  return lowest_m;
}

}  // namespace

double cut_beside(const GroundModel& model, const SpanMap& map, double width_m, const Eigen::Vector3d& motion_m,
                  DragWedge* wedge, GroundState* state) {
  if (!(width_m > 0.0) || !drags(model, motion_m)) return 0.0;
  const std::array<int, 2> back = back_step(motion_m);
  const std::vector<LaneFront> fronts = lane_fronts(map, back);
  if (fronts.empty()) return 0.0;
  const CellOffset off = ground_offset(map.grid, model.grid);
  const double level_m = std::max(lowest_bottom(map), 0.0);
  const bool x = along_x(back);
  double cut_m3 = 0.0;
  cut_m3 += cut_cells(model, x, fronts.front(), off, -1, level_m, width_m, state);
  cut_m3 += cut_cells(model, x, fronts.back(), off, +1, level_m, width_m, state);
  if (cut_m3 > 0.0) keep_pushed_ahead(cut_m3, back, wedge);
  return cut_m3;
}

}  // namespace repose
