#include "models/heightspan/span_lanes.h"

#include "models/core/base/error.h"

namespace repose {

std::vector<LaneFront> lane_fronts(const SpanMap& map, std::array<int, 2> back) {
  REPOSE_DEMAND(back[0] != 0 || back[1] != 0);  // lanes only exist along a drag
  const bool x = along_x(back);
  const int lanes = x ? map.grid.ny : map.grid.nx, length = x ? map.grid.nx : map.grid.ny;
  const int ahead = x ? -back[0] : -back[1];  // +1 or -1 along the axis
  std::vector<LaneFront> fronts;
  for (int l = 0; l < lanes; ++l) {
    for (int s = 0; s < length; ++s) {
      const int a = ahead > 0 ? length - 1 - s : s;  // from the front end backwards
      const int i = x ? a : l, j = x ? l : a;
      if (map.count(map.cell(i, j)) == 0) continue;
      fronts.push_back({l, i, j});
      break;
    }
  }
  return fronts;
}

}  // namespace repose
