#include "models/heightspan/side_cut.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "models/ground/ground_model.h"
#include "models/ground/ground_state.h"
#include "models/heightspan/ground_contact.h"

namespace repose {

namespace {

// The map seen along the drag's main axis: lanes across it, positions along it.
struct Lanes {
  const SpanMap& map;
  bool along_x;
  int count() const { return along_x ? map.grid.ny : map.grid.nx; }
  int length() const { return along_x ? map.grid.nx : map.grid.ny; }
  int spans(int lane, int a) const { return map.count(along_x ? map.cell(a, lane) : map.cell(lane, a)); }
  double bottom(int lane, int a) const { return map.begin(along_x ? map.cell(a, lane) : map.cell(lane, a))[0].bottom_m; }
};

// The lane's frontmost position with a span (-1: none).
int front_of(const Lanes& lanes, int lane, int ahead) {
  for (int s = 0; s < lanes.length(); ++s) {
    const int a = ahead > 0 ? lanes.length() - 1 - s : s;  // from the front end backwards
    if (lanes.spans(lane, a) > 0) return a;
  }
  return -1;
}

// Cuts the cells beside lane `lane` at position `front`, going `outward` across the lanes, down to level_m.
double cut_cells(const GroundModel& model, const Lanes& lanes, CellOffset off, int lane, int outward, int front,
                 double level_m, double width_m, GroundState* state) {
  const Grid& g = model.grid;
  const double cells = width_m / g.cell_size_m;
  const int n = static_cast<int>(std::ceil(cells - 1e-9));
  double cut_m3 = 0.0;
  for (int d = 1; d <= n; ++d) {
    const int l = lane + outward * d;
    const int gi = (lanes.along_x ? front : l) + off.di, gj = (lanes.along_x ? l : front) + off.dj;
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

}  // namespace

double cut_beside(const GroundModel& model, const SpanMap& map, double width_m, const Eigen::Vector3d& motion_m,
                  DragWedge* wedge, GroundState* state) {
  if (!(width_m > 0.0) || !drags(model, motion_m)) return 0.0;
  const std::array<int, 2> back = back_step(motion_m);
  const Lanes lanes{map, back[0] != 0};
  const int ahead = lanes.along_x ? -back[0] : -back[1];
  int first = -1, last = -1;  // the outermost lanes with a span
  double lowest_m = std::numeric_limits<double>::infinity();  // the object's lowest point: the depth its lip cuts to
  for (int l = 0; l < lanes.count(); ++l) {
    for (int a = 0; a < lanes.length(); ++a) {
      if (lanes.spans(l, a) == 0) continue;
      if (first < 0) first = l;
      last = l;
      lowest_m = std::min(lowest_m, lanes.bottom(l, a));
    }
  }
  if (first < 0) return 0.0;
  const CellOffset off = ground_offset(map.grid, model.grid);
  const double level_m = std::max(lowest_m, 0.0);
  double cut_m3 = 0.0;
  cut_m3 += cut_cells(model, lanes, off, first, -1, front_of(lanes, first, ahead), level_m, width_m, state);
  cut_m3 += cut_cells(model, lanes, off, last, +1, front_of(lanes, last, ahead), level_m, width_m, state);
  if (cut_m3 > 0.0) keep_pushed_ahead(cut_m3, back, wedge);
  return cut_m3;
}

}  // namespace repose
