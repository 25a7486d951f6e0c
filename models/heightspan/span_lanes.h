#pragma once
// A held object's span map seen along a drag's main axis (x or y): lanes
// across it (rows along x, columns along y), and in each lane the frontmost
// cell with a span, where the object's front meets new ground. The wedge is
// laid in front of these cells (drag_wedge.h), what rolls over the lip goes
// onto them (drag_wedge.h: feed_over_lip), and the side cut starts beside
// the outermost two (side_cut.h).

#include <array>
#include <vector>

#include "models/heightspan/span_map.h"

namespace repose {

struct LaneFront {
  int lane = 0;  // the row (along x) or column (along y) across the drag
  int i = 0, j = 0;  // the map cell of the lane's frontmost span
};

// True when the drag whose cell step against it is `back` runs along x.
inline bool along_x(std::array<int, 2> back) { return back[0] != 0; }

// Every lane's frontmost cell with a span, going against `back` (the cell
// step against the drag, not {0, 0}), in lane order; lanes with no span are
// left out, so the first and last are the outermost lanes with a span.
std::vector<LaneFront> lane_fronts(const SpanMap& map, std::array<int, 2> back);

}  // namespace repose
